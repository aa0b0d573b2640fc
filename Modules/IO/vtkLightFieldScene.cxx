#include "vtkLightFieldScene.h"

#include "lfdExceptions.h"
#include "lfdFileUtilities.h"
#include "lfdJsonFields.h"
#include "lfdLimits.h"
#include "lfdPinholeCamera.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkLightFieldReader.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLightFieldScene);

namespace
{
using lfd::io::ElementPath;
using lfd::io::FieldError;
using lfd::io::Json;
using lfd::io::MemberPath;

constexpr int SceneVersion = 1;

struct Keyframe
{
  double Time = 0.0;
  vtkSmartPointer<vtkPoints> Points;
};

vtkSmartPointer<vtkPoints> MakePoints(const std::vector<double>& coordinates)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(coordinates.size() / 3));
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, &coordinates[3 * i]);
  }
  return points;
}

Json PointsToJson(vtkDataArray* array)
{
  Json list = Json::array();
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    double p[3];
    array->GetTuple(i, p);
    list.push_back({ p[0], p[1], p[2] });
  }
  return list;
}

Json VectorToJson(const double* v)
{
  return Json::array({ v[0], v[1], v[2] });
}

// The checks Read() and Write() share on the settings that are not plain
// JSON types: the view camera, the image size, the subdivision and the
// keyframe times. Throws FieldError.
void ValidateSettings(vtkCamera* camera,
  int width,
  int height,
  int subdivision,
  const std::vector<Keyframe>& keyframes)
{
  std::string field, problem;
  if (!lfd::CheckLookAt(camera->GetPosition(),
        camera->GetFocalPoint(),
        camera->GetViewUp(),
        camera->GetViewAngle(),
        field,
        problem))
  {
    throw FieldError(MemberPath("camera", field.c_str()), problem);
  }
  const std::string sizeRange = "expected an integer in [1, " +
    std::to_string(lfd::MaximumRenderSize) + "] (the maximum render size)";
  if (width < 1 || width > lfd::MaximumRenderSize)
  {
    throw FieldError("camera.width", sizeRange + ", found " + std::to_string(width));
  }
  if (height < 1 || height > lfd::MaximumRenderSize)
  {
    throw FieldError("camera.height", sizeRange + ", found " + std::to_string(height));
  }
  if (subdivision != 0 &&
    (subdivision < lfd::MinimumSubdivision || subdivision > lfd::MaximumSubdivision))
  {
    throw FieldError("render.subdivision",
      "expected an integer in [" + std::to_string(lfd::MinimumSubdivision) + ", " +
        std::to_string(lfd::MaximumSubdivision) + "] or \"auto\", found " +
        std::to_string(subdivision));
  }
  // Two keyframes at one time would be one pose too many: the interpolator
  // (vtkKeyframeInterpolator::AddKeyframe) refuses the second as well.
  std::set<double> times;
  for (size_t k = 0; k < keyframes.size(); ++k)
  {
    if (!times.insert(keyframes[k].Time).second)
    {
      throw FieldError(MemberPath(ElementPath("keyframes", k), "time"),
        "another keyframe has the same time " + std::to_string(keyframes[k].Time) +
          "; keyframe times must differ");
    }
  }
}

bool AllFinite(vtkDataArray* array)
{
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    if (!std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
          static_cast<int>(i % array->GetNumberOfComponents()))))
    {
      return false;
    }
  }
  return true;
}

// The scene's "format" and "version".
void CheckSceneHeader(const Json& document)
{
  const std::string format =
    lfd::io::GetString(lfd::io::RequireMember(document, "", "format"), "format");
  if (format != "lfd-scene")
  {
    throw FieldError("format", "expected \"lfd-scene\", found \"" + format + "\"");
  }
  const long long version =
    lfd::io::GetInteger(lfd::io::RequireMember(document, "", "version"), "version", 0, VTK_INT_MAX);
  if (version != SceneVersion)
  {
    throw FieldError("version",
      "unsupported version " + std::to_string(version) + " (this reader reads version " +
        std::to_string(SceneVersion) + ")");
  }
}

