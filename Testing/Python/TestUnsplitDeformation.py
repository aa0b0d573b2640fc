"""A cage deforms an unsplit light field (issue 8, item 9; the paper's Fig. 1:
one box over a whole statue, no split). Without a Label pass the light field
is one part: its object pixels belong to the boxes' one label.

(a) Synthetic: the figure captured as one part, rendered under one twisted
box with its Label pass and without it (dropped): close to each other, far
from the rest render; the same through vtkLightFieldMapper; boxes of two
labels on the unlabelled light field are refused, saying to split first.
(b) Real: the templeRing (no Label pass) in one box, its top twisted 60
degrees: the top changes, the bottom face's layer does not, and the render
matches the committed baseline; the object mask has no holes at the
cornice's grooves and keeps the gaps between the columns. Skipped (exit 125)
without the data."""

import sys

import numpy as np

import lfdtesting as t
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIntArray
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import (vtkCamera, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

import lfd

UNLABELLED_PSNR = 40.0  # measured 46.53 dB against the labelled render
TWIST_CHANGED = 10000  # measured 17376 pixels of 256^2 differ from the rest render
MAPPER_CHANGED = 5000  # measured 10645 pixels of 200^2
TEMPLE_TOP_CHANGED = 4000  # measured 6150 pixels (above 32 levels) of 256^2
TEMPLE_BASE_CHANGED = 500  # measured 261
GROOVES_OBJECT = 0.95  # measured 1.000 in views 24 and 25 (0.454 and 0.526 with holes)
GAP_OBJECT = 0.05  # measured 0.000


def render(light_field, cage, camera, size=256, threshold=10.0):
    renderer = lfd.vtkLightFieldRenderer()
    renderer.SetInputData(light_field)
    renderer.SetCageData(cage)
    renderer.SetCamera(camera)
    renderer.SetWidth(size)
    renderer.SetHeight(size)
    renderer.SetObjectThreshold(threshold)
    renderer.Update()
    return renderer


def changed(a, b, tolerance=0):
    """Boolean (H, W) map of the pixels whose colour differs by more than
    `tolerance` in some channel."""
    return np.abs(t.image_array(a.GetOutput()).astype(int) -
                  t.image_array(b.GetOutput()).astype(int)).max(axis=2) > tolerance


def box_cage(low, high, label=1, cage=None):
    """A vtkDeformationCage with one more axis-aligned box, y up."""
    cage = cage or lfd.vtkDeformationCage()
    ids = []
    for c in range(8):
        x = c % 4 in (2, 3)
        z = c % 4 in (1, 2)
        ids.append(cage.AddPoint((high[0] if x else low[0], high[1] if c >= 4 else low[1],
                                  high[2] if z else low[2])))
    cage.AddBox(ids, label)
    return cage


def twist(cage, angle):
    posed = lfd.vtkCagePoseFilter()
    posed.SetInputData(cage)
    posed.SetModeToTwist()
    posed.SetAxis(1)
    posed.SetAngle(angle)
    posed.Update()
    return posed.GetOutput()


# (a) Synthetic ---------------------------------------------------------------
source = lfd.vtkProceduralObjectSource()
source.SetObjectToFigure()
source.Update()
one_part = vtkPolyData()
one_part.ShallowCopy(source.GetOutput())
labels = vtkIntArray()
labels.SetName("Label")
labels.SetNumberOfTuples(one_part.GetNumberOfCells())
labels.Fill(1)
one_part.GetCellData().AddArray(labels)
capture = lfd.vtkLightFieldCapture()
capture.SetInputData(one_part)
capture.SetTextureConnection(source.GetOutputPort(1))
capture.SetViewsPerRing(60)
capture.SetNumberOfRows(1)
capture.SetWidth(128)
capture.SetHeight(128)
capture.CaptureDepthOff()
capture.Update()
labelled = capture.GetOutput()
unlabelled = lfd.vtkLightField()
unlabelled.ShallowCopy(labelled)
unlabelled.GetPointData().RemoveArray("Label")  # as captured with --no-labels

parts = lfd.vtkPartCageSource()
parts.SetInputData(one_part)
parts.SetAxis(1)
parts.Update()
rest = parts.GetOutput()
twisted = twist(rest, 60.0)
why = twisted.Validate(unlabelled)
t.check(why == "", "one twisted box on the unlabelled figure validates", why or "ok")
camera = t.side_camera(labelled.GetRig())
with_labels = render(labelled, twisted, camera)
without_labels = render(unlabelled, twisted, camera)
at_rest = render(unlabelled, rest, camera)
value = t.psnr(t.image_array(with_labels.GetOutput()), t.image_array(without_labels.GetOutput()))
t.check(value > UNLABELLED_PSNR, f"unlabelled vs labelled twist: PSNR > {UNLABELLED_PSNR} dB", value)
count = int(changed(without_labels, at_rest).sum())
t.check(count > TWIST_CHANGED, f"unlabelled twist vs rest: changed pixels > {TWIST_CHANGED}", count)
t.check(unlabelled.GetPass(lfd.vtkLightField.LABEL) is None,
        "the renderer's input keeps no Label pass", unlabelled.GetPass(lfd.vtkLightField.LABEL))

# The same through the mapper, in a render window.
window = vtkRenderWindow()
window.SetSize(200, 200)
window.SetMultiSamples(0)
view = vtkRenderer()
window.AddRenderer(view)
mapper = lfd.vtkLightFieldMapper()
mapper.SetInputData(unlabelled)
actor = lfd.vtkLightFieldActor()
actor.SetMapper(mapper)
view.AddActor(actor)
view.SetActiveCamera(camera)
view.ResetCameraClippingRange()
grabs = []
for cage in (rest, twisted):
    mapper.SetCageData(cage)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    grabs.append(t.image_array(grab.GetOutput()).astype(int))
count = int((np.abs(grabs[0] - grabs[1]).max(axis=2) > 0).sum())
t.check(count > MAPPER_CHANGED, f"mapper: unlabelled twist vs rest, changed pixels > {MAPPER_CHANGED}",
        count)

# Two parts need a split.
two = box_cage((-1, -1, -1), (1, 0, 1), 1)
box_cage((-1, 0, -1), (1, 1, 1), 2, two)
why = two.Validate(unlabelled)
t.check("move different parts" in why, "two labels on the unlabelled figure: the cage is refused",
        why)
renderer = lfd.vtkLightFieldRenderer()
errors = t.error_observer(renderer)
renderer.SetInputData(unlabelled)
renderer.SetCageData(two)
renderer.SetCamera(camera)
renderer.SetWidth(64)
renderer.SetHeight(64)
renderer.Update()
expected = ("cage: box 0 (label 1) and box 1 (label 2) move different parts, but the light field "
            "has no Label pass (it is one part): split it first (lfd split "
            "projector|scanline|propagate ...) or give every box the same label")
t.check(errors.GetErrorMessage().endswith(expected),
        "two labels on the unlabelled figure: the renderer says to split first",
        errors.GetErrorMessage())

# (b) Real: the templeRing ------------------------------------------------------
importer = t.templering("(b) templeRing top twisted in one box")
if importer is None:
    t.finish()
temple = importer.GetOutput()
rig = temple.GetRig()
rig.FitCylinder()
# The dataset's tight bounding box (templeRing README.txt), 1 cm wider, its
# bottom face on the temple's base; as `lfd demo --scene temple`.
low = (-0.023121 - 0.01, -0.038009 - 0.002, -0.091940 - 0.01)
high = (0.078626 + 0.01, 0.121636 + 0.01, -0.017395 + 0.01)
temple_rest = box_cage(low, high)
temple_twisted = twist(temple_rest, 60.0)
why = temple_twisted.Validate(temple)
t.check(why == "", "the temple's twisted box validates", why or "ok")
camera = vtkCamera()
x, y = [0.0] * 3, [0.0] * 3
rig.GetAzimuthFrame(x, y)
c, r, phi = rig.GetCenter(), rig.GetRadius(), np.pi / rig.GetNumberOfViews()
camera.SetPosition([c[i] + 1.15 * r * (np.cos(phi) * x[i] + np.sin(phi) * y[i]) for i in range(3)])
camera.SetFocalPoint([0.5 * (low[i] + high[i]) for i in range(3)])
camera.SetViewUp(rig.GetAxis())
camera.SetViewAngle(rig.GetViewAngle(0))
temple_at_rest = render(temple, temple_rest, camera, 256, 60.0)
temple_top = render(temple, temple_twisted, camera, 256, 60.0)
# Colour changes above 32 levels, by tenths of the temple's rows. The twist
# grows linearly from the box's bottom face (0 degrees) to its top (60): the
# base's tenth turns by 6 degrees at most and changes least.
difference = changed(temple_at_rest, temple_top, 32)
rows = np.nonzero(t.image_array(temple_at_rest.GetOutput(), "Label")[..., 0].any(axis=1))[0]
top, height = rows.min(), rows.max() - rows.min() + 1
tenths = [int(difference[top + k * height // 10:top + (k + 1) * height // 10].sum())
          for k in range(10)]
print(f"temple rows {top}..{top + height - 1}; changed pixels per tenth from the top: {tenths}")
t.check(sum(tenths[:5]) > TEMPLE_TOP_CHANGED,
        f"templeRing twisted: changed pixels in the top half > {TEMPLE_TOP_CHANGED}", sum(tenths[:5]))
t.check(tenths[9] < TEMPLE_BASE_CHANGED,
        f"templeRing twisted: changed pixels in the base's tenth < {TEMPLE_BASE_CHANGED}", tenths[9])
# Anti-aliased silhouettes (vtkLightFieldRenderer::AntiAliasing) blend the
# moved part into the pixels along its labelled silhouette: as wide as the
# two cameras of a ray disagree on it, up to 2 pixels on this real ring
# (between the columns). "Neither render" leaves those pixels out; a few
# faint column edges beyond them remain (8 pixels measured).
near = (t.image_array(temple_at_rest.GetOutput(), "Label")[..., 0] > 0) | \
    (t.image_array(temple_top.GetOutput(), "Label")[..., 0] > 0)
for _ in range(2):
    padded = np.pad(near, 1)
    near = padded[1:-1, 1:-1] | padded[:-2, 1:-1] | padded[2:, 1:-1] | padded[1:-1, :-2] | \
        padded[1:-1, 2:] | padded[:-2, :-2] | padded[:-2, 2:] | padded[2:, :-2] | padded[2:, 2:]
outside = ~near
t.check(difference[outside].sum() <= 10,
        "templeRing: <= 10 pixels changed where the temple is in neither render (nor 2 pixels "
        "around it)", int(difference[outside].sum()))

# The object mask of the label pass (threshold 60, as the demo): the
# cornice's grooves on the pediment, darker than the threshold and open onto
# the backdrop through a few pixels, are object in views 24 and 25 (the
# views the twisted top is looked up in); before their holes were filled a
# ray through them voted background: streaks across the roof. The gap
# between the lower columns of view 25 shows the backdrop and stays one.
split = lfd.vtkScanlineSplit()
split.SetInputData(temple)
split.SetThreshold(60.0)
split.Update()
w, h, v = split.GetOutput().GetDimensions()
labels = vtk_to_numpy(split.GetOutput().GetPass(lfd.vtkLightField.LABEL))
masks = labels.reshape(v, h, w)[:, ::-1] > 0  # image rows top first
for view in (24, 25):
    grooves = float(masks[view, 140:190, 500:540].mean())
    t.check(grooves > GROOVES_OBJECT, f"templeRing view {view}: pediment grooves object > "
            f"{GROOVES_OBJECT}", round(grooves, 3))
gap = float(masks[25, 268:290, 260:380].mean())
t.check(gap < GAP_OBJECT,
        f"templeRing view 25: the gap between the lower columns object < {GAP_OBJECT}",
        round(gap, 3))

passed = t.matches_baseline("TestUnsplitDeformation", temple_top)
t.check(passed, "templeRing with a twisted top matches the baseline", "passed" if passed else "differs (see {})".format(t.TEMP_DIR))
t.finish()
