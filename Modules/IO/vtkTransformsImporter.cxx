#include "vtkTransformsImporter.h"

#include "lfdFileUtilities.h"
#include "lfdJsonFields.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkTransformsImporter);

namespace
{
using lfd::io::FieldError;
using lfd::io::Json;

// An intrinsic of a frame: its own key, else the file's (top level).
struct FrameKeys
{
  const Json& Top;
  const Json& Frame;
  std::string FramePath;

  // The value and its path, or nullptr when neither level has the key.
  const Json* Find(const char* key, std::string& path) const
  {
    if (const Json* own = lfd::io::FindMember(this->Frame, this->FramePath, key))
    {
      path = lfd::io::MemberPath(this->FramePath, key);
      return own;
    }
    path = key;
    return lfd::io::FindMember(this->Top, "", key);
  }

  double Number(const char* key, double fallback) const
  {
    std::string path;
    const Json* value = this->Find(key, path);
    return value ? lfd::io::GetNumber(*value, path) : fallback;
  }

  double RequiredNumber(const char* key) const
  {
    std::string path;
    const Json* value = this->Find(key, path);
    if (!value)
    {
      throw FieldError(lfd::io::MemberPath(this->FramePath, key),
        "missing (neither the frame nor the file gives it)");
    }
    return lfd::io::GetNumber(*value, path);
  }
};

// K and distortion of a frame (see the class documentation).
void ReadIntrinsics(const FrameKeys& keys, int size[2], double K[9], double distortion[5])
{
  std::string path;
  if (const Json* model = keys.Find("camera_model", path))
  {
    const std::string name = lfd::io::GetString(*model, path);
    if (name != "OPENCV" && name != "PINHOLE")
    {
      throw FieldError(path, "camera model \"" + name + "\" is not supported (OPENCV, PINHOLE)");
    }
  }
  const char* const sizeKeys[2] = { "w", "h" };
  for (int c = 0; c < 2; ++c)
  {
    const Json* value = keys.Find(sizeKeys[c], path);
    if (!value)
    {
      throw FieldError(lfd::io::MemberPath(keys.FramePath, sizeKeys[c]),
        "missing (the image size w, h is required)");
    }
    size[c] = static_cast<int>(lfd::io::GetInteger(*value, path, 1, 1 << 30));
  }
  double fx = 0.0;
  if (keys.Find("fl_x", path))
  {
    fx = keys.RequiredNumber("fl_x");
  }
  else if (const Json* angle = keys.Find("camera_angle_x", path))
  {
    const double radians = lfd::io::GetNumber(*angle, path);
    if (!(radians > 0.0 && radians < M_PI))
    {
      throw FieldError(path, "expected an angle in radians between 0 and pi");
    }
    fx = 0.5 * size[0] / std::tan(0.5 * radians);
  }
  else
  {
    throw FieldError(
      lfd::io::MemberPath(keys.FramePath, "fl_x"), "missing (give fl_x or camera_angle_x)");
  }
  std::fill(K, K + 9, 0.0);
  K[0] = fx;
  K[4] = keys.Number("fl_y", fx);
  // The principal point counts from the top-left pixel's corner.
  K[2] = keys.Number("cx", 0.5 * size[0]) - 0.5;
  K[5] = keys.Number("cy", 0.5 * size[1]) - 0.5;
  K[8] = 1.0;
  const char* const coefficients[5] = { "k1", "k2", "p1", "p2", "k3" };
  for (int c = 0; c < 5; ++c)
  {
    distortion[c] = keys.Number(coefficients[c], 0.0);
  }
}

// R and t of a frame from its OpenGL camera-to-world matrix.
void ReadPose(const Json& frame, const std::string& framePath, double R[9], double t[3])
{
  const std::string path = lfd::io::MemberPath(framePath, "transform_matrix");
  const Json& matrix = lfd::io::RequireMember(frame, framePath, "transform_matrix");
  if (!matrix.is_array() || matrix.size() != 4)
  {
    throw FieldError(path, "expected 4 rows of 4 numbers, found " + lfd::io::Describe(matrix));
  }
  double M[4][4];
  for (size_t r = 0; r < 4; ++r)
  {
    const std::vector<double> row =
      lfd::io::GetNumbers(matrix[r], lfd::io::ElementPath(path, r), 4);
    std::copy(row.begin(), row.end(), M[r]);
  }
  if (M[3][0] != 0.0 || M[3][1] != 0.0 || M[3][2] != 0.0 || M[3][3] != 1.0)
  {
    throw FieldError(
      lfd::io::ElementPath(path, 3), "expected [0, 0, 0, 1] (a rigid camera-to-world matrix)");
  }
  // OpenCV axes = OpenGL axes with y and z negated; R = (M3 diag(1,-1,-1))^T.
  const double flip[3] = { 1.0, -1.0, -1.0 };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      R[3 * r + c] = flip[r] * M[c][r];
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    t[r] = -(R[3 * r] * M[0][3] + R[3 * r + 1] * M[1][3] + R[3 * r + 2] * M[2][3]);
  }
}
}

