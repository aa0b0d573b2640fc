// `lfd bench`: rays/s and ms/frame of the renderer, against a reference loop
// and against cage size; with --studio, the frame times of the editing view
// (vtkLightFieldEditor) during a drag.
#include "lfdCommands.h"

#include "vtkCagePoseFilter.h"
#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCamera.h"
#include "vtkCameraRig.h"
#include "vtkDeformationCage.h"
#include "vtkIdList.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkProceduralObjectSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
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

/// A renderer of `lightField` at `size` x `size` from the bench's orbit camera.
vtkSmartPointer<vtkLightFieldRenderer> OrbitRenderer(vtkLightField* lightField, int size)
{
  vtkCameraRig* rig = lightField->GetRig();
  vtkNew<vtkCamera> camera;
  vtkLightFieldSceneLogic::OrbitCamera(rig, 0.37, 1.2, 0.0, rig->GetViewAngle(0), camera);
  auto renderer = vtkSmartPointer<vtkLightFieldRenderer>::New();
  renderer->SetInputData(lightField);
  renderer->SetCamera(camera);
  renderer->SetWidth(size);
  renderer->SetHeight(size);
  return renderer;
}

/**
 * Median render times (s) of `object`'s light field at `size` x `size` from
 * an orbit camera, at rest and deformed: the fish swimming (3 boxes,
 * Fig. 13), the figure twisted by 45 degrees (Fig. 1).
 */
std::pair<double, double> RenderTimes(vtkLightField* lightField,
  const std::string& object,
  int size,
  int repeat)
{
  vtkSmartPointer<vtkLightFieldRenderer> renderer = OrbitRenderer(lightField, size);
  const double rest = MedianRenderTime(renderer, repeat);

  vtkNew<vtkProceduralObjectSource> source;
  source->SetObject(vtkProceduralObjectSource::GetObjectFromString(object.c_str()));
  vtkNew<vtkPartCageSource> parts;
  parts->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputConnection(parts->GetOutputPort());
  if (object == "fish")
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
  return { rest, MedianRenderTime(renderer, repeat) };
}

/// What one recorded drag in the editor measured.
struct DragFigures
{
  double Move = 0.0;    ///< median time (s) from a mouse motion to its frame
  double MoveCpu = 0.0; ///< the process's CPU time (s, all threads) of that motion
  double Release = 0.0; ///< time (s) from the button release to the full-resolution frame
  double ReleaseCpu = 0.0;
  double Still = 0.0; ///< median time (s) of a full-resolution frame of the same view
  int Coarse[2] = { 0, 0 };
  int Full[2] = { 0, 0 };
  vtkIdType Validated = 0; ///< boxes the scene logic re-checked per move
  int Commands = 0;        ///< commands the drag made (1: one undoable drag)
};

/// Wall and CPU seconds of one event.
struct EventTime
{
  double Wall;
  double Cpu; ///< the process's, all threads: on a loaded machine the wall time is longer
  bool operator<(const EventTime& other) const { return this->Wall < other.Wall; }
};

/// Plays one event line through the recorder, as a recorded session does;
/// returns how long the interactor took to handle it (its render included).
EventTime PlayEvent(vtkInteractorEventRecorder* recorder, const std::string& line)
{
  recorder->SetInputString(line.c_str());
  const double start = vtkTimerLog::GetUniversalTime();
  const double cpu = vtkTimerLog::GetCPUTime();
  recorder->Play();
  return { Seconds(start), vtkTimerLog::GetCPUTime() - cpu };
}

/**
 * The visible cage point shared by the most boxes, the highest on screen
 * among those: a corner the animator would drag (upwards it unfolds
 * nothing). -1 when no shared point is visible.
 */
vtkIdType SharedCorner(vtkLightFieldEditor* editor, double display[2])
{
  vtkDeformationCage* cage = editor->GetLogic()->GetCage();
  std::vector<int> uses(cage->GetNumberOfPoints(), 0);
  vtkNew<vtkIdList> corners;
  for (vtkIdType box = 0; box < cage->GetNumberOfBoxes(); ++box)
  {
    cage->GetCellPoints(box, corners);
    for (vtkIdType c = 0; c < corners->GetNumberOfIds(); ++c)
    {
      ++uses[corners->GetId(c)];
    }
  }
  vtkCageRepresentation* rep = editor->GetWidget()->GetCageRepresentation();
  vtkRenderer* renderer = editor->GetRenderer();
  vtkIdType best = -1;
  for (vtkIdType id = 0; id < cage->GetNumberOfPoints(); ++id)
  {
    if (uses[id] < 2 || !rep->IsPointVisible(id))
    {
      continue;
    }
    double p[3];
    cage->GetPoint(id, p);
    renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    if (best < 0 || uses[id] > uses[best] || (uses[id] == uses[best] && d[1] > display[1]))
    {
      best = id;
      display[0] = d[0];
      display[1] = d[1];
    }
  }
  return best;
}

