// `lfd render`, `lfd animate` and `lfd lattice`: a scene's views out.
#include "lfdCommands.h"

#include "lfdLimits.h"
#include "lfdProcessAgreement.h"
#include "lfdProcessGroup.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkImageData.h"
#include "vtkLatticeCageFilter.h"
#include "vtkLightField.h"
#include "vtkLightFieldAnimationWriter.h"
#include "vtkLightFieldRenderer.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldTiler.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtksys/SystemTools.hxx"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
/// What `lfd render` changes of the scene's view before rendering.
struct ViewOptions
{
  int View = -1; // a captured view's camera (-1: the scene's)
  std::string Size;
  std::vector<double> CameraPosition;
  std::vector<double> FocalPoint;
  RenderOverrides Overrides; // of render.focal and render.antialiasing
};

/// The refocusing of a two-plane light field (vtkLightFieldRenderer's
/// FocalDepth and Aperture); a negative value leaves the renderer's default.
struct RefocusOptions
{
  double FocalDepth = -1.0;
  double Aperture = -1.0;
};

/// "WxH" -> width and height, or a refusal naming --size.
void ParseSize(const std::string& text, int& width, int& height)
{
  char* end = nullptr;
  const long w = std::strtol(text.c_str(), &end, 10);
  long h = 0;
  bool valid = end != text.c_str() && *end == 'x';
  if (valid)
  {
    const char* start = end + 1;
    h = std::strtol(start, &end, 10);
    valid = end != start && *end == '\0';
  }
  if (!valid || w < 1 || h < 1 || w > lfd::MaximumRenderSize || h > lfd::MaximumRenderSize)
  {
    Fail("--size " + text + ": expected WxH, each from 1 to " +
      std::to_string(lfd::MaximumRenderSize) + " (e.g. 640x480)");
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
}

/// Applies --view, --size, --camera-position and --focal-point to the scene
/// (edits of the scene logic, validated there).
void ApplyViewOptions(const ViewOptions& options,
  vtkLightFieldSceneLogic* scene,
  vtkLightField* lightField)
{
  vtkNew<vtkCamera> camera;
  camera->DeepCopy(scene->GetScene()->GetCamera());
  int size[2] = { scene->GetScene()->GetWidth(), scene->GetScene()->GetHeight() };
  if (options.View >= 0)
  {
    vtkCameraRig* rig = lightField->GetRig();
    if (options.View >= rig->GetNumberOfViews())
    {
      Fail("--view " + std::to_string(options.View) + ": the light field has " +
        std::to_string(rig->GetNumberOfViews()) + " views (0 to " +
        std::to_string(rig->GetNumberOfViews() - 1) + ")");
    }
    rig->ApplyToCamera(options.View, camera);
    size[0] = rig->GetImageSize()[0];
    size[1] = rig->GetImageSize()[1];
  }
  if (!options.Size.empty())
  {
    ParseSize(options.Size, size[0], size[1]);
  }
  if (!options.CameraPosition.empty())
  {
    camera->SetPosition(options.CameraPosition.data());
  }
  if (!options.FocalPoint.empty())
  {
    camera->SetFocalPoint(options.FocalPoint.data());
  }
  if (!options.CameraPosition.empty() || !options.FocalPoint.empty())
  {
    camera->OrthogonalizeViewUp();
  }
  if (!scene->SetSize(size[0], size[1]) || !scene->SetCamera(camera))
  {
    Fail(""); // the scene logic said why
  }
}

void Render(const std::string& scenePath,
  const std::string& out,
  const double* time,
  const ViewOptions& view,
  const RefocusOptions& refocus,
  std::int64_t cacheBytes)
{
  const double start = vtkTimerLog::GetUniversalTime();
  auto scene = ReadScene(scenePath);
  ApplyRenderOverrides(view.Overrides, scene);
  auto lightField = ReadSceneLightField(scene, Passes::Rendered, cacheBytes);
  ApplyViewOptions(view, scene, lightField);
  auto cage = SceneCage(scene, lightField, time);
  vtkNew<vtkLightFieldRenderer> renderer;
  scene->ConfigureRenderer(renderer, lightField, cage);
  if (refocus.FocalDepth >= 0.0 || refocus.Aperture >= 0.0)
  {
    if (!lightField->GetRig()->IsTwoPlane())
    {
      Fail("--focal-depth and --aperture refocus two-plane light fields; the rig of this one is "
           "not a grid on a plane (a ring's focal plane is render.focal_distance)");
    }
    if (refocus.FocalDepth >= 0.0)
    {
      renderer->SetFocalDepth(refocus.FocalDepth);
    }
    if (refocus.Aperture >= 0.0)
    {
      renderer->SetAperture(refocus.Aperture);
    }
  }
  WarnIfExtrapolating(lightField, scene, cage);
  Run(renderer.Get(), "rendering");
  CheckTexelSource(lightField);
  WriteImage(renderer->GetOutput(), out);
  std::cout << "wrote " << out << " (" << scene->GetScene()->GetWidth() << "x"
            << scene->GetScene()->GetHeight() << ") in " << Seconds(start) << " s\n";
}
}