//------------------------------------------------------------------------------
vtkTransformsImporter::vtkTransformsImporter() = default;

//------------------------------------------------------------------------------
vtkTransformsImporter::~vtkTransformsImporter() = default;

//------------------------------------------------------------------------------
bool vtkTransformsImporter::ParseCalibration(std::vector<CalibratedView>& views,
  unsigned long& errorCode,
  std::string& error)
{
  const std::string file = this->FileName;
  Json document;
  if (!lfd::io::ParseJsonFile(file, document, error))
  {
    std::string problem;
    errorCode = lfd::io::CheckRegularFile(file, problem) ? vtkErrorCode::FileFormatError
                                                         : vtkErrorCode::FileNotFoundError;
    return false;
  }
  try
  {
    const Json& frames = lfd::io::RequireMember(document, "", "frames");
    if (!frames.is_array() || frames.empty())
    {
      throw FieldError("frames", "expected a non-empty array, found " + lfd::io::Describe(frames));
    }
    const std::string folder = this->GetImageFolder();
    for (size_t i = 0; i < frames.size(); ++i)
    {
      const std::string framePath = lfd::io::ElementPath("frames", i);
      const FrameKeys keys{ document, frames[i], framePath };
      CalibratedView view;
      view.Where = file + ": field \"" + framePath + "\"";
      view.Name = lfd::io::GetPath(lfd::io::RequireMember(frames[i], framePath, "file_path"),
        lfd::io::MemberPath(framePath, "file_path"));
      view.Image = lfd::io::ResolvePath(folder, view.Name);
      int size[2];
      ReadIntrinsics(keys, size, view.K, view.Distortion);
      if (i == 0)
      {
        this->CalibratedImageSize[0] = size[0];
        this->CalibratedImageSize[1] = size[1];
      }
      else if (size[0] != this->CalibratedImageSize[0] || size[1] != this->CalibratedImageSize[1])
      {
        throw FieldError(framePath,
          "w x h is " + std::to_string(size[0]) + "x" + std::to_string(size[1]) +
            ", frames[0] has " + std::to_string(this->CalibratedImageSize[0]) + "x" +
            std::to_string(this->CalibratedImageSize[1]) + " (a light field has one image size)");
      }
      ReadPose(frames[i], framePath, view.R, view.t);
      views.push_back(view);
    }
  }
  catch (const FieldError& e)
  {
    errorCode = vtkErrorCode::FileFormatError;
    error = file + ": " + e.what();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkTransformsImporter::GetFormatDescription()
{
  return "transforms.json (nerfstudio / instant-ngp)";
}

//------------------------------------------------------------------------------
std::string vtkTransformsImporter::DescribeField(const std::string& field)
{
  return field == "K" ? "fl_x fl_y cx cy"
    : field == "R"    ? "transform_matrix (rotation)"
    : field == "t"    ? "transform_matrix (position)"
                      : "k1 k2 p1 p2 k3";
}

//------------------------------------------------------------------------------
void vtkTransformsImporter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
