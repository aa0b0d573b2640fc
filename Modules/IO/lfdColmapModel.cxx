#include "lfdColmapModel.h"

#include "lfdFileUtilities.h"
#include "lfdTextFields.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

namespace lfd
{
namespace io
{
namespace
{
namespace fs = std::filesystem;

// The points of a 2D point record in images.bin: float64 X, Y, uint64 POINT3D_ID.
constexpr uint64_t Point2DBytes = 8 + 8 + 8;
// A NAME longer than this is a corrupt file, not a path (PATH_MAX on Linux).
constexpr size_t MaximumNameBytes = 4096;

const ColmapCameraModel* FindModel(const std::string& name)
{
  for (const ColmapCameraModel& model : ColmapCameraModels())
  {
    if (name == model.Name)
    {
      return &model;
    }
  }
  return nullptr;
}

std::string SupportedModelNames()
{
  std::string names;
  for (const ColmapCameraModel& model : ColmapCameraModels())
  {
    if (!model.Parameters.empty())
    {
      names += (names.empty() ? "" : ", ") + std::string(model.Name);
    }
  }
  return names;
}

// A model the rig can hold, or the error naming `model`.
const ColmapCameraModel& SupportedModel(const std::string& where,
  const ColmapCameraModel* model,
  const std::string& given)
{
  if (!model || model->Parameters.empty())
  {
    throw ColmapModelError(
      where, given + " is not supported (supported: " + SupportedModelNames() + ")");
  }
  return *model;
}

void AddCamera(ColmapModel& model, long long id, ColmapCamera camera)
{
  const auto first = model.Cameras.find(id);
  if (first != model.Cameras.end())
  {
    throw ColmapModelError(camera.Where,
      "CAMERA_ID " + std::to_string(id) + " is repeated (first on " + first->second.Where + ")");
  }
  model.Cameras.emplace(id, std::move(camera));
}

void AddImage(ColmapModel& model, std::map<long long, std::string>& ids, ColmapImage image)
{
  const auto first = ids.find(image.Id);
  if (first != ids.end())
  {
    throw ColmapModelError(image.Where,
      "IMAGE_ID " + std::to_string(image.Id) + " is repeated (first on " + first->second + ")");
  }
  ids[image.Id] = image.Where;
  model.Images.push_back(std::move(image));
}

//------------------------------------------------------------------------------
// Text model.

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
  const std::vector<std::string> text = ReadTextLines(path);
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

double TextNumber(const std::string& where, const std::string& field, const std::string& token)
{
  double value = 0.0;
  std::string problem;
  if (!ParseFiniteNumber(token, value, problem))
  {
    throw ColmapModelError(where, field + " " + problem);
  }
  return value;
}

long long TextInteger(const std::string& where,
  const std::string& field,
  const std::string& token,
  long long minimum,
  long long maximum)
{
  long long value = 0;
  std::string problem;
  if (!ParseInteger(token, minimum, maximum, value, problem))
  {
    throw ColmapModelError(where, field + " " + problem);
  }
  return value;
}

// One camera line: CAMERA_ID MODEL WIDTH HEIGHT PARAMS...
void ParseCameraLine(ColmapModel& model,
  const std::string& where,
  const std::vector<std::string>& fields)
{
  if (fields.size() < 4)
  {
    throw ColmapModelError(where,
      "expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS..., found " + std::to_string(fields.size()) +
        " fields");
  }
  const long long id = TextInteger(where, "CAMERA_ID", fields[0], 0, LLONG_MAX);
  ColmapCamera camera;
  camera.Where = where;
  camera.Model = &SupportedModel(where, FindModel(fields[1]), "MODEL " + fields[1]);
  const std::vector<std::string>& names = camera.Model->Parameters;
  if (fields.size() != 4 + names.size())
  {
    throw ColmapModelError(where,
      std::string("a ") + camera.Model->Name + " camera has " + std::to_string(names.size()) +
        " parameters, found " + std::to_string(fields.size() - 4));
  }
  camera.Width = static_cast<int>(TextInteger(where, "WIDTH", fields[2], 1, INT_MAX));
  camera.Height = static_cast<int>(TextInteger(where, "HEIGHT", fields[3], 1, INT_MAX));
  for (size_t p = 0; p < names.size(); ++p)
  {
    camera.Parameters.push_back(TextNumber(where, names[p], fields[4 + p]));
  }
  AddCamera(model, id, std::move(camera));
}

// One image line: IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME.
ColmapImage ParseImageLine(const std::string& where, const std::vector<std::string>& fields)
{
  if (fields.size() != 10)
  {
    throw ColmapModelError(where,
      "expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (10 fields), found " +
        std::to_string(fields.size()));
  }
  ColmapImage image;
  image.Where = where;
  image.Id = TextInteger(where, "IMAGE_ID", fields[0], 0, LLONG_MAX);
  const char* const names[7] = { "QW", "QX", "QY", "QZ", "TX", "TY", "TZ" };
  for (int c = 0; c < 7; ++c)
  {
    const double value = TextNumber(where, names[c], fields[1 + c]);
    (c < 4 ? image.Q[c] : image.T[c - 4]) = value;
  }
  image.CameraId = TextInteger(where, "CAMERA_ID", fields[8], 0, LLONG_MAX);
  image.Name = fields[9];
  return image;
}

void ReadTextCameras(ColmapModel& model)
{
  for (const ModelLine& line : ReadModelLines(model.CamerasFile))
  {
    const std::vector<std::string> fields = SplitFields(line.Text);
    if (!fields.empty())
    {
      ParseCameraLine(model, model.CamerasFile + ":" + std::to_string(line.Number), fields);
    }
  }
}

void ReadTextImages(ColmapModel& model)
{
  const std::vector<ModelLine> lines = ReadModelLines(model.ImagesFile);
  std::map<long long, std::string> ids;
  for (size_t i = 0; i < lines.size(); ++i)
  {
    const std::vector<std::string> fields = SplitFields(lines[i].Text);
    if (!fields.empty())
    {
      AddImage(model,
        ids,
        ParseImageLine(model.ImagesFile + ":" + std::to_string(lines[i].Number), fields));
      // The next line (its 2D points, possibly empty) belongs to this image.
      ++i;
    }
  }
}

//------------------------------------------------------------------------------
// Binary model.

// A binary model file read field by field, little-endian whatever the
// machine; every read names the record and the field when the file ends
// before it.
class BinaryModelFile
{
public:
  explicit BinaryModelFile(const std::string& path)
    : Path(path)
    , Where(path)
  {
    std::string problem;
    if (!CheckRegularFile(path, problem))
    {
      throw std::runtime_error(path + ": " + problem);
    }
    this->Stream.open(path, std::ios::binary);
    std::error_code ec;
    this->Size = fs::file_size(path, ec);
    if (!this->Stream || ec)
    {
      throw std::runtime_error(path + ": cannot open the file for reading");
    }
  }

