// What the cage widget's tests share: cages of boxes on a grid, a render
// window with the widget, display positions of cage points, recorded events
// and point checks.
#ifndef lfdCageWidgetTestUtilities_h
#define lfdCageWidgetTestUtilities_h

#include "lfdTestChecks.h"
#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDeformationCage.h"
#include "vtkIdList.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

namespace lfdtest
{
/// A cage of nx x ny x nz unit boxes from `origin`, corners shared, at rest,
/// box (i, j, k) labelled 1 + (i + j + k) % 3.
inline void MakeGridCage(vtkDeformationCage* cage,
  int nx,
  int ny,
  int nz,
  const double origin[3] = nullptr,
  double size = 1.0)
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double* o = origin ? origin : zero;
  cage->Initialize();
  auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        const double p[3] = { o[0] + size * i, o[1] + size * j, o[2] + size * k };
        cage->AddPoint(p);
      }
    }
  }
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const vtkIdType c[8] = { index(i, j, k),
          index(i + 1, j, k),
          index(i + 1, j + 1, k),
          index(i, j + 1, k),
          index(i, j, k + 1),
          index(i + 1, j, k + 1),
          index(i + 1, j + 1, k + 1),
          index(i, j + 1, k + 1) };
        cage->AddBox(c, 1 + (i + j + k) % 3);
      }
    }
  }
}

/// Appends an axis-aligned box from `lo` to `hi` with 8 new points.
inline void AddBoxAt(vtkDeformationCage* cage, const double lo[3], const double hi[3], int label)
{
  vtkIdType c[8];
  for (int k = 0; k < 8; ++k)
  {
    // VTK hexahedron order: bottom face counter-clockwise, then the top.
    const int i = (k % 4 == 1 || k % 4 == 2) ? 1 : 0;
    const int j = (k % 4 >= 2) ? 1 : 0;
    const double p[3] = { i ? hi[0] : lo[0], j ? hi[1] : lo[1], k >= 4 ? hi[2] : lo[2] };
    c[k] = cage->AddPoint(p);
  }
  cage->AddBox(c, label);
}

/// A 400 x 400 window with a cage widget (enabled) on `cage`, a trackball
/// style and a camera at `position` looking at `focal`.
struct WidgetScene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkInteractorStyleTrackballCamera> Style;
  vtkNew<vtkCageWidget> Widget;
  vtkNew<vtkInteractorEventRecorder> Recorder;
  vtkCageRepresentation* Representation = nullptr;

  WidgetScene(vtkDeformationCage* cage,
    const double focal[3],
    const double position[3],
    const double viewUp[3],
    bool parallel = false,
    double parallelScale = 1.0)
  {
    this->Window->SetSize(400, 400);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Interactor->SetRenderWindow(this->Window);
    this->Interactor->SetInteractorStyle(this->Style);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetFocalPoint(focal[0], focal[1], focal[2]);
    camera->SetPosition(position[0], position[1], position[2]);
    camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(parallelScale);
    camera->SetViewAngle(30.0);
    this->Renderer->ResetCameraClippingRange(-10.0, 10.0, -10.0, 10.0, -10.0, 10.0);
    this->Widget->SetInteractor(this->Interactor);
    this->Widget->CreateDefaultRepresentation();
    this->Representation = this->Widget->GetCageRepresentation();
    this->Representation->SetCage(cage);
    this->Widget->SetCurrentRenderer(this->Renderer);
    this->Widget->On();
    this->Interactor->Initialize();
    this->Window->Render();
    this->Recorder->SetInteractor(this->Interactor);
    this->Recorder->ReadFromInputStringOn();
  }

  /// Display position (x, y, z-buffer depth) of a world point.
  void ToDisplay(const double world[3], double display[3])
  {
    this->Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    this->Renderer->WorldToDisplay();
    this->Renderer->GetDisplayPoint(display);
  }

  /// World point at display (x, y) on the plane parallel to the view through
  /// `through`.
  void ToWorld(double x, double y, const double through[3], double world[3])
  {
    double d[3];
    this->ToDisplay(through, d);
    this->Renderer->SetDisplayPoint(x, y, d[2]);
    this->Renderer->DisplayToWorld();
    const double* w = this->Renderer->GetWorldPoint();
    for (int c = 0; c < 3; ++c)
    {
      world[c] = w[c] / w[3];
    }
  }

  /// Plays recorded events (lines "Event x y ctrl shift keycode repeat keysym").
  void Play(const std::string& events)
  {
    this->Recorder->SetInputString(events.c_str());
    this->Recorder->Play();
  }
};

