/**
 * @file   lfdCommands.h
 * @brief  The subcommands of the `lfd` tool, one source file per group
 *         (lfdCaptureCommands.cxx, lfdRenderCommands.cxx, ...), and what one
 *         group reuses of another.
 *
 * Each Add*Command(s)() function declares its subcommands' options on the
 * CLI11 application and appends what runs each of them to `commands`; main()
 * parses the command line and runs the one selected.
 */
#ifndef lfdCommands_h
#define lfdCommands_h

#include "lfdCommandSupport.h"

#include "vtkPoints.h" // For RowCoverage

class vtkCalibratedImageImporter;

namespace lfd::cli
{
/// `lfd synth`, `lfd import middlebury`, `lfd info` (lfdCaptureCommands.cxx).
void AddCaptureCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd render`, `lfd animate`, `lfd tile`, `lfd lattice` (lfdRenderCommands.cxx).
void AddRenderCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd eval groundtruth`, `lfd eval loo` (lfdEvalCommands.cxx).
void AddEvalCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd split projector|scanline|propagate|check` (lfdSplitCommands.cxx).
void AddSplitCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd import colmap|transforms`, `lfd export colmap|transforms`, `lfd scene init`
/// (lfdImportCommands.cxx; after AddCaptureCommands, which creates `lfd import`).
void AddImportCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd import twoplane` (lfdTwoPlaneCommands.cxx; after AddCaptureCommands).
void AddTwoPlaneCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd bench` (lfdBenchCommand.cxx).
void AddBenchCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd demo` (lfdDemoCommand.cxx).
void AddDemoCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd calibrate board|patterns|camera|ring|projector` (lfdCalibrateCommands.cxx).
void AddCalibrateCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd studio` (lfdStudioCommand.cxx).
void AddStudioCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd gantry-sim`, `lfd gantry status|home|move|stop|reset` (lfdAcquisitionCommands.cxx).
void AddAcquisitionCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd camera-sim` (lfdCameraSimCommand.cxx).
void AddCameraSimCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands);
/// `lfd capture` (lfdCaptureSessionCommand.cxx).
void AddCaptureSessionCommand(CLI::App& app,
  NumericOptions& numbers,
  std::vector<Command>& commands);

//------------------------------------------------------------------------------
// Capture (lfdCaptureCommands.cxx), also used by bench, demo and eval.

/// The options of a synthetic capture (`lfd synth`, and the demos' captures).
struct SynthOptions
{
  std::string Object = "fish";
  std::string Mesh;
  std::string Texture;
  std::string Scene;
  std::string Out;
  int Views = 120;
  int Rows = 3;
  double RowSpacing = 0.0;
  std::vector<double> RowHeights;
  std::vector<double> Elevations;
  double RowMargin = 0.05;
  int Width = 256;
  int Height = 256;
  double Radius = 0.0;
  double ViewAngle = 0.0;
  std::vector<double> Axis = { 0.0, 1.0, 0.0 };
  bool SceneFixedLight = false;
  bool NoDepth = false;
  int Supersample = 1; // samples per pixel along each axis of the Coaxial pass
  int Projectors = 0;
  double ProjectorNoise = 0.0;
  double ProjectorAmbient = 0.0;
  std::vector<std::string> ProjectorMasks;
};

/// The source mesh (and texture) of a capture or a ground-truth comparison: a
/// built-in object by name, or a mesh file.
vtkSmartPointer<vtkPolyData> SourceMesh(const std::string& name,
  vtkSmartPointer<vtkImageData>& texture);

/// Eyes the captured rows must cover and what they look at besides the mesh
/// (vtkLightFieldCapture::SetEyes, SetEyeTargets).
struct RowCoverage
{
  vtkSmartPointer<vtkPoints> Eyes;
  vtkSmartPointer<vtkPoints> Targets;
};

/// The rows `synth --scene` covers: the scene's camera looking at its boxes
/// at rest, as they stand and at every keyframe.
RowCoverage SceneCoverage(vtkLightFieldSceneLogic* scene, vtkDeformationCage* cage);

/// Captures a light field of `mesh` (with `texture`, optional) with the
/// options' rig and light; rows placed by the options, or to cover `coverage`
/// when given and the options set no explicit heights or elevations.
vtkSmartPointer<vtkLightField> Capture(vtkPolyData* mesh,
  vtkImageData* texture,
  const SynthOptions& options,
  const RowCoverage* coverage = nullptr);

/// Says in one warning line when the scene's camera looks beyond the light
/// field's captured rows or into a gap of its ring
/// (vtkCameraRig::DescribeExtrapolation; the view looks at the cage's bounds
/// when there is a cage).
void WarnIfExtrapolating(vtkLightField* lightField,
  vtkLightFieldSceneLogic* scene,
  vtkDeformationCage* cage);

/// Captures a light field of a mesh (or a built-in object) with the options.
vtkSmartPointer<vtkLightField> Synthesize(const SynthOptions& options);

/// Runs an importer (its calibration set) and writes its light field into `out`;
/// `shownAs`: the name the report gives `out` (lfdImportCommands.cxx).
void ImportCalibratedImages(vtkCalibratedImageImporter* importer,
  const std::string& out,
  const std::string& shownAs);

/// Imports a Middlebury set into `out`; `shownAs`: the name the report gives
/// `out` (a staged folder's target).
void ImportMiddlebury(const std::string& par, const std::string& out, const std::string& shownAs);

//------------------------------------------------------------------------------
// Novel views and animations (lfdRenderCommands.cxx), also used by bench and demo.

/**
 * Renders `frames` frames of a scene's keyframes (evenly from the first to
 * the last keyframe time) into the folder `out` with
 * vtkLightFieldAnimationWriter: frame_%04d.png, and animation.mp4 when
 * ffmpeg is installed; its progress is said on stderr ("animating: frame
 * 3/48"). `paraview` adds the ParaView series (frame_NNNN.vti,
 * cage_NNNN.vtu, animation.pvd, cage.pvd). Returns the frames' contact sheet.
 */
vtkSmartPointer<vtkImageData> RenderAnimation(vtkLightFieldSceneLogic* scene,
  vtkLightField* lightField,
  int frames,
  const std::string& out,
  bool paraview = false);

/// The report of an animation written into `folder`, to be known as `out`.
void PrintAnimation(vtkLightFieldSceneLogic* scene,
  int frames,
  double seconds,
  const std::string& folder,
  const std::string& out);
}

#endif