  // The number of records the file announces, then each record in turn.
  uint64_t Count(const std::string& what)
  {
    this->Total = this->Unsigned(8, "the number of " + what);
    return this->Total;
  }

  void StartRecord(uint64_t index)
  {
    this->Where =
      this->Path + ": record " + std::to_string(index + 1) + " of " + std::to_string(this->Total);
  }

  const std::string& GetWhere() const { return this->Where; }

  uint64_t Unsigned(int bytes, const std::string& field)
  {
    unsigned char data[8];
    this->Read(data, static_cast<uint64_t>(bytes), field);
    uint64_t value = 0;
    for (int b = bytes - 1; b >= 0; --b)
    {
      value = (value << 8) | data[b];
    }
    return value;
  }

  int32_t Signed32(const std::string& field)
  {
    const auto bits = static_cast<uint32_t>(this->Unsigned(4, field));
    int32_t value;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }

  double Finite(const std::string& field)
  {
    const uint64_t bits = this->Unsigned(8, field);
    double value;
    std::memcpy(&value, &bits, sizeof(value));
    if (!std::isfinite(value))
    {
      throw ColmapModelError(this->Where, field + " is not finite (" + std::to_string(value) + ")");
    }
    return value;
  }

  int Size32(const std::string& field)
  {
    const uint64_t value = this->Unsigned(8, field);
    if (value < 1 || value > static_cast<uint64_t>(INT_MAX))
    {
      throw ColmapModelError(this->Where,
        field + " is " + std::to_string(value) + ", not an integer from 1 to " +
          std::to_string(INT_MAX));
    }
    return static_cast<int>(value);
  }