vtkSmartPointer<vtkImageData> RenderAnimation(vtkLightFieldSceneLogic* scene,
  vtkLightField* lightField,
  int frames,
  const std::string& out,
  bool paraview)
{
  vtkNew<vtkLightFieldAnimationWriter> writer;
  writer->SetSceneLogic(scene);
  writer->SetLightField(lightField);
  writer->SetNumberOfFrames(frames);
  writer->SetWriteParaView(paraview);
  writer->SetDirectoryName(out.c_str());
  // The processes of `mpirun -np N lfd animate` split the frames.
  writer->SetController(ProcessGroup::GetController());
  lfd::ShowSteps(writer,
    "animating",
    [](vtkObject* caller)
    { return std::string(static_cast<vtkLightFieldAnimationWriter*>(caller)->GetProgressText()); });
  if (!writer->Write())
  {
    Fail(""); // the writer said why
  }
  auto sheet = vtkSmartPointer<vtkImageData>::New();
  sheet->ShallowCopy(writer->GetContactSheet());
  return sheet;
}

void PrintAnimation(vtkLightFieldSceneLogic* scene,
  int frames,
  double seconds,
  const std::string& folder,
  const std::string& out)
{
  std::printf("frames    %d of %dx%d in %s/frame_*.png (%.1f ms/frame)\n",
    frames,
    scene->GetScene()->GetWidth(),
    scene->GetScene()->GetHeight(),
    out.c_str(),
    1000.0 * seconds / frames);
  if (vtksys::SystemTools::FileExists(folder + "/animation.mp4", true))
  {
    std::printf("movie     %s/animation.mp4\n", out.c_str());
  }
}

namespace
{
void Animate(const std::string& scenePath,
  int frames,
  const std::string& out,
  bool paraview,
  const RenderOverrides& overrides,
  std::int64_t cacheBytes)
{
  // Under mpirun every process reads the scene and its piece of the light
  // field's views (on a cluster, from a shared file system), then they
  // exchange the pieces; process 0 stages the output. A process that
  // cannot read stops them all, with the first refusal said once.
  const bool root = ProcessGroup::GetRank() == 0;
  vtkSmartPointer<vtkLightFieldSceneLogic> scene;
  vtkSmartPointer<vtkLightField> lightField;
  std::unique_ptr<StagedFolder> folder;
  std::string refusal;
  {
    // The errors VTK objects report (their warnings are said as they come).
    vtkNew<vtkLightFieldErrorObserver> seen;
    vtkOutputWindow* window = vtkOutputWindow::GetInstance();
    const unsigned long tag = window->AddObserver(vtkCommand::ErrorEvent, seen);
    try
    {
      scene = ReadScene(scenePath);
      ApplyRenderOverrides(overrides, scene);
      if (scene->GetScene()->GetNumberOfKeyframes() < 2)
      {
        Fail("scene '" + scenePath + "' needs at least 2 keyframes to animate");
      }
      lightField = ReadSceneLightField(
        scene, Passes::Rendered, cacheBytes, ProcessGroup::GetRank(), ProcessGroup::GetSize());
      if (root)
      {
        folder =
          std::make_unique<StagedFolder>(out, "lfd animate", lfd::scene::AnimationFilePatterns());
      }
    }
    catch (const Failure& failure)
    {
      // (An empty message: a VTK object said why.)
      refusal = failure.Message.empty() ? std::string(seen->GetErrorMessage()) : failure.Message;
    }
    window->RemoveObserver(tag);
  }
  refusal = lfd::scene::AgreeOnError(ProcessGroup::GetController(), refusal);
  if (!refusal.empty())
  {
    Fail(refusal);
  }
  ProcessGroup::ShareLightField(lightField);
  const double start = vtkTimerLog::GetUniversalTime();
  RenderAnimation(scene, lightField, frames, root ? folder->GetPath() : std::string(), paraview);
  CheckTexelSource(lightField);
  if (!root)
  {
    return;
  }
  PrintAnimation(scene, frames, Seconds(start), folder->GetPath(), out);
  if (paraview)
  {
    std::printf("paraview  %s/animation.pvd, %s/cage.pvd\n", out.c_str(), out.c_str());
  }
  folder->Commit();
}

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
  const std::string why = cage->Validate();
  if (!why.empty())
  {
    Fail(options.Out + ": the sampled cage is refused: " + why);
  }
  if (!scene->ReplaceCage(cage))
  {
    Fail("");
  }
  WriteScene(scene->GetScene(), options.Out);
  std::printf("wrote %s: %lld boxes on %lld points (lattice %d x %d x %d, subdivision %d), "
              "largest corner move %.4g\n",
    options.Out.c_str(),
    static_cast<long long>(cage->GetNumberOfBoxes()),
    static_cast<long long>(cage->GetNumberOfPoints()),
    options.Dimensions[0],
    options.Dimensions[1],
    options.Dimensions[2],
    options.Subdivision,
    cage->GetLargestDisplacement());
}

}

