"""The rig is fitted once, explicitly, and nothing that reads it modifies it
(issue 9, item 7): a captured rig comes fitted; rendering it twice leaves the
input rig's and light field's modification times as they were; a rig set up
view by view is refused by the renderer until FitCylinder() is called, and
the refusal does not fit (modify) it; vtkLightFieldMapper::GetBounds runs no
pipeline and fits no rig. Errors are read through vtkLightFieldErrorObserver
with their exact text."""

import lfdtesting as t
from vtkmodules.vtkCommonCore import vtkCommand, vtkMath
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

NO_CYLINDER = "No cylinder could be fitted to the rig, or every view is excluded."
COLLINEAR = ("FitCylinder: the camera centres are collinear or coincide; no ring can be "
             "fitted to them.")

fish = lfd.vtkProceduralObjectSource()
fish.SetObjectToFish()
capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(fish.GetOutputPort())
capture.SetViewsPerRing(12)
capture.SetNumberOfRows(1)
capture.SetWidth(32)
capture.SetHeight(32)
capture.CaptureDepthOff()
runs = []
capture.AddObserver(vtkCommand.StartEvent, lambda *_: runs.append(1))

# The mapper's bounds before anything ran: none, and the capture still not run.
mapper = lfd.vtkLightFieldMapper()
mapper.SetInputConnection(capture.GetOutputPort())
bounds = mapper.GetBounds()
t.check(not vtkMath.AreBoundsInitialized(bounds) and len(runs) == 0,
        "GetBounds before an update: no bounds, the capture not run",
        f"bounds {bounds}, capture runs {len(runs)}")

capture.Update()
light_field = capture.GetOutput()
rig = light_field.GetRig()
t.check(rig.HasCylinder(), "the captured rig comes fitted", rig.HasCylinder())
center, radius = rig.GetCenter(), rig.GetRadius()
bounds = mapper.GetBounds()
expected = [center[a // 2] + (0.5 if a % 2 else -0.5) * radius for a in range(6)]
t.check(len(runs) == 1 and max(abs(b - e) for b, e in zip(bounds, expected)) < 1e-12,
        "GetBounds after the update: the rig's box, no further run",
        f"bounds {[round(b, 4) for b in bounds]}, capture runs {len(runs)}")

rig_time, field_time = rig.GetMTime(), light_field.GetMTime()
camera = t.side_camera(rig)
renderer = lfd.vtkLightFieldRenderer()
renderer.SetInputData(light_field)
renderer.SetWidth(48)
renderer.SetHeight(48)
for azimuth in (0.2, 0.4):
    renderer.SetCamera(t.side_camera(rig, azimuth))
    renderer.Update()
t.check(renderer.GetErrorCode() == 0 and rig.GetMTime() == rig_time and
        light_field.GetMTime() == field_time,
        "two renders leave the input rig and light field unmodified",
        f"rig MTime {rig_time} -> {rig.GetMTime()}, light field {field_time} -> "
        f"{light_field.GetMTime()}")

# A rig set up view by view has no fit until FitCylinder() is called.
manual = lfd.vtkCameraRig()
manual.SetImageSize(32, 32)
manual.SetNumberOfViews(rig.GetNumberOfViews())
for v in range(rig.GetNumberOfViews()):
    K, R, tr = [0.0] * 9, [0.0] * 9, [0.0] * 3
    rig.GetIntrinsics(v, K)
    rig.GetRotation(v, R)
    rig.GetTranslation(v, tr)
    manual.SetView(v, K, R, tr)
unfitted = lfd.vtkLightField()
unfitted.ShallowCopy(light_field)
unfitted.SetRig(manual)
manual_time = manual.GetMTime()
refusing = lfd.vtkLightFieldRenderer()
refusing.SetInputData(unfitted)
refusing.SetCamera(camera)
refusing.SetWidth(48)
refusing.SetHeight(48)
errors = t.error_observer(refusing)
refusing.Update()
t.check(errors.GetNumberOfErrors() == 1 and errors.GetErrorMessage() == NO_CYLINDER and
        not manual.HasCylinder() and manual.GetMTime() == manual_time,
        "an unfitted rig is refused, not fitted by the renderer",
        f"{errors.GetErrorMessage()!r}, fitted {manual.HasCylinder()}")

t.check(manual.FitCylinder() and manual.HasCylinder(), "FitCylinder() fits it", manual.HasCylinder())
errors.Clear()
refusing.Modified()
refusing.Update()
t.check(refusing.GetErrorCode() == 0 and not errors.HasError(), "then it renders",
        errors.GetErrorMessage() or "ok")
manual.SetDuplicateTolerance(0.02)
t.check(not manual.HasCylinder(), "a changed tolerance makes the fit stale", manual.HasCylinder())

# FitCylinder's own error, through the one observer, without VTK's prefix.
line = lfd.vtkCameraRig()
line.SetImageSize(32, 32)
line.SetNumberOfViews(3)
for v in range(3):
    camera = vtkCamera()
    camera.SetPosition(v, 0, 0)
    camera.SetFocalPoint(v, 0, 1)
    camera.SetViewUp(0, 1, 0)
    K, R, tr = [0.0] * 9, [0.0] * 9, [0.0] * 3
    lfd.vtkCameraRig.CameraToPinhole(camera, 32, 32, K, R, tr)
    line.SetView(v, K, R, tr)
errors = t.error_observer(line)
t.check(not line.FitCylinder() and errors.GetErrorMessage() == COLLINEAR and
        errors.GetNumberOfErrors() == 1, "a collinear rig is refused with one line",
        errors.GetErrorMessage())
t.finish()