// The "cage": rest points, optional deformed points, boxes. Returns the
// number of cage points.
size_t ParseCage(const Json& cageValue, vtkUnstructuredGrid* cage)
{
  const std::vector<double> rest = lfd::io::GetPoints(
    lfd::io::RequireMember(cageValue, "cage", "rest_points"), "cage.rest_points");
  const size_t cagePoints = rest.size() / 3;
  std::vector<double> deformed = rest;
  if (const Json* points = lfd::io::FindMember(cageValue, "cage", "points"))
  {
    deformed = lfd::io::GetPoints(*points, "cage.points");
    if (deformed.size() != rest.size())
    {
      throw FieldError("cage.points",
        "has " + std::to_string(deformed.size() / 3) + " points, cage.rest_points has " +
          std::to_string(cagePoints));
    }
  }
  const Json& boxes = lfd::io::RequireMember(cageValue, "cage", "boxes");
  if (!boxes.is_array())
  {
    throw FieldError("cage.boxes", "expected an array of boxes, found " + lfd::io::Describe(boxes));
  }
  cage->SetPoints(MakePoints(deformed));
  vtkNew<vtkDoubleArray> restArray;
  restArray->SetName("RestPosition");
  restArray->SetNumberOfComponents(3);
  restArray->SetNumberOfTuples(static_cast<vtkIdType>(cagePoints));
  std::copy(rest.begin(), rest.end(), restArray->GetPointer(0));
  cage->GetPointData()->AddArray(restArray);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  cage->Allocate(static_cast<vtkIdType>(boxes.size()));
  for (size_t b = 0; b < boxes.size(); ++b)
  {
    const std::string boxPath = ElementPath("cage.boxes", b);
    const Json& corners = lfd::io::RequireMember(boxes[b], boxPath, "corners");
    const std::string cornersPath = MemberPath(boxPath, "corners");
    if (!corners.is_array() || corners.size() != 8)
    {
      throw FieldError(cornersPath,
        "a box has 8 corners (VTK hexahedron order), found " + lfd::io::Describe(corners));
    }
    vtkIdType ids[8];
    for (size_t c = 0; c < 8; ++c)
    {
      const std::string cornerPath = ElementPath(cornersPath, c);
      const double index = lfd::io::GetNumber(corners[c], cornerPath);
      if (index != std::floor(index) || index < 0 || index >= static_cast<double>(cagePoints))
      {
        throw FieldError(cornerPath,
          "corner index " + corners[c].dump() + " out of range (the cage has " +
            std::to_string(cagePoints) + " points, indices 0.." +
            std::to_string(static_cast<long long>(cagePoints) - 1) + ")");
      }
      ids[c] = static_cast<vtkIdType>(index);
    }
    const long long label = lfd::io::GetInteger(
      lfd::io::RequireMember(boxes[b], boxPath, "label"), MemberPath(boxPath, "label"), 0, 255);
    cage->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
    labels->InsertNextValue(static_cast<int>(label));
  }
  cage->GetCellData()->AddArray(labels);
  return cagePoints;
}

// The "keyframes" of a cage of `cagePoints` points.
std::vector<Keyframe> ParseKeyframes(const Json& list, size_t cagePoints)
{
  std::vector<Keyframe> keyframes;
  if (!list.is_array())
  {
    throw FieldError("keyframes", "expected an array, found " + lfd::io::Describe(list));
  }
  if (!list.empty() && cagePoints == 0)
  {
    throw FieldError("keyframes", "keyframes move cage points, but the scene has no cage");
  }
  for (size_t k = 0; k < list.size(); ++k)
  {
    const std::string path = ElementPath("keyframes", k);
    Keyframe keyframe;
    keyframe.Time =
      lfd::io::GetNumber(lfd::io::RequireMember(list[k], path, "time"), MemberPath(path, "time"));
    const std::vector<double> points = lfd::io::GetPoints(
      lfd::io::RequireMember(list[k], path, "points"), MemberPath(path, "points"));
    if (points.size() / 3 != cagePoints)
    {
      throw FieldError(MemberPath(path, "points"),
        "has " + std::to_string(points.size() / 3) + " points, the cage has " +
          std::to_string(cagePoints));
    }
    keyframe.Points = MakePoints(points);
    keyframes.push_back(keyframe);
  }
  return keyframes;
}

