// lfd: the LightField Deform command-line tool.
//
// Every subcommand is a thin layer over the library's VTK algorithms (the
// same classes Python scripts use through `import lfd`): it parses options,
// wires the pipeline, reports progress and turns errors into one line and a
// non-zero exit status.
#include "lfdConsole.h"
#include "lfdFileUtilities.h"

#include "vtkBoxCoverageCheck.h"
#include "vtkCagePoseFilter.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkCellData.h"
#include "vtkDeformationCage.h"
#include "vtkExecutive.h"
#include "vtkGroundTruthEvaluator.h"
#include "vtkImageData.h"
#include "vtkImageFileReader.h"
#include "vtkImageFileWriter.h"
#include "vtkImageResize.h"
#include "vtkIntArray.h"
#include "vtkKeyframeInterpolator.h"
#include "vtkLabelCellsByBoxes.h"
#include "vtkLabelPalette.h"
#include "vtkLabelPropagation.h"
#include "vtkLatticeCageFilter.h"
#include "vtkLeaveOneOutEvaluator.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldReader.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldWriter.h"
#include "vtkMath.h"
#include "vtkMiddleburyImporter.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPartCageSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkProceduralObjectSource.h"
#include "vtkProjectorSegmentation.h"
#include "vtkSMPTools.h"
#include "vtkSTLReader.h"
#include "vtkScanlineSplit.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPolyDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <fnmatch.h>

namespace
{
/// Thrown by a subcommand to stop with exit status 1; an empty message
/// means the error was already reported by VTK.
struct Failure
{
  std::string Message;
};

[[noreturn]] void Fail(const std::string& message)
{
  throw Failure{ message };
}

/// Updates an algorithm and fails with its own error text when it reports one.
template<typename Algorithm>
void Run(Algorithm* algorithm, const std::string& what)
{
  const bool before = lfd::ErrorReported();
  algorithm->Update();
  if (lfd::ErrorReported() != before)
  {
    Fail("");
  }
  if (algorithm->GetErrorCode() != 0)
  {
    Fail(what + " failed");
  }
}

/// Stops before an output is written when any error was reported so far.
void CheckNoError()
{
  if (lfd::ErrorReported())
  {
    Fail("");
  }
}

/**
 * A multi-file output folder written under a temporary sibling name
 * (lfd::io::TemporaryDirectoryName) and renamed onto its target by Commit()
 * only when complete: a command that fails leaves neither a partial folder
 * nor the temporary, and an existing target is replaced only on success.
 * Since the whole target is replaced, an existing one must hold nothing but
 * files the command writes (`patterns`, fnmatch globs): a folder of the
 * user's is never swept away.
 */
class StagedFolder
{
public:
  StagedFolder(const std::string& target,
    const std::string& command,
    const std::vector<std::string>& patterns)
    : Target(lfd::io::TrimSeparators(target))
    , Temporary(lfd::io::TemporaryDirectoryName(target))
  {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::file_status status = fs::status(this->Target, error);
    if (fs::exists(status) && !fs::is_directory(status))
    {
      Fail("--out " + this->Target + ": exists and is not a folder");
    }
    if (fs::is_directory(status))
    {
      for (const fs::directory_entry& entry : fs::directory_iterator(this->Target, error))
      {
        const std::string name = entry.path().filename().string();
        if (std::none_of(patterns.begin(),
              patterns.end(),
              [&name](const std::string& pattern)
              { return fnmatch(pattern.c_str(), name.c_str(), 0) == 0; }))
        {
          Fail("--out " + this->Target + ": holds '" + name + "', which " + command +
            " does not write; it replaces the whole folder, so choose a new or empty one");
        }
      }
    }
    lfd::io::RemoveQuietly(this->Temporary);
    if (!fs::create_directories(this->Temporary, error))
    {
      Fail("--out " + this->Target + ": cannot create " + this->Temporary + ": " + error.message());
    }
    lfd::AliasPath(this->Temporary, this->Target);
  }
  ~StagedFolder()
  {
    if (!this->Committed)
    {
      lfd::io::RemoveQuietly(this->Temporary);
    }
  }
  StagedFolder(const StagedFolder&) = delete;
  void operator=(const StagedFolder&) = delete;

  /// Where the command writes.
  const std::string& GetPath() const { return this->Temporary; }

  /// Replaces the target with the complete folder.
  void Commit()
  {
    CheckNoError();
    std::string error;
    if (!lfd::io::CommitDirectory(this->Temporary, this->Target, error))
    {
      Fail(error);
    }
    this->Committed = true;
  }

private:
  std::string Target;
  std::string Temporary;
  bool Committed = false;
};

/**
 * The numeric options of every subcommand. CLI11 stores their text; after
 * parsing, Convert() turns each given one into its variable and refuses a
 * value that is not a number or outside its range the same way as any other
 * refused input (one line naming the option, exit status 1). The ranges are
 * the ones the receiving classes accept (their vtkSetClampMacro limits)
 * where there is such a class.
 */
class NumericOptions
{
public:
  /// A single value in [lowest, highest].
  template<typename T>
  CLI::Option* Add(CLI::App* command,
    const std::string& name,
    T& value,
    T lowest,
    T highest,
    const std::string& description)
  {
    Entry* entry = this->NewEntry();
    entry->Assign = [&value, name, lowest, highest](const std::vector<std::string>& text)
    { value = Parse(name, text.back(), lowest, highest); };
    return command->add_option(name, entry->Text, description + " (" + Range(lowest, highest) + ")")
      ->type_name(std::is_integral<T>::value ? "INT" : "FLOAT")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)
      ->default_str(Format(value));
  }

  /// A list of values, each in [lowest, highest].
  template<typename T>
  CLI::Option* Add(CLI::App* command,
    const std::string& name,
    std::vector<T>& values,
    T lowest,
    T highest,
    const std::string& description)
  {
    Entry* entry = this->NewEntry();
    entry->Assign = [&values, name, lowest, highest](const std::vector<std::string>& text)
    {
      values.clear();
      for (const std::string& item : text)
      {
        values.push_back(Parse(name, item, lowest, highest));
      }
    };
    std::string defaults;
    for (const T& value : values)
    {
      defaults += (defaults.empty() ? "" : " ") + Format(value);
    }
    return command
      ->add_option(name, entry->Text, description + " (each " + Range(lowest, highest) + ")")
      ->type_name(std::is_integral<T>::value ? "INT" : "FLOAT")
      ->default_str(defaults);
  }

  /// A finite real number (no other bound).
  CLI::Option* AddReal(CLI::App* command,
    const std::string& name,
    double& value,
    const std::string& description)
  {
    return this->Add(command, name, value, -Huge, Huge, description);
  }
  CLI::Option* AddReal(CLI::App* command,
    const std::string& name,
    std::vector<double>& values,
    const std::string& description)
  {
    return this->Add(command, name, values, -Huge, Huge, description);
  }

  /// Converts every numeric option given on the command line.
  void Convert()
  {
    for (const auto& entry : this->Entries)
    {
      if (!entry->Text.empty())
      {
        entry->Assign(entry->Text);
      }
    }
  }

private:
  static constexpr double Huge = std::numeric_limits<double>::max();

  struct Entry
  {
    std::vector<std::string> Text;
    std::function<void(const std::vector<std::string>&)> Assign;
  };

  Entry* NewEntry()
  {
    this->Entries.push_back(std::make_unique<Entry>());
    return this->Entries.back().get();
  }

  template<typename T>
  static std::string Format(T value)
  {
    std::ostringstream text;
    text << value;
    return text.str();
  }

  template<typename T>
  static std::string Range(T lowest, T highest)
  {
    const char* kind = std::is_integral<T>::value ? "an integer" : "a number";
    if (static_cast<double>(highest) >= static_cast<double>(std::numeric_limits<int>::max()))
    {
      return static_cast<double>(lowest) <= -Huge ? std::string(kind)
                                                  : std::string(kind) + " >= " + Format(lowest);
    }
    return std::string(kind) + " from " + Format(lowest) + " to " + Format(highest);
  }

  template<typename T>
  static T Parse(const std::string& name, const std::string& text, T lowest, T highest)
  {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    double number = 0.0;
    if (std::is_integral<T>::value)
    {
      number = static_cast<double>(std::strtoll(begin, &end, 10));
    }
    else
    {
      number = std::strtod(begin, &end);
    }
    // !(a <= b) also refuses NaN.
    if (end == begin || *end != '\0' || errno != 0 || !std::isfinite(number) ||
      !(number >= static_cast<double>(lowest) && number <= static_cast<double>(highest)))
    {
      Fail(name + " " + text + ": expected " + Range(lowest, highest));
    }
    return static_cast<T>(number);
  }

  std::vector<std::unique_ptr<Entry>> Entries;
};

double Seconds(double start)
{
  return vtkTimerLog::GetUniversalTime() - start;
}

//------------------------------------------------------------------------------
// lfd synth

struct SynthOptions
{
  std::string Object = "fish";
  std::string Mesh;
  std::string Texture;
  std::string Scene;
  std::string Out;
  int Views = 120;
  int Rows = 3;
  int Width = 256;
  int Height = 256;
  double Radius = 0.0;
  double ViewAngle = 0.0;
  std::vector<double> Axis = { 0.0, 1.0, 0.0 };
  bool SceneFixedLight = false;
  bool NoDepth = false;
  int Projectors = 0;
  double ProjectorNoise = 0.0;
  double ProjectorAmbient = 0.0;
  std::vector<std::string> ProjectorMasks;
};

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

vtkSmartPointer<vtkLightFieldScene> ReadScene(const std::string& path)
{
  ExpectSceneFile(path);
  auto scene = vtkSmartPointer<vtkLightFieldScene>::New();
  if (!scene->Read(path.c_str()))
  {
    Fail(scene->GetErrorMessage());
  }
  return scene;
}

/// An image file (PNG, EXR, ... through OpenImageIO), rows bottom first.
vtkSmartPointer<vtkImageData> ReadImage(const std::string& path)
{
  vtkNew<vtkImageFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    Fail(reader->GetErrorMessage());
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

vtkSmartPointer<vtkLightField> ReadLightField(const std::string& path)
{
  vtkNew<vtkLightFieldReader> reader;
  reader->SetFileName(path.c_str());
  lfd::ShowProgress(reader, "reading");
  reader->Update();
  if (reader->GetErrorCode() != 0)
  {
    Fail(reader->GetErrorMessage());
  }
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->ShallowCopy(reader->GetOutput());
  return lightField;
}

/// The light field a scene names (an error naming the scene and its field
/// "lightfield" when it names none or a missing one).
vtkSmartPointer<vtkLightField> ReadSceneLightField(vtkLightFieldScene* scene)
{
  if (!scene->ConfigureReader(nullptr))
  {
    Fail(scene->GetErrorMessage());
  }
  return ReadLightField(scene->GetResolvedLightFieldPath());
}

/// Records the last error an object reports instead of printing it, so that
/// the caller says it once, with the file it came from.
class ErrorCatcher
{
public:
  explicit ErrorCatcher(vtkObject* object)
  {
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long, void* clientData, void* callData)
      {
        *static_cast<std::string*>(clientData) =
          lfd::StripLocation(static_cast<const char*>(callData));
      });
    this->Callback->SetClientData(&this->Message);
    object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
  }
  const std::string& GetMessage() const { return this->Message; }

