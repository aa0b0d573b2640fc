// What every `lfd` subcommand shares (see lfdCommandSupport.h).
#include "lfdCommandSupport.h"

#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkImageFileReader.h"
#include "vtkImageFileWriter.h"
#include "vtkLightField.h"
#include "vtkLightFieldImageCache.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkLightFieldWriter.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkXMLPolyDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <filesystem>
#include <string>

namespace lfd::cli
{
double Seconds(double start)
{
  return vtkTimerLog::GetUniversalTime() - start;
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    Fail("mesh '" + path + "' does not exist");
  }
  const std::string ext =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".ply")
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(path.c_str());
    reader = ply;
  }
  else if (ext == ".obj")
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    reader = obj;
  }
  else if (ext == ".stl")
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(path.c_str());
    reader = stl;
  }
  else if (ext == ".vtp")
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    vtp->SetFileName(path.c_str());
    reader = vtp;
  }
  else if (ext == ".vtk")
  {
    auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(path.c_str());
    reader = legacy;
  }
  else
  {
    Fail("mesh '" + path + "': unknown format '" + ext +
      "' (expected .ply, .obj, .stl, .vtp or .vtk)");
  }
  Run(reader.Get(), "reading mesh '" + path + "'");
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutputDataObject(0));
  if (mesh->GetNumberOfCells() == 0)
  {
    Fail("mesh '" + path + "' has no cells");
  }
  return mesh;
}

namespace
{
/**
 * A scene is a JSON file: a folder (a light-field dataset given where its
 * scene is expected, a common slip) or a device is refused with a line that
 * says what was expected.
 */
void ExpectSceneFile(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status))
  {
    if (fs::is_regular_file(fs::path(path) / "lightfield.json", error))
    {
      Fail(path +
        ": is a light-field dataset, not a scene file; write a scene.json whose "
        "\"lightfield\" names it (see Data/README.md), or try 'lfd demo'");
    }
    Fail(path + ": is a folder, not a scene file (scene.json)");
  }
  if (fs::exists(status) && !fs::is_regular_file(status))
  {
    Fail(path + ": is not a regular file; a scene file (scene.json) was expected");
  }
}
}

vtkSmartPointer<vtkLightFieldSceneLogic> ReadScene(const std::string& path)
{
  ExpectSceneFile(path);
  auto scene = vtkSmartPointer<vtkLightFieldSceneLogic>::New();
  if (!scene->Load(path.c_str()))
  {
    Fail(""); // the logic said why
  }
  return scene;
}

