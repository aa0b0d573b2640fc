"""The animation export from Python, as the Studio's export dialog drives it
(vtkLightFieldAnimationWriter): the fish in its 3 boxes sheared over 2
keyframes, exported into a folder with a progress observer (the texts and
values a progress dialog shows), the contact sheet written; then cancelled
from the observer after frame 2, which leaves the first export untouched,
and a folder of the user's refused with one error naming it."""
import os
import shutil

import lfdtesting as t
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_DOUBLE
from vtkmodules.vtkCommonCore import vtkCommand

import lfd

source, light_field = t.capture(lfd.vtkProceduralObjectSource.FISH, ViewsPerRing=12, NumberOfRows=1, Width=48, Height=48)
logic = lfd.vtkLightFieldSceneLogic()
logic.SetLightField(light_field)
t.check(logic.BuildCageFromLabels(source.GetOutput(), -1), "a cage from the fish's labels", "")
logic.SetKeyframe(0.0)
cage = logic.GetCage()
for p in range(cage.GetNumberOfPoints()):
    x, y, z = cage.GetPoint(p)
    logic.MovePoint(p, x, y + 0.05 * x, z)  # a slight shear along the body
logic.SetKeyframe(1.0)
logic.SetCamera(t.side_camera(light_field.GetRig()))
logic.SetSize(40, 30)

out = t.temp_path("TestAnimationWriter", "export")
shutil.rmtree(os.path.dirname(out), ignore_errors=True)
writer = lfd.vtkLightFieldAnimationWriter()
writer.SetSceneLogic(logic)
writer.SetNumberOfFrames(3)
writer.SetDirectoryName(out)
writer.WriteContactSheetOn()
writer.SetContactSheetColumns(3)
writer.SetContactSheetThumbnailSize(20)
progress = []
cancel_after = [None]


@calldata_type(VTK_DOUBLE)
def on_progress(caller, event, value):
    progress.append((caller.GetProgressText(), round(value, 3)))
    if caller.GetProgressText() == cancel_after[0]:
        caller.SetAbort(True)


writer.AddObserver(vtkCommand.ProgressEvent, on_progress)
errors = t.error_observer(writer)
t.check(writer.Write() and not errors.HasError(), "3 frames exported", errors.GetErrorMessage())
movie = lfd.vtkLightFieldAnimationWriter.IsMovieEncoderAvailable()
files = sorted(os.listdir(out)) if os.path.isdir(out) else []
t.check(files == sorted(["contact_sheet.png", "frame_0000.png", "frame_0001.png", "frame_0002.png"]
                        + (["animation.mp4"] if movie else [])),
        "the exported files", files)
steps = [text for text, _ in dict.fromkeys(progress)]
t.check(steps[:3] == ["frame 1/3", "frame 2/3", "frame 3/3"] and steps[-1] == "done"
        and progress[-1][1] == 1.0, "the progress texts and the final value", steps)
t.check(progress[0][1] == (0.25 if movie else round(1 / 3, 3)), "the first frame's progress",
        progress[0])
t.check(writer.GetContactSheet().GetDimensions() == (60, 20, 1), "the contact sheet's size",
        writer.GetContactSheet().GetDimensions())

before = {name: open(os.path.join(out, name), "rb").read() for name in files}
progress.clear()
cancel_after[0] = "frame 2/3"
t.check(not writer.Write() and writer.GetAborted() and not errors.HasError(),
        "cancelled from the observer after frame 2, without an error", writer.GetAborted())
after = {name: open(os.path.join(out, name), "rb").read() for name in sorted(os.listdir(out))}
t.check(after == before, "the cancel leaves the first export untouched", sorted(after))
t.check([text for text, _ in progress] == ["frame 1/3", "frame 2/3"], "no step after the cancel",
        progress)
t.check(not any(".tmp-" in name for name in os.listdir(os.path.dirname(out))),
        "no temporary left", os.listdir(os.path.dirname(out)))

mine = t.temp_path("TestAnimationWriter", "mine", "notes.txt")
with open(mine, "w") as f:
    f.write("keep")
writer.SetDirectoryName(os.path.dirname(mine))
cancel_after[0] = None
t.check(not writer.Write() and errors.GetNumberOfErrors() == 1 and errors.GetErrorMessage() ==
        f"{os.path.dirname(mine)}: holds 'notes.txt', which an animation export does not write; "
        "it replaces the whole folder, so choose a new or empty one",
        "a folder of the user's is refused with one error", errors.GetErrorMessage())
t.finish()
