#include "vtkColmapExporter.h"

#include "lfdColmapModel.h"
#include "vtkCameraRig.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <array>

vtkStandardNewMacro(vtkColmapExporter);

namespace
{
// fx fy cx cy k1 k2 p1 p2 k3: what makes two views one COLMAP camera.
using Intrinsics = std::array<double, 9>;

Intrinsics ViewIntrinsics(vtkCameraRig* rig, int view)
{
  double K[9];
  double d[5];
  rig->GetIntrinsics(view, K);
  rig->GetDistortion(view, d);
  return { K[0], K[4], K[2], K[5], d[0], d[1], d[2], d[3], d[4] };
}
}

//------------------------------------------------------------------------------
vtkColmapExporter::vtkColmapExporter() = default;

//------------------------------------------------------------------------------
vtkColmapExporter::~vtkColmapExporter() = default;

//------------------------------------------------------------------------------
bool vtkColmapExporter::FormatCalibration(vtkCameraRig* rig,
  const std::vector<std::string>& imageNames,
  std::map<std::string, std::string>& files,
  std::string& error)
{
  const int* size = rig->GetImageSize();
  std::map<Intrinsics, int> cameraIds;
  lfd::io::ColmapModel model;
  for (int i = 0; i < rig->GetNumberOfViews(); ++i)
  {
    error = CheckNoSkew(rig, i);
    if (!error.empty())
    {
      return false;
    }
    const Intrinsics intrinsics = ViewIntrinsics(rig, i);
    auto camera = cameraIds.find(intrinsics);
    if (camera == cameraIds.end())
    {
      const int id = static_cast<int>(cameraIds.size()) + 1;
      camera = cameraIds.emplace(intrinsics, id).first;
      double K[9];
      double distortion[5];
      rig->GetIntrinsics(i, K);
      rig->GetDistortion(i, distortion);
      model.Cameras[id] = lfd::io::OpenCVToColmapCamera(K, distortion, size[0], size[1]);
    }
    lfd::io::ColmapImage image;
    image.Id = i + 1;
    double R[9];
    rig->GetRotation(i, R);
    rig->GetTranslation(i, image.T);
    const double rotation[3][3] = {
      { R[0], R[1], R[2] }, { R[3], R[4], R[5] }, { R[6], R[7], R[8] }
    };
    vtkMath::Matrix3x3ToQuaternion(rotation, image.Q);
    const double sign = image.Q[0] < 0.0 ? -1.0 : 1.0; // q and -q are one rotation
    for (double& value : image.Q)
    {
      value *= sign;
    }
    image.CameraId = camera->second;
    image.Name = imageNames[i];
    model.Images.push_back(image);
  }
  for (const auto& file : lfd::io::FormatColmapModel(model, this->Binary))
  {
    files["sparse/" + file.first] = file.second;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkColmapExporter::GetMarkerFile()
{
  return this->Binary ? "sparse/cameras.bin" : "sparse/cameras.txt";
}

//------------------------------------------------------------------------------
void vtkColmapExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Binary: " << this->Binary << "\n";
}
