// vtkLightFieldEditor (issue 10, items 2 and 3): the fish's light field and
// its 3 part boxes in the editor's own window, edited with recorded events.
// A drag of a corner shared by two boxes is exactly one command of the scene
// logic and puts the point under the cursor; the mapper renders coarse frames
// during the drag and a full-resolution one on release; Ctrl+Z / Ctrl+Shift+Z
// and the logic's Undo() move the handles; undo restores the points and the
// saved scene byte for byte; a folding drag is refused (the cage stays valid,
// the handles on it, the logic's message in the status line); the timeline
// shows and edits poses between keyframes; and the window matches a baseline.
#include "lfdIOTestUtilities.h"

#include "vtkCageRepresentation.h"
#include "vtkCageWidget.h"
#include "vtkCamera.h"
#include "vtkDeformationCage.h"
#include "vtkInteractorEventRecorder.h"
#include "vtkLightField.h"
#include "vtkLightFieldCapture.h"
#include "vtkLightFieldEditor.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkProceduralObjectSource.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using lfdtest::Check;
using lfdtest::CheckEqual;

namespace
{
/// The part cage's corners on the front face, shared by two boxes each:
/// the top one between the tail and body boxes and the next one along.
constexpr vtkIdType TopCorner = 11;
constexpr vtkIdType TailCorner = 7;

/// One recorded event line (stream version 1: ctrl shift keycode repeat keysym).
std::string Event(const char* name,
  int x,
  int y,
  int ctrl = 0,
  int shift = 0,
  int keycode = 0,
  const char* keysym = "0")
{
  std::ostringstream line;
  line << name << " " << x << " " << y << " " << ctrl << " " << shift << " " << keycode << " 0 "
       << keysym << "\n";
  return line.str();
}

void Play(vtkInteractorEventRecorder* recorder, const std::string& events)
{
  recorder->SetInputString(events.c_str());
  recorder->Play();
}

/// Display position (x, y, z) of a world point in the renderer.
void ToDisplay(vtkRenderer* renderer, const double p[3], double display[3])
{
  renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
}

/// The cage's points, to compare exactly.
std::vector<double> Points(vtkDeformationCage* cage)
{
  std::vector<double> points(3 * cage->GetNumberOfPoints());
  for (vtkIdType id = 0; id < cage->GetNumberOfPoints(); ++id)
  {
    cage->GetPoint(id, &points[3 * id]);
  }
  return points;
}

/// Whether every handle sits exactly on `cage`'s point.
bool HandlesOn(vtkLightFieldEditor* editor, vtkDeformationCage* cage)
{
  vtkCageRepresentation* rep = editor->GetWidget()->GetCageRepresentation();
  for (vtkIdType id = 0; id < cage->GetNumberOfPoints(); ++id)
  {
    double handle[3], point[3];
    cage->GetPoint(id, point);
    if (!rep->GetHandlePosition(id, handle) || handle[0] != point[0] || handle[1] != point[1] ||
      handle[2] != point[2])
    {
      return false;
    }
  }
  return true;
}

std::string Size(const int* size)
{
  return std::to_string(size[0]) + "x" + std::to_string(size[1]);
}

/// A drag from (x0, y0) to (x1, y1) in `steps` motions; the release only with `release`.
std::string Drag(int x0, int y0, int x1, int y1, int steps, bool release)
{
  std::string events = Event("MouseMoveEvent", x0, y0) + Event("LeftButtonPressEvent", x0, y0);
  for (int k = 1; k <= steps; ++k)
  {
    events += Event("MouseMoveEvent", x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps);
  }
  return release ? events + Event("LeftButtonReleaseEvent", x1, y1) : events;
}

/// 4. The timeline: keys at 0 (rest) and 1 (the top corner raised); the pose
/// at 0.5 is shown without being edited, then edited.
void CheckTimeline(vtkLightFieldEditor* editor, const std::vector<double>& rest)
{
  vtkLightFieldSceneLogic* logic = editor->GetLogic();
  vtkDeformationCage* cage = logic->GetCage();
  Check(logic->SetKeyframe(0.0), "key at 0");
  Check(logic->MovePoint(TopCorner, rest[33], rest[34] + 0.1, rest[35]), "raise the corner");
  Check(logic->SetKeyframe(1.0), "key at 1");
  vtkNew<vtkDeformationCage> pose;
  Check(logic->GetCageAtTime(0.5, nullptr, pose), "the pose at 0.5");
  Check(editor->ShowTime(0.5) && editor->GetShowingTime(), "the editor shows time 0.5");
  Check(HandlesOn(editor, pose) && !HandlesOn(editor, cage), "the handles show the pose");
  Check(!editor->GetWidget()->GetProcessEvents(), "a shown time is not edited");
  const int keyed = logic->GetNumberOfCommands();
  Check(editor->EditAtTime(0.5) && !editor->GetShowingTime(), "edit at time 0.5");
  Check(Points(cage) == Points(pose), "the current cage is the pose");
  CheckEqual(logic->GetNumberOfCommands(), keyed + 1, "in one command");
  Check(HandlesOn(editor, cage) && editor->GetWidget()->GetProcessEvents(), "and is edited");
}
}