private:
  std::string Message;
  vtkNew<vtkCallbackCommand> Callback;
};

/**
 * The scene's cage, validated (against the light field when given; nullptr
 * when the scene has none): the one check of a scene's boxes for every
 * command. With keyframes and a time, the cage points are the keyframes'
 * Catmull-Rom interpolation at that time.
 */
vtkSmartPointer<vtkDeformationCage> SceneCage(vtkLightFieldScene* scene,
  vtkLightField* lightField,
  const double* time = nullptr)
{
  if (!scene->HasCage())
  {
    return nullptr;
  }
  auto cage = vtkSmartPointer<vtkDeformationCage>::New();
  cage->InitializeFromGrid(scene->GetCage());
  if (time && scene->GetNumberOfKeyframes() > 0)
  {
    vtkNew<vtkKeyframeInterpolator> keyframes;
    ErrorCatcher refusal(keyframes);
    for (int k = 0; k < scene->GetNumberOfKeyframes(); ++k)
    {
      keyframes->AddKeyframe(scene->GetKeyframeTime(k), scene->GetKeyframePoints(k));
      if (!refusal.GetMessage().empty())
      {
        Fail(std::string(scene->GetFileName()) + ": keyframes: " + refusal.GetMessage());
      }
    }
    vtkNew<vtkPoints> points;
    keyframes->InterpolatePoints(*time, points);
    cage->SetPoints(points);
  }
  // The refusal is said once, with the scene's file name: the observer keeps
  // the cage's own error event from the console.
  vtkNew<vtkCallbackCommand> quiet;
  cage->AddObserver(vtkCommand::ErrorEvent, quiet);
  if (!cage->Validate(lightField))
  {
    Fail(std::string(scene->GetFileName()) + ": " + cage->GetErrorMessage());
  }
  return cage;
}

/**
 * The mesh with its cells labelled by the scene's rest boxes (a triangle
 * takes the box holding its centroid), after the boxes passed SceneCage():
 * how `synth --scene` splits a mesh into parts and how `eval groundtruth`
 * gives the ground truth the parts the light field was split into.
 */
vtkSmartPointer<vtkPolyData> LabelByScene(vtkPolyData* mesh, vtkLightFieldScene* scene)
{
  vtkNew<vtkLabelCellsByBoxes> labeler;
  labeler->SetInputData(mesh);
  labeler->SetBoxesData(scene->GetCage());
  Run(labeler.Get(), "labelling the mesh by the scene's boxes");
  return labeler->GetOutput();
}

/// The scene's view and render settings on a renderer or an evaluator.
template<typename Target>
void ApplySceneView(Target* target, vtkLightFieldScene* scene)
{
  target->SetCamera(scene->GetCamera());
  target->SetWidth(scene->GetWidth());
  target->SetHeight(scene->GetHeight());
  target->SetFocalDistance(scene->GetFocalDistance());
  target->SetSubdivision(scene->GetSubdivision()); // 0 = "auto" in all three
  target->SetWidenedSearch(scene->GetWidenedSearch());
  target->SetObjectThreshold(scene->GetObjectThreshold());
}

/// A renderer of the scene's light field from the scene's camera.
void ConfigureRenderer(vtkLightFieldRenderer* renderer,
  vtkLightFieldScene* scene,
  vtkLightField* lightField,
  vtkDeformationCage* cage)
{
  renderer->SetInputData(lightField);
  renderer->SetCageData(cage);
  ApplySceneView(renderer, scene);
  renderer->SetBackground(scene->GetBackground());
}

void WriteLightField(vtkLightField* lightField, const std::string& directory)
{
  CheckNoError();
  vtkNew<vtkLightFieldWriter> writer;
  writer->SetInputData(lightField);
  writer->SetDirectory(directory.c_str());
  lfd::ShowProgress(writer, "writing");
  if (!writer->Write())
  {
    Fail(writer->GetErrorMessage());
  }
}

void WriteScene(vtkLightFieldScene* scene, const std::string& path)
{
  CheckNoError();
  if (!scene->Write(path.c_str()))
  {
    Fail(scene->GetErrorMessage());
  }
}

void WriteImage(vtkImageData* image, const std::string& path)
{
  CheckNoError();
  vtkNew<vtkImageFileWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  if (!writer->Write())
  {
    Fail(writer->GetErrorMessage());
  }
}

/// The source mesh (and texture) of a capture or a ground-truth comparison: a
/// built-in object by name, or a mesh file.
vtkSmartPointer<vtkPolyData> SourceMesh(const std::string& name,
  vtkSmartPointer<vtkImageData>& texture)
{
  const int object = vtkProceduralObjectSource::GetObjectFromString(name.c_str());
  if (object < 0)
  {
    return ReadMesh(name);
  }
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObject(object);
  source->Update();
  texture = source->GetTextureOutput();
  return source->GetOutput();
}

/// The painted masks of `projectors` projectors, one RGB image each, stacked
/// into one image of Wp x Hp x projectors (the "Mask" array).
vtkSmartPointer<vtkImageData> ReadProjectorMasks(const std::vector<std::string>& files,
  int projectors)
{
  if (static_cast<int>(files.size()) != projectors)
  {
    Fail("--projector-mask: " + std::to_string(files.size()) + " masks for " +
      std::to_string(projectors) + " projectors (give one per projector)");
  }
  auto masks = vtkSmartPointer<vtkImageData>::New();
  vtkNew<vtkUnsignedCharArray> stack;
  stack->SetName("Mask");
  stack->SetNumberOfComponents(3);
  for (size_t p = 0; p < files.size(); ++p)
  {
    vtkSmartPointer<vtkImageData> image = ReadImage(files[p]);
    vtkDataArray* rgb = image->GetPointData()->GetScalars();
    const int* dims = image->GetDimensions();
    if (!rgb || rgb->GetNumberOfComponents() < 3)
    {
      Fail(files[p] + ": a projector mask is an RGB image");
    }
    if (p == 0)
    {
      masks->SetDimensions(dims[0], dims[1], projectors);
      stack->SetNumberOfTuples(masks->GetNumberOfPoints());
    }
    else if (dims[0] != masks->GetDimensions()[0] || dims[1] != masks->GetDimensions()[1])
    {
      Fail(files[p] + ": is " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + ", " +
        files[0] + " " + std::to_string(masks->GetDimensions()[0]) + "x" +
        std::to_string(masks->GetDimensions()[1]) + " (every projector mask has the same size)");
    }
    const vtkIdType pixels = static_cast<vtkIdType>(dims[0]) * dims[1];
    for (vtkIdType i = 0; i < pixels; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        stack->SetTypedComponent(
          p * pixels + i, c, static_cast<unsigned char>(rgb->GetComponent(i, c)));
      }
    }
  }
  masks->GetPointData()->SetScalars(stack);
  return masks;
}

/// Captures a light field of `mesh` (with `texture`, optional) with the options' rig and light.
vtkSmartPointer<vtkLightField> Capture(vtkPolyData* mesh,
  vtkImageData* texture,
  const SynthOptions& options)
{
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputData(mesh);
  capture->SetTextureData(texture);
  capture->SetViewsPerRing(options.Views);
  capture->SetNumberOfRows(options.Rows);
  capture->SetWidth(options.Width);
  capture->SetHeight(options.Height);
  capture->SetRadius(options.Radius);
  if (options.ViewAngle > 0.0)
  {
    capture->SetViewAngle(options.ViewAngle);
  }
  capture->SetAxis(options.Axis[0], options.Axis[1], options.Axis[2]);
  capture->SetSceneFixedLight(options.SceneFixedLight);
  capture->SetCaptureDepth(!options.NoDepth);
  if (options.Projectors > 0)
  {
    // One palette colour per part of the mesh, as far apart as the camera
    // can tell them; the projectors paint each part with its colour.
    vtkDataArray* labels = mesh->GetCellData()->GetArray("Label");
    double range[2] = { 1.0, 1.0 };
    if (labels)
    {
      labels->GetRange(range, 0);
    }
    vtkNew<vtkLabelPalette> chooser;
    chooser->SetNumberOfLabels(std::max(1, static_cast<int>(range[1])));
    vtkNew<vtkUnsignedCharArray> palette;
    if (!chooser->Build(palette))
    {
      Fail("cannot choose " + std::to_string(static_cast<int>(range[1])) + " label colours");
    }
    capture->SetPalette(palette);
    capture->SetNumberOfProjectors(options.Projectors);
    if (!options.ProjectorMasks.empty())
    {
      capture->SetProjectorMasks(ReadProjectorMasks(options.ProjectorMasks, options.Projectors));
      capture->SetProjectorWidth(capture->GetProjectorMasks()->GetDimensions()[0]);
      capture->SetProjectorHeight(capture->GetProjectorMasks()->GetDimensions()[1]);
    }
    capture->SetProjectorNoise(options.ProjectorNoise);
    capture->SetProjectorAmbient(options.ProjectorAmbient);
  }
  lfd::ShowProgress(capture, "capturing");
  Run(capture.Get(), "synthetic capture");
  auto lightField = vtkSmartPointer<vtkLightField>::New();
  lightField->ShallowCopy(capture->GetOutput());
  return lightField;
}

/// Captures a light field of a mesh (or a built-in object) with the options.
vtkSmartPointer<vtkLightField> Synthesize(const SynthOptions& options)
{
  vtkSmartPointer<vtkImageData> texture;
  vtkSmartPointer<vtkPolyData> mesh;
  if (!options.Mesh.empty())
  {
    mesh = ReadMesh(options.Mesh);
    if (!options.Texture.empty())
    {
      texture = ReadImage(options.Texture);
    }
  }
  else
  {
    mesh = SourceMesh(options.Object, texture);
  }
  if (!options.Scene.empty())
  {
    auto scene = ReadScene(options.Scene);
    if (!scene->HasCage())
    {
      Fail("scene '" + options.Scene + "' has no cage: its rest boxes are what label the mesh");
    }
    SceneCage(scene, nullptr);
    mesh = LabelByScene(mesh, scene);
  }
  return Capture(mesh, texture, options);
}