// The keyframes' "interpolation": its names in scene.json, by value.
const char* const InterpolationNames[] = { "linear", "catmull-rom" };

int ParseInterpolation(const Json& value)
{
  const std::string name = lfd::io::GetString(value, "interpolation");
  for (int i = 0; i < 2; ++i)
  {
    if (name == InterpolationNames[i])
    {
      return i;
    }
  }
  throw FieldError(
    "interpolation", "expected \"linear\" or \"catmull-rom\", found " + lfd::io::Describe(value));
}

// The view "camera" and the rendered image size.
void ParseCamera(const Json& cam, vtkCamera* camera, int& width, int& height)
{
  if (const Json* v = lfd::io::FindMember(cam, "camera", "position"))
  {
    camera->SetPosition(lfd::io::GetNumbers(*v, "camera.position", 3).data());
  }
  if (const Json* v = lfd::io::FindMember(cam, "camera", "focal_point"))
  {
    camera->SetFocalPoint(lfd::io::GetNumbers(*v, "camera.focal_point", 3).data());
  }
  if (const Json* v = lfd::io::FindMember(cam, "camera", "view_up"))
  {
    camera->SetViewUp(lfd::io::GetNumbers(*v, "camera.view_up", 3).data());
  }
  if (const Json* v = lfd::io::FindMember(cam, "camera", "view_angle"))
  {
    // vtkCamera clamps the angle it is given: checked here, unclamped.
    const double angle = lfd::io::GetNumber(*v, "camera.view_angle");
    if (!(angle >= lfd::MinimumViewAngle && angle <= lfd::MaximumViewAngle))
    {
      throw FieldError(
        "camera.view_angle", "expected degrees in [0.5, 179], found " + lfd::io::Describe(*v));
    }
    camera->SetViewAngle(angle);
  }
  if (const Json* v = lfd::io::FindMember(cam, "camera", "width"))
  {
    width = static_cast<int>(lfd::io::GetInteger(*v, "camera.width", 1, lfd::MaximumRenderSize));
  }
  if (const Json* v = lfd::io::FindMember(cam, "camera", "height"))
  {
    height = static_cast<int>(lfd::io::GetInteger(*v, "camera.height", 1, lfd::MaximumRenderSize));
  }
}

// render.focal, in the order of vtkLightFieldRenderer::FocalSurfaceType.
const char* const FocalSurfaceNames[] = { "auto", "plane", "proxy" };

// The "render" settings, with their defaults.
struct RenderSettings
{
  double FocalDistance = 0.0;
  int FocalSurface = 0;
  bool AntiAliasing = true;
  double FocalDepth = 0.0;
  double Aperture = 0.0;
  int Subdivision = 1;
  int WidenedSearch = 2;
  double ObjectThreshold = 10.0;
  double Background[3] = { 0.0, 0.0, 0.0 };
};