int TestLightFieldEditor(int argc, char* argv[])
{
  // A small capture of the fish (one ring) and its 3 part boxes, as the demo has.
  vtkNew<vtkProceduralObjectSource> fish;
  fish->SetObjectToFish();
  vtkNew<vtkLightFieldCapture> capture;
  capture->SetInputConnection(fish->GetOutputPort());
  capture->SetNumberOfRows(1);
  capture->SetViewsPerRing(60);
  capture->SetWidth(128);
  capture->SetHeight(128);
  capture->CaptureDepthOff();
  capture->Update();
  vtkNew<vtkLightFieldSceneLogic> logic;
  logic->SetLightField(capture->GetOutput());
  Check(logic->BuildCageFromLabels(fish->GetOutput(), -1), "the fish's part cage is built");
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.6, 0.05, 3.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(30.0);
  logic->SetCamera(camera);
  logic->SetBackground(0.1, 0.1, 0.2);
  logic->ClearUndo();
  const std::string folder = lfdtest::ScratchFolder("TestLightFieldEditor");
  const std::string scene = folder + "/scene.json";
  Check(logic->Save(scene.c_str()), "the scene saves");
  const std::string saved = lfdtest::ReadText(scene);
  vtkDeformationCage* cage = logic->GetCage();
  const std::vector<double> rest = Points(cage);
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(logic);

  vtkNew<vtkLightFieldEditor> editor;
  editor->SetLogic(logic);
  Check(editor->Initialize(), "the editor shows the scene");
  vtkRenderWindow* window = editor->GetRenderWindow();
  vtkRenderer* renderer = editor->GetRenderer();
  CheckEqual(std::string(window->GetWindowName()), std::string("LightField Editor"), "own window");
  window->SetSize(400, 300);
  editor->Render();
  vtkLightFieldMapper* mapper = editor->GetMapper();
  // Coarse frames of exactly 1/4 whatever the machine's load (the adaptive
  // subsampling has its own test, TestLightFieldMapper.py).
  Check(mapper->GetAdaptiveSubsampling(), "the editor subsamples adaptively");
  mapper->AdaptiveSubsamplingOff();
  CheckEqual(Size(mapper->GetLastImageSize()), std::string("400x300"), "first frame: full size");
  vtkNew<vtkInteractorEventRecorder> recorder;
  recorder->SetInteractor(editor->GetInteractor());
  recorder->ReadFromInputStringOn();

  // 1. Drag the shared top corner 24 pixels up: coarse frames while dragging.
  double start[3];
  ToDisplay(renderer, &rest[3 * TopCorner], start);
  const int x0 = static_cast<int>(std::lround(start[0]));
  const int y0 = static_cast<int>(std::lround(start[1]));
  Play(recorder, Drag(x0, y0, x0, y0 + 24, 4, false));
  Check(editor->GetInteracting(), "a drag is under way");
  CheckEqual(
    Size(mapper->GetLastImageSize()), std::string("100x75"), "coarse frame while dragging");
  Check(std::string(editor->GetFrameTimeActor()->GetInput()).find("ms/frame") != std::string::npos,
    std::string("the frame time is shown: ") + editor->GetFrameTimeActor()->GetInput());
  Check(std::string(editor->GetFrameTimeActor()->GetInput()).find("coarse") != std::string::npos,
    "and says coarse");
  Play(recorder, Event("LeftButtonReleaseEvent", x0, y0 + 24));
  Check(!editor->GetInteracting(), "the drag ended");
  CheckEqual(Size(mapper->GetLastImageSize()), std::string("400x300"), "full frame on release");
  Check(std::string(editor->GetFrameTimeActor()->GetInput()).find("full") != std::string::npos,
    std::string("the frame time says full: ") + editor->GetFrameTimeActor()->GetInput());
  CheckEqual(logic->GetNumberOfCommands(), 1, "one drag, one command");
  CheckEqual(logic->GetUndoName(), std::string("Move 1 point"), "the command");
  CheckEqual(logic->GetNumberOfBoxesLastValidated(), vtkIdType(2), "the two boxes re-checked");
  const std::vector<double> dragged = Points(cage);
  double end[3];
  ToDisplay(renderer, &dragged[3 * TopCorner], end);
  Check(std::abs(end[0] - x0) < 0.5 && std::abs(end[1] - (y0 + 24)) < 0.5 &&
      std::abs(end[2] - start[2]) < 1e-9,
    "the corner is under the cursor, at its depth: display " + std::to_string(end[0]) + " " +
      std::to_string(end[1]) + " (cursor " + std::to_string(x0) + " " + std::to_string(y0 + 24) +
      ")");
  bool othersStay = true;
  for (vtkIdType id = 0; id < cage->GetNumberOfPoints(); ++id)
  {
    for (int a = 0; a < 3 && id != TopCorner; ++a)
    {
      othersStay = othersStay && dragged[3 * id + a] == rest[3 * id + a];
    }
  }
  Check(othersStay, "no other point moved");
  Check(HandlesOn(editor, cage), "the handles are on the logic's cage");

  // The window after the drag (the frame time varies: hidden for the image).
  editor->GetFrameTimeActor()->VisibilityOff();
  editor->Render();
  const int image = vtkRegressionTestImage(window);
  editor->GetFrameTimeActor()->VisibilityOn();

  // 2. Ctrl+Z in the window undoes the drag byte for byte; Ctrl+Shift+Z redoes it.
  Play(recorder, Event("KeyPressEvent", 10, 10, 1, 0, 26, "z"));
  Check(Points(cage) == rest, "Ctrl+Z: the points are back, exactly");
  Check(HandlesOn(editor, cage), "and so are the handles");
  Check(logic->Save(scene.c_str()) && lfdtest::ReadText(scene) == saved,
    "the undone scene saves byte for byte as before");
  Play(recorder, Event("KeyPressEvent", 10, 10, 1, 1, 26, "Z"));
  Check(Points(cage) == dragged, "Ctrl+Shift+Z: the drag again");
  Check(HandlesOn(editor, cage), "the handles follow the redo");
  Check(logic->Undo() && Points(cage) == rest && HandlesOn(editor, cage),
    "the logic's Undo() moves the handles");

  // 3. Dragging the tail-body corner past the next corner along folds the
  // body box: refused at that step, the corner stays at its last valid
  // position, the logic's message in the status line.
  double tail[3], next[3];
  ToDisplay(renderer, &rest[3 * TailCorner], tail);
  ToDisplay(renderer, &rest[3 * TopCorner], next);
  const int tx = static_cast<int>(std::lround(tail[0]));
  const int ty = static_cast<int>(std::lround(tail[1]));
  const int fx = static_cast<int>(std::lround(next[0] + 0.6 * (next[0] - tail[0])));
  const int undoIndex = logic->GetUndoIndex();
  errors->Clear();
  Play(recorder, Drag(tx, ty, fx, ty, 8, false));
  Check(
    errors->HasError() && std::string(errors->GetErrorMessage()).find("folds") != std::string::npos,
    std::string("the folding move is refused: ") + errors->GetErrorMessage());
  CheckEqual(std::string(editor->GetStatusActor()->GetInput()),
    std::string(errors->GetError(errors->GetNumberOfErrors() - 1)),
    "the status line says why (the last refusal)");
  Check(HandlesOn(editor, cage), "the handles stay on the logic's cage");
  Play(recorder, Event("LeftButtonReleaseEvent", fx, ty));
  Check(logic->Validate(), "the cage is valid");
  double moved[3];
  cage->GetPoint(TailCorner, moved);
  Check(moved[0] > rest[3 * TailCorner] && moved[0] < rest[3 * TopCorner],
    "the corner moved right, short of the next corner: x " + std::to_string(moved[0]));
  CheckEqual(logic->GetUndoIndex(), undoIndex + 1, "the valid part of the drag: one command");
  CheckEqual(logic->GetUndoName(), std::string("Move 1 point"), "a move");
  Check(HandlesOn(editor, cage), "the handles match the logic's cage");
  Check(logic->Undo() && Points(cage) == rest, "and its undo restores the rest");

  CheckTimeline(editor, rest);

  Check(image == vtkTesting::PASSED || image == vtkTesting::DO_INTERACTOR,
    "the editor's window matches the baseline");
  if (image == vtkTesting::DO_INTERACTOR)
  {
    editor->Start();
  }
  return lfdtest::Result();
}
