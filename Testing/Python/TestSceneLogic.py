"""The scene logic from Python (issue 9, item 1), as the Studio will drive it:
a cage built from the fish's labels, a 10-step drag that is one undoable
command, the events an observer sees (counted), a folding move refused with
a message naming the box, a label the light field does not hold refused,
and undo back to the saved scene byte for byte."""
import os

import lfdtesting as t
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand

import lfd

Logic = lfd.vtkLightFieldSceneLogic
logic = Logic()
counts = {}
errors = []


def counter(event):
    """An observer of `event`: Python passes user events to it by name,
    the same name ("NoEvent") for all of them."""
    def count(caller, name):
        counts[event] = counts.get(event, 0) + 1
    return count


for event in (Logic.CageModifiedEvent, Logic.KeyframesModifiedEvent, Logic.SettingsModifiedEvent,
              Logic.UndoStackModifiedEvent):
    logic.AddObserver(event, counter(event))


@calldata_type(VTK_STRING)
def record_error(caller, event, text):
    errors.append(text)


logic.AddObserver(vtkCommand.ErrorEvent, record_error)

fish = lfd.vtkProceduralObjectSource()
fish.SetObjectToFish()
fish.Update()
t.check(logic.BuildCageFromLabels(fish.GetOutput(), -1), "a cage from the fish's labels", errors)
cage = logic.GetCage()
t.check(cage.GetNumberOfBoxes() == 3, "boxes (head, body, tail)", cage.GetNumberOfBoxes())
t.check(logic.GetUndoName() == "Build cage from labels", "undo name", logic.GetUndoName())

capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(fish.GetOutputPort())
capture.SetViewsPerRing(12)
capture.SetNumberOfRows(1)
capture.SetWidth(48)
capture.SetHeight(48)
capture.Update()
logic.SetLightField(capture.GetOutput())
t.check(logic.Validate(), "the cage fits the captured light field", errors)

scene_file = os.path.join(t.TEMP_DIR, "TestSceneLogic.json")
logic.ClearUndo()
t.check(logic.Save(scene_file), "the scene saves", errors)
with open(scene_file, "rb") as f:
    saved = f.read()

counts.clear()
corner = [0.0, 0.0, 0.0]
cage.GetDeformedPoint(2, corner)
logic.BeginInteraction()
for step in range(1, 11):
    logic.MovePoint(2, corner[0], corner[1] + 0.004 * step, corner[2])
logic.EndInteraction()
t.check(logic.GetNumberOfCommands() == 1, "a 10-step drag is one command", logic.GetNumberOfCommands())
t.check(logic.GetUndoName() == "Move 1 point", "its undo name", logic.GetUndoName())
t.check(counts.get(Logic.CageModifiedEvent) == 10 and counts.get(Logic.UndoStackModifiedEvent) == 1,
        "events of the drag: 10 cage modified, 1 undo stack modified", counts)
t.check(logic.GetNumberOfBoxesLastValidated() == 1, "boxes validated per drag step (point 2 is the "
        "first box's only)", logic.GetNumberOfBoxesLastValidated())

# Corner 2 of the first box dragged past its opposite corner (4) folds it.
near, far = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
cage.GetDeformedPoint(2, near)
cage.GetDeformedPoint(4, far)
refused = not logic.MovePoint(2, *[f + 0.1 * (f - n) for n, f in zip(near, far)])
t.check(refused and len(errors) == 1 and "box 0" in errors[0], "a folding move is refused", errors)
t.check(logic.GetNumberOfCommands() == 1, "and not applied", logic.GetNumberOfCommands())

t.check(not logic.SetBoxLabel(1, 7) and len(errors) == 2 and "7" in errors[-1],
        "a label the light field does not hold is refused", errors[-1:])

t.check(logic.SetFocalDistance(0.05) and logic.GetUndoName() == "Set focal distance",
        "a setting is a command", logic.GetUndoName())
while logic.Undo():
    pass
t.check(logic.Save(scene_file), "the undone scene saves", errors[2:])
with open(scene_file, "rb") as f:
    t.check(f.read() == saved, "undo restores the saved scene byte for byte", len(saved))

loaded = Logic()
t.check(loaded.Load(scene_file) and loaded.GetCage().GetNumberOfBoxes() == 3,
        "the saved scene loads with its 3 boxes", loaded.GetCage().GetNumberOfBoxes())
t.finish()