  // Bytes up to a 0 byte.
  std::string Text(const std::string& field)
  {
    std::string text;
    for (;;)
    {
      if (this->Position == this->Size)
      {
        throw ColmapModelError(this->Where,
          field + " has no terminating 0 byte (the file ends at byte " +
            std::to_string(this->Size) + ")");
      }
      char c = 0;
      this->Read(&c, 1, field);
      if (c == '\0')
      {
        break;
      }
      if (text.size() == MaximumNameBytes)
      {
        throw ColmapModelError(this->Where,
          field + " has no terminating 0 byte within " + std::to_string(MaximumNameBytes) +
            " bytes");
      }
      text += c;
    }
    if (text.empty())
    {
      throw ColmapModelError(this->Where, field + " is empty");
    }
    return text;
  }

  // `count` items of `bytes` bytes each, not read.
  void Skip(uint64_t count, uint64_t bytes, const std::string& field)
  {
    const uint64_t left = this->Size - this->Position;
    if (count > left / bytes)
    {
      throw ColmapModelError(this->Where,
        "truncated in " + field + ": " + std::to_string(count) + " of " + std::to_string(bytes) +
          " bytes, " + std::to_string(left) + " bytes left");
    }
    this->Position += count * bytes;
    this->Stream.seekg(static_cast<std::streamoff>(this->Position));
  }

  void ExpectEnd()
  {
    if (this->Position != this->Size)
    {
      throw ColmapModelError(this->Path,
        std::to_string(this->Size - this->Position) + " bytes after the last of the " +
          std::to_string(this->Total) + " records");
    }
  }

private:
  void Read(void* data, uint64_t bytes, const std::string& field)
  {
    if (bytes > this->Size - this->Position ||
      !this->Stream.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes)))
    {
      throw ColmapModelError(this->Where,
        "truncated in " + field + " (the file ends at byte " + std::to_string(this->Size) + ")");
    }
    this->Position += bytes;
  }

