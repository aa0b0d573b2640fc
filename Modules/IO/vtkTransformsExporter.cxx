#include "vtkTransformsExporter.h"

#include "lfdJsonFields.h"
#include "vtkCameraRig.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkTransformsExporter);

namespace
{
using lfd::io::Json;

// The intrinsics of a view as transforms.json keys.
Json ViewIntrinsics(vtkCameraRig* rig, int view, bool withK3)
{
  double K[9];
  double d[5];
  rig->GetIntrinsics(view, K);
  rig->GetDistortion(view, d);
  // The file's principal point counts from the top-left pixel's corner.
  Json keys = { { "fl_x", K[0] },
    { "fl_y", K[4] },
    { "cx", K[2] + 0.5 },
    { "cy", K[5] + 0.5 },
    { "k1", d[0] },
    { "k2", d[1] },
    { "p1", d[2] },
    { "p2", d[3] } };
  if (withK3)
  {
    keys["k3"] = d[4];
  }
  return keys;
}

// The camera-to-world matrix in OpenGL camera axes (y and z negated).
Json TransformMatrix(vtkCameraRig* rig, int view)
{
  double R[9];
  double center[3];
  rig->GetRotation(view, R);
  rig->GetCameraCenter(view, center);
  const double flip[3] = { 1.0, -1.0, -1.0 };
  Json matrix = Json::array();
  for (int r = 0; r < 3; ++r)
  {
    matrix.push_back({ flip[0] * R[r], flip[1] * R[3 + r], flip[2] * R[6 + r], center[r] });
  }
  matrix.push_back({ 0.0, 0.0, 0.0, 1.0 });
  return matrix;
}
}

//------------------------------------------------------------------------------
vtkTransformsExporter::vtkTransformsExporter() = default;

//------------------------------------------------------------------------------
vtkTransformsExporter::~vtkTransformsExporter() = default;

//------------------------------------------------------------------------------
bool vtkTransformsExporter::FormatCalibration(vtkCameraRig* rig,
  const std::vector<std::string>& imageNames,
  std::map<std::string, std::string>& files,
  std::string& error)
{
  const int views = rig->GetNumberOfViews();
  bool withK3 = false;
  for (int i = 0; i < views; ++i)
  {
    error = CheckNoSkew(rig, i);
    if (!error.empty())
    {
      return false;
    }
    double d[5];
    rig->GetDistortion(i, d);
    withK3 = withK3 || d[4] != 0.0;
  }
  bool shared = true;
  const Json first = ViewIntrinsics(rig, 0, withK3);
  for (int i = 1; i < views && shared; ++i)
  {
    shared = ViewIntrinsics(rig, i, withK3) == first;
  }
  Json document = {
    { "camera_model", "OPENCV" }, { "w", rig->GetImageSize()[0] }, { "h", rig->GetImageSize()[1] }
  };
  if (shared)
  {
    document.update(first);
  }
  Json frames = Json::array();
  for (int i = 0; i < views; ++i)
  {
    Json frame = { { "file_path", "images/" + imageNames[i] } };
    if (!shared)
    {
      frame.update(ViewIntrinsics(rig, i, withK3));
    }
    frame["transform_matrix"] = TransformMatrix(rig, i);
    frames.push_back(frame);
  }
  document["frames"] = frames;
  files["transforms.json"] = document.dump(2) + "\n";
  return true;
}

//------------------------------------------------------------------------------
void vtkTransformsExporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
