#include "vtkColmapImporter.h"

#include "lfdColmapModel.h"
#include "lfdFileUtilities.h"
#include "vtkErrorCode.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

vtkStandardNewMacro(vtkColmapImporter);

namespace
{
using lfd::io::ColmapModelError;

// The rotation of an image's quaternion (Hamilton, w first), normalised.
void ImageRotation(const lfd::io::ColmapImage& image, double R[9])
{
  const double norm = std::sqrt(image.Q[0] * image.Q[0] + image.Q[1] * image.Q[1] +
    image.Q[2] * image.Q[2] + image.Q[3] * image.Q[3]);
  if (!(norm > 1e-12) || !std::isfinite(norm))
  {
    throw ColmapModelError(image.Where, "QW QX QY QZ: not a rotation (a zero quaternion)");
  }
  double unit[4];
  for (int c = 0; c < 4; ++c)
  {
    unit[c] = image.Q[c] / norm;
  }
  double rotation[3][3];
  vtkMath::QuaternionToMatrix3x3(unit, rotation);
  for (int r = 0; r < 3; ++r)
  {
    std::copy(rotation[r], rotation[r] + 3, R + 3 * r);
  }
}
}

//------------------------------------------------------------------------------
vtkColmapImporter::vtkColmapImporter() = default;

//------------------------------------------------------------------------------
vtkColmapImporter::~vtkColmapImporter() = default;

//------------------------------------------------------------------------------
bool vtkColmapImporter::ParseCalibration(std::vector<CalibratedView>& views,
  unsigned long& errorCode,
  std::string& error)
{
  try
  {
    const lfd::io::ColmapModel model =
      lfd::io::ReadColmapModel(lfd::io::TrimSeparators(this->FileName));
    this->BinaryModel = model.Binary;
    const std::string camerasFile = std::filesystem::path(model.CamerasFile).filename().string();
    const std::string imageFolder = this->GetImageFolder();
    // Every camera converted, used or not: a malformed one is an error anyway.
    struct OpenCVCamera
    {
      double K[9];
      double Distortion[5];
    };
    std::map<long long, OpenCVCamera> opencv;
    for (const auto& camera : model.Cameras)
    {
      OpenCVCamera& converted = opencv[camera.first];
      lfd::io::ColmapCameraToOpenCV(camera.second, converted.K, converted.Distortion);
    }
    std::map<std::string, std::string> names;
    const lfd::io::ColmapCamera* sized = nullptr;
    for (const lfd::io::ColmapImage& image : model.Images)
    {
      const auto first = names.find(image.Name);
      if (first != names.end())
      {
        throw ColmapModelError(
          image.Where, "NAME " + image.Name + " is repeated (first on " + first->second + ")");
      }
      names[image.Name] = image.Where;
      CalibratedView view;
      ImageRotation(image, view.R);
      std::copy(image.T, image.T + 3, view.t);
      const auto camera = model.Cameras.find(image.CameraId);
      if (camera == model.Cameras.end())
      {
        throw ColmapModelError(
          image.Where, "CAMERA_ID " + std::to_string(image.CameraId) + " is not in " + camerasFile);
      }
      if (!sized)
      {
        sized = &camera->second;
      }
      else if (camera->second.Width != sized->Width || camera->second.Height != sized->Height)
      {
        throw ColmapModelError(camera->second.Where,
          "the camera is " + std::to_string(camera->second.Width) + "x" +
            std::to_string(camera->second.Height) + ", " + sized->Where + " is " +
            std::to_string(sized->Width) + "x" + std::to_string(sized->Height) +
            " (a light field has one image size)");
      }
      const OpenCVCamera& converted = opencv[camera->first];
      std::copy(converted.K, converted.K + 9, view.K);
      std::copy(converted.Distortion, converted.Distortion + 5, view.Distortion);
      view.Where = image.Where;
      view.CameraWhere = camera->second.Where;
      view.Name = image.Name;
      view.Image = lfd::io::ResolvePath(imageFolder, image.Name);
      views.push_back(view);
    }
    if (views.empty())
    {
      throw ColmapModelError(model.ImagesFile, "no registered image");
    }
    this->CalibratedImageSize[0] = sized->Width;
    this->CalibratedImageSize[1] = sized->Height;
  }
  catch (const ColmapModelError& e)
  {
    errorCode = vtkErrorCode::FileFormatError;
    error = e.what();
    return false;
  }
  catch (const std::runtime_error& e)
  {
    errorCode = vtkErrorCode::FileNotFoundError;
    error = e.what();
    return false;
  }
  std::sort(views.begin(),
    views.end(),
    [](const CalibratedView& a, const CalibratedView& b) { return a.Name < b.Name; });
  return true;
}

//------------------------------------------------------------------------------
std::string vtkColmapImporter::GetFormatDescription()
{
  return this->BinaryModel ? "COLMAP binary model (cameras.bin, images.bin)"
                           : "COLMAP text model (cameras.txt, images.txt)";
}

//------------------------------------------------------------------------------
std::string vtkColmapImporter::DescribeField(const std::string& field)
{
  return field == "K" ? "camera parameters"
    : field == "R"    ? "QW QX QY QZ"
    : field == "t"    ? "TX TY TZ"
                      : "distortion parameters";
}

//------------------------------------------------------------------------------
void vtkColmapImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BinaryModel: " << this->BinaryModel << "\n";
}