void AddSynthOptions(CLI::App* command, SynthOptions& options, NumericOptions& numbers)
{
  vtkNew<vtkLightFieldCapture> limits; // the capture's own ranges
  command->add_option("--object", options.Object, "built-in object")
    ->check(CLI::IsMember({ "fish", "figure", "checkerboard" }))
    ->capture_default_str();
  numbers.Add(command,
    "--views",
    options.Views,
    limits->GetViewsPerRingMinValue(),
    limits->GetViewsPerRingMaxValue(),
    "views per ring");
  numbers.Add(command,
    "--rows",
    options.Rows,
    limits->GetNumberOfRowsMinValue(),
    limits->GetNumberOfRowsMaxValue(),
    "rings (rows) of views");
  numbers.Add(command,
    "--width",
    options.Width,
    limits->GetWidthMinValue(),
    limits->GetWidthMaxValue(),
    "image width in pixels");
  numbers.Add(command,
    "--height",
    options.Height,
    limits->GetHeightMinValue(),
    limits->GetHeightMaxValue(),
    "image height in pixels");
  numbers.Add(command,
    "--radius",
    options.Radius,
    limits->GetRadiusMinValue(),
    limits->GetRadiusMaxValue(),
    "ring radius (0: frame the mesh)");
  numbers.Add(command,
    "--view-angle",
    options.ViewAngle,
    0.0,
    limits->GetViewAngleMaxValue(),
    "vertical field of view in degrees (0: frame the mesh)");
  numbers.AddReal(command, "--axis", options.Axis, "rig axis x y z")->expected(3);
  command->add_flag("--scene-fixed-light",
    options.SceneFixedLight,
    "light fixed in the scene instead of travelling with the camera (paper Fig. 5)");
  command->add_flag("--no-depth", options.NoDepth, "skip the Depth pass");
  numbers.Add(command,
    "--projectors",
    options.Projectors,
    limits->GetNumberOfProjectorsMinValue(),
    limits->GetNumberOfProjectorsMaxValue(),
    "also capture the Coded and Flood passes lit by N projectors on the ring, painting each "
    "part with its palette colour");
  numbers.Add(command,
    "--projector-noise",
    options.ProjectorNoise,
    limits->GetProjectorNoiseMinValue(),
    limits->GetProjectorNoiseMaxValue(),
    "sensor noise sigma of the projector passes (8-bit levels)");
  command->add_option("--projector-mask",
    options.ProjectorMasks,
    "a painted mask (RGB image in the palette's colours, see the palette printed) for each "
    "projector, in order; repeat (default: masks generated from the part labels)");
  numbers.Add(command,
    "--projector-ambient",
    options.ProjectorAmbient,
    limits->GetProjectorAmbientMinValue(),
    limits->GetProjectorAmbientMaxValue(),
    "room light in the projector passes (fraction of the albedo)");
}

//------------------------------------------------------------------------------
// Novel views around a light field's rig

/// A camera on a circle `scale` x the rig radius around the rig axis, at
/// azimuth `phi` (radians from view 0) and `height` along the axis, looking
/// at the rig centre.
void OrbitCamera(vtkCameraRig* rig,
  double phi,
  double scale,
  double height,
  double viewAngle,
  vtkCamera* camera)
{
  const double* axis = rig->GetAxis();
  const double* center = rig->GetCenter();
  double x[3], y[3];
  rig->GetAzimuthFrame(x, y);
  const double r = scale * rig->GetRadius();
  double position[3], focal[3];
  for (int c = 0; c < 3; ++c)
  {
    focal[c] = center[c];
    position[c] = center[c] + height * axis[c] + r * (std::cos(phi) * x[c] + std::sin(phi) * y[c]);
  }
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  camera->SetViewUp(axis[0], axis[1], axis[2]);
  camera->SetViewAngle(viewAngle);
}

/// A grid of thumbnails of the frames.
vtkSmartPointer<vtkImageData> ContactSheet(const std::vector<vtkSmartPointer<vtkImageData>>& frames,
  int columns,
  int thumb)
{
  const int rows = (static_cast<int>(frames.size()) + columns - 1) / columns;
  auto sheet = vtkSmartPointer<vtkImageData>::New();
  sheet->SetDimensions(columns * thumb, rows * thumb, 1);
  sheet->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(sheet->GetScalarPointer());
  std::fill(out, out + 3 * columns * thumb * rows * thumb, 0);
  for (std::size_t f = 0; f < frames.size(); ++f)
  {
    vtkNew<vtkImageResize> resize;
    resize->SetInputData(frames[f]);
    resize->SetOutputDimensions(thumb, thumb, 1);
    resize->Update();
    const auto* in = static_cast<unsigned char*>(resize->GetOutput()->GetScalarPointer());
    const int col = static_cast<int>(f) % columns;
    const int row = rows - 1 - static_cast<int>(f) / columns; // first frame top-left
    for (int j = 0; j < thumb; ++j)
    {
      std::copy(in + 3 * j * thumb,
        in + 3 * (j + 1) * thumb,
        out + 3 * ((row * thumb + j) * columns * thumb + col * thumb));
    }
  }
  return sheet;
}

//------------------------------------------------------------------------------
// Subcommands

void Synth(const SynthOptions& options)
{
  const double start = vtkTimerLog::GetUniversalTime();
  auto lightField = Synthesize(options);
  WriteLightField(lightField, options.Out);
  if (vtkUnsignedCharArray* palette = lightField->GetPalette())
  {
    std::cout << "palette:";
    for (vtkIdType label = 1; label < palette->GetNumberOfTuples(); ++label)
    {
      std::cout << " " << label << "=(" << static_cast<int>(palette->GetTypedComponent(label, 0))
                << "," << static_cast<int>(palette->GetTypedComponent(label, 1)) << ","
                << static_cast<int>(palette->GetTypedComponent(label, 2)) << ")";
    }
    std::cout << "\n";
  }
  std::cout << "wrote " << lightField->GetNumberOfViews() << " views of " << lightField->GetWidth()
            << "x" << lightField->GetHeight() << " to " << options.Out << " in " << Seconds(start)
            << " s\n";
}

/// `shownAs`: the name the report gives `out` (a staged folder's target).
void ImportMiddlebury(const std::string& par, const std::string& out, const std::string& shownAs)
{
  vtkNew<vtkMiddleburyImporter> importer;
  importer->SetFileName(par.c_str());
  lfd::ShowProgress(importer, "importing");
  importer->Update();
  if (importer->GetErrorCode() != 0)
  {
    Fail(importer->GetErrorMessage());
  }
  WriteLightField(importer->GetOutput(), out);
  vtkCameraRig* rig = importer->GetOutput()->GetRig();
  std::cout << "imported " << rig->GetNumberOfViews() << " views (" << rig->GetNumberOfDuplicates()
            << " near-duplicates) into " << shownAs << "\n";
}

void Info(const std::string& path)
{
  auto lightField = ReadLightField(path);
  vtkCameraRig* rig = lightField->GetRig();
  std::cout << "light field  " << path << "\n";
  std::cout << "views        " << lightField->GetNumberOfViews() << " of " << lightField->GetWidth()
            << " x " << lightField->GetHeight() << " pixels\n";
  std::cout << "passes      ";
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (lightField->GetPass(pass))
    {
      std::cout << " " << vtkLightField::GetPassName(pass);
    }
  }
  std::cout << "\n";
  if (vtkUnsignedCharArray* palette = lightField->GetPalette())
  {
    std::cout << "palette      " << palette->GetNumberOfTuples() - 1 << " label colours\n";
  }
  if (vtkCameraRig* projectors = lightField->GetProjectors();
      projectors && projectors->GetNumberOfViews() > 0)
  {
    std::cout << "projectors   " << projectors->GetNumberOfViews() << " of "
              << projectors->GetImageSize()[0] << " x " << projectors->GetImageSize()[1]
              << (lightField->GetProjectorMasks() ? ", with masks" : "") << "\n";
  }
  if (!rig->FitCylinder())
  {
    Fail("no cylinder can be fitted to the cameras of '" + path + "'");
  }
  const double* axis = rig->GetAxis();
  const double* center = rig->GetCenter();
  std::printf("rig axis     (%.4f, %.4f, %.4f)\n", axis[0], axis[1], axis[2]);
  std::printf("rig centre   (%.4f, %.4f, %.4f)\n", center[0], center[1], center[2]);
  std::printf("rig radius   %.4f (RMS residual %.4f)\n", rig->GetRadius(), rig->GetFitResidual());
  std::printf("rows         %d\n", rig->GetNumberOfRows());
  std::printf("duplicates   %d\n", rig->GetNumberOfDuplicates());
  for (int row = 0; row < rig->GetNumberOfRows(); ++row)
  {
    std::vector<double> azimuths;
    for (int v = 0; v < rig->GetNumberOfViews(); ++v)
    {
      if (rig->GetRow(v) == row && rig->GetDuplicateOf(v) < 0)
      {
        azimuths.push_back(vtkMath::DegreesFromRadians(rig->GetAzimuth(v)));
      }
    }
    std::sort(azimuths.begin(), azimuths.end());
    double gap = 360.0 - azimuths.back() + azimuths.front();
    for (std::size_t i = 1; i < azimuths.size(); ++i)
    {
      gap = std::max(gap, azimuths[i] - azimuths[i - 1]);
    }
    std::printf("row %-8d height %.4f, %zu views, largest azimuth gap %.1f degrees\n",
      row,
      rig->GetRowHeight(row),
      azimuths.size(),
      gap);
  }
}

void Render(const std::string& scenePath, const std::string& out, const double* time)
{
  const double start = vtkTimerLog::GetUniversalTime();
  auto scene = ReadScene(scenePath);
  auto lightField = ReadSceneLightField(scene);
  auto cage = SceneCage(scene, lightField, time);
  vtkNew<vtkLightFieldRenderer> renderer;
  ConfigureRenderer(renderer, scene, lightField, cage);
  Run(renderer.Get(), "rendering");
  WriteImage(renderer->GetOutput(), out);
  std::cout << "wrote " << out << " (" << scene->GetWidth() << "x" << scene->GetHeight() << ") in "
            << Seconds(start) << " s\n";
}

/// Encodes frame_%04d.png of a folder into an MP4 with ffmpeg, when installed
/// (the folder is staged: a failed encoding leaves nothing behind).
void EncodeMovie(const std::string& frameDir, const std::string& movie)
{
  if (std::system("command -v ffmpeg > /dev/null 2>&1") != 0)
  {
    return;
  }
  const std::string command = "ffmpeg -y -loglevel error -framerate 24 -i '" + frameDir +
    "/frame_%04d.png' -pix_fmt yuv420p '" + movie + "'";
  if (std::system(command.c_str()) != 0)
  {
    Fail("ffmpeg could not encode '" + movie + "'");
  }
}

/// What `lfd animate` writes into its folder.
const std::vector<std::string> AnimationFiles = { "frame_[0-9][0-9][0-9][0-9].png",
  "animation.mp4" };

/**
 * Renders `frames` frames of a scene's keyframes (evenly from the first to
 * the last keyframe time) into out/frame_%04d.png, and an MP4 when ffmpeg is
 * installed. Returns the frames.
 */
std::vector<vtkSmartPointer<vtkImageData>> RenderAnimation(vtkLightFieldScene* scene,
  vtkLightField* lightField,
  int frames,
  const std::string& out)
{
  if (!vtksys::SystemTools::MakeDirectory(out))
  {
    Fail("cannot create the folder " + out);
  }
  const double t0 = scene->GetKeyframeTime(0);
  const double t1 = scene->GetKeyframeTime(scene->GetNumberOfKeyframes() - 1);
  vtkNew<vtkLightFieldRenderer> renderer;
  std::vector<vtkSmartPointer<vtkImageData>> images;
  for (int f = 0; f < frames; ++f)
  {
    const double time = t0 + (t1 - t0) * f / std::max(frames - 1, 1);
    auto cage = SceneCage(scene, lightField, &time);
    ConfigureRenderer(renderer, scene, lightField, cage);
    Run(renderer.Get(), "rendering frame " + std::to_string(f));
    auto frame = vtkSmartPointer<vtkImageData>::New();
    frame->DeepCopy(renderer->GetOutput());
    char name[64];
    std::snprintf(name, sizeof(name), "/frame_%04d.png", f);
    WriteImage(frame, out + name);
    images.push_back(frame);
    std::fprintf(stderr, "animating: frame %d/%d\n", f + 1, frames);
  }
  EncodeMovie(out, out + "/animation.mp4");
  return images;
}

