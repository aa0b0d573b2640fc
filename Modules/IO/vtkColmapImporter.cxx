#include "vtkColmapImporter.h"

#include "lfdFileUtilities.h"
#include "lfdTextFields.h"
#include "vtkErrorCode.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

vtkStandardNewMacro(vtkColmapImporter);

namespace
{
// A malformed model file: the message already names file and line.
struct ModelError : std::runtime_error
{
  ModelError(const std::string& where, const std::string& problem)
    : std::runtime_error(where + ": " + problem)
  {
  }
};

// A camera model: its parameter names, in COLMAP's order.
struct CameraModel
{
  const char* Name;
  std::vector<std::string> Parameters;
};

const std::vector<CameraModel>& SupportedModels()
{
  static const std::vector<CameraModel> models = {
    { "SIMPLE_PINHOLE", { "f", "cx", "cy" } },
    { "PINHOLE", { "fx", "fy", "cx", "cy" } },
    { "SIMPLE_RADIAL", { "f", "cx", "cy", "k" } },
    { "RADIAL", { "f", "cx", "cy", "k1", "k2" } },
    { "OPENCV", { "fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2" } },
    { "FULL_OPENCV", { "fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6" } },
  };
  return models;
}

struct ModelCamera
{
  std::string Where;
  int Width = 0;
  int Height = 0;
  double K[9] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0 };
  double Distortion[5] = { 0.0, 0.0, 0.0, 0.0, 0.0 };
};

// The lines of a model file that are not comments, with their numbers.
// Blank lines are kept: the second line of an image (its 2D points) may be
// empty and still counts.
struct ModelLine
{
  int Number;
  std::string Text;
};

std::vector<ModelLine> ReadModelLines(const std::string& path)
{
  const std::vector<std::string> text = lfd::io::ReadTextLines(path);
  std::vector<ModelLine> lines;
  for (size_t index = 0; index < text.size(); ++index)
  {
    const size_t first = text[index].find_first_not_of(" \t\r");
    if (first == std::string::npos || text[index][first] != '#')
    {
      lines.push_back({ static_cast<int>(index) + 1, text[index] });
    }
  }
  return lines;
}

std::string Where(const std::string& path, int line)
{
  return path + ":" + std::to_string(line);
}

double Number(const std::string& where, const std::string& field, const std::string& token)
{
  double value = 0.0;
  std::string problem;
  if (!lfd::io::ParseFiniteNumber(token, value, problem))
  {
    throw ModelError(where, field + " " + problem);
  }
  return value;
}

long long Integer(const std::string& where,
  const std::string& field,
  const std::string& token,
  long long minimum,
  long long maximum)
{
  long long value = 0;
  std::string problem;
  if (!lfd::io::ParseInteger(token, minimum, maximum, value, problem))
  {
    throw ModelError(where, field + " " + problem);
  }
  return value;
}

// One camera line: CAMERA_ID MODEL WIDTH HEIGHT PARAMS...
std::pair<long long, ModelCamera> ParseCamera(const std::string& where,
  const std::vector<std::string>& fields)
{
  if (fields.size() < 4)
  {
    throw ModelError(where,
      "expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS..., found " + std::to_string(fields.size()) +
        " fields");
  }
  const long long id = Integer(where, "CAMERA_ID", fields[0], 0, LLONG_MAX);
  const auto& models = SupportedModels();
  const auto model = std::find_if(models.begin(),
    models.end(),
    [&](const CameraModel& candidate) { return fields[1] == candidate.Name; });
  if (model == models.end())
  {
    std::string names;
    for (const CameraModel& candidate : models)
    {
      names += (names.empty() ? "" : ", ") + std::string(candidate.Name);
    }
    throw ModelError(where, "MODEL " + fields[1] + " is not supported (supported: " + names + ")");
  }
  if (fields.size() != 4 + model->Parameters.size())
  {
    throw ModelError(where,
      std::string("a ") + model->Name + " camera has " + std::to_string(model->Parameters.size()) +
        " parameters, found " + std::to_string(fields.size() - 4));
  }
  ModelCamera camera;
  camera.Where = where;
  camera.Width = static_cast<int>(Integer(where, "WIDTH", fields[2], 1, INT_MAX));
  camera.Height = static_cast<int>(Integer(where, "HEIGHT", fields[3], 1, INT_MAX));
  std::map<std::string, double> value;
  for (size_t p = 0; p < model->Parameters.size(); ++p)
  {
    value[model->Parameters[p]] = Number(where, model->Parameters[p], fields[4 + p]);
  }
  for (const char* rational : { "k4", "k5", "k6" })
  {
    if (value.count(rational) && value[rational] != 0.0)
    {
      throw ModelError(where,
        std::string(rational) +
          " is not 0: the rational terms of FULL_OPENCV have no equivalent in the rig's "
          "distortion (k1, k2, p1, p2, k3)");
    }
  }
  const bool single = value.count("f") != 0;
  camera.K[0] = single ? value["f"] : value["fx"];
  camera.K[4] = single ? value["f"] : value["fy"];
  // COLMAP's pixel centres are at half-integers, the rig's at integers.
  camera.K[2] = value["cx"] - 0.5;
  camera.K[5] = value["cy"] - 0.5;
  camera.Distortion[0] = value.count("k") ? value["k"] : value["k1"];
  camera.Distortion[1] = value["k2"];
  camera.Distortion[2] = value["p1"];
  camera.Distortion[3] = value["p2"];
  camera.Distortion[4] = value["k3"];
  return { id, camera };
}