void ParseRender(const Json& render, RenderSettings& settings)
{
  if (const Json* v = lfd::io::FindMember(render, "render", "focal_distance"))
  {
    settings.FocalDistance = lfd::io::GetNumber(*v, "render.focal_distance");
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "focal"))
  {
    const auto name = std::find(std::begin(FocalSurfaceNames),
      std::end(FocalSurfaceNames),
      v->is_string() ? v->get<std::string>() : std::string());
    if (name == std::end(FocalSurfaceNames))
    {
      throw FieldError("render.focal",
        "expected \"auto\", \"plane\" or \"proxy\", found " + lfd::io::Describe(*v));
    }
    settings.FocalSurface = static_cast<int>(name - std::begin(FocalSurfaceNames));
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "antialiasing"))
  {
    if (!v->is_boolean())
    {
      throw FieldError(
        "render.antialiasing", "expected true or false, found " + lfd::io::Describe(*v));
    }
    settings.AntiAliasing = v->get<bool>();
  }
  for (const auto& [name, value] : { std::make_pair("focal_depth", &settings.FocalDepth),
         std::make_pair("aperture", &settings.Aperture) })
  {
    if (const Json* v = lfd::io::FindMember(render, "render", name))
    {
      const std::string path = std::string("render.") + name;
      *value = lfd::io::GetNumber(*v, path);
      if (!(*value >= 0.0))
      {
        throw FieldError(path, "expected a distance >= 0, found " + lfd::io::Describe(*v));
      }
    }
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "subdivision"))
  {
    if (v->is_string() && v->get<std::string>() == "auto")
    {
      settings.Subdivision = 0;
    }
    else if (v->is_number())
    {
      settings.Subdivision = static_cast<int>(lfd::io::GetInteger(
        *v, "render.subdivision", lfd::MinimumSubdivision, lfd::MaximumSubdivision));
    }
    else
    {
      throw FieldError("render.subdivision",
        "expected an integer in [" + std::to_string(lfd::MinimumSubdivision) + ", " +
          std::to_string(lfd::MaximumSubdivision) + "] or \"auto\", found " +
          lfd::io::Describe(*v));
    }
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "widened_search"))
  {
    settings.WidenedSearch =
      static_cast<int>(lfd::io::GetInteger(*v, "render.widened_search", 0, 64));
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "object_threshold"))
  {
    settings.ObjectThreshold = lfd::io::GetNumber(*v, "render.object_threshold");
    if (!(settings.ObjectThreshold >= 0.0 && settings.ObjectThreshold <= 255.0))
    {
      throw FieldError("render.object_threshold",
        "expected a brightness in [0, 255], found " + lfd::io::Describe(*v));
    }
  }
  if (const Json* v = lfd::io::FindMember(render, "render", "background"))
  {
    const std::vector<double> rgb = lfd::io::GetNumbers(*v, "render.background", 3);
    for (size_t c = 0; c < 3; ++c)
    {
      if (rgb[c] < 0.0 || rgb[c] > 1.0)
      {
        throw FieldError(ElementPath("render.background", c),
          "expected a colour component in [0, 1], found " + lfd::io::Describe((*v)[c]));
      }
      settings.Background[c] = rgb[c];
    }
  }
}
}

struct vtkLightFieldScene::Internals
{
  vtkSmartPointer<vtkUnstructuredGrid> Cage = vtkSmartPointer<vtkUnstructuredGrid>::New();
  std::vector<Keyframe> Keyframes;
  vtkSmartPointer<vtkCamera> Camera = vtkSmartPointer<vtkCamera>::New();
  std::string ResolvedPath;
};

