"""Edit a scene's cage in a plain VTK window, without Qt: drag the box
corners and watch the light field follow (vtkLightFieldEditor).

    lfd demo --out demo                      # the swimming fish: demo/swim.json
    PYTHONPATH=build/lib/python3/dist-packages \\
        /usr/bin/python3 Examples/EditScene.py demo/swim.json [--save edited.json]

Mouse: drag a corner (a corner two boxes share moves both), shift-click to
select several, B for a rubber band, G / R / S to grab / rotate / scale the
selection (X / Y / Z constrain it); Ctrl+Z undoes a drag, Ctrl+Shift+Z
redoes it. Closing the window saves to --save when given.

--replay plays a recorded drag of a corner shared by two boxes instead of
waiting for the mouse, prints what the scene logic recorded, undoes it and
exits (what the tests run, under xvfb-run -a).
"""

import argparse
import sys

import lfd
from vtkmodules.vtkRenderingCore import vtkInteractorEventRecorder


def shared_corner(editor):
    """The visible cage point shared by the most boxes, and its display position."""
    cage = editor.GetLogic().GetCage()
    uses = [0] * cage.GetNumberOfPoints()
    for box in range(cage.GetNumberOfBoxes()):
        corners = cage.GetCell(box).GetPointIds()
        for c in range(corners.GetNumberOfIds()):
            uses[corners.GetId(c)] += 1
    rep = editor.GetWidget().GetCageRepresentation()
    visible = [i for i in range(len(uses)) if uses[i] > 1 and rep.IsPointVisible(i)]
    point = max(visible, key=lambda i: uses[i])
    renderer = editor.GetRenderer()
    renderer.SetWorldPoint(*cage.GetPoint(point), 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    return point, round(x), round(y)


def replay_drag(editor):
    """Drags a shared corner 30 pixels up with recorded events, reports, undoes."""
    logic = editor.GetLogic()
    point, x, y = shared_corner(editor)
    before = logic.GetCage().GetPoint(point)
    events = "MouseMoveEvent {0} {1} 0 0 0 0 0\nLeftButtonPressEvent {0} {1} 0 0 0 0 0\n".format(x, y)
    events += "".join("MouseMoveEvent {} {} 0 0 0 0 0\n".format(x, y + 5 * k) for k in range(1, 7))
    events += "LeftButtonReleaseEvent {} {} 0 0 0 0 0\n".format(x, y + 30)
    recorder = vtkInteractorEventRecorder()
    recorder.SetInteractor(editor.GetInteractor())
    recorder.ReadFromInputStringOn()
    recorder.SetInputString(events)
    recorder.Play()
    after = logic.GetCage().GetPoint(point)
    print("dragged point {} from {} to {}".format(point, before, after))
    print("commands: {}, undo: {}".format(logic.GetNumberOfCommands(), logic.GetUndoName()))
    print("last frame: {}x{}".format(*editor.GetMapper().GetLastImageSize()))
    logic.Undo()
    print("undone: {}".format(logic.GetCage().GetPoint(point) == before))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", help="scene.json (e.g. from lfd demo)")
    parser.add_argument("--save", help="write the edited scene here when the window closes")
    parser.add_argument("--replay", action="store_true", help="play a recorded drag and exit")
    args = parser.parse_args()

    editor = lfd.vtkLightFieldEditor()
    errors = lfd.vtkLightFieldErrorObserver()
    errors.Observe(editor.GetLogic())
    if not editor.GetLogic().Load(args.scene) or not editor.Initialize():
        sys.exit("EditScene.py: " + errors.GetErrorMessage())
    if args.replay:
        editor.Render()
        replay_drag(editor)
    else:
        editor.Start()
    if args.save and not editor.GetLogic().Save(args.save):
        sys.exit("EditScene.py: " + errors.GetErrorMessage())


if __name__ == "__main__":
    main()