  std::string Path;
  std::string Where;
  std::ifstream Stream;
  uint64_t Size = 0;
  uint64_t Position = 0;
  uint64_t Total = 0;
};

void ReadBinaryCameras(ColmapModel& model)
{
  BinaryModelFile file(model.CamerasFile);
  const uint64_t count = file.Count("cameras");
  for (uint64_t record = 0; record < count; ++record)
  {
    file.StartRecord(record);
    ColmapCamera camera;
    camera.Where = file.GetWhere();
    const auto id = static_cast<long long>(file.Unsigned(4, "CAMERA_ID"));
    const int32_t modelId = file.Signed32("MODEL_ID");
    const auto& models = ColmapCameraModels();
    const bool known = modelId >= 0 && static_cast<size_t>(modelId) < models.size();
    camera.Model = &SupportedModel(camera.Where,
      known ? &models[static_cast<size_t>(modelId)] : nullptr,
      "MODEL_ID " + std::to_string(modelId) +
        (known ? std::string(" (") + models[static_cast<size_t>(modelId)].Name + ")"
               : std::string(" (not a COLMAP 3.8 camera model)")));
    camera.Width = file.Size32("WIDTH");
    camera.Height = file.Size32("HEIGHT");
    for (const std::string& parameter : camera.Model->Parameters)
    {
      camera.Parameters.push_back(file.Finite(parameter));
    }
    AddCamera(model, id, std::move(camera));
  }
  file.ExpectEnd();
}

void ReadBinaryImages(ColmapModel& model)
{
  BinaryModelFile file(model.ImagesFile);
  const uint64_t count = file.Count("images");
  std::map<long long, std::string> ids;
  for (uint64_t record = 0; record < count; ++record)
  {
    file.StartRecord(record);
    ColmapImage image;
    image.Where = file.GetWhere();
    image.Id = static_cast<long long>(file.Unsigned(4, "IMAGE_ID"));
    const char* const names[7] = { "QW", "QX", "QY", "QZ", "TX", "TY", "TZ" };
    for (int c = 0; c < 7; ++c)
    {
      const double value = file.Finite(names[c]);
      (c < 4 ? image.Q[c] : image.T[c - 4]) = value;
    }
    image.CameraId = static_cast<long long>(file.Unsigned(4, "CAMERA_ID"));
    image.Name = file.Text("NAME");
    file.Skip(file.Unsigned(8, "POINTS2D"), Point2DBytes, "POINTS2D");
    AddImage(model, ids, std::move(image));
  }
  file.ExpectEnd();
}

//------------------------------------------------------------------------------
// Writing.

// Shortest text that reads back as the same double.
std::string Exact(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

void AppendUnsigned(std::string& bytes, uint64_t value, int size)
{
  for (int b = 0; b < size; ++b)
  {
    bytes += static_cast<char>((value >> (8 * b)) & 0xff);
  }
}

void AppendDouble(std::string& bytes, double value)
{
  uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  AppendUnsigned(bytes, bits, 8);
}

std::map<std::string, std::string> FormatText(const ColmapModel& model)
{
  std::string cameras = "# Camera list with one line of data per camera:\n"
                        "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
                        "# Written by lfd (vtkColmapExporter)\n";
  for (const auto& entry : model.Cameras)
  {
    const ColmapCamera& camera = entry.second;
    cameras += std::to_string(entry.first) + " " + camera.Model->Name + " " +
      std::to_string(camera.Width) + " " + std::to_string(camera.Height);
    for (double p : camera.Parameters)
    {
      cameras += " " + Exact(p);
    }
    cameras += "\n";
  }
  std::string images = "# Image list with two lines of data per image:\n"
                       "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
                       "#   POINTS2D[] as (X, Y, POINT3D_ID)\n";
  for (const ColmapImage& image : model.Images)
  {
    images += std::to_string(image.Id);
    for (double value : image.Q)
    {
      images += " " + Exact(value);
    }
    for (double value : image.T)
    {
      images += " " + Exact(value);
    }
    images += " " + std::to_string(image.CameraId) + " " + image.Name + "\n\n";
  }
  return { { "cameras.txt", cameras },
    { "images.txt", images },
    { "points3D.txt",
      "# 3D point list with one line of data per point:\n"
      "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n" } };
}

std::map<std::string, std::string> FormatBinary(const ColmapModel& model)
{
  std::string cameras;
  AppendUnsigned(cameras, model.Cameras.size(), 8);
  for (const auto& entry : model.Cameras)
  {
    const ColmapCamera& camera = entry.second;
    AppendUnsigned(cameras, static_cast<uint64_t>(entry.first), 4);
    AppendUnsigned(cameras, static_cast<uint64_t>(camera.Model->Id), 4);
    AppendUnsigned(cameras, static_cast<uint64_t>(camera.Width), 8);
    AppendUnsigned(cameras, static_cast<uint64_t>(camera.Height), 8);
    for (double p : camera.Parameters)
    {
      AppendDouble(cameras, p);
    }
  }
  std::string images;
  AppendUnsigned(images, model.Images.size(), 8);
  for (const ColmapImage& image : model.Images)
  {
    AppendUnsigned(images, static_cast<uint64_t>(image.Id), 4);
    for (double value : image.Q)
    {
      AppendDouble(images, value);
    }
    for (double value : image.T)
    {
      AppendDouble(images, value);
    }
    AppendUnsigned(images, static_cast<uint64_t>(image.CameraId), 4);
    images += image.Name;
    images += '\0';
    AppendUnsigned(images, 0, 8); // no 2D points
  }
  std::string points;
  AppendUnsigned(points, 0, 8);
  return { { "cameras.bin", cameras }, { "images.bin", images }, { "points3D.bin", points } };
}
}

//------------------------------------------------------------------------------
const std::vector<ColmapCameraModel>& ColmapCameraModels()
{
  // COLMAP 3.8, src/base/camera_models.h: MODEL_ID is the index.
  static const std::vector<ColmapCameraModel> models = {
    { "SIMPLE_PINHOLE", 0, { "f", "cx", "cy" } },
    { "PINHOLE", 1, { "fx", "fy", "cx", "cy" } },
    { "SIMPLE_RADIAL", 2, { "f", "cx", "cy", "k" } },
    { "RADIAL", 3, { "f", "cx", "cy", "k1", "k2" } },
    { "OPENCV", 4, { "fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2" } },
    { "OPENCV_FISHEYE", 5, {} },
    { "FULL_OPENCV",
      6,
      { "fx", "fy", "cx", "cy", "k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6" } },
    { "FOV", 7, {} },
    { "SIMPLE_RADIAL_FISHEYE", 8, {} },
    { "RADIAL_FISHEYE", 9, {} },
    { "THIN_PRISM_FISHEYE", 10, {} },
  };
  return models;
}

//------------------------------------------------------------------------------
ColmapModel ReadColmapModel(const std::string& folder)
{
  ColmapModel model;
  std::error_code ec;
  model.Binary = fs::exists(folder + "/cameras.bin", ec);
  if (!model.Binary && !fs::exists(folder + "/cameras.txt", ec))
  {
    throw std::runtime_error(folder + ": no COLMAP sparse model (no cameras.bin, no cameras.txt)");
  }
  const std::string extension = model.Binary ? ".bin" : ".txt";
  model.CamerasFile = folder + "/cameras" + extension;
  model.ImagesFile = folder + "/images" + extension;
  if (model.Binary)
  {
    ReadBinaryCameras(model);
  }
  else
  {
    ReadTextCameras(model);
  }
  if (model.Cameras.empty())
  {
    throw ColmapModelError(model.CamerasFile, "no camera");
  }
  if (model.Binary)
  {
    ReadBinaryImages(model);
  }
  else
  {
    ReadTextImages(model);
  }
  return model;
}

//------------------------------------------------------------------------------
void ColmapCameraToOpenCV(const ColmapCamera& camera, double K[9], double distortion[5])
{
  std::map<std::string, double> value;
  for (size_t p = 0; p < camera.Parameters.size(); ++p)
  {
    value[camera.Model->Parameters[p]] = camera.Parameters[p];
  }
  for (const char* rational : { "k4", "k5", "k6" })
  {
    if (value.count(rational) && value[rational] != 0.0)
    {
      throw ColmapModelError(camera.Where,
        std::string(rational) +
          " is not 0: the rational terms of FULL_OPENCV have no equivalent in the rig's "
          "distortion (k1, k2, p1, p2, k3)");
    }
  }
  const bool single = value.count("f") != 0;
  const double matrix[9] = { single ? value["f"] : value["fx"],
    0.0,
    value["cx"] - 0.5,
    0.0,
    single ? value["f"] : value["fy"],
    value["cy"] - 0.5,
    0.0,
    0.0,
    1.0 };
  std::copy(matrix, matrix + 9, K);
  distortion[0] = value.count("k") ? value["k"] : value["k1"];
  distortion[1] = value["k2"];
  distortion[2] = value["p1"];
  distortion[3] = value["p2"];
  distortion[4] = value["k3"];
}

//------------------------------------------------------------------------------
ColmapCamera OpenCVToColmapCamera(const double K[9],
  const double distortion[5],
  int width,
  int height)
{
  ColmapCamera camera;
  camera.Width = width;
  camera.Height = height;
  const bool distorted =
    std::any_of(distortion, distortion + 5, [](double coefficient) { return coefficient != 0.0; });
  const std::string name = !distorted ? "PINHOLE" : distortion[4] == 0.0 ? "OPENCV" : "FULL_OPENCV";
  camera.Model = FindModel(name);
  camera.Parameters = { K[0], K[4], K[2] + 0.5, K[5] + 0.5 };
  const int coefficients = !distorted ? 0 : distortion[4] == 0.0 ? 4 : 5;
  camera.Parameters.insert(camera.Parameters.end(), distortion, distortion + coefficients);
  if (coefficients == 5)
  {
    camera.Parameters.insert(camera.Parameters.end(), 3, 0.0); // k4 k5 k6: rational, unused
  }
  return camera;
}

//------------------------------------------------------------------------------
std::map<std::string, std::string> FormatColmapModel(const ColmapModel& model, bool binary)
{
  return binary ? FormatBinary(model) : FormatText(model);
}
}
}