//------------------------------------------------------------------------------
vtkLightFieldScene::vtkLightFieldScene()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkLightFieldScene::~vtkLightFieldScene()
{
  this->SetFileName(nullptr);
  this->SetLightFieldPath(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldScene::Initialize()
{
  this->SetLightFieldPath(nullptr);
  this->Internal->Cage = vtkSmartPointer<vtkUnstructuredGrid>::New();
  this->Internal->Keyframes.clear();
  this->Internal->Camera = vtkSmartPointer<vtkCamera>::New();
  this->Width = 512;
  this->Height = 512;
  this->FocalDistance = 0.0;
  this->FocalSurface = 0;
  this->AntiAliasing = true;
  this->FocalDepth = 0.0;
  this->Aperture = 0.0;
  this->Subdivision = 1;
  this->WidenedSearch = 2;
  this->ObjectThreshold = 10.0;
  this->Background[0] = this->Background[1] = this->Background[2] = 0.0;
  this->Interpolation = INTERPOLATION_CATMULL_ROM;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::Fail(const std::string& message)
{
  vtkErrorMacro(<< message);
  return false;
}

//------------------------------------------------------------------------------
const char* vtkLightFieldScene::GetResolvedLightFieldPath()
{
  if (!this->LightFieldPath)
  {
    this->Internal->ResolvedPath.clear();
  }
  else
  {
    this->Internal->ResolvedPath = lfd::io::ResolvePath(
      this->FileName ? lfd::io::ParentFolder(this->FileName) : std::string(), this->LightFieldPath);
  }
  return this->Internal->ResolvedPath.c_str();
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::ConfigureReader(vtkLightFieldReader* reader)
{
  const std::string scene = this->FileName ? this->FileName : "(scene)";
  if (!this->LightFieldPath || !*this->LightFieldPath)
  {
    return this->Fail(
      scene + ": field \"lightfield\": missing (the scene names no light-field dataset)");
  }
  const std::string path = this->GetResolvedLightFieldPath();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    return this->Fail(scene + ": field \"lightfield\": " + path + ": file not found");
  }
  if (reader)
  {
    reader->SetFileName(path.c_str());
  }
  return true;
}

//------------------------------------------------------------------------------
vtkUnstructuredGrid* vtkLightFieldScene::GetCage()
{
  return this->Internal->Cage;
}

//------------------------------------------------------------------------------
void vtkLightFieldScene::SetCage(vtkUnstructuredGrid* cage)
{
  this->Internal->Cage =
    cage ? vtkSmartPointer<vtkUnstructuredGrid>(cage) : vtkSmartPointer<vtkUnstructuredGrid>::New();
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::HasCage()
{
  return this->Internal->Cage->GetNumberOfPoints() > 0;
}

//------------------------------------------------------------------------------
int vtkLightFieldScene::GetNumberOfKeyframes() const
{
  return static_cast<int>(this->Internal->Keyframes.size());
}

//------------------------------------------------------------------------------
double vtkLightFieldScene::GetKeyframeTime(int i) const
{
  return (i >= 0 && i < this->GetNumberOfKeyframes()) ? this->Internal->Keyframes[i].Time : 0.0;
}

//------------------------------------------------------------------------------
vtkPoints* vtkLightFieldScene::GetKeyframePoints(int i) const
{
  return (i >= 0 && i < this->GetNumberOfKeyframes()) ? this->Internal->Keyframes[i].Points.Get()
                                                      : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldScene::AddKeyframe(double time, vtkPoints* points)
{
  Keyframe keyframe;
  keyframe.Time = time;
  keyframe.Points = vtkSmartPointer<vtkPoints>::New();
  keyframe.Points->SetDataTypeToDouble();
  if (points)
  {
    keyframe.Points->DeepCopy(points);
  }
  this->Internal->Keyframes.push_back(keyframe);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldScene::RemoveAllKeyframes()
{
  this->Internal->Keyframes.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkCamera* vtkLightFieldScene::GetCamera()
{
  return this->Internal->Camera;
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::Read(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return this->Fail("vtkLightFieldScene::Read: no file name given");
  }
  Json document;
  std::string error;
  if (!lfd::io::ParseJsonFile(fileName, document, error))
  {
    return this->Fail(error);
  }

  // Parse into locals; the scene changes only when the whole file is valid.
  std::string lightField;
  bool hasLightField = false;
  auto cage = vtkSmartPointer<vtkUnstructuredGrid>::New();
  std::vector<Keyframe> keyframes;
  int interpolation = INTERPOLATION_CATMULL_ROM;
  auto camera = vtkSmartPointer<vtkCamera>::New();
  int width = 512, height = 512;
  RenderSettings settings;
  try
  {
    CheckSceneHeader(document);
    if (const Json* value = lfd::io::FindMember(document, "", "lightfield"))
    {
      lightField = lfd::io::GetPath(*value, "lightfield");
      hasLightField = true;
    }
    size_t cagePoints = 0;
    if (const Json* cageValue = lfd::io::FindMember(document, "", "cage"))
    {
      cagePoints = ParseCage(*cageValue, cage);
    }
    if (const Json* list = lfd::io::FindMember(document, "", "keyframes"))
    {
      keyframes = ParseKeyframes(*list, cagePoints);
    }
    if (const Json* value = lfd::io::FindMember(document, "", "interpolation"))
    {
      interpolation = ParseInterpolation(*value);
    }
    if (const Json* cam = lfd::io::FindMember(document, "", "camera"))
    {
      ParseCamera(*cam, camera, width, height);
    }
    if (const Json* render = lfd::io::FindMember(document, "", "render"))
    {
      ParseRender(*render, settings);
    }
    ValidateSettings(camera, width, height, settings.Subdivision, keyframes);
  }
  catch (...)
  {
    return this->Fail(std::string(fileName) + ": " + lfd::CurrentExceptionMessage());
  }

  this->SetFileName(fileName);
  this->SetLightFieldPath(hasLightField ? lightField.c_str() : nullptr);
  this->Internal->Cage = cage;
  this->Internal->Keyframes = std::move(keyframes);
  this->Interpolation = interpolation;
  this->Internal->Camera = camera;
  this->Width = width;
  this->Height = height;
  this->FocalDistance = settings.FocalDistance;
  this->FocalSurface = settings.FocalSurface;
  this->AntiAliasing = settings.AntiAliasing;
  this->FocalDepth = settings.FocalDepth;
  this->Aperture = settings.Aperture;
  this->Subdivision = settings.Subdivision;
  this->WidenedSearch = settings.WidenedSearch;
  this->ObjectThreshold = settings.ObjectThreshold;
  std::copy(settings.Background, settings.Background + 3, this->Background);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldScene::CheckSettings()
{
  try
  {
    ValidateSettings(this->Internal->Camera,
      this->Width,
      this->Height,
      this->Subdivision,
      this->Internal->Keyframes);
  }
  catch (const FieldError& e)
  {
    return e.what();
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::Write(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return this->Fail("vtkLightFieldScene::Write: no file name given");
  }
  // std::filesystem and the JSON library throw (e.g. on a path or a name
  // that is not UTF-8): no exception may leave Write().
  try
  {
    return this->WriteFile(fileName);
  }
  catch (...)
  {
    return this->Fail(std::string(fileName) + ": " + lfd::CurrentExceptionMessage());
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldScene::WriteFile(const char* fileName)
{
  const std::string file = fileName;
  const std::string problem = this->CheckSettings();
  if (!problem.empty())
  {
    return this->Fail(file + ": " + problem);
  }
  Json document;
  document["format"] = "lfd-scene";
  document["version"] = SceneVersion;
  // A relative light-field path is relative to the scene file: written into
  // another folder, it is rewritten to name the same light field from there.
  std::string lightFieldPath = this->LightFieldPath ? this->LightFieldPath : "";
  if (this->LightFieldPath && this->FileName &&
    !std::filesystem::path(this->LightFieldPath).is_absolute())
  {
    const std::filesystem::path target =
      std::filesystem::absolute(std::filesystem::path(file)).parent_path().lexically_normal();
    const std::filesystem::path source =
      std::filesystem::absolute(this->GetResolvedLightFieldPath()).lexically_normal();
    const std::filesystem::path relative = source.lexically_relative(target);
    lightFieldPath = relative.empty() ? source.string() : relative.string();
  }
  if (this->LightFieldPath)
  {
    document["lightfield"] = lightFieldPath;
  }
  const vtkIdType cagePoints = this->Internal->Cage->GetNumberOfPoints();
  if (cagePoints > 0)
  {
    const std::string why = vtkDeformationCage::CheckGridArrays(this->Internal->Cage);
    if (!why.empty())
    {
      return this->Fail(file + ": " + why);
    }
    vtkNew<vtkDeformationCage> cage;
    cage->InitializeFromGrid(this->Internal->Cage);
    vtkDataArray* rest = cage->GetRestPositions();
    if (!AllFinite(rest) || !AllFinite(cage->GetPoints()->GetData()))
    {
      return this->Fail(file + ": the cage has non-finite coordinates");
    }
    Json boxes = Json::array();
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < cage->GetNumberOfBoxes(); ++c)
    {
      if (cage->GetCellType(c) != VTK_HEXAHEDRON)
      {
        return this->Fail(file + ": cage cell " + std::to_string(c) + " is not a hexahedron");
      }
      cage->GetCellPoints(c, ids);
      Json corners = Json::array();
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        corners.push_back(ids->GetId(k));
      }
      Json box;
      box["corners"] = corners;
      box["label"] = cage->GetBoxLabel(c);
      boxes.push_back(box);
    }
    Json cageJson;
    cageJson["rest_points"] = PointsToJson(rest);
    cageJson["points"] = PointsToJson(cage->GetPoints()->GetData());
    cageJson["boxes"] = boxes;
    document["cage"] = cageJson;
  }
  if (!this->Internal->Keyframes.empty())
  {
    Json list = Json::array();
    for (size_t k = 0; k < this->Internal->Keyframes.size(); ++k)
    {
      const Keyframe& keyframe = this->Internal->Keyframes[k];
      if (keyframe.Points->GetNumberOfPoints() != cagePoints)
      {
        return this->Fail(file + ": keyframe " + std::to_string(k) + " has " +
          std::to_string(keyframe.Points->GetNumberOfPoints()) + " points, the cage has " +
          std::to_string(cagePoints));
      }
      if (!std::isfinite(keyframe.Time) || !AllFinite(keyframe.Points->GetData()))
      {
        return this->Fail(file + ": keyframe " + std::to_string(k) + " has non-finite values");
      }
      Json entry;
      entry["time"] = keyframe.Time;
      entry["points"] = PointsToJson(keyframe.Points->GetData());
      list.push_back(entry);
    }
    document["keyframes"] = list;
  }
  // Written with keyframes, or when it is not the default: a scene with
  // neither writes as it did before the field existed.
  if (!this->Internal->Keyframes.empty() || this->Interpolation != INTERPOLATION_CATMULL_ROM)
  {
    document["interpolation"] = InterpolationNames[this->Interpolation];
  }
  vtkCamera* camera = this->Internal->Camera;
  Json cameraJson;
  cameraJson["position"] = VectorToJson(camera->GetPosition());
  cameraJson["focal_point"] = VectorToJson(camera->GetFocalPoint());
  cameraJson["view_up"] = VectorToJson(camera->GetViewUp());
  cameraJson["view_angle"] = camera->GetViewAngle();
  cameraJson["width"] = this->Width;
  cameraJson["height"] = this->Height;
  document["camera"] = cameraJson;
  Json render;
  render["focal_distance"] = this->FocalDistance;
  if (this->FocalSurface != 0)
  {
    render["focal"] = FocalSurfaceNames[this->FocalSurface];
  }
  if (!this->AntiAliasing)
  {
    render["antialiasing"] = false;
  }
  if (this->FocalDepth != 0.0)
  {
    render["focal_depth"] = this->FocalDepth;
  }
  if (this->Aperture != 0.0)
  {
    render["aperture"] = this->Aperture;
  }
  if (this->Subdivision == 0)
  {
    render["subdivision"] = "auto";
  }
  else
  {
    render["subdivision"] = this->Subdivision;
  }
  render["widened_search"] = this->WidenedSearch;
  render["object_threshold"] = this->ObjectThreshold;
  render["background"] = VectorToJson(this->Background);
  document["render"] = render;
  if (!std::isfinite(this->FocalDistance))
  {
    return this->Fail(file + ": render.focal_distance is not finite");
  }

  std::string error;
  if (!lfd::io::WriteFileAtomically(file, document.dump(2) + "\n", error))
  {
    return this->Fail(file + ": " + error);
  }
  this->SetFileName(fileName);
  this->SetLightFieldPath(this->LightFieldPath ? lightFieldPath.c_str() : nullptr);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "LightFieldPath: " << (this->LightFieldPath ? this->LightFieldPath : "(none)")
     << "\n";
  os << indent << "Cage: " << this->Internal->Cage->GetNumberOfPoints() << " points, "
     << this->Internal->Cage->GetNumberOfCells() << " boxes\n";
  os << indent << "Keyframes: " << this->Internal->Keyframes.size() << "\n";
  os << indent << "Interpolation: " << InterpolationNames[this->Interpolation] << "\n";
  for (const Keyframe& keyframe : this->Internal->Keyframes)
  {
    os << indent.GetNextIndent() << "time " << keyframe.Time << ": "
       << keyframe.Points->GetNumberOfPoints() << " points\n";
  }
  os << indent << "Camera:\n";
  this->Internal->Camera->PrintSelf(os, indent.GetNextIndent());
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "FocalDistance: " << this->FocalDistance << "\n";
  os << indent << "FocalSurface: " << FocalSurfaceNames[this->FocalSurface] << "\n";
  os << indent << "AntiAliasing: " << (this->AntiAliasing ? "On" : "Off") << "\n";
  os << indent << "FocalDepth: " << this->FocalDepth << "\n";
  os << indent << "Aperture: " << this->Aperture << "\n";
  os << indent << "Subdivision: " << this->Subdivision << (this->Subdivision == 0 ? " (auto)" : "")
     << "\n";
  os << indent << "WidenedSearch: " << this->WidenedSearch << "\n";
  os << indent << "ObjectThreshold: " << this->ObjectThreshold << "\n";
  os << indent << "Background: (" << this->Background[0] << ", " << this->Background[1] << ", "
     << this->Background[2] << ")\n";
}