/// A recorded left-button drag from (x0, y0) to (x1, y1) in `steps` moves,
/// shift held when `shift`.
inline std::string Drag(int x0, int y0, int x1, int y1, int steps = 5, bool shift = false)
{
  std::ostringstream s;
  const int sh = shift ? 1 : 0;
  s << "MouseMoveEvent " << x0 << " " << y0 << " 0 " << sh << " 0 0 0\n";
  s << "LeftButtonPressEvent " << x0 << " " << y0 << " 0 " << sh << " 0 0 0\n";
  for (int k = 1; k <= steps; ++k)
  {
    s << "MouseMoveEvent " << x0 + (x1 - x0) * k / steps << " " << y0 + (y1 - y0) * k / steps
      << " 0 " << sh << " 0 0 0\n";
  }
  s << "LeftButtonReleaseEvent " << x1 << " " << y1 << " 0 " << sh << " 0 0 0\n";
  return s.str();
}

/// A recorded key (CharEvent, the one the widget acts on) at (x, y).
inline std::string Key(char key, int x, int y, bool shift = false)
{
  std::ostringstream s;
  s << "KeyPressEvent " << x << " " << y << " 0 " << (shift ? 1 : 0) << " " << static_cast<int>(key)
    << " 1 " << key << "\n";
  s << "CharEvent " << x << " " << y << " 0 " << (shift ? 1 : 0) << " " << static_cast<int>(key)
    << " 1 " << key << "\n";
  return s.str();
}

/// A left click at (x, y).
inline std::string Click(int x, int y, bool shift = false)
{
  return Drag(x, y, x, y, 0, shift);
}

/// Checks a cage point against `expected`, printing both; false on a
/// difference above `tolerance`.
inline bool CheckPoint(vtkDeformationCage* cage,
  vtkIdType id,
  const double expected[3],
  double tolerance,
  const char* what)
{
  double p[3];
  cage->GetDeformedPoint(id, p);
  const double error = std::sqrt((p[0] - expected[0]) * (p[0] - expected[0]) +
    (p[1] - expected[1]) * (p[1] - expected[1]) + (p[2] - expected[2]) * (p[2] - expected[2]));
  if (!(error <= tolerance))
  {
    std::cerr << what << ": point " << id << " is (" << p[0] << ", " << p[1] << ", " << p[2]
              << "), expected (" << expected[0] << ", " << expected[1] << ", " << expected[2]
              << "), error " << error << " > " << tolerance << "\n";
    return false;
  }
  return true;
}

/// The selected point ids as "a b c" (sorted), for one comparison.
inline std::string SelectedIds(vtkCageRepresentation* rep)
{
  vtkNew<vtkIdList> ids;
  rep->GetSelectedPointIds(ids);
  std::string s;
  for (vtkIdType i = 0; i < ids->GetNumberOfIds(); ++i)
  {
    s += (i ? " " : "") + std::to_string(ids->GetId(i));
  }
  return s;
}

/// Counts the interaction events an object invokes (start, interaction,
/// end); stops observing when destroyed.
class InteractionCounter
{
public:
  explicit InteractionCounter(vtkObject* object)
    : Observed(object)
  {
    this->Callback->SetClientData(this->Counts);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long event, void* counts, void*)
      {
        const int slot = event == vtkCommand::StartInteractionEvent ? 0
          : event == vtkCommand::InteractionEvent                   ? 1
                                                                    : 2;
        ++static_cast<int*>(counts)[slot];
      });
    for (unsigned long event : { vtkCommand::StartInteractionEvent,
           vtkCommand::InteractionEvent,
           vtkCommand::EndInteractionEvent })
    {
      object->AddObserver(event, this->Callback);
    }
  }
  ~InteractionCounter() { this->Observed->RemoveObserver(this->Callback); }
  InteractionCounter(const InteractionCounter&) = delete;
  void operator=(const InteractionCounter&) = delete;

  /// "start interaction end".
  std::string Summary() const
  {
    return std::to_string(this->Counts[0]) + " " + std::to_string(this->Counts[1]) + " " +
      std::to_string(this->Counts[2]);
  }
  void Reset() { std::fill(this->Counts, this->Counts + 3, 0); }

private:
  int Counts[3] = { 0, 0, 0 };
  vtkNew<vtkCallbackCommand> Callback;
  vtkObject* Observed;
};
}

#endif