void AddRenderCommands(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  static const std::string CacheSizeHelp =
    "read the light field's colours, labels and depth (the proxy) out of core, tile by tile "
    "through an image cache "
    "of SIZE bytes (K, M or G; e.g. 512M) instead of into memory (the default); the dataset must "
    "be tiled (lfd tile)";
  struct RenderOptions
  {
    std::string Scene;
    std::string Out;
    double Time = 0.0;
    ViewOptions View;
    RefocusOptions Refocus;
    std::int64_t CacheSize = 0;
  };
  auto render = std::make_shared<RenderOptions>();
  auto* renderCommand = app.add_subcommand("render",
    "render a scene's camera view of its light field, deformed by its cage, into the image OUT "
    "(replaced when complete)");
  renderCommand->add_option("SCENE", render->Scene, "scene.json")->required();
  renderCommand->add_option("--out", render->Out, "output image (.png, .exr, ...)")->required();
  auto* timeOption = numbers.AddReal(renderCommand,
    "--time",
    render->Time,
    "time of the keyframes to render (default: the cage's points)");
  numbers
    .Add(renderCommand,
      "--view",
      render->View.View,
      0,
      std::numeric_limits<int>::max(),
      "render from captured view N's camera (its pinhole, without lens distortion) at the light "
      "field's image size, instead of the scene's camera; --size, --camera-position and "
      "--focal-point still apply")
    ->default_str("");
  renderCommand->add_option(
    "--size", render->View.Size, "image size WxH (default: the scene's, or the view's)");
  numbers
    .AddReal(renderCommand,
      "--camera-position",
      render->View.CameraPosition,
      "camera position x,y,z (default: the scene's camera)")
    ->expected(3)
    ->delimiter(',');
  numbers
    .AddReal(renderCommand,
      "--focal-point",
      render->View.FocalPoint,
      "point x,y,z the camera looks at (default: the scene's camera)")
    ->expected(3)
    ->delimiter(',');
  numbers
    .Add(renderCommand,
      "--focal-depth",
      render->Refocus.FocalDepth,
      0.0,
      1e9,
      "two-plane light fields: depth D of the focal plane in front of the camera plane (world "
      "units along the cameras' axis; 0, the default, is infinity): points at D are sharp, a point "
      "at depth z blurs over f |du| |1/z - 1/D| pixels for cameras du apart")
    ->default_str("");
  numbers
    .Add(renderCommand,
      "--aperture",
      render->Refocus.Aperture,
      0.0,
      1e9,
      "two-plane light fields: synthetic aperture R, world units on the camera plane: every camera "
      "closer than R along both grid axes contributes, tent-weighted (default 0: the 4 nearest, "
      "bilinearly); with a Label pass each pixel keeps its winning part's colour, so the blur "
      "stops at part borders")
    ->default_str("");
  AddRenderOverrideOptions(renderCommand, render->View.Overrides);
  numbers.AddByteSize(renderCommand, "--cache-size", render->CacheSize, CacheSizeHelp);
  commands.push_back({ renderCommand,
    [render, timeOption]
    {
      Render(render->Scene,
        render->Out,
        *timeOption ? &render->Time : nullptr,
        render->View,
        render->Refocus,
        render->CacheSize);
    },
    false });

  struct AnimateOptions
  {
    std::string Scene;
    std::string Out;
    int Frames = 48;
    bool ParaView = false;
    RenderOverrides Overrides;
    std::int64_t CacheSize = 0;
  };
  auto animate = std::make_shared<AnimateOptions>();
  auto* animateCommand = app.add_subcommand("animate",
    "render the scene's keyframes (its interpolation: Catmull-Rom or linear) into the folder "
    "OUT: frame_NNNN.png, and animation.mp4 when ffmpeg is installed; replaces OUT when "
    "complete (an existing OUT may hold only such files)");
  animateCommand->add_option("SCENE", animate->Scene, "scene.json with keyframes")->required();
  numbers.Add(animateCommand, "--frames", animate->Frames, 1, MaximumFrames, "number of frames");
  animateCommand->add_option("--out", animate->Out, "output folder")->required();
  animateCommand->add_flag("--paraview",
    animate->ParaView,
    "also write the ParaView series: each frame as frame_NNNN.vti (Radiance, Label, Depth) and "
    "its cage as cage_NNNN.vtu, listed with their times in animation.pvd and cage.pvd");
  AddRenderOverrideOptions(animateCommand, animate->Overrides);
  numbers.AddByteSize(animateCommand, "--cache-size", animate->CacheSize, CacheSizeHelp);
  commands.push_back({ animateCommand,
    [animate]
    {
      Animate(animate->Scene,
        animate->Frames,
        animate->Out,
        animate->ParaView,
        animate->Overrides,
        animate->CacheSize);
    },
    false });

  struct TileOptions
  {
    std::string In;
    std::string Out;
    int TileSize = 64;
  };
  auto tile = std::make_shared<TileOptions>();
  auto* tileCommand = app.add_subcommand("tile",
    "rewrite the light-field dataset LF as OUT with tiled, MIP-mapped TIFF images (same manifest, "
    "rig and passes), which lfd render and lfd animate --cache-size read tile by tile; one image "
    "in memory at a time, so LF may be larger than memory; replaces OUT when complete");
  tileCommand->add_option("LF", tile->In, "light-field dataset")->required();
  tileCommand->add_option("--out", tile->Out, "output dataset")->required();
  numbers.Add(tileCommand,
    "--tile-size",
    tile->TileSize,
    16,
    4096,
    "tile width and height in pixels, a multiple of 16");
  commands.push_back({ tileCommand,
    [tile]
    {
      const double start = vtkTimerLog::GetUniversalTime();
      vtkNew<vtkLightFieldTiler> tiler;
      tiler->SetFileName(tile->In.c_str());
      tiler->SetDirectory(tile->Out.c_str());
      tiler->SetTileSize(tile->TileSize);
      lfd::ShowProgress(tiler, "tiling");
      StepErrors errors;
      errors->Observe(tiler);
      tiler->Write();
      errors.FailOnError();
      std::cout << "wrote " << tile->Out << " (" << tile->TileSize << "x" << tile->TileSize
                << " tiles) in " << Seconds(start) << " s\n";
    },
    false });

  auto lattice = std::make_shared<LatticeOptions>();
  vtkNew<vtkLatticeCageFilter> latticeLimits;
  auto* latticeCommand = app.add_subcommand("lattice",
    "bend a scene's boxes with a smooth lattice (Sederberg-Parry free-form deformation) sampled "
    "into boxes; writes the scene file OUT with the deformed cage (replaced when complete)");
  latticeCommand->add_option("SCENE", lattice->Scene, "scene.json with a cage")->required();
  latticeCommand->add_option("--out", lattice->Out, "output scene.json")->required();
  numbers
    .Add(
      latticeCommand, "--dimensions", lattice->Dimensions, 2, 16, "control points per axis x y z")
    ->expected(3);
  numbers
    .AddReal(latticeCommand,
      "--move",
      lattice->Moves,
      "I J K DX DY DZ: move control point (I, J, K) by (DX, DY, DZ); repeat for more")
    ->expected(6)
    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  numbers
    .AddReal(latticeCommand,
      "--region",
      lattice->Region,
      "XMIN XMAX YMIN YMAX ZMIN ZMAX of the lattice (default: the cage's rest bounds)")
    ->expected(6);
  numbers.Add(latticeCommand,
    "--subdivision",
    lattice->Subdivision,
    latticeLimits->GetSubdivisionMinValue(),
    latticeLimits->GetSubdivisionMaxValue(),
    "split each box into K^3 sub-boxes");
  commands.push_back({ latticeCommand, [lattice] { Lattice(*lattice); }, false });
}
}
