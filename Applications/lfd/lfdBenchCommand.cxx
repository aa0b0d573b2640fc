// `lfd bench`: rays/s and ms/frame of the renderer.
#include "lfdCommands.h"

#include "vtkCagePoseFilter.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkProceduralObjectSource.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace lfd::cli
{
namespace
{
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
    vtkLightFieldSceneLogic::OrbitCamera(rig, 0.37, 1.2, 0.0, rig->GetViewAngle(0), camera);
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

}

void AddBenchCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto repeat = std::make_shared<int>(15);
  auto size = std::make_shared<int>(512);
  vtkNew<vtkLightFieldCapture> captureLimits;
  auto* benchCommand = app.add_subcommand("bench",
    "print rays/s and ms/frame of the renderer on fixed scenes (median of repeated renders; "
    "writes nothing); needs an X display (xvfb-run -a)");
  numbers.Add(benchCommand, "--repeat", *repeat, 1, 1000, "renders per scene");
  numbers.Add(
    benchCommand, "--size", *size, 1, captureLimits->GetWidthMaxValue(), "image width and height");
  commands.push_back({ benchCommand, [repeat, size] { Bench(*repeat, *size); }, true });
}
}
