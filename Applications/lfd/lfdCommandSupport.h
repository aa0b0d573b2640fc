/**
 * @file   lfdCommandSupport.h
 * @brief  What every `lfd` subcommand shares: refusals (Fail), numeric
 *         options with ranges, staged output folders, and reading/writing
 *         light fields, scenes and images with one error line naming the file.
 */
#ifndef lfdCommandSupport_h
#define lfdCommandSupport_h

#include "lfdConsole.h"
#include "lfdFileUtilities.h"
#include "lfdStagedFolder.h"

#include "vtkCommand.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

class vtkCamera;
class vtkCameraRig;
class vtkDeformationCage;
class vtkImageData;
class vtkLightField;
class vtkLightFieldRenderer;
class vtkPolyData;

namespace lfd::cli
{
/// Frames of `lfd animate` and `lfd demo`: an hour at 24 frames/s is plenty.
constexpr int MaximumFrames = 100000;

/// A (leaf) subcommand and what runs it once its options are parsed.
struct Command
{
  CLI::App* App;
  std::function<void()> Run;
  /// It opens an OpenGL window (captures or renders meshes): RequireDisplay() first.
  bool NeedsDisplay;
};

/// Thrown by a subcommand to stop with exit status 1 and its one-line
/// message (lfd::CommandErrors::Refuse()).
struct Failure
{
  std::string Message;
};

[[noreturn]] inline void Fail(const std::string& message)
{
  throw Failure{ message };
}

/**
 * The errors of the objects one step of a command uses, recorded (not
 * printed) while the step runs: the step fails with the first one, said
 * once, with the file it concerns. Their warnings are said when the step
 * ends, and the objects are no longer observed.
 */
class StepErrors
{
public:
  StepErrors() = default;
  ~StepErrors()
  {
    lfd::PrintWarnings(this->Errors);
    this->Errors->StopObserving();
  }
  StepErrors(const StepErrors&) = delete;
  void operator=(const StepErrors&) = delete;

  vtkLightFieldErrorObserver* Get() { return this->Errors; }
  vtkLightFieldErrorObserver* operator->() { return this->Errors; }

  /// Fails with the first error, after `context` (e.g. "scene.json: ").
  void FailOnError(const std::string& context = std::string())
  {
    if (this->Errors->HasError())
    {
      Fail(context + this->Errors->GetErrorMessage());
    }
  }

private:
  vtkNew<vtkLightFieldErrorObserver> Errors;
};

/**
 * Updates an algorithm and fails with the first error it or any algorithm
 * upstream reports, or any object they use (which reaches VTK's output
 * window), else with "<what> failed" when it sets an error code silently.
 */
template<typename Algorithm>
void Run(Algorithm* algorithm, const std::string& what)
{
  StepErrors errors;
  errors->ObservePipeline(algorithm);
  vtkOutputWindow* window = vtkOutputWindow::GetInstance();
  const unsigned long tag = window->AddObserver(vtkCommand::ErrorEvent, errors.Get());
  algorithm->Update();
  window->RemoveObserver(tag);
  errors.FailOnError();
  if (algorithm->GetErrorCode() != 0)
  {
    Fail(what + " failed");
  }
}

/**
 * A command's multi-file output folder (lfd::scene::StagedFolder: written
 * under a temporary sibling name, renamed onto `target` by Commit() only
 * when complete, an existing target holding only `patterns`). A refusal
 * fails the command naming the option: "--out <target>: ...".
 */
class StagedFolder
{
public:
  StagedFolder(const std::string& target,
    const std::string& command,
    const std::vector<std::string>& patterns)
  {
    std::string error;
    if (!this->Folder.Open(target, command, patterns, error))
    {
      Fail("--out " + error);
    }
  }

  /// Where the command writes.
  const std::string& GetPath() const { return this->Folder.GetPath(); }

  /// Replaces the target with the complete folder.
  void Commit()
  {
    std::string error;
    if (!this->Folder.Commit(error))
    {
      Fail(error);
    }
  }

private:
  lfd::scene::StagedFolder Folder;
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

