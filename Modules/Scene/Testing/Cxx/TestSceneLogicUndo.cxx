// The scene logic's undo/redo stack (issue 9, item 1): 100 random edits of
// every kind (moves, add/remove/split box, labels, keyframes, settings,
// camera) then 100 undos restore the scene byte for byte on save; redoing
// all of them gives the edited scene byte for byte; each undo and redo
// invokes one UndoStackModifiedEvent and the event of what it changed.
#include "lfdIOTestUtilities.h"
#include "lfdSceneTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDeformationCage.h"
#include "vtkIdList.h"
#include "vtkLightFieldErrorObserver.h"
#include "vtkLightFieldScene.h"
#include "vtkLightFieldSceneLogic.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <map>
#include <random>

using lfdtest::Check;
using lfdtest::CheckEqual;
using lfdtest::EventCounter;

namespace
{
/// One random edit; returns whether the logic applied it.
bool RandomEdit(vtkLightFieldSceneLogic* logic, std::mt19937& random, int& added)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkDeformationCage* cage = logic->GetCage();
  const vtkIdType boxes = cage->GetNumberOfBoxes();
  const auto pick = [&random](vtkIdType count)
  { return std::uniform_int_distribution<vtkIdType>(0, count - 1)(random); };
  switch (std::uniform_int_distribution<int>(0, 13)(random))
  {
    case 0:
    case 1:
    case 2:
    {
      // Up to 3 points, moved by under 1% of the smallest box (no fold).
      vtkNew<vtkIdList> ids;
      vtkNew<vtkPoints> positions;
      const int count = std::uniform_int_distribution<int>(1, 3)(random);
      for (int i = 0; i < count; ++i)
      {
        const vtkIdType id = pick(cage->GetNumberOfPoints());
        if (ids->IsId(id) < 0)
        {
          double p[3];
          cage->GetDeformedPoint(id, p);
          ids->InsertNextId(id);
          positions->InsertNextPoint(p[0] + 0.002 * (unit(random) - 0.5),
            p[1] + 0.002 * (unit(random) - 0.5),
            p[2] + 0.002 * (unit(random) - 0.5));
        }
      }
      return logic->MovePoints(ids, positions);
    }
    case 3:
    {
      // Away from the others: no rest overlap.
      const double x = 10.0 + 2.0 * added++;
      const double bounds[6] = { x, x + 1.0 + unit(random), 0.0, 1.0, 0.0, 0.5 + unit(random) };
      return logic->AddBox(bounds, 1 + static_cast<int>(pick(3))) >= 0;
    }
    case 4:
      return boxes > 2 && logic->RemoveBox(pick(boxes));
    case 5:
      return boxes < 40 && logic->SplitBox(pick(boxes), static_cast<int>(pick(3)));
    case 6:
      return logic->SetBoxLabel(pick(boxes), 1 + static_cast<int>(pick(5)));
    case 7:
      return logic->SetKeyframe(static_cast<double>(pick(4)));
    case 8:
    {
      const int keyframes = logic->GetScene()->GetNumberOfKeyframes();
      return keyframes > 0 && logic->RemoveKeyframe(static_cast<int>(pick(keyframes)));
    }
    case 9:
      return logic->SetSize(64 + static_cast<int>(pick(512)), 64 + static_cast<int>(pick(512)));
    case 10:
      return logic->SetFocalDistance(unit(random) / 3.0);
    case 11:
      return logic->SetSubdivision(static_cast<int>(pick(5))) &&
        logic->SetWidenedSearch(static_cast<int>(pick(8)));
    case 12:
      return logic->SetObjectThreshold(255.0 * unit(random)) &&
        logic->SetBackground(unit(random), unit(random), unit(random));
    default:
    {
      vtkNew<vtkCamera> camera;
      camera->SetPosition(unit(random) + 1.5, 2.0 * unit(random) + 3.0, 7.0 + unit(random) / 7.0);
      camera->SetFocalPoint(1.5, 0.5, 0.5);
      camera->SetViewUp(0.1 * unit(random), 1.0, 0.0);
      camera->SetViewAngle(20.0 + 20.0 * unit(random));
      return logic->SetCamera(camera);
    }
  }
}
}

int TestSceneLogicUndo(int, char*[])
{
  const std::string folder = lfdtest::ScratchFolder("TestSceneLogicUndo");
  const std::string file = folder + "/scene.json";

  vtkNew<vtkLightFieldSceneLogic> logic;
  const double bounds[6] = { 0.0, 3.0, 0.0, 1.0, 0.0, 1.0 };
  Check(logic->BuildCageFromSlabs(bounds, 3, 0, 1), "a cage of 3 slabs along x");
  logic->GetScene()->SetLightFieldPath("fish.lf");
  Check(logic->SetKeyframe(0.0) && logic->MovePoint(13, 3.1, 1.0, 0.0) && logic->SetKeyframe(2.0),
    "two keyframes");
  logic->ClearUndo();
  Check(logic->Save(file.c_str()), "the scene saves");
  const std::string original = lfdtest::ReadText(file);
  Check(logic->Load(file.c_str()), "the scene loads");

  // Single edits grouped in pairs (case 11, 12) count as two commands.
  std::mt19937 random(9);
  int added = 0, attempts = 0;
  vtkNew<vtkLightFieldErrorObserver> refusals;
  refusals->Observe(logic);
  while (logic->GetNumberOfCommands() < 100 && attempts < 1000)
  {
    ++attempts;
    RandomEdit(logic, random, added);
  }
  // A pair may end at 101: the 100 are counted from the stack.
  const int edits = logic->GetNumberOfCommands();
  Check(edits >= 100 && edits <= 101, "100 random edits on the stack: " + std::to_string(edits));
  CheckEqual(refusals->GetNumberOfErrors(), 0, "edits refused");
  Check(logic->Save(file.c_str()), "the edited scene saves");
  const std::string edited = lfdtest::ReadText(file);
  Check(edited != original, "the edits changed the scene file");

  EventCounter events(logic);
  int undone = 0;
  while (logic->Undo())
  {
    ++undone;
  }
  CheckEqual(undone, edits, "undos");
  CheckEqual(events[vtkLightFieldSceneLogic::UndoStackModifiedEvent],
    edits,
    "UndoStackModifiedEvents of the undos");
  CheckEqual(events[vtkCommand::ModifiedEvent] >= edits, true, "ModifiedEvents of the undos");
  Check(!logic->CanUndo() && logic->CanRedo(), "nothing left to undo, all to redo");
  Check(logic->Save(file.c_str()), "the undone scene saves");
  Check(lfdtest::ReadText(file) == original, "undoing every edit restores the file byte for byte");

  int redone = 0;
  while (logic->Redo())
  {
    ++redone;
  }
  CheckEqual(redone, edits, "redos");
  CheckEqual(events[vtkLightFieldSceneLogic::UndoStackModifiedEvent],
    2 * edits,
    "UndoStackModifiedEvents of the undos and redos");
  const int changes = events[vtkLightFieldSceneLogic::CageModifiedEvent] +
    events[vtkLightFieldSceneLogic::KeyframesModifiedEvent] +
    events[vtkLightFieldSceneLogic::SettingsModifiedEvent];
  Check(
    changes >= 2 * edits, "each undo and redo says what it changed: " + std::to_string(changes));
  Check(logic->Save(file.c_str()), "the redone scene saves");
  Check(
    lfdtest::ReadText(file) == edited, "redoing every edit gives the edited file byte for byte");
  return lfdtest::Result();
}