/**
 * The editor on `logic`'s scene in its own 800 x 600 window: a recorded
 * drag of a shared corner by `moves` motions of 1 pixel up and right
 * (progressive: coarse frames), then the release (the full-resolution frame).
 */
DragFigures RecordedDrag(vtkLightFieldSceneLogic* logic, int moves)
{
  vtkNew<vtkLightFieldEditor> editor;
  editor->SetLogic(logic);
  if (!editor->Initialize())
  {
    Fail("bench --studio: the editor could not show the scene");
  }
  DragFigures figures;
  std::vector<double> stills;
  for (int i = 0; i < std::max(3, moves / 4); ++i)
  {
    editor->GetRenderer()->GetActiveCamera()->Modified(); // a new view each time
    const double start = vtkTimerLog::GetUniversalTime();
    editor->Render();
    stills.push_back(Seconds(start));
  }
  std::sort(stills.begin(), stills.end());
  figures.Still = stills[stills.size() / 2];

  double display[2] = { 0.0, 0.0 };
  if (SharedCorner(editor, display) < 0)
  {
    Fail("bench --studio: no visible corner shared by two boxes");
  }
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(editor->GetInteractor());
  recorder->ReadFromInputStringOn();
  int x = static_cast<int>(display[0] + 0.5), y = static_cast<int>(display[1] + 0.5);
  auto event = [&](const char* name)
  { return std::string(name) + " " + std::to_string(x) + " " + std::to_string(y) + " 0 0 0 0\n"; };
  const int commands = logic->GetNumberOfCommands();
  PlayEvent(recorder, event("MouseMoveEvent"));
  PlayEvent(recorder, event("LeftButtonPressEvent"));
  std::vector<EventTime> times;
  for (int i = 0; i < moves; ++i)
  {
    ++x;
    ++y;
    times.push_back(PlayEvent(recorder, event("MouseMoveEvent")));
    const int* size = editor->GetMapper()->GetLastImageSize();
    figures.Coarse[0] = size[0];
    figures.Coarse[1] = size[1];
  }
  figures.Validated = logic->GetNumberOfBoxesLastValidated();
  const EventTime release = PlayEvent(recorder, event("LeftButtonReleaseEvent"));
  figures.Release = release.Wall;
  figures.ReleaseCpu = release.Cpu;
  const int* size = editor->GetMapper()->GetLastImageSize();
  figures.Full[0] = size[0];
  figures.Full[1] = size[1];
  figures.Commands = logic->GetNumberOfCommands() - commands;
  std::sort(times.begin(), times.end());
  figures.Move = times[times.size() / 2].Wall;
  figures.MoveCpu = times[times.size() / 2].Cpu;
  return figures;
}

/**
 * The fish's scene for the editor: its light field, the cage of its 3 parts
 * (`boxes` 3) or `boxes` slabs along its longest axis, each labelled by the
 * part holding its centre, and a camera on the ring.
 */
vtkSmartPointer<vtkLightFieldSceneLogic> FishScene(vtkLightField* lightField, int boxes)
{
  auto logic = vtkSmartPointer<vtkLightFieldSceneLogic>::New();
  logic->SetLightField(lightField);
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  Run(source.Get(), "building the fish");
  if (!logic->BuildCageFromLabels(source->GetOutput(), -1))
  {
    Fail("bench --studio: the fish's cage was refused");
  }
  if (boxes != 3)
  {
    vtkNew<vtkDeformationCage> parts;
    parts->DeepCopy(logic->GetCage());
    double bounds[6];
    parts->GetBounds(bounds);
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      axis = bounds[2 * a + 1] - bounds[2 * a] > bounds[2 * axis + 1] - bounds[2 * axis] ? a : axis;
    }
    logic->BuildCageFromSlabs(bounds, boxes, axis, 1);
    vtkDeformationCage* slabs = logic->GetCage();
    for (vtkIdType b = 0; b < slabs->GetNumberOfBoxes(); ++b)
    {
      double centre[3] = { 0.0, 0.0, 0.0 }, corners[24], partCorners[24];
      slabs->GetRestCorners(b, corners);
      for (int c = 0; c < 8; ++c)
      {
        centre[axis] += corners[3 * c + axis] / 8.0;
      }
      for (vtkIdType part = 0; part < parts->GetNumberOfBoxes(); ++part)
      {
        parts->GetRestCorners(part, partCorners);
        double low = partCorners[axis], high = partCorners[axis];
        for (int c = 1; c < 8; ++c)
        {
          low = std::min(low, partCorners[3 * c + axis]);
          high = std::max(high, partCorners[3 * c + axis]);
        }
        if (centre[axis] >= low && centre[axis] <= high)
        {
          logic->SetBoxLabel(b, parts->GetBoxLabel(part));
        }
      }
    }
  }
  vtkCameraRig* rig = lightField->GetRig();
  vtkNew<vtkCamera> camera;
  vtkLightFieldSceneLogic::OrbitCamera(rig, 0.37, 1.2, 0.0, rig->GetViewAngle(0), camera);
  logic->SetCamera(camera);
  logic->ClearUndo();
  return logic;
}