/// The report of an animation written into `folder`, to be known as `out`.
void PrintAnimation(vtkLightFieldScene* scene,
  int frames,
  double seconds,
  const std::string& folder,
  const std::string& out)
{
  std::printf("frames    %d of %dx%d in %s/frame_*.png (%.1f ms/frame)\n",
    frames,
    scene->GetWidth(),
    scene->GetHeight(),
    out.c_str(),
    1000.0 * seconds / frames);
  if (vtksys::SystemTools::FileExists(folder + "/animation.mp4", true))
  {
    std::printf("movie     %s/animation.mp4\n", out.c_str());
  }
}

void Animate(const std::string& scenePath, int frames, const std::string& out)
{
  auto scene = ReadScene(scenePath);
  if (scene->GetNumberOfKeyframes() < 2)
  {
    Fail("scene '" + scenePath + "' needs at least 2 keyframes to animate");
  }
  auto lightField = ReadSceneLightField(scene);
  StagedFolder folder(out, "lfd animate", AnimationFiles);
  const double start = vtkTimerLog::GetUniversalTime();
  RenderAnimation(scene, lightField, frames, folder.GetPath());
  PrintAnimation(scene, frames, Seconds(start), folder.GetPath(), out);
  folder.Commit();
}

void EvalGroundTruth(const std::string& scenePath,
  const std::string& meshName,
  const std::string& out,
  const double* time)
{
  auto scene = ReadScene(scenePath);
  auto lightField = ReadSceneLightField(scene);
  auto cage = SceneCage(scene, lightField, time);
  vtkSmartPointer<vtkImageData> texture;
  auto mesh = SourceMesh(meshName, texture);
  if (cage)
  {
    // The light field's parts are its scene's boxes: so are the ground truth's.
    mesh = LabelByScene(mesh, scene);
  }
  vtkNew<vtkGroundTruthEvaluator> evaluator;
  evaluator->SetInputData(lightField);
  evaluator->SetMeshData(mesh);
  evaluator->SetCageData(cage);
  evaluator->SetTextureData(texture);
  ApplySceneView(evaluator.Get(), scene);
  Run(evaluator.Get(), "ground-truth evaluation");
  std::printf("PSNR (object)     %.2f dB\n", evaluator->GetPSNR());
  std::printf("SSIM (object)     %.4f\n", evaluator->GetSSIM());
  std::printf("silhouette IoU    %.4f\n", evaluator->GetIoU());
  std::printf("label agreement   %.4f\n", evaluator->GetLabelAgreement());
  std::printf("object pixels     %lld\n", static_cast<long long>(evaluator->GetObjectPixels()));
  if (!out.empty())
  {
    // Both images or neither: each is written under a temporary name first.
    const std::string names[2] = { out + "_lightfield.png", out + "_groundtruth.png" };
    std::string temporaries[2];
    for (int i = 0; i < 2; ++i)
    {
      temporaries[i] = lfd::io::TemporaryFileName(names[i]);
      lfd::AliasPath(temporaries[i], names[i]);
    }
    try
    {
      WriteImage(evaluator->GetOutput(0), temporaries[0]);
      WriteImage(evaluator->GetOutput(1), temporaries[1]);
    }
    catch (const Failure&)
    {
      lfd::io::RemoveQuietly(temporaries[0]);
      lfd::io::RemoveQuietly(temporaries[1]);
      throw;
    }
    for (int i = 0; i < 2; ++i)
    {
      std::string error;
      if (!lfd::io::CommitFile(temporaries[i], names[i], error))
      {
        lfd::io::RemoveQuietly(temporaries[1]);
        Fail(error);
      }
    }
  }
}

void EvalLeaveOneOut(const std::string& path,
  int stride,
  const std::vector<int>& views,
  double focalDistance,
  int threshold)
{
  auto lightField = ReadLightField(path);
  vtkNew<vtkLeaveOneOutEvaluator> evaluator;
  evaluator->SetInputData(lightField);
  evaluator->SetStride(stride);
  for (int v : views)
  {
    evaluator->AddView(v);
  }
  evaluator->SetFocalDistance(focalDistance);
  evaluator->SetObjectThreshold(threshold);
  lfd::ShowProgress(evaluator, "evaluating");
  Run(evaluator.Get(), "leave-one-out evaluation");
  vtkTable* table = evaluator->GetOutput();
  std::printf("%6s %10s %12s %12s\n", "view", "PSNR", "object PSNR", "object px");
  for (vtkIdType row = 0; row < table->GetNumberOfRows(); ++row)
  {
    std::printf("%6d %10.2f %12.2f %12d\n",
      table->GetValue(row, 0).ToInt(),
      table->GetValue(row, 1).ToDouble(),
      table->GetValue(row, 2).ToDouble(),
      table->GetValue(row, 3).ToInt());
  }
  std::printf("mean   %10.2f %12.2f   (%lld views, dB)\n",
    evaluator->GetMeanPSNR(),
    evaluator->GetMeanObjectPSNR(),
    static_cast<long long>(table->GetNumberOfRows()));
}

//------------------------------------------------------------------------------
// lfd lattice

struct LatticeOptions
{
  std::string Scene;
  std::string Out;
  std::vector<int> Dimensions = { 2, 2, 2 };
  std::vector<double> Moves; // I J K DX DY DZ, repeated
  std::vector<double> Region;
  int Subdivision = 1;
};

/**
 * Deforms a scene's rest boxes by a Sederberg-Parry lattice (control points
 * moved with --move) sampled into boxes, and writes the scene with that cage
 * (an ordinary cage: points = the FFD of the rest points; keyframes dropped,
 * since they name the old points). The light field is the same one, its
 * path made relative to the new scene file.
 */
void Lattice(const LatticeOptions& options)
{
  auto scene = ReadScene(options.Scene);
  if (!scene->HasCage())
  {
    Fail("scene '" + options.Scene + "' has no cage: the lattice deforms its rest boxes");
  }
  vtkNew<vtkLatticeCageFilter> lattice;
  lattice->SetInputData(scene->GetCage());
  lattice->SetLatticeDimensions(options.Dimensions.data());
  if (options.Moves.size() % 6 != 0)
  {
    Fail("--move takes 6 numbers: I J K DX DY DZ");
  }
  for (std::size_t m = 0; m < options.Moves.size(); m += 6)
  {
    const double* move = &options.Moves[m];
    int index[3];
    for (int a = 0; a < 3; ++a)
    {
      index[a] = static_cast<int>(std::lround(move[a]));
      if (index[a] != move[a] || index[a] < 0 || index[a] >= options.Dimensions[a])
      {
        char message[256];
        std::snprintf(message,
          sizeof(message),
          "--move %g %g %g: control point indices are integers in 0..%d, 0..%d, 0..%d "
          "(--dimensions)",
          move[0],
          move[1],
          move[2],
          options.Dimensions[0] - 1,
          options.Dimensions[1] - 1,
          options.Dimensions[2] - 1);
        Fail(message);
      }
    }
    lattice->SetControlPointDisplacement(index[0], index[1], index[2], move + 3);
  }
  if (!options.Region.empty())
  {
    lattice->SetRegion(options.Region.data());
  }
  lattice->SetSubdivision(options.Subdivision);
  Run(lattice.Get(), "sampling the lattice into boxes");
  vtkDeformationCage* cage = lattice->GetOutput();
  vtkNew<vtkCallbackCommand> quiet; // the refusal is said once, below
  cage->AddObserver(vtkCommand::ErrorEvent, quiet);
  if (!cage->Validate())
  {
    Fail(options.Out + ": the sampled cage is refused: " + cage->GetErrorMessage());
  }

  scene->SetCage(cage);
  scene->RemoveAllKeyframes();
  WriteScene(scene, options.Out);
  double largest = 0.0;
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    double rest[3], deformed[3];
    cage->GetRestPoint(i, rest);
    cage->GetDeformedPoint(i, deformed);
    largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(rest, deformed)));
  }
  std::printf("wrote %s: %lld boxes on %lld points (lattice %d x %d x %d, subdivision %d), "
              "largest corner move %.4g\n",
    options.Out.c_str(),
    static_cast<long long>(cage->GetNumberOfBoxes()),
    static_cast<long long>(cage->GetNumberOfPoints()),
    options.Dimensions[0],
    options.Dimensions[1],
    options.Dimensions[2],
    options.Subdivision,
    largest);
}

