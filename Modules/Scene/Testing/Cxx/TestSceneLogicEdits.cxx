// The scene logic's edits one by one (issue 9, item 1): the events each
// invokes (counted), a folding move refused and not applied, per-drag
// validation of only the boxes a move touched, one drag = one undo, the
// command names of an Edit menu, settings refused as scene.json refuses
// them, box splits that keep the deformation, the three cage builds and the
// cage at a time of the keyframes.
#include "lfdIOTestUtilities.h"
#include "lfdPartCageTestMeshes.h"
#include "lfdSceneTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDeformationCage.h"
#include "vtkIdList.h"
#include "vtkKeyframeInterpolator.h"
#include "vtkLatticeCageFilter.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <map>

using lfdtest::Check;
using lfdtest::CheckEqual;
using lfdtest::CheckFailure;
using lfdtest::EventCounter;
using lfdtest::LastError;

namespace
{
using Logic = vtkLightFieldSceneLogic;

/// An edit that must be refused (`applied` false) with an error line
/// holding every string of `mustContain`.
void CheckRefused(vtkLightFieldErrorObserver* errors,
  const std::string& name,
  bool applied,
  const std::vector<std::string>& mustContain)
{
  CheckFailure(name, !applied, LastError(errors), mustContain);
}

void TestEvents(Logic* logic)
{
  EventCounter events(logic);
  logic->MovePoint(4, 1.0, -0.05, 0.0);
  CheckEqual(events.Summary(),
    std::string("1 0 0 1 1 0"),
    "a move: cage, keyframes, settings, modified, stack, error events");
  events.Reset();
  logic->SetKeyframe(1.0);
  CheckEqual(events.Summary(), std::string("0 1 0 1 1 0"), "a keyframe's events");
  events.Reset();
  logic->SetFocalDistance(0.25);
  CheckEqual(events.Summary(), std::string("0 0 1 1 1 0"), "a setting's events");
  events.Reset();
  logic->Undo();
  logic->Undo();
  CheckEqual(events.Summary(), std::string("0 1 1 2 2 0"), "two undos' events");
  events.Reset();
  logic->Redo();
  CheckEqual(events.Summary(), std::string("0 1 0 1 1 0"), "a redo's events");
  events.Reset();
  logic->SplitBox(0, 0);
  CheckEqual(events.Summary(),
    std::string("1 1 0 1 1 0"),
    "a split (new points in the keyframe too): events");
  logic->Undo();
}

void TestRefusedFold(Logic* logic, vtkLightFieldErrorObserver* errors)
{
  EventCounter events(logic);
  const int commands = logic->GetNumberOfCommands();
  double before[3], after[3];
  logic->GetCage()->GetDeformedPoint(0, before);
  // Corner 0 of box 0 dragged past the box's opposite corner folds it.
  const bool moved = logic->MovePoint(0, 1.5, 1.5, 1.5);
  CheckRefused(errors, "a folding move", moved, { "box 0", "label 1" });
  logic->GetCage()->GetDeformedPoint(0, after);
  Check(before[0] == after[0] && before[1] == after[1] && before[2] == after[2],
    "the refused move is not applied");
  CheckEqual(logic->GetNumberOfCommands(), commands, "commands after the refused move");
  CheckEqual(events.Summary(), std::string("0 0 0 0 0 1"), "a refusal's events");
}

void TestPerDragValidation(Logic* logic)
{
  // 10 slabs along x: layer k holds points 4k..4k+3, used by boxes k - 1, k.
  CheckEqual(logic->GetCage()->GetNumberOfBoxes(), static_cast<vtkIdType>(10), "slab boxes");
  logic->MovePoint(1, 0.0, 1.05, 0.0);
  CheckEqual(logic->GetNumberOfBoxesLastValidated(),
    static_cast<vtkIdType>(1),
    "boxes validated after moving an end point");
  logic->MovePoint(21, 5.0, 1.05, 0.0);
  CheckEqual(logic->GetNumberOfBoxesLastValidated(),
    static_cast<vtkIdType>(2),
    "boxes validated after moving a shared point");
  vtkNew<vtkIdList> ids;
  vtkNew<vtkPoints> positions;
  for (vtkIdType id : { 8, 12, 16 })
  {
    double p[3];
    logic->GetCage()->GetDeformedPoint(id, p);
    ids->InsertNextId(id);
    positions->InsertNextPoint(p[0], p[1] - 0.01, p[2]);
  }
  logic->MovePoints(ids, positions);
  CheckEqual(logic->GetNumberOfBoxesLastValidated(),
    static_cast<vtkIdType>(4),
    "boxes validated after moving 3 points of layers 2-4");
  CheckEqual(logic->GetUndoName(), std::string("Move 3 points"), "undo name of a 3-point move");
  Check(logic->Validate(), "the whole cage validates");
  CheckEqual(logic->GetNumberOfBoxesLastValidated(),
    static_cast<vtkIdType>(10),
    "boxes validated by Validate()");
}

void TestDrag(Logic* logic)
{
  const int commands = logic->GetNumberOfCommands();
  double start[3], end[3];
  logic->GetCage()->GetDeformedPoint(7, start);
  logic->BeginInteraction();
  for (int step = 1; step <= 5; ++step)
  {
    logic->MovePoint(7, start[0], start[1] + 0.01 * step, start[2] + 0.01 * step);
  }
  logic->EndInteraction();
  CheckEqual(logic->GetNumberOfCommands(), commands + 1, "commands after a 5-step drag");
  CheckEqual(logic->GetUndoName(), std::string("Move 1 point"), "undo name of the drag");
  logic->Undo();
  logic->GetCage()->GetDeformedPoint(7, end);
  Check(start[0] == end[0] && start[1] == end[1] && start[2] == end[2],
    "one undo puts the dragged point back where the drag started");
  logic->Redo();
  logic->GetCage()->GetDeformedPoint(7, end);
  CheckEqual(end[2], start[2] + 0.01 * 5, "one redo replays the whole drag");
  // A second drag of the same point is a second command.
  logic->BeginInteraction();
  logic->MovePoint(7, start[0], start[1], start[2]);
  logic->EndInteraction();
  CheckEqual(logic->GetNumberOfCommands(), commands + 2, "commands after a second drag");
}

void TestNames(Logic* logic)
{
  const double bounds[6] = { 20.0, 21.0, 0.0, 1.0, 0.0, 1.0 };
  const vtkIdType box = logic->AddBox(bounds, 2);
  CheckEqual(box, static_cast<vtkIdType>(10), "index of the added box");
  CheckEqual(logic->GetUndoName(), std::string("Add box"), "undo name");
  logic->SplitBox(box, 2);
  CheckEqual(logic->GetUndoName(), std::string("Split box"), "undo name");
  logic->SetBoxLabel(box, 3);
  CheckEqual(logic->GetUndoName(), std::string("Set box label"), "undo name");
  logic->RemoveBox(box);
  CheckEqual(logic->GetUndoName(), std::string("Remove box"), "undo name");
  logic->RemoveBox(box);
  CheckEqual(logic->GetCage()->GetNumberOfPoints(),
    static_cast<vtkIdType>(44),
    "points after removing both halves: those only they used are gone");
  logic->SetKeyframe(3.0);
  CheckEqual(logic->GetUndoName(), std::string("Set keyframe"), "undo name");
  logic->RemoveKeyframe(0);
  CheckEqual(logic->GetUndoName(), std::string("Remove keyframe"), "undo name");
  logic->SetSize(320, 240);
  CheckEqual(logic->GetUndoName(), std::string("Set image size"), "undo name");
  vtkNew<vtkCamera> camera;
  camera->SetPosition(5.0, 0.5, 8.0);
  logic->SetCamera(camera);
  CheckEqual(logic->GetUndoName(), std::string("Set camera"), "undo name");
  logic->Undo();
  CheckEqual(logic->GetRedoName(), std::string("Set camera"), "redo name after an undo");
  CheckEqual(logic->GetUndoName(), std::string("Set image size"), "undo name after an undo");
  // A new edit drops the redo branch.
  logic->SetObjectThreshold(42.0);
  CheckEqual(logic->GetRedoName(), std::string(), "redo name after a new edit");
  logic->ClearUndo();
  Check(!logic->CanUndo() && !logic->CanRedo() && logic->GetUndoName().empty(),
    "ClearUndo() empties the stack");
}

void TestRefusedEdits(Logic* logic, vtkLightFieldErrorObserver* errors)
{
  CheckRefused(errors,
    "an image size above the maximum",
    logic->SetSize(20000, 10),
    { "camera.width", "16384" });
  CheckRefused(errors, "a zero image size", logic->SetSize(0, 10), { "camera.width" });
  CheckRefused(errors, "subdivision 17", logic->SetSubdivision(17), { "render.subdivision" });
  CheckRefused(errors,
    "widened search 65",
    logic->SetWidenedSearch(65),
    { "render.widened_search", "[0, 64]", "65" });
  CheckRefused(errors,
    "object threshold 300",
    logic->SetObjectThreshold(300.0),
    { "render.object_threshold", "300" });
  CheckRefused(
    errors, "background 1.5", logic->SetBackground(0.0, 1.5, 0.0), { "render.background", "1.5" });
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.0, 0.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  CheckRefused(errors,
    "a camera whose view up is its viewing direction",
    logic->SetCamera(camera),
    { "camera.view_up" });
  CheckRefused(errors, "label 256", logic->SetBoxLabel(0, 256), { "box 0", "256" });
  const double over[6] = { 0.5, 1.5, 0.2, 0.8, 0.2, 0.8 };
  CheckRefused(errors, "a box over another", logic->AddBox(over, 1) >= 0, { "overlaps" });
  CheckRefused(errors, "removing box 99", logic->RemoveBox(99), { "box 99" });
  CheckEqual(logic->GetNumberOfCommands(), 0, "commands after the refusals");
  CheckEqual(logic->GetScene()->GetWidth(), 320, "width after the refusals");
  CheckEqual(logic->GetScene()->GetSubdivision(), 1, "subdivision after the refusals");
}

void TestSplitKeepsDeformation(Logic* logic)
{
  vtkDeformationCage* cage = logic->GetCage();
  double a[3], b[3];
  cage->GetDeformedPoint(1, a); // corners 1 and 0 of box 0: its u edge
  cage->GetDeformedPoint(0, b);
  const vtkIdType points = cage->GetNumberOfPoints();
  Check(logic->SplitBox(0, 0), "split box 0 across u");
  CheckEqual(cage->GetNumberOfPoints(), points + 4, "points after a split");
  CheckEqual(cage->GetNumberOfBoxes(), static_cast<vtkIdType>(11), "boxes after a split");
  double middle[3];
  cage->GetDeformedPoint(points, middle);
  CheckEqual(middle[0], 0.5 * (a[0] + b[0]), "new point x: the edge's deformed midpoint");
  CheckEqual(middle[1], 0.5 * (a[1] + b[1]), "new point y");
  CheckEqual(cage->GetBoxLabel(10), cage->GetBoxLabel(0), "both halves keep the label");
  CheckEqual(logic->GetNumberOfBoxesLastValidated(),
    static_cast<vtkIdType>(2),
    "boxes validated after a split");
  logic->Undo();
  CheckEqual(cage->GetNumberOfPoints(), points, "points after undoing the split");
}

void TestBuildsAndTime(Logic* logic)
{
  // The fish's three parts along x give three slab boxes.
  auto mesh = lfdtest::MakeFishMesh();
  Check(logic->BuildCageFromLabels(mesh, -1), "a cage from the fish's labels");
  CheckEqual(logic->GetCage()->GetNumberOfBoxes(), static_cast<vtkIdType>(3), "boxes (3 parts)");
  CheckEqual(logic->GetScene()->GetNumberOfKeyframes(), 0, "keyframes after a build");
  CheckEqual(logic->GetUndoName(), std::string("Build cage from labels"), "undo name");
  logic->Undo();
  CheckEqual(logic->GetCage()->GetNumberOfBoxes(),
    static_cast<vtkIdType>(10),
    "boxes after undoing the build");

  vtkNew<vtkLatticeCageFilter> lattice;
  const int dimensions[3] = { 2, 2, 2 };
  lattice->SetLatticeDimensions(dimensions);
  const double up[3] = { 0.0, 0.0, 0.25 };
  lattice->SetControlPointDisplacement(1, 1, 1, up);
  Check(logic->BuildCageFromLattice(lattice), "a cage from a lattice");
  Check(logic->GetCage()->IsDeformed(), "the lattice deformed the cage");
  CheckEqual(logic->GetUndoName(), std::string("Build cage from lattice"), "undo name");
  logic->Undo();
  Check(logic->ReplaceCage(lattice->GetOutput()) && logic->GetCage()->IsDeformed(),
    "the lattice's cage given as is");
  CheckEqual(logic->GetUndoName(), std::string("Replace cage"), "undo name");
  logic->Undo();

  // Two keyframes: Catmull-Rom with clamped ends is the midpoint halfway.
  const int keyframes = logic->GetScene()->GetNumberOfKeyframes();
  Check(keyframes >= 1, "the scene has keyframes");
  double rest[3];
  logic->GetCage()->GetRestPoint(41, rest);
  logic->RemoveKeyframe(0);
  logic->MovePoint(41, rest);
  logic->SetKeyframe(0.0);
  logic->MovePoint(41, rest[0], rest[1] + 0.2, rest[2]);
  logic->SetKeyframe(2.0);
  vtkNew<vtkDeformationCage> atTime;
  Check(logic->GetCageAtTime(1.0, nullptr, atTime), "the cage at time 1");
  double p[3];
  atTime->GetDeformedPoint(41, p);
  // The interpolated points are single precision, as the CLI's animation
  // frames always were.
  lfdtest::CheckRange(
    p[1], rest[1] + 0.1 - 1e-6, rest[1] + 0.1 + 1e-6, "point 41 halfway between its keyframes");

  // A quarter of the way: the Catmull-Rom Hermite weights (clamped ends)
  // give 0.203125 of the move, linear interpolation 0.25.
  Check(logic->GetCageAtTime(0.5, nullptr, atTime), "the cage at time 0.5");
  atTime->GetDeformedPoint(41, p);
  lfdtest::CheckRange(p[1] - rest[1], 0.040625 - 1e-6, 0.040625 + 1e-6, "Catmull-Rom at 0.5");
  Check(logic->SetInterpolation(vtkKeyframeInterpolator::LINEAR), "set linear interpolation");
  Check(logic->GetCageAtTime(0.5, nullptr, atTime), "the linear cage at time 0.5");
  atTime->GetDeformedPoint(41, p);
  lfdtest::CheckRange(p[1] - rest[1], 0.05 - 1e-6, 0.05 + 1e-6, "linear at 0.5");
  // The interpolation is the scene's, one undoable command.
  CheckEqual(logic->GetScene()->GetInterpolation(),
    static_cast<int>(vtkLightFieldScene::INTERPOLATION_LINEAR),
    "the scene's interpolation");
  CheckEqual(logic->GetUndoName(), std::string("Set interpolation"), "undo name");
  Check(logic->Undo(), "undo the interpolation");
  CheckEqual(logic->GetInterpolation(),
    static_cast<int>(vtkKeyframeInterpolator::CATMULL_ROM),
    "interpolation after undo");
  Check(!logic->SetInterpolation(2), "interpolation 2 is refused");
  CheckEqual(logic->GetInterpolation(),
    static_cast<int>(vtkKeyframeInterpolator::CATMULL_ROM),
    "interpolation after a refused edit");
}
}