vtkSmartPointer<vtkImageData> ReadImage(const std::string& path)
{
  vtkNew<vtkImageFileReader> reader;
  reader->SetFileName(path.c_str());
  Run(reader.Get(), "reading " + path);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

vtkSmartPointer<vtkLightField> ReadLightField(const std::string& path,
  Passes passes,
  std::int64_t cacheBytes,
  int piece,
  int pieces)
{
  vtkNew<vtkLightFieldReader> reader;
  reader->SetFileName(path.c_str());
  reader->SetCacheSize(cacheBytes);
  reader->SetPiece(piece);
  reader->SetNumberOfPieces(pieces);
  if (passes != Passes::All)
  {
    reader->ReadNoPasses();
    reader->SetReadPass(vtkLightField::COAXIAL, true);
    reader->SetReadPass(vtkLightField::LABEL, true);
    reader->SetReadPass(vtkLightField::DEPTH, passes == Passes::Rendered);
  }
  lfd::ShowProgress(reader, "reading");
  Run(reader.Get(), "reading " + path);
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->ShallowCopy(reader->GetOutput());
  return lightField;
}

CLI::Option* AddFocalOption(CLI::App* command, std::string& name, const std::string& otherwise)
{
  return command
    ->add_option("--focal",
      name,
      "focal surface: auto (the proxy when the light field has a depth pass), plane (the paper's "
      "focal plane at the focal distance) or proxy (the depth pass, per pixel; see lfd proxy); "
      "default: " +
        otherwise)
    ->check(CLI::IsMember({ "auto", "plane", "proxy" }));
}

int FocalSurfaceFromName(const std::string& name)
{
  return name == "plane" ? vtkLightFieldRenderer::FOCAL_PLANE
    : name == "proxy"    ? vtkLightFieldRenderer::FOCAL_PROXY
                         : vtkLightFieldRenderer::FOCAL_AUTOMATIC;
}

void AddRenderOverrideOptions(CLI::App* command, RenderOverrides& overrides)
{
  AddFocalOption(command, overrides.Focal, "the scene's render.focal");
  command
    ->add_option("--antialiasing",
      overrides.AntiAliasing,
      "anti-aliased silhouettes from label coverage (on) or hard label edges (off); default: the "
      "scene's render.antialiasing (on when absent)")
    ->check(CLI::IsMember({ "on", "off" }));
}

void ApplyRenderOverrides(const RenderOverrides& overrides, vtkLightFieldSceneLogic* scene)
{
  if (!overrides.Focal.empty())
  {
    scene->GetScene()->SetFocalSurface(FocalSurfaceFromName(overrides.Focal));
  }
  if (!overrides.AntiAliasing.empty())
  {
    scene->GetScene()->SetAntiAliasing(overrides.AntiAliasing == "on");
  }
}

vtkSmartPointer<vtkLightField> ReadSceneLightField(vtkLightFieldSceneLogic* scene,
  Passes passes,
  std::int64_t cacheBytes,
  int piece,
  int pieces)
{
  StepErrors errors;
  errors->Observe(scene->GetScene());
  scene->GetScene()->ConfigureReader(nullptr);
  errors.FailOnError();
  // The Depth pass is the renderer's proxy: a scene focused on the plane never reads it.
  if (passes == Passes::Rendered &&
    scene->GetScene()->GetFocalSurface() == vtkLightFieldRenderer::FOCAL_PLANE)
  {
    passes = Passes::RenderedOnPlane;
  }
  return ReadLightField(
    scene->GetScene()->GetResolvedLightFieldPath(), passes, cacheBytes, piece, pieces);
}

void CheckTexelSource(vtkLightField* lightField)
{
  auto* cache = vtkLightFieldImageCache::SafeDownCast(lightField->GetTexelSource());
  if (cache && *cache->GetError())
  {
    Fail(std::string("reading the light field's tiles: ") + cache->GetError());
  }
}

std::int64_t NumericOptions::ParseByteSize(const std::string& name, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long number = std::strtoll(begin, &end, 10);
  std::int64_t unit = 1;
  if (end != begin && (*end == 'K' || *end == 'M' || *end == 'G') && end[1] == '\0')
  {
    unit = std::int64_t(1) << (*end == 'K' ? 10 : *end == 'M' ? 20 : 30);
    ++end;
  }
  const std::int64_t largest = std::numeric_limits<std::int64_t>::max() / unit;
  if (end == begin || *end != '\0' || errno != 0 || number < 1 || number > largest ||
    number * unit < (std::int64_t(1) << 20))
  {
    Fail(name + " " + text +
      ": expected a size of at least 1M: an integer with an optional unit "
      "K, M or G (e.g. 512M)");
  }
  return number * unit;
}

vtkSmartPointer<vtkDeformationCage> SceneCage(vtkLightFieldSceneLogic* scene,
  vtkLightField* lightField,
  const double* time)
{
  if (!scene->HasCage())
  {
    return nullptr;
  }
  auto cage = vtkSmartPointer<vtkDeformationCage>::New();
  const bool valid =
    time ? scene->GetCageAtTime(*time, lightField, cage) : scene->GetCurrentCage(lightField, cage);
  if (!valid)
  {
    Fail(""); // the logic said why, naming the scene file
  }
  return cage;
}

vtkSmartPointer<vtkPolyData> LabelByScene(vtkPolyData* mesh, vtkLightFieldSceneLogic* scene)
{
  auto labelled = vtkSmartPointer<vtkPolyData>::New();
  if (!scene->LabelMesh(mesh, labelled))
  {
    Fail("");
  }
  return labelled;
}

void WriteLightField(vtkLightField* lightField, const std::string& directory, int tileSize)
{
  vtkNew<vtkLightFieldWriter> writer;
  writer->SetInputData(lightField);
  writer->SetDirectory(directory.c_str());
  writer->SetTileSize(tileSize);
  lfd::ShowProgress(writer, "writing");
  Run(writer.Get(), "writing " + directory);
}

void WriteScene(vtkLightFieldScene* scene, const std::string& path)
{
  StepErrors errors;
  errors->Observe(scene);
  scene->Write(path.c_str());
  errors.FailOnError();
}

void WriteImage(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkImageFileWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  Run(writer.Get(), "writing " + path);
}
}