/// Median time (s) of `repeat` updates of the renderer, after a warm-up.
double MedianRenderTime(vtkLightFieldRenderer* renderer, int repeat)
{
  Run(renderer, "rendering"); // warm-up (rig layout, threads)
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i)
  {
    renderer->Modified();
    const double start = vtkTimerLog::GetUniversalTime();
    renderer->Update();
    times.push_back(Seconds(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

void Bench(int repeat, int size)
{
  std::printf("threads: %d (vtkSMPTools, %s backend)\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    vtkSMPTools::GetBackend());
  std::printf("%-46s %8s %10s %12s %8s\n",
    "scene (light fields: 120x3 views of 256^2)",
    "pixels",
    "ms/frame",
    "rays/s",
    "vs rest");
  for (const char* object : { "fish", "figure" })
  {
    SynthOptions options;
    options.Object = object;
    options.NoDepth = true;
    auto lightField = Synthesize(options);
    vtkCameraRig* rig = lightField->GetRig();
    vtkNew<vtkCamera> camera;
    OrbitCamera(rig, 0.37, 1.2, 0.0, rig->GetViewAngle(0), camera);
    vtkNew<vtkLightFieldRenderer> renderer;
    renderer->SetInputData(lightField);
    renderer->SetCamera(camera);
    renderer->SetWidth(size);
    renderer->SetHeight(size);
    const double rest = MedianRenderTime(renderer, repeat);

    // The deformed counterpart: the fish swimming (3 boxes, Fig. 13), the
    // figure twisted by 45 degrees (Fig. 1).
    vtkNew<vtkProceduralObjectSource> source;
    source->SetObject(vtkProceduralObjectSource::GetObjectFromString(object));
    vtkNew<vtkPartCageSource> parts;
    parts->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkCagePoseFilter> pose;
    pose->SetInputConnection(parts->GetOutputPort());
    const bool fish = std::string(object) == "fish";
    if (fish)
    {
      pose->SetModeToSwim();
      pose->SetAngle(20.0);
      pose->SetPhase(1.0);
      pose->SetTurnAxis(0.0, 0.0, 1.0);
    }
    else
    {
      pose->SetModeToTwist();
      pose->SetAngle(45.0);
    }
    Run(pose.Get(), "posing the cage");
    renderer->SetCageData(pose->GetOutput());
    const double deformed = MedianRenderTime(renderer, repeat);

    const std::string restName = std::string("undeformed ") + object;
    const std::string deformedName =
      fish ? "deformed fish (swim, 3 boxes)" : "deformed figure (twist 45, 3 boxes)";
    std::printf("%-46s %8d %10.2f %12.3g %8s\n",
      restName.c_str(),
      size * size,
      1000.0 * rest,
      size * size / rest,
      "");
    std::printf("%-46s %8d %10.2f %12.3g %7.2fx\n",
      deformedName.c_str(),
      size * size,
      1000.0 * deformed,
      size * size / deformed,
      deformed / rest);
  }
  std::printf("(median of %d renders each)\n", repeat);
}

/**
 * A built-in scene of `lfd demo`: an object, its cage at rest, keyframes of
 * a pose, and the light(s) it is captured under.
 */
struct DemoScene
{
  const char* Object; ///< the built-in object
  const char* Name;   ///< the scene file's name (and the light field's, see below)
  const char* Motion; ///< what the keyframes do, for the report
  bool SingleBox;     ///< one box (label 1) around the whole object, as in Fig. 1
  int Axis;           ///< the slab axis of the cage and of the pose
  int Mode;           ///< vtkCagePoseFilter mode
  double Angle;       ///< the pose's angle (degrees)
  bool Wave;          ///< keyframes run the swim's phase over a cycle, else ramp the angle
  bool BothLights;    ///< also capture under a scene-fixed light (Figs. 4 and 5)
  double TurnAxis[3];
};

/// The demos: the swimming fish (Fig. 13), the single-box twist of the
/// figure (Fig. 1) and the twisted checkerboard under coaxial and scene-fixed
/// light (Figs. 4 and 5).
const DemoScene DemoScenes[] = {
  { "fish", "swim", "swim", false, -1, vtkCagePoseFilter::SWIM, 20.0, true, false, { 0, 0, 1 } },
  { "figure",
    "twist",
    "twist 0-90 degrees",
    true,
    1,
    vtkCagePoseFilter::TWIST,
    90.0,
    false,
    false,
    { 0, 1, 0 } },
  { "checkerboard",
    "checkerboard",
    "top twisted 0-60 degrees",
    true,
    1,
    vtkCagePoseFilter::TWIST,
    60.0,
    false,
    true,
    { 0, 1, 0 } },
};

/// What `lfd demo` writes into its folder: light fields, scenes, frame
/// folders and contact sheets.
const std::vector<std::string> DemoFiles = { "*.lf",
  "*.json",
  "frames",
  "frames_*",
  "contact_sheet*.png" };

/// The object's mesh with every cell in part 1: one sub-light field for one box.
vtkSmartPointer<vtkPolyData> SinglePart(vtkPolyData* mesh)
{
  auto single = vtkSmartPointer<vtkPolyData>::New();
  single->ShallowCopy(mesh);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Label");
  labels->SetNumberOfTuples(mesh->GetNumberOfCells());
  labels->FillValue(1);
  single->GetCellData()->AddArray(labels); // replaces the parts' labels
  return single;
}

/**
 * A demo's animation in its staged folder `staged` (to be known as `out`):
 * frames`suffix`/ and contact_sheet`suffix`.png.
 */
void AnimateDemo(vtkLightFieldScene* scene,
  vtkLightField* lightField,
  int frames,
  const std::string& staged,
  const std::string& out,
  const std::string& suffix)
{
  const double start = vtkTimerLog::GetUniversalTime();
  const std::string frameDir = "/frames" + suffix;
  const auto images = RenderAnimation(scene, lightField, frames, staged + frameDir);
  PrintAnimation(scene, frames, Seconds(start), staged + frameDir, out + frameDir);
  const std::string sheet = "/contact_sheet" + suffix + ".png";
  WriteImage(ContactSheet(images, 6, 128), staged + sheet);
  std::printf("sheet     %s%s\n", out.c_str(), sheet.c_str());
}

/**
 * `lfd demo`: captures the scene's object (under each light), writes the
 * light field, a scene with the cage and its keyframes, the animation's
 * frames and a contact sheet. A second light writes its files with the
 * suffix "_fixed_light".
 */
void Demo(const std::string& sceneName,
  const std::string& out,
  int frames,
  int size,
  const SynthOptions& capture)
{
  const DemoScene* demo = nullptr;
  for (const DemoScene& candidate : DemoScenes)
  {
    if (sceneName == candidate.Name || sceneName == candidate.Object)
    {
      demo = &candidate;
    }
  }
  StagedFolder folder(out, "lfd demo", DemoFiles);
  const std::string& staged = folder.GetPath();
  vtkSmartPointer<vtkImageData> texture;
  vtkSmartPointer<vtkPolyData> mesh = SourceMesh(demo->Object, texture);
  if (demo->SingleBox)
  {
    mesh = SinglePart(mesh);
  }
  vtkNew<vtkPartCageSource> parts;
  parts->SetInputData(mesh);
  parts->SetAxis(demo->Axis);
  Run(parts.Get(), "building the cage");
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(parts->GetOutputPort());
  pose->SetMode(demo->Mode);
  pose->SetAxis(parts->GetUsedAxis());
  pose->SetAngle(demo->Angle);
  pose->SetTurnAxis(demo->TurnAxis);
  const int keyframes = 8;
  std::vector<vtkSmartPointer<vtkPoints>> poses;
  for (int k = 0; k <= keyframes; ++k)
  {
    const double t = static_cast<double>(k) / keyframes;
    if (demo->Wave)
    {
      pose->SetPhase(2.0 * vtkMath::Pi() * t);
    }
    else
    {
      pose->SetAngle(demo->Angle * t);
    }
    Run(pose.Get(), "posing the cage");
    poses.push_back(vtkSmartPointer<vtkPoints>::New());
    poses.back()->DeepCopy(pose->GetOutput()->GetPoints());
  }

  for (const bool sceneFixedLight : { false, true })
  {
    if (sceneFixedLight && !demo->BothLights)
    {
      continue;
    }
    const std::string suffix = sceneFixedLight ? "_fixed_light" : "";
    double start = vtkTimerLog::GetUniversalTime();
    SynthOptions options = capture;
    options.SceneFixedLight = sceneFixedLight;
    auto lightField = Capture(mesh, texture, options);
    const double captureTime = Seconds(start);
    start = vtkTimerLog::GetUniversalTime();
    const std::string lightFieldName = std::string(demo->Object) + suffix + ".lf";
    WriteLightField(lightField, staged + "/" + lightFieldName);
    const double writeTime = Seconds(start);

    vtkNew<vtkLightFieldScene> scene;
    scene->SetLightFieldPath(lightFieldName.c_str());
    scene->SetCage(parts->GetOutput());
    for (int k = 0; k <= keyframes; ++k)
    {
      scene->AddKeyframe(k, poses[k]);
    }
    vtkCameraRig* rig = lightField->GetRig();
    const double step = 2.0 * vtkMath::Pi() / rig->GetNumberOfViews() * rig->GetNumberOfRows();
    // Half-way between two captured views, further out than the ring. For
    // the fish, swimming about the camera's viewing axis keeps the motion in
    // the picture (a ring light field has horizontal parallax only).
    OrbitCamera(rig, 0.5 * step, 1.15, 0.0, 0.7 * rig->GetViewAngle(0), scene->GetCamera());
    scene->SetWidth(size);
    scene->SetHeight(size);
    const std::string sceneName = std::string(demo->Name) + suffix + ".json";
    WriteScene(scene, staged + "/" + sceneName);

    std::printf("capture   %d views of %dx%d%s in %.2f s; written to %s/%s in %.2f s\n",
      lightField->GetNumberOfViews(),
      lightField->GetWidth(),
      lightField->GetHeight(),
      sceneFixedLight ? " under a scene-fixed light" : "",
      captureTime,
      out.c_str(),
      lightFieldName.c_str(),
      writeTime);
    std::printf("scene     %s/%s (%lld boxes, %d keyframes: %s)\n",
      out.c_str(),
      sceneName.c_str(),
      static_cast<long long>(parts->GetOutput()->GetNumberOfBoxes()),
      keyframes + 1,
      demo->Motion);
    AnimateDemo(scene, lightField, frames, staged, out, suffix);
  }
  folder.Commit();
}

/**
 * `lfd demo --scene temple`: Fig. 1 on real data. The Middlebury templeRing
 * (47 photographs, no split) is one part in one box around the temple, whose
 * top turns 0-60 degrees about the vertical: the renderer finds the object
 * pixels (brighter than 60: the cloth behind the temple reaches about 45)
 * and the box moves them. `dataDir` holds templeR_par.txt; empty: look in
 * ../shared/data/templeRing, then in the configured shared data folder.
 */
void DemoTemple(const std::string& dataDir, const std::string& out, int frames, int size)
{
  std::vector<std::string> candidates;
  if (!dataDir.empty())
  {
    candidates.push_back(dataDir);
  }
  else
  {
    candidates = { "../shared/data/templeRing", LFD_SHARED_DATA_DIR "/templeRing" };
  }
  std::string par;
  for (const std::string& folder : candidates)
  {
    if (par.empty() && vtksys::SystemTools::FileExists(folder + "/templeR_par.txt", true))
    {
      par = folder + "/templeR_par.txt";
    }
  }
  if (par.empty())
  {
    Fail("templeRing not found (no templeR_par.txt in " + candidates.front() +
      (candidates.size() > 1 ? " nor " + candidates.back() : std::string()) +
      "): download templeRing.zip from https://vision.middlebury.edu/mview/data/, unzip it and "
      "pass its folder with --data DIR");
  }
  StagedFolder folder(out, "lfd demo", DemoFiles);
  const std::string& staged = folder.GetPath();
  ImportMiddlebury(par, staged + "/temple.lf", out + "/temple.lf");
  auto lightField = ReadLightField(staged + "/temple.lf");

  // The box: the dataset's published tight bounding box (templeRing
  // README.txt), 1 cm wider, its bottom face on the temple's base so the
  // cloth under it stays out. World y is the temple's vertical.
  const double low[3] = { -0.023121 - 0.01, -0.038009 - 0.002, -0.091940 - 0.01 };
  const double high[3] = { 0.078626 + 0.01, 0.121636 + 0.01, -0.017395 + 0.01 };
  vtkNew<vtkDeformationCage> cage;
  vtkIdType corners[8];
  for (int c = 0; c < 8; ++c)
  {
    // VTK hexahedron order: the bottom face counter-clockwise seen from +y.
    const bool x = c % 4 == 2 || c % 4 == 3, z = c % 4 == 1 || c % 4 == 2;
    const double corner[3] = {
      x ? high[0] : low[0], c < 4 ? low[1] : high[1], z ? high[2] : low[2]
    };
    corners[c] = cage->AddPoint(corner);
  }
  cage->AddBox(corners, 1);
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputData(cage);
  pose->SetModeToTwist();
  pose->SetAxis(1);
  const int keyframes = 8;
  vtkNew<vtkLightFieldScene> scene;
  scene->SetLightFieldPath("temple.lf");
  scene->SetCage(cage);
  for (int k = 0; k <= keyframes; ++k)
  {
    pose->SetAngle(60.0 * k / keyframes);
    Run(pose.Get(), "posing the cage");
    scene->AddKeyframe(k, pose->GetOutput()->GetPoints());
  }
  vtkCameraRig* rig = lightField->GetRig();
  if (!rig->HasCylinder() && !rig->FitCylinder())
  {
    Fail(par + ": no ring could be fitted to the cameras");
  }
  OrbitCamera(rig,
    vtkMath::Pi() / rig->GetNumberOfViews(),
    1.15,
    0.0,
    0.8 * rig->GetViewAngle(0),
    scene->GetCamera());
  scene->GetCamera()->SetFocalPoint(
    0.5 * (low[0] + high[0]), 0.5 * (low[1] + high[1]), 0.5 * (low[2] + high[2]));
  scene->SetWidth(size);
  scene->SetHeight(size);
  scene->SetObjectThreshold(60.0);
  WriteScene(scene, staged + "/temple.json");
  std::printf("scene     %s/temple.json (1 box over the unsplit light field, %d keyframes: top "
              "twisted 0-60 degrees)\n",
    out.c_str(),
    keyframes + 1);
  AnimateDemo(scene, lightField, frames, staged, out, "");
  folder.Commit();
}

//------------------------------------------------------------------------------
// lfd split

struct SplitOptions
{
  std::string In;
  std::string Out;
  std::string Truth;
  std::vector<int> Rows;
  std::vector<int> Labels;
  std::vector<std::string> Paint;
  std::string Proxy = "auto";
  int Resolution = 128;
  double Tolerance = 1.5;
  double Threshold = -1.0;
  int Morphology = 1;
  std::string Scene;
};

/**
 * Prints the accuracy of `split`'s labels against the Label pass of the
 * light field `truthPath` on the truth's object pixels, and the confusion
 * per label.
 */
void ReportAccuracy(vtkLightField* split, const std::string& truthPath)
{
  auto truth = ReadLightField(truthPath);
  auto* expected = vtkUnsignedCharArray::SafeDownCast(truth->GetPass(vtkLightField::LABEL));
  auto* found = vtkUnsignedCharArray::SafeDownCast(split->GetPass(vtkLightField::LABEL));
  if (!expected || expected->GetNumberOfTuples() != found->GetNumberOfTuples())
  {
    Fail(truthPath + ": " +
      (expected ? "its Label pass has another size than the split light field's"
                : "has no Label pass to compare with"));
  }
  vtkIdType object = 0, correct = 0;
  std::vector<std::vector<vtkIdType>> confusion(256, std::vector<vtkIdType>(256, 0));
  int labels = 0;
  for (vtkIdType i = 0; i < expected->GetNumberOfTuples(); ++i)
  {
    const int e = expected->GetValue(i);
    const int f = found->GetValue(i);
    if (e == 0)
    {
      continue;
    }
    ++object;
    correct += e == f ? 1 : 0;
    ++confusion[e][f];
    labels = std::max({ labels, e, f });
  }
  std::printf("accuracy on object pixels: %.2f %% (%lld of %lld)\n",
    object ? 100.0 * correct / object : 0.0,
    static_cast<long long>(correct),
    static_cast<long long>(object));
  std::printf("confusion (rows: truth, columns: split; column 0 = unlabelled)\n");
  for (int e = 1; e <= labels; ++e)
  {
    std::printf("  %3d:", e);
    for (int f = 0; f <= labels; ++f)
    {
      std::printf(" %9lld", static_cast<long long>(confusion[e][f]));
    }
    std::printf("\n");
  }
}

/// Runs a splitter on `input` quietly (its error is reported once, here),
/// prints the figures and writes the split light field.
void RunSplit(vtkLightFieldSplitter* splitter, vtkLightField* input, const SplitOptions& options)
{
  vtkNew<vtkCallbackCommand> quiet;
  splitter->AddObserver(vtkCommand::ErrorEvent, quiet);
  splitter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, quiet);
  splitter->SetInputData(input);
  lfd::ShowProgress(splitter, "splitting");
  splitter->Update();
  if (*splitter->GetErrorMessage())
  {
    Fail(options.In + ": " + splitter->GetErrorMessage());
  }
  auto* label =
    vtkUnsignedCharArray::SafeDownCast(splitter->GetOutput()->GetPass(vtkLightField::LABEL));
  vtkIdType labelled = 0;
  for (vtkIdType i = 0; i < label->GetNumberOfTuples(); ++i)
  {
    labelled += label->GetValue(i) ? 1 : 0;
  }
  std::printf("labelled pixels: %lld of %lld\n",
    static_cast<long long>(labelled),
    static_cast<long long>(label->GetNumberOfTuples()));
  if (!options.Truth.empty())
  {
    ReportAccuracy(splitter->GetOutput(), options.Truth);
  }
  WriteLightField(splitter->GetOutput(), options.Out);
  std::printf("wrote %s\n", options.Out.c_str());
}

void SplitProjector(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkProjectorSegmentation> segmentation;
  segmentation->SetMorphologyRadius(options.Morphology);
  if (options.Threshold >= 0.0)
  {
    segmentation->SetDarkThreshold(options.Threshold);
  }
  RunSplit(segmentation, lightField, options);
  std::printf("sensor noise sigma: %.2f\n", segmentation->GetEstimatedNoise());
}

void SplitScanline(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkScanlineSplit> split;
  for (int row : options.Rows)
  {
    split->AddBoundary(row);
  }
  if (!options.Labels.empty() && options.Labels.size() != options.Rows.size() + 1)
  {
    Fail("--labels: " + std::to_string(options.Rows.size()) + " rows make " +
      std::to_string(options.Rows.size() + 1) + " bands, " + std::to_string(options.Labels.size()) +
      " labels given");
  }
  for (size_t band = 0; band < options.Labels.size(); ++band)
  {
    split->SetBandLabel(static_cast<int>(band), options.Labels[band]);
  }
  if (options.Threshold >= 0.0)
  {
    split->SetThreshold(options.Threshold);
  }
  split->SetMorphologyRadius(options.Morphology);
  RunSplit(split, lightField, options);
}

void SplitPropagate(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  vtkNew<vtkLabelPropagation> propagation;
  for (const std::string& paint : options.Paint)
  {
    const size_t equals = paint.find('=');
    char* end = nullptr;
    const long view = equals == std::string::npos ? -1 : std::strtol(paint.c_str(), &end, 10);
    if (equals == std::string::npos || end != paint.c_str() + equals || view < 0)
    {
      Fail("--paint '" + paint + "': expected VIEW=LABELS.png, e.g. 0=paint/view0.png");
    }
    const std::string file = paint.substr(equals + 1);
    vtkSmartPointer<vtkImageData> image = ReadImage(file);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    if (scalars && scalars->GetNumberOfComponents() > 1)
    {
      Fail(file + ": a label image has one channel (label values), this one has " +
        std::to_string(scalars->GetNumberOfComponents()));
    }
    propagation->SetPaintedView(static_cast<int>(view), image);
  }
  propagation->SetProxy(options.Proxy == "depth" ? vtkLabelPropagation::DEPTH
      : options.Proxy == "hull"                  ? vtkLabelPropagation::VISUAL_HULL
                                                 : vtkLabelPropagation::AUTOMATIC);
  propagation->SetResolution(options.Resolution);
  propagation->SetSilhouetteTolerance(options.Tolerance);
  if (options.Threshold >= 0.0)
  {
    propagation->SetThreshold(options.Threshold);
  }
  RunSplit(propagation, lightField, options);
  std::printf(
    "proxy voxels: %lld\n", static_cast<long long>(propagation->GetNumberOfProxyVoxels()));
}

void SplitCheck(const SplitOptions& options)
{
  auto lightField = ReadLightField(options.In);
  auto scene = ReadScene(options.Scene);
  if (!scene->HasCage())
  {
    Fail(options.Scene + ": the scene has no cage to check");
  }
  if (!lightField->GetPass(vtkLightField::LABEL))
  {
    Fail(options.In +
      ": has no Label pass to check; split it first (lfd split projector|scanline|propagate)");
  }
  // Every box's label must have pixels and every label value a box: a
  // mismatch (a scene written for another split) is warned about per label.
  std::set<int> boxLabels;
  vtkDataArray* cellLabels = scene->GetCage()->GetCellData()->GetArray("Label");
  for (vtkIdType box = 0; cellLabels && box < cellLabels->GetNumberOfTuples(); ++box)
  {
    boxLabels.insert(static_cast<int>(cellLabels->GetTuple1(box)));
  }
  bool mismatch = false;
  for (int label = 1; label < 256; ++label)
  {
    const bool boxed = boxLabels.count(label) > 0;
    if (boxed != lightField->HasLabel(label))
    {
      mismatch = true;
      lfd::ReportWarning(boxed
          ? options.Scene + ": box label " + std::to_string(label) + " has no pixels in " +
            options.In
          : options.In + ": label " + std::to_string(label) + " has no box in " + options.Scene);
    }
  }
  if (mismatch)
  {
    Fail("the labels of " + options.Scene + " and " + options.In +
      " do not match (see the warnings); split again or fix the boxes' labels");
  }
  vtkNew<vtkBoxCoverageCheck> check;
  check->SetInputData(0, lightField);
  check->SetCageData(scene->GetCage());
  check->SetThreshold(options.Threshold >= 0.0 ? options.Threshold : 0.95);
  Run(check.Get(), "box coverage check");
  std::printf("label  worst fraction  worst view  views below %.3f\n", check->GetThreshold());
  for (int i = 0; i < check->GetNumberOfLabels(); ++i)
  {
    const std::vector<int> below = check->GetViewsBelow(i);
    std::string list;
    for (size_t k = 0; k < below.size() && k < 10; ++k)
    {
      list += (k ? "," : " (") + std::to_string(below[k]);
    }
    list += below.empty() ? "" : (below.size() > 10 ? ",...)" : ")");
    std::printf("%5d  %14.4f  %10d  %zu%s\n",
      check->GetLabel(i),
      check->GetWorstFraction(i),
      check->GetWorstView(i),
      below.size(),
      list.c_str());
  }
  if (!check->GetPassed())
  {
    Fail("some labels fall outside their boxes (fraction under " +
      std::to_string(check->GetThreshold()) + "); grow the boxes or fix the labels");
  }
  std::printf("every label is inside its boxes\n");
}

//------------------------------------------------------------------------------
// The command line itself

/// Levenshtein distance: how many letters to insert, delete or change.
std::size_t EditDistance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
  {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1) });
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// " (did you mean 'X'?)" for the candidate nearest to `word` when it is
/// close (at most a third of its letters differ), else "".
std::string Suggestion(const std::string& word,
  const std::vector<std::string>& candidates,
  const std::string& prefix = "")
{
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& candidate : candidates)
  {
    const std::size_t distance = EditDistance(word, candidate);
    if (distance < bestDistance)
    {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best.empty() ? "" : " (did you mean '" + prefix + best + "'?)";
}

/// "lfd eval loo" for the loo subcommand.
std::string CommandName(const CLI::App* command)
{
  std::string name;
  for (; command; command = command->get_parent())
  {
    name = (command->get_parent() ? command->get_name() : std::string("lfd")) +
      (name.empty() ? "" : " " + name);
  }
  return name;
}

std::vector<std::string> SubcommandNames(const CLI::App* command)
{
  std::vector<std::string> names;
  for (const CLI::App* sub : command->get_subcommands({}))
  {
    names.push_back(sub->get_name());
  }
  return names;
}

/// The deepest subcommand the parser selected (the root when none).
CLI::App* SelectedCommand(CLI::App* app)
{
  for (;;)
  {
    const std::vector<CLI::App*> selected = app->get_subcommands();
    if (selected.empty())
    {
      return app;
    }
    app = selected.front();
  }
}

/**
 * Checks the leading words of the command line name existing commands
 * ("lfd rendr" would otherwise be "A subcommand is required"). Returns the
 * usage error, or "".
 */
std::string CheckCommandWords(CLI::App* app, int argc, char* argv[])
{
  CLI::App* level = app;
  for (int i = 1; i < argc && !level->get_subcommands({}).empty(); ++i)
  {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-')
    {
      break;
    }
    const std::vector<std::string> names = SubcommandNames(level);
    if (std::find(names.begin(), names.end(), word) == names.end())
    {
      std::string list;
      for (const std::string& name : names)
      {
        list += (list.empty() ? "" : ", ") + name;
      }
      const std::string prefix = level == app ? "" : CommandName(level).substr(4) + " ";
      const std::string hint = Suggestion(word, names, prefix);
      return "unknown command '" + prefix + word + "'" +
        (hint.empty() ? " (commands: " + list + ")" : hint);
    }
    level = level->get_subcommand(word);
  }
  return "";
}

/// One line for a command line CLI11 refused.
std::string DescribeParseError(CLI::App* app, const CLI::ParseError& error)
{
  CLI::App* command = SelectedCommand(app);
  const std::string name = CommandName(command);
  if (dynamic_cast<const CLI::RequiredError*>(&error) &&
    std::string(error.what()).find("subcommand") != std::string::npos)
  {
    std::string list;
    for (const std::string& sub : SubcommandNames(command))
    {
      list += (list.empty() ? "" : ", ") + sub;
    }
    return name + ": a command is required: " + list;
  }
  return name + ": " + error.what() + " (see " + name + " --help)";
}

/// Arguments the parser could not place: an unknown option or a surplus word.
std::string DescribeExtras(CLI::App* app)
{
  const std::vector<std::string> extras = app->remaining(true);
  if (extras.empty())
  {
    return "";
  }
  CLI::App* command = SelectedCommand(app);
  const std::string name = CommandName(command);
  const std::string extra = extras.front();
  if (extra.size() > 1 && extra[0] == '-')
  {
    std::vector<std::string> options;
    for (const CLI::Option* option : command->get_options())
    {
      for (const std::string& longName : option->get_lnames())
      {
        options.push_back("--" + longName);
      }
    }
    const std::string word = extra.substr(0, extra.find('='));
    const std::string hint = Suggestion(word, options);
    return name + ": unknown option '" + word + "'" +
      (hint.empty() ? " (see " + name + " --help)" : hint);
  }
  return name + ": unexpected argument '" + extra + "' (see " + name + " --help)";
}

/// Commands that capture or render meshes open an OpenGL window, which
/// aborts the process without an X display: say so first.
void RequireDisplay(const CLI::App* command)
{
  if (lfd::DisplayAvailable())
  {
    return;
  }
  const char* display = std::getenv("DISPLAY");
  const std::string name = CommandName(command);
  Fail(name + " renders with OpenGL and needs an X display (" +
    (display && *display ? "cannot open DISPLAY=" + std::string(display) : "DISPLAY is not set") +
    "); run it as: xvfb-run -a " + name + " ...");
}

/// Footer of every command's --help.
const char* ExitStatusHelp =
  "Exit status: 0 done; 1 refused input or failed (one 'lfd: error:' line, no output "
  "written); 2 malformed command line (unknown command or option, missing argument, value "
  "not among the choices).";

/// Every command: extras collected (reported by DescribeExtras, with a
/// suggestion) and the exit statuses in its --help.
void ConfigureCommands(CLI::App* command)
{
  command->allow_extras();
  command->footer(ExitStatusHelp);
  for (CLI::App* sub : command->get_subcommands({}))
  {
    ConfigureCommands(sub);
  }
}
}

namespace
{
/// Frames of `lfd animate` and `lfd demo`: an hour at 24 frames/s is plenty.
constexpr int MaximumFrames = 100000;

/// The commands, their options and what they run.
int Main(int argc, char* argv[])
{
  CLI::App app{ "LightField Deform: capture, render and deform light fields.\n"
                "Run 'lfd <command> --help' for the options of a command." };
  app.require_subcommand(1);
  app.set_version_flag("--version", "lfd " LFD_VERSION, "print the version (lfd X.Y.Z) and exit");
  NumericOptions numbers;
  vtkNew<vtkLightFieldCapture> captureLimits;
  const int largestImage = captureLimits->GetWidthMaxValue();

  SynthOptions synth;
  auto* synthCommand = app.add_subcommand("synth",
    "capture a synthetic light field of a mesh or a built-in object into the dataset folder "
    "OUT (replaced when complete); needs an X display (xvfb-run -a)");
  synthCommand->add_option("--mesh", synth.Mesh, "mesh file (.ply .obj .stl .vtp .vtk)");
  synthCommand->add_option("--texture",
    synth.Texture,
    "texture image for a mesh with texture "
    "coordinates");
  synthCommand->add_option("--scene",
    synth.Scene,
    "scene.json whose rest boxes label the mesh (a triangle takes the box holding its centroid); "
    "its boxes are validated as lfd render validates them");
  synthCommand->add_option("--out", synth.Out, "output light-field directory")->required();
  AddSynthOptions(synthCommand, synth, numbers);

  auto* importCommand = app.add_subcommand("import", "import a calibrated image set");
  importCommand->require_subcommand(1);
  std::string par, importOut;
  auto* middlebury = importCommand->add_subcommand("middlebury",
    "Middlebury multi-view stereo set (*_par.txt: name k11..k33 r11..r33 t1 t2 t3) into the "
    "dataset folder OUT (replaced when complete)");
  middlebury->add_option("PAR_FILE", par, "the *_par.txt file")->required();
  middlebury->add_option("--out", importOut, "output light-field directory")->required();

  std::string infoPath;
  auto* infoCommand = app.add_subcommand(
    "info", "describe a light field and fit its rig (prints only, writes nothing)");
  infoCommand->add_option("DIR", infoPath, "light-field directory")->required();

  std::string scenePath, renderOut;
  double renderTime = 0.0;
  auto* renderCommand = app.add_subcommand("render",
    "render a scene's camera view of its light field, deformed by its cage, into the image OUT "
    "(replaced when complete)");
  renderCommand->add_option("SCENE", scenePath, "scene.json")->required();
  renderCommand->add_option("--out", renderOut, "output image (.png, .exr, ...)")->required();
  auto* timeOption = numbers.AddReal(renderCommand,
    "--time",
    renderTime,
    "time of the keyframes to render (default: the cage's points)");

  std::string animateScene, animateOut;
  int animateFrames = 48;
  auto* animateCommand = app.add_subcommand("animate",
    "render the scene's keyframes (Catmull-Rom) into the folder OUT: frame_NNNN.png, and "
    "animation.mp4 when ffmpeg is installed; replaces OUT when complete (an existing OUT may "
    "hold only such files)");
  animateCommand->add_option("SCENE", animateScene, "scene.json with keyframes")->required();
  numbers.Add(animateCommand, "--frames", animateFrames, 1, MaximumFrames, "number of frames");
  animateCommand->add_option("--out", animateOut, "output folder")->required();

  auto* evalCommand = app.add_subcommand("eval", "measure rendering quality");
  evalCommand->require_subcommand(1);
  std::string gtScene, gtMesh, gtOut;
  auto* groundTruth = evalCommand->add_subcommand("groundtruth",
    "render the source mesh, labelled by the scene's rest boxes and deformed by its cage, and "
    "compare it with the deformed light field: PSNR and SSIM over the object pixels, "
    "silhouette IoU, label agreement (prints; writes images only with --out); needs an X "
    "display (xvfb-run -a)");
  groundTruth->add_option("SCENE", gtScene, "scene.json")->required();
  groundTruth
    ->add_option(
      "--mesh", gtMesh, "the light field's source: fish, figure, checkerboard or a mesh file")
    ->required();
  groundTruth->add_option("--out",
    gtOut,
    "also write OUT_lightfield.png and OUT_groundtruth.png (both or neither, replaced when "
    "complete)");
  double gtTime = 0.0;
  auto* gtTimeOption = numbers.AddReal(groundTruth,
    "--time",
    gtTime,
    "time of the keyframes to evaluate (default: the cage's points)");
  std::string looPath;
  int looStride = 1;
  std::vector<int> looViews;
  double looFocal = 0.0;
  int looThreshold = 20;
  vtkNew<vtkLeaveOneOutEvaluator> looLimits;
  auto* loo = evalCommand->add_subcommand("loo",
    "leave-one-out: render each chosen view from all the others, print PSNR per view and mean "
    "(writes nothing)");
  loo->add_option("DIR", looPath, "light-field directory")->required();
  numbers.Add(loo,
    "--stride",
    looStride,
    looLimits->GetStrideMinValue(),
    looLimits->GetStrideMaxValue(),
    "evaluate every N-th view");
  numbers
    .Add(loo, "--views", looViews, 0, VTK_INT_MAX, "evaluate these views (overrides --stride)")
    ->delimiter(',');
  numbers.AddReal(loo, "--focal-distance", looFocal, "focal distance d");
  numbers.Add(loo,
    "--threshold",
    looThreshold,
    looLimits->GetObjectThresholdMinValue(),
    looLimits->GetObjectThresholdMaxValue(),
    "object pixel threshold for light fields without labels");

  LatticeOptions lattice;
  vtkNew<vtkLatticeCageFilter> latticeLimits;
  auto* latticeCommand = app.add_subcommand("lattice",
    "bend a scene's boxes with a smooth lattice (Sederberg-Parry free-form deformation) sampled "
    "into boxes; writes the scene file OUT with the deformed cage (replaced when complete)");
  latticeCommand->add_option("SCENE", lattice.Scene, "scene.json with a cage")->required();
  latticeCommand->add_option("--out", lattice.Out, "output scene.json")->required();
  numbers
    .Add(latticeCommand, "--dimensions", lattice.Dimensions, 2, 16, "control points per axis x y z")
    ->expected(3);
  numbers
    .AddReal(latticeCommand,
      "--move",
      lattice.Moves,
      "I J K DX DY DZ: move control point (I, J, K) by (DX, DY, DZ); repeat for more")
    ->expected(6)
    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  numbers
    .AddReal(latticeCommand,
      "--region",
      lattice.Region,
      "XMIN XMAX YMIN YMAX ZMIN ZMAX of the lattice (default: the cage's rest bounds)")
    ->expected(6);
  numbers.Add(latticeCommand,
    "--subdivision",
    lattice.Subdivision,
    latticeLimits->GetSubdivisionMinValue(),
    latticeLimits->GetSubdivisionMaxValue(),
    "split each box into K^3 sub-boxes");

  int benchRepeat = 15, benchSize = 512;
  auto* benchCommand = app.add_subcommand("bench",
    "print rays/s and ms/frame of the renderer on fixed scenes (median of repeated renders; "
    "writes nothing); needs an X display (xvfb-run -a)");
  numbers.Add(benchCommand, "--repeat", benchRepeat, 1, 1000, "renders per scene");
  numbers.Add(benchCommand, "--size", benchSize, 1, largestImage, "image width and height");

  std::string demoOut;
  int demoFrames = 36, demoSize = 512;
  auto* demoCommand = app.add_subcommand("demo",
    "synthesise a built-in scene (default: the fish, in a cage of 3 boxes, swimming) and render "
    "its animation into the folder OUT: light field(s) *.lf, scene file(s) *.json, frames*/, "
    "contact_sheet*.png (MP4s with ffmpeg); replaces OUT when complete (an existing OUT may hold "
    "only such files); needs an X display (xvfb-run -a)");
  std::string demoScene = "fish";
  demoCommand
    ->add_option("--scene",
      demoScene,
      "fish: swimming, 3 boxes (Fig. 13); twist: the figure in one box, its top turned (Fig. 1); "
      "checkerboard: its top turned, captured under coaxial and under scene-fixed light (Figs. 4, "
      "5); temple: the real templeRing, unsplit, its top turned in one box (Fig. 1, see --data)")
    ->check(CLI::IsMember({ "fish", "twist", "checkerboard", "temple" }))
    ->capture_default_str();
  std::string demoData;
  demoCommand->add_option("--data",
    demoData,
    "--scene temple: the templeRing folder (templeR_par.txt; default ../shared/data/templeRing, "
    "then " LFD_SHARED_DATA_DIR "/templeRing)");
  demoCommand->add_option(
    "--out", demoOut, "output folder (default: lfd-demo, or lfd-demo-SCENE for the others)");
  numbers.Add(demoCommand, "--frames", demoFrames, 1, MaximumFrames, "number of frames");
  numbers.Add(demoCommand, "--size", demoSize, 1, largestImage, "frame width and height");
  SynthOptions demoCapture;
  numbers.Add(demoCommand,
    "--views",
    demoCapture.Views,
    captureLimits->GetViewsPerRingMinValue(),
    captureLimits->GetViewsPerRingMaxValue(),
    "captured views per ring");
  numbers.Add(demoCommand,
    "--rows",
    demoCapture.Rows,
    captureLimits->GetNumberOfRowsMinValue(),
    captureLimits->GetNumberOfRowsMaxValue(),
    "captured rings");
  numbers.Add(demoCommand,
    "--capture-size",
    demoCapture.Width,
    captureLimits->GetWidthMinValue(),
    largestImage,
    "captured views' width and height");

  SplitOptions split;
  vtkNew<vtkProjectorSegmentation> projectorLimits;
  vtkNew<vtkScanlineSplit> scanlineLimits;
  vtkNew<vtkLabelPropagation> propagationLimits;
  vtkNew<vtkBoxCoverageCheck> checkLimits;
  auto* splitCommand = app.add_subcommand("split",
    "split a light field into parts: label its rays (projector masks, image rows, or labels "
    "painted in a few views) into the dataset folder OUT (IN + Label, replaced when complete), "
    "or check the boxes against the labels");
  splitCommand->require_subcommand(1);
  auto addSplitIO = [&split](CLI::App* command)
  {
    command->add_option("IN", split.In, "light-field directory")->required();
    command->add_option("--out", split.Out, "output light-field directory (IN + Label)")
      ->required();
    command->add_option("--truth",
      split.Truth,
      "a light field with the true Label pass: print the accuracy and confusion");
  };
  auto* splitProjector = splitCommand->add_subcommand("projector",
    "label by the projector colour masks: Eq. 1 normalisation of Coded by Flood, nearest "
    "palette colour (CIELAB), morphological clean-up");
  addSplitIO(splitProjector);
  numbers
    .Add(splitProjector,
      "--dark",
      split.Threshold,
      0.0,
      255.0,
      "Flood level below which a channel is dark (default: from the noise)")
    ->default_str("");
  numbers.Add(splitProjector,
    "--morphology",
    split.Morphology,
    projectorLimits->GetMorphologyRadiusMinValue(),
    projectorLimits->GetMorphologyRadiusMaxValue(),
    "clean-up radius in pixels (0 = none)");
  auto* splitScanline = splitCommand->add_subcommand("scanline",
    "label by image rows within the object (aligned rings): band 1 above the first row, ...");
  addSplitIO(splitScanline);
  numbers.Add(splitScanline, "--rows", split.Rows, 0, VTK_INT_MAX, "boundary rows, from the top")
    ->delimiter(',')
    ->required();
  numbers
    .Add(splitScanline, "--labels", split.Labels, 1, 255, "label of each band (default 1, 2, ...)")
    ->delimiter(',');
  numbers
    .Add(splitScanline,
      "--threshold",
      split.Threshold,
      scanlineLimits->GetThresholdMinValue(),
      scanlineLimits->GetThresholdMaxValue(),
      "object brightness threshold when IN has no Label pass (default 10)")
    ->default_str("");
  numbers.Add(splitScanline,
    "--morphology",
    split.Morphology,
    scanlineLimits->GetMorphologyRadiusMinValue(),
    scanlineLimits->GetMorphologyRadiusMaxValue(),
    "clean-up radius of the object mask");
  auto* splitPropagate = splitCommand->add_subcommand("propagate",
    "carry labels painted in a few views to every view through the Depth pass or a visual hull");
  addSplitIO(splitPropagate);
  splitPropagate
    ->add_option("--paint", split.Paint, "VIEW=LABELS.png (one channel, 0 = unpainted); repeat")
    ->required();
  splitPropagate->add_option("--proxy", split.Proxy, "auto (depth when present), depth or hull")
    ->check(CLI::IsMember({ "auto", "depth", "hull" }))
    ->capture_default_str();
  numbers.Add(splitPropagate,
    "--resolution",
    split.Resolution,
    propagationLimits->GetResolutionMinValue(),
    propagationLimits->GetResolutionMaxValue(),
    "proxy voxels along its longest side");
  numbers.Add(splitPropagate,
    "--tolerance",
    split.Tolerance,
    propagationLimits->GetSilhouetteToleranceMinValue(),
    propagationLimits->GetSilhouetteToleranceMaxValue(),
    "pixels of silhouette or calibration error the visual hull tolerates");
  numbers
    .Add(splitPropagate,
      "--threshold",
      split.Threshold,
      propagationLimits->GetThresholdMinValue(),
      propagationLimits->GetThresholdMaxValue(),
      "silhouette brightness threshold (default 20)")
    ->default_str("");
  auto* splitCheck = splitCommand->add_subcommand("check",
    "project each rest box into every view and report the fraction of its label's pixels "
    "inside (writes nothing); exits 1 under the threshold, or when a box label has no pixels "
    "or a label no box");
  splitCheck->add_option("IN", split.In, "light-field directory (with a Label pass)")->required();
  splitCheck->add_option("--scene", split.Scene, "scene.json whose cage holds the boxes")
    ->required();
  numbers
    .Add(splitCheck,
      "--threshold",
      split.Threshold,
      checkLimits->GetThresholdMinValue(),
      checkLimits->GetThresholdMaxValue(),
      "smallest acceptable fraction (default 0.95)")
    ->default_str("");

  ConfigureCommands(&app);
  const std::string unknown = CheckCommandWords(&app, argc, argv);
  if (!unknown.empty())
  {
    lfd::ReportError(unknown);
    return 2;
  }
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::Success& success) // --help, --version
  {
    return app.exit(success);
  }
  catch (const CLI::ParseError& error)
  {
    const std::string extras = DescribeExtras(&app);
    lfd::ReportError(extras.empty() ? DescribeParseError(&app, error) : extras);
    return 2;
  }
  const std::string extras = DescribeExtras(&app);
  if (!extras.empty())
  {
    lfd::ReportError(extras);
    return 2;
  }

  try
  {
    numbers.Convert();
    if (*synthCommand || *groundTruth || *benchCommand || *demoCommand)
    {
      RequireDisplay(SelectedCommand(&app));
    }
    if (*synthCommand)
    {
      Synth(synth);
    }
    else if (*middlebury)
    {
      ImportMiddlebury(par, importOut, importOut);
    }
    else if (*infoCommand)
    {
      Info(infoPath);
    }
    else if (*renderCommand)
    {
      Render(scenePath, renderOut, *timeOption ? &renderTime : nullptr);
    }
    else if (*animateCommand)
    {
      Animate(animateScene, animateFrames, animateOut);
    }
    else if (*groundTruth)
    {
      EvalGroundTruth(gtScene, gtMesh, gtOut, *gtTimeOption ? &gtTime : nullptr);
    }
    else if (*loo)
    {
      EvalLeaveOneOut(looPath, looStride, looViews, looFocal, looThreshold);
    }
    else if (*splitProjector)
    {
      SplitProjector(split);
    }
    else if (*splitScanline)
    {
      SplitScanline(split);
    }
    else if (*splitPropagate)
    {
      SplitPropagate(split);
    }
    else if (*splitCheck)
    {
      SplitCheck(split);
    }
    else if (*latticeCommand)
    {
      Lattice(lattice);
    }
    else if (*benchCommand)
    {
      Bench(benchRepeat, benchSize);
    }
    else if (*demoCommand)
    {
      demoCapture.Height = demoCapture.Width;
      if (demoScene == "temple")
      {
        DemoTemple(demoData, demoOut.empty() ? "lfd-demo-temple" : demoOut, demoFrames, demoSize);
      }
      else
      {
        Demo(demoScene,
          demoOut.empty() ? (demoScene == "fish" ? "lfd-demo" : "lfd-demo-" + demoScene) : demoOut,
          demoFrames,
          demoSize,
          demoCapture);
      }
    }
  }
  catch (const Failure& failure)
  {
    if (!failure.Message.empty())
    {
      lfd::ReportError(failure.Message);
    }
  }
  // Whatever reported an error, a refusal of ours or any VTK object's
  // message, decides the exit status.
  return lfd::ErrorReported() ? 1 : 0;
}
}

int main(int argc, char* argv[])
{
  lfd::InstallConsoleOutput();
  // No exception leaves lfd: whatever escapes a command is one error line.
  try
  {
    return Main(argc, argv);
  }
  catch (const std::bad_alloc&)
  {
    lfd::ReportError("out of memory");
  }
  catch (const std::exception& exception)
  {
    lfd::ReportError(exception.what());
  }
  catch (...)
  {
    lfd::ReportError("unexpected internal error");
  }
  return 1;
}