int TestSceneLogicEdits(int, char*[])
{
  vtkNew<Logic> logic;
  vtkNew<vtkLightFieldErrorObserver> errors;
  errors->Observe(logic);
  const double bounds[6] = { 0.0, 10.0, 0.0, 1.0, 0.0, 1.0 };
  Check(logic->BuildCageFromSlabs(bounds, 10, 0, 1), "10 slabs along x");
  CheckEqual(logic->GetCage()->GetNumberOfPoints(), static_cast<vtkIdType>(44), "slab points");
  CheckEqual(logic->GetUndoName(), std::string("Build cage from slabs"), "undo name");
  logic->ClearUndo();

  TestEvents(logic);
  TestRefusedFold(logic, errors);
  TestPerDragValidation(logic);
  TestDrag(logic);
  TestNames(logic);
  TestRefusedEdits(logic, errors);
  TestSplitKeepsDeformation(logic);
  TestBuildsAndTime(logic);

  vtkNew<Logic> empty;
  vtkNew<vtkLightFieldErrorObserver> loadErrors;
  loadErrors->Observe(empty);
  loadErrors->Observe(empty->GetScene());
  CheckRefused(loadErrors,
    "loading a missing scene",
    empty->Load("/nonexistent/scene.json"),
    { "/nonexistent/scene.json" });
  return lfdtest::Result();
}