/**
 * The reference loop (issue 14): for every pixel of a size x size frame, the
 * 16 texel reads of one light-field lookup (2 x 2 bilinear texels in each of
 * 4 views, as lfd::LightFieldSampler::Gather reads them) and their weighted
 * blend, without any geometry (no cylinder, projection or label), rows in
 * parallel as vtkLightFieldRenderer's. The floor a lookup cannot go under:
 * the renderer's figures print as ratios to its time, taken in the same run.
 */
struct ReferenceLoop
{
  const std::uint8_t* Radiance; // the views' RGB pixels, view after view
  int Views;
  int Width;
  int Height;
  int Size;
  std::uint8_t* Out; // Size x Size RGB

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    // Two neighbouring views in each of two rows, as a lookup between rows.
    const int views[4] = { 0, 1, this->Views / 2, this->Views / 2 + 1 };
    const double scale = static_cast<double>(this->Width - 1) / this->Size;
    for (vtkIdType j = begin; j < end; ++j)
    {
      const double v = (static_cast<double>(j) + 0.5) * scale;
      const int y0 = static_cast<int>(v);
      const double ay = v - y0;
      for (int i = 0; i < this->Size; ++i)
      {
        const double u = (i + 0.5) * scale;
        const int x0 = static_cast<int>(u);
        const double ax = u - x0;
        double sum[3] = { 0.0, 0.0, 0.0 };
        for (int view : views)
        {
          for (int corner = 0; corner < 4; ++corner)
          {
            const int px = x0 + (corner & 1);
            const int py = std::min(y0 + (corner >> 1), this->Height - 1);
            const double weight =
              0.25 * ((corner & 1) ? ax : 1.0 - ax) * ((corner >> 1) ? ay : 1.0 - ay);
            const std::uint8_t* rgb = this->Radiance +
              3 * ((static_cast<std::size_t>(view) * this->Height + py) * this->Width + px);
            for (int c = 0; c < 3; ++c)
            {
              sum[c] += weight * rgb[c];
            }
          }
        }
        std::uint8_t* out = this->Out + 3 * (j * this->Size + i);
        for (int c = 0; c < 3; ++c)
        {
          out[c] = static_cast<std::uint8_t>(std::lround(sum[c]));
        }
      }
    }
  }
};