std::map<long long, ModelCamera> ParseCameras(const std::string& path)
{
  std::map<long long, ModelCamera> cameras;
  for (const ModelLine& line : ReadModelLines(path))
  {
    const std::vector<std::string> fields = lfd::io::SplitFields(line.Text);
    if (fields.empty())
    {
      continue;
    }
    const std::string where = Where(path, line.Number);
    auto parsed = ParseCamera(where, fields);
    if (cameras.count(parsed.first))
    {
      throw ModelError(where,
        "CAMERA_ID " + fields[0] + " is repeated (first on " + cameras[parsed.first].Where + ")");
    }
    cameras.emplace(parsed);
  }
  if (cameras.empty())
  {
    throw ModelError(path, "no camera");
  }
  return cameras;
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
  const std::string folder = lfd::io::TrimSeparators(this->FileName);
  const std::string imagesPath = folder + "/images.txt";
  try
  {
    const std::map<long long, ModelCamera> cameras = ParseCameras(folder + "/cameras.txt");
    const std::vector<ModelLine> lines = ReadModelLines(imagesPath);
    const std::string imageFolder = this->GetImageFolder();
    std::map<long long, std::string> ids;
    std::map<std::string, std::string> names;
    const ModelCamera* sized = nullptr;
    for (size_t i = 0; i < lines.size(); ++i)
    {
      const std::vector<std::string> fields = lfd::io::SplitFields(lines[i].Text);
      if (fields.empty())
      {
        continue;
      }
      // The next line (its 2D points, possibly empty) belongs to this image.
      ++i;
      const std::string where = Where(imagesPath, lines[i - 1].Number);
      if (fields.size() != 10)
      {
        throw ModelError(where,
          "expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (10 fields), found " +
            std::to_string(fields.size()));
      }
      const long long id = Integer(where, "IMAGE_ID", fields[0], 0, LLONG_MAX);
      if (ids.count(id))
      {
        throw ModelError(
          where, "IMAGE_ID " + fields[0] + " is repeated (first on " + ids[id] + ")");
      }
      ids[id] = where;
      const std::string& name = fields[9];
      if (names.count(name))
      {
        throw ModelError(where, "NAME " + name + " is repeated (first on " + names[name] + ")");
      }
      names[name] = where;
      double q[4];
      const char* const quaternion[4] = { "QW", "QX", "QY", "QZ" };
      for (int c = 0; c < 4; ++c)
      {
        q[c] = Number(where, quaternion[c], fields[1 + c]);
      }
      const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(norm > 1e-12) || !std::isfinite(norm))
      {
        throw ModelError(where, "QW QX QY QZ: not a rotation (a zero quaternion)");
      }
      CalibratedView view;
      const char* const translation[3] = { "TX", "TY", "TZ" };
      for (int c = 0; c < 3; ++c)
      {
        view.t[c] = Number(where, translation[c], fields[5 + c]);
      }
      const long long cameraId = Integer(where, "CAMERA_ID", fields[8], 0, LLONG_MAX);
      const auto camera = cameras.find(cameraId);
      if (camera == cameras.end())
      {
        throw ModelError(where, "CAMERA_ID " + fields[8] + " is not in cameras.txt");
      }
      if (!sized)
      {
        sized = &camera->second;
      }
      else if (camera->second.Width != sized->Width || camera->second.Height != sized->Height)
      {
        throw ModelError(camera->second.Where,
          "the camera is " + std::to_string(camera->second.Width) + "x" +
            std::to_string(camera->second.Height) + ", " + sized->Where + " is " +
            std::to_string(sized->Width) + "x" + std::to_string(sized->Height) +
            " (a light field has one image size)");
      }
      double unit[4];
      for (int c = 0; c < 4; ++c)
      {
        unit[c] = q[c] / norm;
      }
      double rotation[3][3];
      vtkMath::QuaternionToMatrix3x3(unit, rotation);
      for (int r = 0; r < 3; ++r)
      {
        std::copy(rotation[r], rotation[r] + 3, view.R + 3 * r);
      }
      std::copy(camera->second.K, camera->second.K + 9, view.K);
      std::copy(camera->second.Distortion, camera->second.Distortion + 5, view.Distortion);
      view.Where = where;
      view.CameraWhere = camera->second.Where;
      view.Name = name;
      view.Image = lfd::io::ResolvePath(imageFolder, name);
      views.push_back(view);
    }
    if (views.empty())
    {
      throw ModelError(imagesPath, "no registered image");
    }
    this->CalibratedImageSize[0] = sized->Width;
    this->CalibratedImageSize[1] = sized->Height;
  }
  catch (const ModelError& e)
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
  return "COLMAP text model (cameras.txt, images.txt)";
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
}
