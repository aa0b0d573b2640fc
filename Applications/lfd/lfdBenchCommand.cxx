// `lfd bench`: rays/s, ms/frame (wall clock, process CPU time and run-queue
// wait of the same frame) and peak memory of the renderer at several frame
// sizes, against a reference loop, on the run's threads and on one thread,
// against light-field size (memory against raw bytes too) and against cage
// size, as tables and as JSON; with --studio, the frame times of the editing
// view (vtkLightFieldEditor) during a drag.
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
#include "vtkLightFieldImageCache.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldRenderer.h"
#include "vtkNew.h"
#include "vtkPartCageSource.h"
#include "vtkPointData.h"
#include "vtkProceduralObjectSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"

#include <CLI/CLI.hpp>
#include <fcntl.h>
#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#endif
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

namespace lfd::cli
{
namespace
{
/**
 * The process's resident memory: its current size, and its peak over a
 * stretch of work: Reset() sets the kernel's high-water mark (VmHWM) back to
 * the current resident size (/proc/self/clear_refs, Linux 4.0 and later),
 * Read() gives it in bytes, so that each configuration's peak is its own.
 * Where the mark cannot be reset, Read() is the process's peak so far and
 * Scope() says so.
 */
class PeakMemory
{
public:
  void Reset()
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.close();
    this->Resettable = !clear.fail();
  }

  long long Read() const { return Status("VmHWM:"); }

  /// The resident size now (bytes).
  long long Resident() const { return Status("VmRSS:"); }

  const char* Scope() const { return this->Resettable ? "configuration" : "process"; }

private:
  /// A size in kB of /proc/self/status, in bytes (0 where absent).
  static long long Status(const std::string& field)
  {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
    {
      if (line.rfind(field, 0) == 0)
      {
        return 1024LL * std::atoll(line.c_str() + field.size());
      }
    }
    return 0;
  }

  bool Resettable = false;
};

/**
 * The time (s) the calling thread has spent ready to run without a core:
 * the second field of /proc/thread-self/schedstat (the scheduler's
 * run-queue delay, in ns), kept open so that a reading costs a few
 * microseconds. The thread that asks for a frame is on its critical path: on
 * one thread a frame's wall time is its CPU time plus this wait, and the
 * other processes' load shows here, not as a slower lookup. (Not the sum
 * over the process's threads: an idle TBB worker that the scheduler wakes
 * for a few microseconds may have waited milliseconds for a core without
 * delaying the frame.)
 */
class RunQueueWait
{
public:
  RunQueueWait()
    : File(open("/proc/thread-self/schedstat", O_RDONLY | O_CLOEXEC))
  {
  }
  ~RunQueueWait()
  {
    if (this->File >= 0)
    {
      close(this->File);
    }
  }
  RunQueueWait(const RunQueueWait&) = delete;
  RunQueueWait& operator=(const RunQueueWait&) = delete;

  /// The wait so far; -1 where the kernel does not say.
  double Seconds() const
  {
    char text[128];
    const ssize_t length = this->File < 0 ? -1 : pread(this->File, text, sizeof(text) - 1, 0);
    unsigned long long running = 0, waiting = 0;
    if (length <= 0)
    {
      return -1.0;
    }
    text[length] = '\0';
    return std::sscanf(text, "%llu %llu", &running, &waiting) == 2
      ? 1e-9 * static_cast<double>(waiting)
      : -1.0;
  }

private:
  int File;
};

/**
 * Keeps the calling thread on the core it runs on, while it lives (then its
 * former cores are restored). The one-thread figures are ratios between
 * loops timed one after the other: on a virtual machine whose cores run at
 * different speeds (on the CI machine kind, one of the two took 1.6x the
 * other's time for the same loop, the reference loop and the lookup alike:
 * `taskset -c 0` / `-c 1`), a thread that moved between them gave ratios
 * from 1.0x to 2.0x for the same build; on one core they agree. With one
 * vtkSMPTools thread the work runs on the calling thread, so this pins it.
 * Linux only; elsewhere nothing is pinned. Core() is the pinned core, -1 when
 * none.
 */
class PinnedToCore
{
public:
  PinnedToCore()
  {
#ifdef __linux__
    const int core = sched_getcpu();
    if (core >= 0 &&
      pthread_getaffinity_np(pthread_self(), sizeof(this->Former), &this->Former) == 0)
    {
      cpu_set_t one;
      CPU_ZERO(&one);
      CPU_SET(core, &one);
      if (pthread_setaffinity_np(pthread_self(), sizeof(one), &one) == 0)
      {
        this->Pinned = core;
      }
    }
#endif
  }
  ~PinnedToCore()
  {
#ifdef __linux__
    if (this->Pinned >= 0)
    {
      pthread_setaffinity_np(pthread_self(), sizeof(this->Former), &this->Former);
    }
#endif
  }
  PinnedToCore(const PinnedToCore&) = delete;
  PinnedToCore& operator=(const PinnedToCore&) = delete;