  /// A size in bytes: an integer with an optional unit K, M or G (powers of
  /// 1024), e.g. 512M; at least 1M.
  CLI::Option* AddByteSize(CLI::App* command,
    const std::string& name,
    std::int64_t& value,
    const std::string& description)
  {
    Entry* entry = this->NewEntry();
    entry->Assign = [&value, name](const std::vector<std::string>& text)
    { value = ParseByteSize(name, text.back()); };
    return command->add_option(name, entry->Text, description)
      ->type_name("SIZE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
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

  static std::int64_t ParseByteSize(const std::string& name, const std::string& text);

  std::vector<std::unique_ptr<Entry>> Entries;
};

double Seconds(double start);

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path);

/// A scene file read into the scene logic, through which every command
/// uses it.
vtkSmartPointer<vtkLightFieldSceneLogic> ReadScene(const std::string& path);

/// An image file (PNG, EXR, ... through OpenImageIO), rows bottom first.
vtkSmartPointer<vtkImageData> ReadImage(const std::string& path);

/**
 * Which passes of a light-field dataset a command reads: all of them, or
 * only those vtkLightFieldRenderer looks up (Coaxial, Label, and Depth: the
 * proxy of its per-pixel focal surface; without Depth when it focuses on the
 * plane), so that a dataset's Coded, Flood and Confidence passes take no
 * memory in `lfd render` and `lfd animate`.
 */
enum class Passes
{
  All,
  Rendered,
  RenderedOnPlane
};

/// With `cacheBytes` > 0 the Coaxial, Label and Depth passes stay on disk and are
/// read tile by tile through an image cache of that many bytes
/// (vtkLightFieldReader::SetCacheSize; the dataset must be tiled, `lfd tile`).
/// With `pieces` > 1, only the views of piece `piece` of the passes read into
/// memory are read, the others left zero (vtkLightFieldReader::SetPiece();
/// ProcessGroup::ShareLightField()).
vtkSmartPointer<vtkLightField> ReadLightField(const std::string& path,
  Passes passes = Passes::All,
  std::int64_t cacheBytes = 0,
  int piece = 0,
  int pieces = 1);

/// The light field a scene names (an error naming the scene and its field
/// "lightfield" when it names none or a missing one).
vtkSmartPointer<vtkLightField> ReadSceneLightField(vtkLightFieldSceneLogic* scene,
  Passes passes = Passes::All,
  std::int64_t cacheBytes = 0,
  int piece = 0,
  int pieces = 1);

/**
 * `--focal auto|plane|proxy` on `command`: the renderer's focal surface
 * (vtkLightFieldRenderer::FocalSurfaceType), into `name`; `otherwise` says
 * what applies without the option. FocalSurfaceFromName() turns a given name
 * into the renderer's value.
 */
CLI::Option* AddFocalOption(CLI::App* command, std::string& name, const std::string& otherwise);
int FocalSurfaceFromName(const std::string& name);

/**
 * Render settings a command may override on its scene, empty when not
 * given: `--focal` (render.focal) and `--antialiasing on|off`
 * (render.antialiasing).
 */
struct RenderOverrides
{
  std::string Focal;
  std::string AntiAliasing;
};

/// Adds --focal and --antialiasing to `command`.
void AddRenderOverrideOptions(CLI::App* command, RenderOverrides& overrides);

/// The given overrides set on the scene, before its light field is read (a
/// scene focused on the plane does not read the Depth pass).
void ApplyRenderOverrides(const RenderOverrides& overrides, vtkLightFieldSceneLogic* scene);

/// Fails with the file name when a tile of a light field read out of core
/// could not be read while rendering (those texels read as zeros).
void CheckTexelSource(vtkLightField* lightField);

/**
 * The scene's cage, validated by the scene logic (against the light field
 * when given; nullptr when the scene has none): the one check of a scene's
 * boxes for every command. With keyframes and a time, the cage points are
 * the keyframes' Catmull-Rom interpolation at that time.
 */
vtkSmartPointer<vtkDeformationCage> SceneCage(vtkLightFieldSceneLogic* scene,
  vtkLightField* lightField,
  const double* time = nullptr);

/**
 * The mesh with its cells labelled by the scene's rest boxes
 * (vtkLightFieldSceneLogic::LabelMesh), after the boxes passed SceneCage():
 * how `synth --scene` splits a mesh into parts and how `eval groundtruth`
 * gives the ground truth the parts the light field was split into.
 */
vtkSmartPointer<vtkPolyData> LabelByScene(vtkPolyData* mesh, vtkLightFieldSceneLogic* scene);

/// Writes a dataset (tileSize > 0: tiled, MIP-mapped TIFF images, see
/// vtkLightFieldWriter::SetTileSize).
void WriteLightField(vtkLightField* lightField, const std::string& directory, int tileSize = 0);

void WriteScene(vtkLightFieldScene* scene, const std::string& path);

void WriteImage(vtkImageData* image, const std::string& path);
}

#endif
