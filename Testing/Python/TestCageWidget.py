"""The cage widget's representation from Python (issue 10, item 1), wired to
the scene logic as an editor wires it: ApplyToCage off, each edit pushed to
vtkLightFieldSceneLogic.MovePoints between BeginInteraction and
EndInteraction (one edit = one undoable command), a refused edit puts the
handles back; then the standalone mode on a plain cage (bend, mirror,
reset)."""
import lfdtesting as t
from vtkmodules.vtkCommonCore import vtkCommand, vtkIdList, vtkPoints

import lfd

Rep = lfd.vtkCageRepresentation
logic = lfd.vtkLightFieldSceneLogic()
errors = t.error_observer(logic)
fish = lfd.vtkProceduralObjectSource()
fish.SetObjectToFish()
fish.Update()
t.check(logic.BuildCageFromLabels(fish.GetOutput(), -1), "a cage from the fish's labels",
        errors.GetErrorMessage())
logic.ClearUndo()
cage = logic.GetCage()

widget = lfd.vtkCageWidget()
widget.CreateDefaultRepresentation()
rep = widget.GetCageRepresentation()
rep.SetCage(cage)
rep.SetApplyToCage(False)
events = {"selection": 0, "refused": 0}


def begin(caller, event):
    logic.BeginInteraction()


def push(caller, event):
    ids, positions = vtkIdList(), vtkPoints()
    rep.GetMovedPointIds(ids)
    rep.GetMovedPositions(positions)
    if not logic.MovePoints(ids, positions):
        events["refused"] += 1
        rep.UpdateFromCage()


def end(caller, event):
    logic.EndInteraction()


def selection(caller, event):
    events["selection"] += 1


widget.AddObserver(vtkCommand.StartInteractionEvent, begin)
widget.AddObserver(vtkCommand.InteractionEvent, push)
widget.AddObserver(vtkCommand.EndInteractionEvent, end)
widget.AddObserver(Rep.SelectionChangedEvent, selection)

rest = [list(cage.GetPoint(i)) for i in range(cage.GetNumberOfPoints())]
rep.SelectBox(1)
ids = vtkIdList()
rep.GetSelectedPointIds(ids)
box1 = [ids.GetId(i) for i in range(ids.GetNumberOfIds())]
t.check(len(box1) == 8 and events["selection"] == 1, "SelectBox: 8 points, one selection event",
        (box1, events["selection"]))
t.check(rep.TranslateSelection(0.0, 0.01, 0.0), "a numeric move through the logic", errors.GetErrorMessage())
moved = [cage.GetPoint(i)[1] - rest[i][1] for i in box1]
# The scene stores float points.
t.check(all(abs(d - 0.01) < 1e-6 for d in moved), "box 1 moved by 0.01 in y", moved)
t.check(logic.GetNumberOfCommands() == 1 and logic.GetUndoName() == "Move 8 points",
        "one edit = one command", (logic.GetNumberOfCommands(), logic.GetUndoName()))

rep.SelectFace(1, 5)
t.check(rep.TwistFace(1, 5, 10.0), "TwistFace through the logic", errors.GetErrorMessage())
t.check(logic.GetNumberOfCommands() == 2, "the twist is the second command", logic.GetNumberOfCommands())

# Moving one corner of box 1 onto the far side of the box folds it: the logic
# refuses, the handle goes back to the cage's point, the edit reports it.
before = [list(cage.GetPoint(i)) for i in range(cage.GetNumberOfPoints())]
corner = box1[0]
rep.SelectPoint(corner, False)
lo = cage.GetPoint(corner)
far = cage.GetPoint(box1[-1])
t.check(not rep.TranslateSelection(2 * (far[0] - lo[0]), 2 * (far[1] - lo[1]), 2 * (far[2] - lo[2])),
        "a folding move is refused", errors.GetErrorMessage())
handle = [0.0, 0.0, 0.0]
rep.GetHandlePosition(corner, handle)
t.check(events["refused"] == 1 and handle == before[corner] and
        [list(cage.GetPoint(i)) for i in range(cage.GetNumberOfPoints())] == before,
        "the cage and the handle stay where they were", handle)
t.check(logic.GetNumberOfCommands() == 2, "no command for the refused move", logic.GetNumberOfCommands())

t.check(logic.Undo() and logic.Undo() and not cage.IsDeformed(), "two undos: the cage at rest",
        cage.GetLargestDisplacement())

# Standalone: the representation edits a plain cage itself.
bar = lfd.vtkDeformationCage()
bar.InitializeFromGrid(cage)
bar.SetPointsToRest()
solo = Rep()
solo.SetCage(bar)
solo.SelectAll()
t.check(solo.Bend(1, 30.0) and bar.Validate() == "" and bar.IsDeformed(), "Bend keeps the cage valid",
        bar.GetLargestDisplacement())
t.check(solo.ResetSelection() and not bar.IsDeformed(), "ResetSelection", bar.GetLargestDisplacement())
solo.SelectPoint(0, False)
t.check(solo.GetNumberOfSelectedPoints() == 1 and solo.IsPointSelected(0), "SelectPoint",
        solo.GetNumberOfSelectedPoints())
t.finish()