  int Core() const
  {
    return this->Pinned;
  }

private:
  int Pinned = -1;
#ifdef __linux__
  cpu_set_t Former;
#endif
};

/**
 * The process's CPU time (s): every thread's, to the nanosecond
 * (CLOCK_PROCESS_CPUTIME_ID; clock() reads the same clock in microseconds).
 * With several threads it includes the time TBB's workers spin waiting for
 * work, so it is compared like for like only between runs on one thread.
 */
double ProcessCpuTime()
{
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/**
 * One configuration's figures: the wall time, the process's CPU time and
 * the calling thread's run-queue wait (s) of ONE frame, the median frame by wall
 * time of the repeats (so the three figures belong together), the
 * vtkSMPTools threads it ran on, and the process's resident memory when it
 * started and at its peak (bytes).
 */
struct Measure
{
  double Seconds = 0.0;
  double CpuSeconds = 0.0;
  double WaitSeconds = 0.0; ///< -1 where the kernel does not say
  int Threads = 0;
  long long StartBytes = 0;
  long long PeakBytes = 0;
};

/// The figures of one call of `work`.
template<typename Work>
Measure TimeOnce(const RunQueueWait& queue, Work&& work)
{
  // The wall clock encloses the other two: a frame never waits longer than it lasts.
  const double start = vtkTimerLog::GetUniversalTime();
  const double wait = queue.Seconds();
  const double cpu = ProcessCpuTime();
  work();
  Measure run;
  run.CpuSeconds = ProcessCpuTime() - cpu;
  run.WaitSeconds = wait < 0.0 ? -1.0 : queue.Seconds() - wait;
  run.Seconds = Seconds(start);
  return run;
}

/// The median (by wall time) of `runs`.
Measure Median(std::vector<Measure> runs)
{
  const auto median = runs.begin() + runs.size() / 2;
  std::nth_element(runs.begin(),
    median,
    runs.end(),
    [](const Measure& a, const Measure& b) { return a.Seconds < b.Seconds; });
  median->Threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  return *median;
}

/// The figures of the median (by wall time) of `repeat` calls of `work`.
template<typename Work>
Measure MedianTimes(int repeat, Work&& work)
{
  std::vector<Measure> runs;
  const RunQueueWait queue;
  for (int i = 0; i < repeat; ++i)
  {
    runs.push_back(TimeOnce(queue, work));
  }
  return Median(std::move(runs));
}

/**
 * Median times of `repeat` updates of each renderer after a warm-up of
 * each, the renderers updated in turn (a, b, a, b, ...), and the peak
 * memory over them. A ratio of two holds while the machine's speed drifts
 * (other jobs, the host changing the core's clock): measured one after the
 * other, two configurations of a few ms each can see different machines.
 * With `alongside`, that work is timed in the same turns, after the
 * renderers, and its figures come last.
 */
std::vector<Measure> MeasureRenders(const std::vector<vtkLightFieldRenderer*>& renderers,
  int repeat,
  PeakMemory& peak,
  const std::function<void()>& alongside = nullptr)
{
  peak.Reset();
  const long long start = peak.Resident();
  for (vtkLightFieldRenderer* renderer : renderers)
  {
    Run(renderer, "rendering"); // warm-up (rig layout, threads)
  }
  if (alongside)
  {
    alongside();
  }
  std::vector<std::vector<Measure>> runs(renderers.size() + (alongside ? 1 : 0));
  const RunQueueWait queue;
  for (int i = 0; i < repeat; ++i)
  {
    for (std::size_t k = 0; k < renderers.size(); ++k)
    {
      vtkLightFieldRenderer* renderer = renderers[k];
      runs[k].push_back(TimeOnce(queue,
        [renderer]
        {
          renderer->Modified();
          renderer->Update();
        }));
    }
    if (alongside)
    {
      runs.back().push_back(TimeOnce(queue, alongside));
    }
  }
  std::vector<Measure> figures;
  for (std::vector<Measure>& times : runs)
  {
    figures.push_back(Median(std::move(times)));
    figures.back().StartBytes = start;
    figures.back().PeakBytes = peak.Read();
  }
  return figures;
}

/// MeasureRenders of one renderer.
Measure MeasureRender(vtkLightFieldRenderer* renderer, int repeat, PeakMemory& peak)
{
  return MeasureRenders({ renderer }, repeat, peak).front();
}

/// MeasureRenders of two renderers in turn.
std::pair<Measure, Measure> MeasureInTurn(vtkLightFieldRenderer* a,
  vtkLightFieldRenderer* b,
  int repeat,
  PeakMemory& peak)
{
  const std::vector<Measure> figures = MeasureRenders({ a, b }, repeat, peak);
  return { figures[0], figures[1] };
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
 * Renderers of `object`'s light field at `size` x `size` from an orbit
 * camera, at rest and deformed: the fish swimming (3 boxes, Fig. 13), the
 * figure twisted by 45 degrees (Fig. 1); focused as `focal` says
 * (vtkLightFieldRenderer::FocalSurfaceType).
 */
std::pair<vtkSmartPointer<vtkLightFieldRenderer>, vtkSmartPointer<vtkLightFieldRenderer>>
SceneRenderers(vtkLightField* lightField,
  const std::string& object,
  int size,
  int focal = vtkLightFieldRenderer::FOCAL_AUTOMATIC)
{
  vtkSmartPointer<vtkLightFieldRenderer> rest = OrbitRenderer(lightField, size);
  rest->SetFocalSurface(focal);

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
  vtkSmartPointer<vtkLightFieldRenderer> deformed = OrbitRenderer(lightField, size);
  deformed->SetFocalSurface(focal);
  deformed->SetCageData(pose->GetOutput());
  return { rest, deformed };
}

/// Median render times and peaks of SceneRenderers, at rest and deformed.
std::pair<Measure, Measure> RenderTimes(vtkLightField* lightField,
  const std::string& object,
  int size,
  int repeat,
  PeakMemory& peak)
{
  const auto [rest, deformed] = SceneRenderers(lightField, object, size);
  const Measure restFigures = MeasureRender(rest, repeat, peak);
  return { restFigures, MeasureRender(deformed, repeat, peak) };
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
  const double cpu = ProcessCpuTime();
  recorder->Play();
  return { Seconds(start), ProcessCpuTime() - cpu };
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
 * parallel as vtkLightFieldRenderer's (the same vtkSMPTools::For over the
 * frame's rows, the same default grain). The floor a lookup cannot go
 * under: the renderer's figures print as ratios to its time, taken in the
 * same run on as many threads.
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

/// The reference loop over `lightField`'s Coaxial pass at `size` x `size`,
/// with its frame; a call runs it once.
class ReferenceFrame
{
public:
  ReferenceFrame(vtkLightField* lightField, int size)
    : Out(3 * static_cast<std::size_t>(size) * size)
    , Loop{ vtkUnsignedCharArray::SafeDownCast(lightField->GetPass(vtkLightField::COAXIAL))
              ->GetPointer(0),
      lightField->GetNumberOfViews(),
      lightField->GetWidth(),
      lightField->GetHeight(),
      size,
      this->Out.data() }
  {
  }
  ReferenceFrame(const ReferenceFrame&) = delete; // Loop points into Out
  ReferenceFrame& operator=(const ReferenceFrame&) = delete;

  void operator()() const { vtkSMPTools::For(0, this->Loop.Size, this->Loop); }

private:
  std::vector<std::uint8_t> Out;
  ReferenceLoop Loop;
};

/// Median times of `repeat` runs of the reference loop over `lightField`, after a
/// warm-up, and the peak memory over them.
Measure ReferenceTime(vtkLightField* lightField, int size, int repeat, PeakMemory& peak)
{
  peak.Reset();
  const long long start = peak.Resident();
  const ReferenceFrame loop(lightField, size);
  loop();
  Measure figures = MedianTimes(repeat, [&loop] { loop(); });
  figures.StartBytes = start;
  figures.PeakBytes = peak.Read();
  return figures;
}

/**
 * RenderTimes of the two renderers and the reference loop over `reference`
 * (the fish), the three timed in turn: their ratios hold while the machine's
 * speed drifts between turns (on a virtual machine a core's speed may change
 * by 1.6x from one second to the next: the ratios of rows timed one after
 * the other moved from 1.0x to 2.0x for the same build). Figures: at rest,
 * deformed, the loop.
 */
std::vector<Measure> RenderTimesInTurn(vtkLightField* lightField,
  const std::string& object,
  vtkLightField* reference,
  int size,
  int repeat,
  PeakMemory& peak)
{
  const auto [rest, deformed] = SceneRenderers(lightField, object, size);
  const ReferenceFrame loop(reference, size);
  return MeasureRenders({ rest, deformed }, repeat, peak, [&loop] { loop(); });
}

/**
 * A renderer of the fish bent by 30 degrees under the cage of FishScene with
 * `boxes` boxes, at `size` x `size`, with or without the renderer's
 * per-frame acceleration (vtkLightFieldRenderer::CageAcceleration).
 */
vtkSmartPointer<vtkLightFieldRenderer> CageRenderer(vtkLightField* lightField,
  int boxes,
  int size,
  bool accelerated)
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
  return renderer;
}

/// What `lfd bench` measures: the sizes, tables and repeats of a run.
struct BenchSettings
{
  int Repeat = 15;
  int Threads = 0; ///< vtkSMPTools threads (0: its default, every core)
  std::vector<int> Sizes = { 256, 512, 1024 };
  bool Quick = false;
  std::string Json;
};

/**
 * One measured configuration, a row of one of the bench's tables. Every
 * table is a list of such rows, printed and written to JSON by the same
 * code: a new path of the renderer is a new row (or a new table name).
 */
struct BenchRow
{
  std::string Table; ///< "reference", "render", "light-field size", "cage size"
  std::string Name;
  int Size = 0;                  ///< frame width and height
  int Views = 0;                 ///< the light field's views
  int ImageSize = 0;             ///< its image width (= height)
  long long LightFieldBytes = 0; ///< its passes in memory (Coaxial, Label)
  int Boxes = 0;                 ///< cage boxes (0: undeformed)
  Measure Figures;
  /// Further figures of the row's table, by name (e.g. "vs_rest": a ratio).
  std::vector<std::pair<std::string, double>> Extra;

  /// Adds the ratio of this row's times to `other`'s as `name` (wall
  /// clock) and "cpu_" `name` (CPU time).
  void AddRatio(const std::string& name, const Measure& other)
  {
    this->Extra.emplace_back(name, this->Figures.Seconds / other.Seconds);
    this->Extra.emplace_back("cpu_" + name, this->Figures.CpuSeconds / other.CpuSeconds);
  }
};

/// The light field of the bench's fish (or figure): `views` x `rows` views
/// of `image` x `image` pixels, without the Depth pass (so that the renderer
/// focuses on the paper's plane) unless `depth` (then on that proxy).
vtkSmartPointer<vtkLightField> BenchLightField(const std::string& object,
  int views,
  int rows,
  int image,
  bool depth = false)
{
  SynthOptions options;
  options.Object = object;
  options.Views = views;
  options.Rows = rows;
  options.Width = image;
  options.Height = image;
  options.NoDepth = !depth;
  return Synthesize(options);
}

/// The bytes of a light field's passes.
long long LightFieldBytes(vtkLightField* lightField)
{
  long long bytes = 0;
  for (int pass = 0; pass < vtkLightField::NUMBER_OF_PASSES; ++pass)
  {
    if (vtkDataArray* array = lightField->GetPass(pass))
    {
      bytes += static_cast<long long>(array->GetNumberOfValues()) * array->GetDataTypeSize();
    }
  }
  return bytes;
}

/// The row of a configuration of `lightField`.
BenchRow Row(const std::string& table,
  const std::string& name,
  int size,
  vtkLightField* lightField,
  int boxes,
  const Measure& figures)
{
  return { table,
    name,
    size,
    lightField->GetNumberOfViews(),
    lightField->GetWidth(),
    LightFieldBytes(lightField),
    boxes,
    figures,
    {} };
}

/// The frame size of the light-field-size and cage-size tables: 512 (the
/// issue's figures) when measured, else the largest size measured.
int TableSize(const BenchSettings& settings)
{
  const auto& sizes = settings.Sizes;
  return std::find(sizes.begin(), sizes.end(), 512) != sizes.end()
    ? 512
    : *std::max_element(sizes.begin(), sizes.end());
}

/**
 * The cost against light-field size: the undeformed fish at TableSize()
 * from light fields of several view counts and resolutions, and the memory
 * against the light field's raw image bytes (its passes: Coaxial, Label):
 * "rss_vs_raw" the process's peak during the render, "render_mb" and
 * "render_vs_raw" what the render added to the process as it was (the
 * light field in memory). Measured before the bench makes any other light
 * field, so that the process then holds the start-up floor, the OpenGL
 * state of the capture and this light field only.
 */
void LightFieldSizeRows(const BenchSettings& settings,
  PeakMemory& peak,
  std::vector<BenchRow>& rows)
{
  struct Layout
  {
    int Views, Rows, Image;
  };
  const std::vector<Layout> layouts = settings.Quick
    ? std::vector<Layout>{ { 12, 1, 32 }, { 24, 1, 64 } }
    : std::vector<Layout>{ { 30, 3, 256 },
        { 120, 3, 128 },
        { 120, 3, 256 },
        { 120, 3, 512 },
        { 240, 3, 256 },
        { 240, 3, 512 } };
  const int size = TableSize(settings);
  for (const Layout& layout : layouts)
  {
    auto lightField = BenchLightField("fish", layout.Views, layout.Rows, layout.Image);
    const std::string name = std::to_string(layout.Views) + "x" + std::to_string(layout.Rows) +
      " views of " + std::to_string(layout.Image) + "^2";
    const Measure figures = MeasureRender(OrbitRenderer(lightField, size), settings.Repeat, peak);
    rows.push_back(Row("light-field size", name, size, lightField, 0, figures));
    const double raw = static_cast<double>(rows.back().LightFieldBytes);
    const double added = static_cast<double>(figures.PeakBytes - figures.StartBytes);
    rows.back().Extra.emplace_back("rss_vs_raw", figures.PeakBytes / raw);
    rows.back().Extra.emplace_back("render_mb", added / 1048576.0);
    rows.back().Extra.emplace_back("render_vs_raw", added / raw);
  }
}

/**
 * The cost against cage size: the fish bent under 1, 3 (its parts), 10, 30
 * and 100 boxes (slabs labelled by part) at TableSize(), against the 3-box
 * cage rendered in turn with it (MeasureInTurn); "no_accel_ms": the same
 * cage without the per-frame acceleration.
 */
void CageSizeRows(vtkLightField* fish,
  const BenchSettings& settings,
  PeakMemory& peak,
  std::vector<BenchRow>& rows)
{
  const std::vector<int> counts =
    settings.Quick ? std::vector<int>{ 1, 3 } : std::vector<int>{ 1, 3, 10, 30, 100 };
  const int size = TableSize(settings);
  const std::size_t first = rows.size();
  vtkSmartPointer<vtkLightFieldRenderer> threeBoxes = CageRenderer(fish, 3, size, true);
  std::vector<Measure> threes;
  for (int boxes : counts)
  {
    Measure figures, three;
    if (boxes == 3)
    {
      figures = three = MeasureRender(threeBoxes, settings.Repeat, peak);
    }
    else
    {
      std::tie(three, figures) =
        MeasureInTurn(threeBoxes, CageRenderer(fish, boxes, size, true), settings.Repeat, peak);
    }
    threes.push_back(three);
    const std::string name = std::to_string(boxes) + (boxes == 1 ? " box" : " boxes") +
      (boxes == 3      ? " (its parts)"
          : boxes == 1 ? " (one slab)"
                       : " (slabs)");
    rows.push_back(Row("cage size", name, size, fish, boxes, figures));
  }
  for (std::size_t r = first; r < rows.size(); ++r)
  {
    const Measure plain =
      MeasureRender(CageRenderer(fish, rows[r].Boxes, size, false), settings.Repeat, peak);
    rows[r].AddRatio("vs_3_boxes", threes[r - first]);
    rows[r].Extra.emplace_back("no_accel_ms", 1000.0 * plain.Seconds);
    rows[r].Extra.emplace_back("no_accel_cpu_ms", 1000.0 * plain.CpuSeconds);
  }
}

/**
 * The proxy rows: the fish again with its Depth pass, so that the renderer
 * focuses every ray on that proxy (vtkLightFieldRenderer::FOCAL_AUTOMATIC),
 * at rest and swimming, each against the same light field rendered through
 * the plane (`vs_plane`), the two rendered in turn (MeasureInTurn).
 */
void ProxyRows(const BenchSettings& settings,
  int views,
  int rowsOfViews,
  int image,
  PeakMemory& peak,
  std::vector<BenchRow>& rows)
{
  auto fish = BenchLightField("fish", views, rowsOfViews, image, true);
  const int size = TableSize(settings);
  const auto plane = SceneRenderers(fish, "fish", size, vtkLightFieldRenderer::FOCAL_PLANE);
  const auto proxy = SceneRenderers(fish, "fish", size);
  const auto [restPlane, rest] = MeasureInTurn(plane.first, proxy.first, settings.Repeat, peak);
  const auto [deformedPlane, deformed] =
    MeasureInTurn(plane.second, proxy.second, settings.Repeat, peak);
  rows.push_back(Row("proxy", "undeformed fish, proxy", size, fish, 0, rest));
  rows.back().AddRatio("vs_plane", restPlane);
  rows.push_back(Row("proxy", "deformed fish (swim, 3 boxes), proxy", size, fish, 3, deformed));
  rows.back().AddRatio("vs_plane", deformedPlane);
}

/**
 * The two-plane rows (Levoy and Hanrahan 1996, lfdTwoPlaneSampling.h): the
 * fish captured from a 16 x 16 grid of `image`^2 views 0.05 apart on the plane
 * z = 3, rendered from a camera on that plane between four of them, focused
 * on the fish (depth 3): with the 4 nearest cameras, and refocused through
 * an aperture of 3 spacings (every camera within 0.15: 5 x 5 of them).
 */
void TwoPlaneRows(const BenchSettings& settings,
  int image,
  PeakMemory& peak,
  std::vector<BenchRow>& rows)
{
  vtkNew<vtkProceduralObjectSource> source;
  source->SetObjectToFish();
  const double centre[3] = { 0.0, 0.0, 3.0 };
  const double forward[3] = { 0.0, 0.0, -1.0 };
  const double up[3] = { 0.0, 1.0, 0.0 };
  vtkNew<vtkCameraRig> grid;
  grid->MakePlaneGrid(centre, forward, up, 16, 16, 0.05, image, image, 30.0);
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(source->GetOutputPort());
  capture->SetRig(grid);
  capture->CaptureDepthOff();
  Run(capture.Get(), "capturing the two-plane fish");
  vtkLightField* lightField = capture->GetOutput();
  const int size = TableSize(settings);
  vtkNew<vtkCameraRig> eye;
  const double between[3] = { 0.025, 0.025, 3.0 };
  eye->MakePlaneGrid(between, forward, up, 1, 1, 1.0, size, size, 30.0);
  double K[9], R[9], t[3];
  eye->GetIntrinsics(0, K);
  eye->GetRotation(0, R);
  eye->GetTranslation(0, t);
  vtkNew<vtkLightFieldRenderer> renderer;
  renderer->SetInputData(lightField);
  renderer->SetPinhole(K, R, t);
  renderer->SetWidth(size);
  renderer->SetHeight(size);
  renderer->SetFocalDepth(3.0);
  for (const double aperture : { 0.0, 0.15 })
  {
    renderer->SetAperture(aperture);
    const Measure figures = MeasureRender(renderer, settings.Repeat, peak);
    rows.push_back(Row("two-plane",
      aperture > 0.0 ? "fish 16x16 grid, aperture 3 spacings" : "fish 16x16 grid, 4 nearest",
      size,
      lightField,
      0,
      figures));
  }
}

/**
 * Out of core: the undeformed fish at TableSize() read tile by tile (`lfd
 * tile`, 64^2 tiles) through image caches of 1/4, 1/2 and 1x its bytes,
 * against the same render from memory in the same run ("vs_in_memory"),
 * with the cache's reads and whether the frame equals the in-memory one
 * pixel for pixel ("identical", 1 or 0). The in-memory fish stays resident
 * in the bench's process: "peak MB" counts it too.
 */
void OutOfCoreRows(vtkLightField* fish,
  const BenchSettings& settings,
  PeakMemory& peak,
  std::vector<BenchRow>& rows)
{
  const int size = TableSize(settings);
  const std::string folder = lfd::io::TemporaryDirectoryName(
    (std::filesystem::temp_directory_path() / "lfd-bench-tiles").string());
  WriteLightField(fish, folder, 64);
  vtkSmartPointer<vtkLightFieldRenderer> memory = OrbitRenderer(fish, size);
  const Measure inMemory = MeasureRender(memory, settings.Repeat, peak);
  vtkDataArray* expected = memory->GetOutput()->GetPointData()->GetScalars();
  const long long bytes = LightFieldBytes(fish);
  for (const auto& [name, fraction] :
    std::vector<std::pair<std::string, double>>{ { "cache 1/4 of the data", 0.25 },
      { "cache 1/2 of the data", 0.5 },
      { "cache as large as the data", 1.0 } })
  {
    auto lightField =
      ReadLightField(folder, Passes::RenderedOnPlane, static_cast<std::int64_t>(fraction * bytes));
    auto* cache = vtkLightFieldImageCache::SafeDownCast(lightField->GetTexelSource());
    vtkSmartPointer<vtkLightFieldRenderer> renderer = OrbitRenderer(lightField, size);
    const Measure figures = MeasureRender(renderer, settings.Repeat, peak);
    vtkDataArray* frame = renderer->GetOutput()->GetPointData()->GetScalars();
    const bool identical = frame->GetNumberOfValues() == expected->GetNumberOfValues() &&
      std::memcmp(frame->GetVoidPointer(0),
        expected->GetVoidPointer(0),
        static_cast<std::size_t>(frame->GetNumberOfValues())) == 0;
    rows.push_back(Row("out of core", name, size, fish, 0, figures));
    rows.back().AddRatio("vs_in_memory", inMemory);
    rows.back().Extra.emplace_back("cache_mb", cache->GetCacheSize() / 1048576.0);
    rows.back().Extra.emplace_back("tiles_read", static_cast<double>(cache->GetTilesRead()));
    rows.back().Extra.emplace_back("identical", identical ? 1.0 : 0.0);
  }
  lfd::io::RemoveQuietly(folder);
}

/// The reference loop's figures at each frame size and thread count.
using ReferenceTimes = std::map<std::pair<int, int>, Measure>;

/// The reference loop's figures at `row`'s frame size and thread count.
const Measure& ReferenceOf(const ReferenceTimes& reference, const BenchRow& row)
{
  return reference.at({ row.Size, row.Figures.Threads });
}

/**
 * The lookup rows: the reference loop (into `referenceTable`), then the
 * undeformed and deformed fish and figure (into `renderTable`), at each
 * --size, on the threads vtkSMPTools has now.
 */
void LookupRows(const std::string& referenceTable,
  const std::string& renderTable,
  vtkLightField* fish,
  vtkLightField* figure,
  const BenchSettings& settings,
  PeakMemory& peak,
  ReferenceTimes& reference,
  std::vector<BenchRow>& rows)
{
  for (int size : settings.Sizes)
  {
    const Measure loop = ReferenceTime(fish, size, settings.Repeat, peak);
    reference[{ size, loop.Threads }] = loop;
    rows.push_back(
      Row(referenceTable, "reference loop (16 texel reads, no geometry)", size, fish, 0, loop));
  }
  for (vtkLightField* lightField : { fish, figure })
  {
    const std::string object = lightField == fish ? "fish" : "figure";
    const std::string deformedName =
      lightField == fish ? "deformed fish (swim, 3 boxes)" : "deformed figure (twist 45, 3 boxes)";
    for (int size : settings.Sizes)
    {
      const std::vector<Measure> figures =
        RenderTimesInTurn(lightField, object, fish, size, settings.Repeat, peak);
      const Measure& rest = figures[0];
      rows.push_back(Row(renderTable, "undeformed " + object, size, lightField, 0, rest));
      rows.back().AddRatio("vs_ref_in_turn", figures[2]);
      rows.push_back(Row(renderTable, deformedName, size, lightField, 3, figures[1]));
      rows.back().AddRatio("vs_rest", rest);
      rows.back().AddRatio("vs_ref_in_turn", figures[2]);
    }
  }
}

/**
 * The lookup rows again on one thread (vtkSMPTools::Initialize(1)), as the
 * table "one thread", each with "vs_threads": its time over that of the
 * same row on the run's threads (their speedup; in CPU time, below 1 where
 * those threads spent more CPU: spinning, sharing the cores). On one thread
 * no worker spins and no worker waits to be woken, so these ratios to the
 * reference loop are like for like; then the run's threads are restored.
 */
void OneThreadRows(vtkLightField* fish,
  vtkLightField* figure,
  const BenchSettings& settings,
  int threads,
  PeakMemory& peak,
  ReferenceTimes& reference,
  std::vector<BenchRow>& rows)
{
  const std::size_t first = rows.size();
  vtkSMPTools::Initialize(1);
  {
    const PinnedToCore pinned;
    LookupRows("one thread", "one thread", fish, figure, settings, peak, reference, rows);
  }
  vtkSMPTools::Initialize(threads);
  for (std::size_t r = first; r < rows.size(); ++r)
  {
    const auto same = std::find_if(rows.begin(),
      rows.begin() + first,
      [&row = rows[r]](const BenchRow& other)
      {
        return (other.Table == "reference" || other.Table == "render") && other.Name == row.Name &&
          other.Size == row.Size;
      });
    rows[r].AddRatio("vs_threads", same->Figures);
  }
}

/// Prints the rows of `table` as one table, each figure also as a ratio to
/// the reference loop at the row's frame size.
void PrintTable(const std::string& title,
  const std::string& table,
  const std::vector<BenchRow>& rows,
  const ReferenceTimes& reference)
{
  // The table's rows, and the further figures any of them has (a column each).
  std::vector<const BenchRow*> selected;
  std::vector<std::string> columns;
  for (const BenchRow& row : rows)
  {
    if (row.Table == table)
    {
      selected.push_back(&row);
      for (const auto& figure : row.Extra)
      {
        if (std::find(columns.begin(), columns.end(), figure.first) == columns.end())
        {
          columns.push_back(figure.first);
        }
      }
    }
  }
  if (selected.empty())
  {
    return;
  }
  std::printf("\n%-44s %8s %10s %12s %8s %8s %8s %8s %8s",
    title.c_str(),
    "pixels",
    "ms/frame",
    "rays/s",
    "vs ref",
    "cpu ms",
    "cpu/ref",
    "wait ms",
    "peak MB");
  for (const std::string& column : columns)
  {
    std::printf(" %12s", column.c_str());
  }
  std::printf("\n");
  for (const BenchRow* row : selected)
  {
    const double pixels = static_cast<double>(row->Size) * row->Size;
    const double seconds = row->Figures.Seconds;
    const Measure& floor = ReferenceOf(reference, *row);
    char wait[32] = "-"; // where the kernel does not say
    if (row->Figures.WaitSeconds >= 0.0)
    {
      std::snprintf(wait, sizeof(wait), "%.2f", 1000.0 * row->Figures.WaitSeconds);
    }
    std::printf("%-44s %8.0f %10.2f %12.3g %7.2fx %8.2f %7.2fx %8s %8.0f",
      row->Name.c_str(),
      pixels,
      1000.0 * seconds,
      pixels / seconds,
      seconds / floor.Seconds,
      1000.0 * row->Figures.CpuSeconds,
      row->Figures.CpuSeconds / floor.CpuSeconds,
      wait,
      row->Figures.PeakBytes / 1048576.0);
    for (const std::string& column : columns)
    {
      const auto figure = std::find_if(row->Extra.begin(),
        row->Extra.end(),
        [&column](const std::pair<std::string, double>& f) { return f.first == column; });
      if (figure == row->Extra.end())
      {
        std::printf(" %12s", "");
      }
      else
      {
        std::printf(" %12.3g", figure->second);
      }
    }
    std::printf("\n");
  }
}

/// Every figure of the run as JSON (format "lfd-bench", version 1; Data/README.md).
nlohmann::json BenchJson(const BenchSettings& settings,
  const std::vector<BenchRow>& rows,
  const ReferenceTimes& reference,
  const double load[2][3],
  const char* peakScope,
  long long startupBytes)
{
  nlohmann::json machine = { { "cores", std::thread::hardware_concurrency() },
    { "threads", vtkSMPTools::GetEstimatedNumberOfThreads() },
    { "smp_backend", vtkSMPTools::GetBackend() },
    { "load_average_start", { load[0][0], load[0][1], load[0][2] } },
    { "load_average_end", { load[1][0], load[1][1], load[1][2] } } };
  nlohmann::json out = { { "format", "lfd-bench" },
    { "version", 1 },
    { "machine", machine },
    { "repeat", settings.Repeat },
    { "sizes", settings.Sizes },
    { "quick", settings.Quick },
    { "peak_rss_scope", peakScope },
    { "startup_rss_bytes", startupBytes },
    { "rows", nlohmann::json::array() } };
  for (const BenchRow& row : rows)
  {
    const double pixels = static_cast<double>(row.Size) * row.Size;
    nlohmann::json item = { { "table", row.Table },
      { "name", row.Name },
      { "size", row.Size },
      { "pixels", static_cast<long long>(pixels) },
      { "views", row.Views },
      { "image_size", row.ImageSize },
      { "light_field_bytes", row.LightFieldBytes },
      { "boxes", row.Boxes },
      { "threads", row.Figures.Threads },
      { "ms_per_frame", 1000.0 * row.Figures.Seconds },
      { "rays_per_second", pixels / row.Figures.Seconds },
      { "vs_reference", row.Figures.Seconds / ReferenceOf(reference, row).Seconds },
      { "cpu_ms_per_frame", 1000.0 * row.Figures.CpuSeconds },
      { "cpu_vs_reference", row.Figures.CpuSeconds / ReferenceOf(reference, row).CpuSeconds },
      { "wait_ms_per_frame",
        row.Figures.WaitSeconds < 0.0 ? nlohmann::json()
                                      : nlohmann::json(1000.0 * row.Figures.WaitSeconds) },
      { "start_rss_bytes", row.Figures.StartBytes },
      { "peak_rss_bytes", row.Figures.PeakBytes } };
    for (const auto& [name, value] : row.Extra)
    {
      item[name] = value;
    }
    out["rows"].push_back(item);
  }
  return out;
}

/// The machine's load average (1, 5, 15 minutes); zeros where unknown.
void LoadAverage(double load[3])
{
  load[0] = load[1] = load[2] = 0.0;
  getloadavg(load, 3);
}

void Bench(const BenchSettings& settings)
{
  PeakMemory peak;
  const long long startup = peak.Resident();
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  // On one thread every figure is timed on one core (PinnedToCore).
  std::optional<PinnedToCore> pinned;
  if (threads == 1)
  {
    pinned.emplace();
  }
  double load[2][3];
  LoadAverage(load[0]);
  std::printf("threads: %d (vtkSMPTools, %s backend)%s, cores: %u, load average: %.2f %.2f %.2f, "
              "start-up floor: %.0f MB resident\n",
    threads,
    vtkSMPTools::GetBackend(),
    pinned && pinned->Core() >= 0 ? (", on core " + std::to_string(pinned->Core())).c_str() : "",
    std::thread::hardware_concurrency(),
    load[0][0],
    load[0][1],
    load[0][2],
    startup / 1048576.0);
  // Quick: the same tables from tiny light fields, to check a run end to end.
  const int views = settings.Quick ? 24 : 120, rowsOfViews = settings.Quick ? 1 : 3;
  const int image = settings.Quick ? 64 : 256;
  std::vector<BenchRow> rows;
  ReferenceTimes reference;
  LightFieldSizeRows(settings, peak, rows);
  auto fish = BenchLightField("fish", views, rowsOfViews, image);
  auto figure = BenchLightField("figure", views, rowsOfViews, image);
  LookupRows("reference", "render", fish, figure, settings, peak, reference, rows);
  if (threads > 1)
  {
    OneThreadRows(fish, figure, settings, threads, peak, reference, rows);
  }
  figure = nullptr;
  ProxyRows(settings, views, rowsOfViews, image, peak, rows);
  CageSizeRows(fish, settings, peak, rows);
  TwoPlaneRows(settings, image, peak, rows);
  OutOfCoreRows(fish, settings, peak, rows);
  LoadAverage(load[1]);

  const std::string scene = "light field: " + std::to_string(views) + "x" +
    std::to_string(rowsOfViews) + " views of " + std::to_string(image) + "^2";
  PrintTable("reference loop", "reference", rows, reference);
  PrintTable("scene (" + scene + ")", "render", rows, reference);
  PrintTable("one thread (like for like; " + scene + ")", "one thread", rows, reference);
  PrintTable("focal surface: proxy (Depth pass)", "proxy", rows, reference);
  PrintTable("undeformed fish, light-field size", "light-field size", rows, reference);
  PrintTable("deformed fish (bend 30), cage size", "cage size", rows, reference);
  PrintTable(
    "two-plane fish (16x16 grid of " + std::to_string(image) + "^2)", "two-plane", rows, reference);
  PrintTable(
    "undeformed fish out of core (lfd tile, --cache-size)", "out of core", rows, reference);
  std::printf(
    "(the median frame (by wall time) of %d renders each; vs ref: against the reference loop at "
    "the same frame size on as many threads, timed in the same run; cpu ms: the process's CPU "
    "time in that frame, all threads (with %d threads it includes TBB's workers spinning for "
    "work), and cpu/ref its ratio to the reference loop's; wait ms: the time the thread that "
    "asked for that frame was ready to run without a core (the machine's load: on one "
    "thread ms/frame = cpu ms + wait ms); one thread: the same rows on one thread "
    "(vtkSMPTools::Initialize(1)), like for like, the thread kept on one core, vs_threads: their "
    "time over the same row's "
    "on %d threads; peak MB: the process's peak resident memory during the configuration "
    "(its light fields included; the start-up floor of its libraries alone: %.0f MB); "
    "rss_vs_raw: that peak over the light field's raw image bytes, render_mb and "
    "render_vs_raw: what the render added to the resident memory, and over those bytes; "
    "cpu_ columns: the ratio before them in CPU time; vs_ref_in_turn: against the reference loop "
    "timed in turn with the undeformed and deformed renders (the ratio that holds when the "
    "machine's speed drifts between rows); vs_rest: against the "
    "undeformed render, rendered in turn with it; vs_plane: against the same render through the "
    "focal plane, "
    "the two rendered in turn; "
    "vs_3_boxes: against the 3 boxes of the same table, rendered in turn with it; "
    "no_accel_ms: the same cage with vtkLightFieldRenderer::CageAcceleration off; "
    "vs_in_memory: against the same frame from memory, identical: 1 when its pixels "
    "equal it, cache_mb and tiles_read: the image cache's budget and reads; "
    "load average at the end: %.2f %.2f %.2f)\n",
    settings.Repeat,
    threads,
    threads,
    startup / 1048576.0,
    load[1][0],
    load[1][1],
    load[1][2]);
  if (!settings.Json.empty())
  {
    std::string error;
    const std::string text =
      BenchJson(settings, rows, reference, load, peak.Scope(), startup).dump(2) + "\n";
    if (!lfd::io::WriteFileAtomically(settings.Json, text, error))
    {
      Fail("--json " + settings.Json + ": " + error);
    }
    std::printf("wrote %s\n", settings.Json.c_str());
  }
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
  PeakMemory peak;
  const double reference =
    RenderTimes(lightField, "fish", 512, std::min(repeat, 5), peak).second.Seconds;
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
  auto settings = std::make_shared<BenchSettings>();
  auto studio = std::make_shared<bool>(false);
  vtkNew<vtkLightFieldCapture> captureLimits;
  auto* benchCommand = app.add_subcommand("bench",
    "print rays/s, ms/frame (wall clock, the process's CPU time over all threads and the "
    "run-queue wait, of the median frame of repeated renders) and peak memory of the renderer "
    "on fixed scenes (writes nothing unless --json), undeformed and deformed at each --size, "
    "each also as a ratio to a reference loop (16 texel reads per pixel, no geometry) timed in "
    "the same run, again on one thread (like for like), the cost and the memory (against the "
    "raw image bytes) against light-field size (views x resolution) and the cost against cage "
    "size (the fish bent under 1 to 100 boxes, with and without the renderer's cage "
    "acceleration), and a two-plane light field (the fish from a 16x16 grid, with the 4 "
    "nearest cameras and through a synthetic aperture); needs an X display (xvfb-run -a)");
  auto* repeat =
    numbers.Add(benchCommand, "--repeat", settings->Repeat, 1, 1000, "renders per configuration");
  numbers.Add(benchCommand,
    "--threads",
    settings->Threads,
    0,
    1024,
    "threads of the renderer and the reference loop (vtkSMPTools::Initialize; 0: every core, "
    "or VTK_SMP_MAX_THREADS); with more than one, the reference loop and the undeformed and "
    "deformed fish and figure are also timed on one thread, in a table of their own; on one thread "
    "the thread is kept on one core (cores may run at different speeds)");
  auto* sizes = numbers.Add(benchCommand,
    "--size",
    settings->Sizes,
    1,
    captureLimits->GetWidthMaxValue(),
    "frame widths and heights (the light-field-size and cage-size tables at 512 when listed, "
    "else at the largest)");
  benchCommand->add_flag("--quick",
    settings->Quick,
    "a quick run that checks the tables end to end: tiny light fields (24 views of 64^2), "
    "light-field sizes 12 and 24 views, cages of 1 and 3 boxes, and unless given --size 64 "
    "128 and --repeat 1 (figures not comparable with a full run)");
  benchCommand->add_option("--json",
    settings->Json,
    "also write every figure, the machine's core count and load average to FILE (format "
    "lfd-bench, see Data/README.md; replaced when complete)");
  benchCommand->add_flag("--studio",
    *studio,
    "instead: the editing view of the Studio (vtkLightFieldEditor, 800x600): ms/frame during a "
    "recorded corner drag (--repeat motions), release to full resolution, with 3 and 100 boxes");
  commands.push_back({ benchCommand,
    [settings, studio, repeat, sizes]
    {
      if (settings->Quick && repeat->count() == 0)
      {
        settings->Repeat = 1;
      }
      if (settings->Quick && sizes->count() == 0)
      {
        settings->Sizes = { 64, 128 };
      }
      if (settings->Threads > 0)
      {
        vtkSMPTools::Initialize(settings->Threads);
      }
      *studio ? StudioBench(settings->Repeat) : Bench(*settings);
    },
    true });
}
}