/// Median time (s) of `repeat` runs of the reference loop over `lightField`, after a warm-up.
double ReferenceTime(vtkLightField* lightField, int size, int repeat)
{
  auto* radiance = vtkUnsignedCharArray::SafeDownCast(lightField->GetPass(vtkLightField::COAXIAL));
  std::vector<std::uint8_t> out(3 * static_cast<std::size_t>(size) * size);
  const ReferenceLoop loop{ radiance->GetPointer(0),
    lightField->GetNumberOfViews(),
    lightField->GetWidth(),
    lightField->GetHeight(),
    size,
    out.data() };
  vtkSMPTools::For(0, size, loop);
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i)
  {
    const double start = vtkTimerLog::GetUniversalTime();
    vtkSMPTools::For(0, size, loop);
    times.push_back(Seconds(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

/**
 * Median render time (s) of the fish bent by 30 degrees under the cage of
 * FishScene with `boxes` boxes, at `size` x `size`, with or without
 * the renderer's per-frame acceleration (vtkLightFieldRenderer::CageAcceleration).
 */
double CageRenderTime(vtkLightField* lightField, int boxes, int size, int repeat, bool accelerated)
{
  auto logic = FishScene(lightField, boxes);
  vtkNew<vtkCagePoseFilter> pose;
  pose->SetInputData(logic->GetCage());
  // (A swim folds slabs as thin as 100 along the fish; a bend does not.)
  pose->SetModeToBend();
  pose->SetAngle(30.0);
  pose->SetTurnAxis(0.0, 0.0, 1.0);
  Run(pose.Get(), "posing the cage");
  vtkSmartPointer<vtkLightFieldRenderer> renderer = OrbitRenderer(lightField, size);
  renderer->SetCageData(pose->GetOutput());
  renderer->SetCageAcceleration(accelerated);
  return MedianRenderTime(renderer, repeat);
}

/**
 * The cost against cage size: the fish bent under 1, 3 (its parts), 10,
 * 30 and 100 boxes (slabs labelled by part), against the 3-box figure and
 * the reference loop; the last column without the per-frame acceleration.
 */
void CageSizeBench(vtkLightField* fish, int repeat, int size, double reference)
{
  std::printf("%-46s %8s %10s %12s %8s %8s %10s\n",
    "deformed fish (bend 30), cage size",
    "pixels",
    "ms/frame",
    "rays/s",
    "vs 3",
    "vs ref",
    "no accel");
  std::vector<std::pair<int, double>> rows;
  double three = 0.0;
  for (int boxes : { 1, 3, 10, 30, 100 })
  {
    const double time = CageRenderTime(fish, boxes, size, repeat, true);
    three = boxes == 3 ? time : three;
    rows.emplace_back(boxes, time);
  }
  for (const auto& [boxes, time] : rows)
  {
    const double plain = CageRenderTime(fish, boxes, size, repeat, false);
    const std::string name = std::to_string(boxes) + (boxes == 1 ? " box" : " boxes") +
      (boxes == 3      ? " (its parts)"
          : boxes == 1 ? " (one slab)"
                       : " (slabs)");
    std::printf("%-46s %8d %10.2f %12.3g %7.2fx %7.2fx %10.2f\n",
      name.c_str(),
      size * size,
      1000.0 * time,
      size * size / time,
      time / three,
      time / reference,
      1000.0 * plain);
  }
}

/**
 * The fish again with its Depth pass, so that the renderer focuses every
 * ray on that proxy (vtkLightFieldRenderer::FOCAL_AUTOMATIC): its cost
 * against `plane` (the undeformed and deformed times through the plane).
 */
void ProxyBench(int size, int repeat, const std::pair<double, double>& plane)
{
  SynthOptions options;
  auto fish = Synthesize(options);
  const auto [rest, deformed] = RenderTimes(fish, "fish", size, repeat);
  std::printf("%-46s %8s %10s %12s %8s\n",
    "focal surface: proxy (Depth pass)",
    "pixels",
    "ms/frame",
    "rays/s",
    "vs plane");
  std::printf("%-46s %8d %10.2f %12.3g %7.2fx\n",
    "undeformed fish, proxy",
    size * size,
    1000.0 * rest,
    size * size / rest,
    rest / plane.first);
  std::printf("%-46s %8d %10.2f %12.3g %7.2fx\n",
    "deformed fish (swim, 3 boxes), proxy",
    size * size,
    1000.0 * deformed,
    size * size / deformed,
    deformed / plane.second);
}

void Bench(int repeat, int size)
{
  std::printf("threads: %d (vtkSMPTools, %s backend)\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    vtkSMPTools::GetBackend());
  SynthOptions fishOptions;
  fishOptions.NoDepth = true;
  auto fish = Synthesize(fishOptions);
  const double reference = ReferenceTime(fish, size, repeat);
  std::printf("%-46s %8s %10s %12s %8s %8s\n",
    "scene (light fields: 120x3 views of 256^2)",
    "pixels",
    "ms/frame",
    "rays/s",
    "vs rest",
    "vs ref");
  std::printf("%-46s %8d %10.2f %12.3g %8s %7.2fx\n",
    "reference loop (16 texel reads, no geometry)",
    size * size,
    1000.0 * reference,
    size * size / reference,
    "",
    1.0);
  std::pair<double, double> fishPlane;
  for (const char* object : { "fish", "figure" })
  {
    const bool isFish = std::string(object) == "fish";
    SynthOptions options;
    options.Object = object;
    options.NoDepth = true;
    auto lightField = isFish ? fish : Synthesize(options);
    const auto [rest, deformed] = RenderTimes(lightField, object, size, repeat);
    fishPlane = isFish ? std::make_pair(rest, deformed) : fishPlane;
    const std::string restName = std::string("undeformed ") + object;
    const std::string deformedName =
      isFish ? "deformed fish (swim, 3 boxes)" : "deformed figure (twist 45, 3 boxes)";
    std::printf("%-46s %8d %10.2f %12.3g %8s %7.2fx\n",
      restName.c_str(),
      size * size,
      1000.0 * rest,
      size * size / rest,
      "",
      rest / reference);
    std::printf("%-46s %8d %10.2f %12.3g %7.2fx %7.2fx\n",
      deformedName.c_str(),
      size * size,
      1000.0 * deformed,
      size * size / deformed,
      deformed / rest,
      deformed / reference);
  }
  ProxyBench(size, repeat, fishPlane);
  CageSizeBench(fish, repeat, size, reference);
  std::printf("(median of %d renders each; vs ref: against the reference loop; vs 3: against "
              "the 3 boxes of the same table; no accel: ms/frame of the same cage with "
              "vtkLightFieldRenderer::CageAcceleration off; vs plane: against the same render "
              "through the focal plane above)\n",
    repeat);
}

/// `lfd bench --studio`: the editing view's frame times during a recorded drag.
void StudioBench(int repeat)
{
  std::printf("threads: %d (vtkSMPTools, %s backend)\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(),
    vtkSMPTools::GetBackend());
  std::printf("%-18s %8s %6s %7s %7s %8s %8s %7s %7s %8s %8s %5s\n",
    "editor 800x600",
    "drag ms",
    "fps",
    "cpu ms",
    "vs ref",
    "coarse",
    "release",
    "cpu ms",
    "vs ref",
    "full",
    "still ms",
    "boxes");
  SynthOptions options;
  options.NoDepth = true;
  auto lightField = Synthesize(options);
  // The reference loop of `lfd bench` (deformed fish, 512x512) in the same
  // conditions: the ratios to it do not depend on the machine's load.
  const double reference = RenderTimes(lightField, "fish", 512, std::min(repeat, 5)).second;
  for (int boxes : { 3, 100 })
  {
    auto logic = FishScene(lightField, boxes);
    const DragFigures figures = RecordedDrag(logic, repeat);
    if (figures.Commands != 1)
    {
      Fail("bench --studio: the drag made " + std::to_string(figures.Commands) +
        " commands instead of 1");
    }
    const std::string name = "fish, " + std::to_string(boxes) + " boxes";
    const std::string coarse =
      std::to_string(figures.Coarse[0]) + "x" + std::to_string(figures.Coarse[1]);
    const std::string full =
      std::to_string(figures.Full[0]) + "x" + std::to_string(figures.Full[1]);
    std::printf("%-18s %8.1f %6.1f %7.1f %6.2fx %8s %8.1f %7.1f %6.2fx %8s %8.1f %5lld\n",
      name.c_str(),
      1000.0 * figures.Move,
      1.0 / figures.Move,
      1000.0 * figures.MoveCpu,
      figures.Move / reference,
      coarse.c_str(),
      1000.0 * figures.Release,
      1000.0 * figures.ReleaseCpu,
      figures.Release / reference,
      full.c_str(),
      1000.0 * figures.Still,
      static_cast<long long>(figures.Validated));
  }
  std::printf("(drag ms: median time from a mouse motion to its coarse frame over %d motions; "
              "release: from the button release to the full-resolution frame; cpu ms: the "
              "process's CPU time of the same, all threads; vs ref: against the deformed fish "
              "at 512x512 of lfd bench, %.1f ms here; still ms: median full-resolution "
              "frame; boxes: re-validated per motion; targets: 30 fps, 150 ms)\n",
    repeat,
    1000.0 * reference);
}

}

void AddBenchCommand(CLI::App& app, NumericOptions& numbers, std::vector<Command>& commands)
{
  auto repeat = std::make_shared<int>(15);
  auto size = std::make_shared<int>(512);
  auto studio = std::make_shared<bool>(false);
  vtkNew<vtkLightFieldCapture> captureLimits;
  auto* benchCommand = app.add_subcommand("bench",
    "print rays/s and ms/frame of the renderer on fixed scenes (median of repeated renders; "
    "writes nothing), each also as a ratio to a reference loop (16 texel reads per pixel, no "
    "geometry) timed in the same run, and the cost against cage size (the fish bent under 1 "
    "to 100 boxes, with and without the renderer's cage acceleration); needs an X display "
    "(xvfb-run -a)");
  numbers.Add(benchCommand, "--repeat", *repeat, 1, 1000, "renders per scene");
  numbers.Add(
    benchCommand, "--size", *size, 1, captureLimits->GetWidthMaxValue(), "image width and height");
  benchCommand->add_flag("--studio",
    *studio,
    "instead: the editing view of the Studio (vtkLightFieldEditor, 800x600): ms/frame during a "
    "recorded corner drag (--repeat motions), release to full resolution, with 3 and 100 boxes");
  commands.push_back({ benchCommand,
    [repeat, size, studio] { *studio ? StudioBench(*repeat) : Bench(*repeat, *size); },
    true });
}
}
