"""Per-frame acceleration of the cage (vtkLightFieldRenderer::CageAcceleration,
lfd::FrameCage: culling tiles, front-to-back walk, boxes at rest skipped
where the view ray shows another label) against every ray tested through
every box: a cage of 100 slabs over the fish, each labelled by the part
holding its centre, bent as a whole and with one shared corner dragged (98
boxes at rest), renders the same labels, and the same pixels and depths but
where a run's jump ahead of its focal piece parts (counted), with the
acceleration on and off, from a camera outside the cage and from one inside
it (boxes behind and around the eye have no bounded projection)."""

import lfdtesting as t
import numpy as np
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

SIZE = 128

fish, fish_lf = t.capture(lfd.vtkProceduralObjectSource.FISH, ViewsPerRing=40, NumberOfRows=1,
                          Width=96, Height=96)
parts = lfd.vtkPartCageSource()
parts.SetInputConnection(fish.GetOutputPort())
parts.Update()
part_cage = parts.GetOutput()
bounds = part_cage.GetBounds()
axis = max(range(3), key=lambda a: bounds[2 * a + 1] - bounds[2 * a])

logic = lfd.vtkLightFieldSceneLogic()
logic.SetLightField(fish_lf)
t.check(logic.BuildCageFromSlabs(bounds, 100, axis, 1), "100 slabs built", 100)
slabs = logic.GetCage()
for box in range(slabs.GetNumberOfBoxes()):
    corners = [0.0] * 24
    slabs.GetRestCorners(box, corners)
    centre = sum(corners[3 * c + axis] for c in range(8)) / 8.0
    for part in range(part_cage.GetNumberOfBoxes()):
        part_corners = [0.0] * 24
        part_cage.GetRestCorners(part, part_corners)
        along = part_corners[axis::3]
        if min(along) <= centre <= max(along):
            logic.SetBoxLabel(box, part_cage.GetBoxLabel(part))
# (A swim folds slabs this thin; a bend does not.)
bend = lfd.vtkCagePoseFilter()
bend.SetInputData(slabs)
bend.SetModeToBend()
bend.SetAngle(30.0)
bend.SetTurnAxis(0.0, 0.0, 1.0)
bend.Update()
cage = bend.GetOutput()
why = cage.Validate(fish_lf)
t.check(why == "", "the bent 100-slab cage validates", why or "ok")

# One corner shared by slabs 49 and 50 dragged by a tenth of the fish's length.
dragged = lfd.vtkDeformationCage()
dragged.DeepCopy(slabs)
corner = dragged.GetCell(50).GetPointId(6)
position = list(dragged.GetPoint(corner))
position[(axis + 1) % 3] += 0.1 * (bounds[2 * axis + 1] - bounds[2 * axis])
dragged.GetPoints().SetPoint(corner, position)
dragged.GetPoints().Modified()
why = dragged.Validate(fish_lf)
t.check(why == "", "the dragged 100-slab cage validates", why or "ok")


def render(cage, camera, accelerated):
    renderer = lfd.vtkLightFieldRenderer()
    renderer.SetInputData(fish_lf)
    renderer.SetCageData(cage)
    renderer.SetCamera(camera)
    renderer.SetWidth(SIZE)
    renderer.SetHeight(SIZE)
    renderer.SetCageAcceleration(accelerated)
    renderer.Update()
    image = renderer.GetOutput()
    return [t.image_array(image, name) for name in ("Radiance", "Label", "Depth")]


outside = t.side_camera(fish_lf.GetRig())
inside = vtkCamera()
# In the head's slabs, looking down the fish's length: slabs lie behind the
# eye, around it and in front of it.
low, high = cage.GetBounds()[2 * axis], cage.GetBounds()[2 * axis + 1]
eye = [0.5 * (cage.GetBounds()[2 * a] + cage.GetBounds()[2 * a + 1]) for a in range(3)]
focal = list(eye)
eye[axis] = low + 0.1 * (high - low)
focal[axis] = high
inside.SetPosition(eye)
inside.SetFocalPoint(focal)
inside.SetViewUp(*((0, 1, 0) if axis != 1 else (1, 0, 0)))
inside.SetViewAngle(60.0)
# (Fewer since a run of slabs is looked up once, from its focal piece: the
# pieces behind it no longer add the part's coverage again at its silhouette.)
# Pixels that differ: a run's jump ahead of its focal piece follows face
# neighbours with the acceleration (lfd::FrameCage::FollowRun), the intervals
# themselves without it; they part where a ray leaves the slabs by a side
# inside the pieces jumped over (5 pixels of the bent cage from outside).
for name, scene, camera, expected_parts, differ in (
        ("bent, outside", cage, outside, 4867, (5, 0, 3)),
        ("bent, inside", cage, inside, 7566, (0, 0, 0)),
        ("dragged, outside", dragged, outside, 4906, (0, 0, 0)),
        ("dragged, inside", dragged, inside, 7411, (0, 0, 0))):
    fast = render(scene, camera, True)
    reference = render(scene, camera, False)
    for array, a, b, expected in zip(("Radiance", "Label", "Depth"), fast, reference, differ):
        count = int(np.count_nonzero((a != b).any(axis=2)))
        t.check(count == expected,
                f"{name} camera: {array} pixels unlike without the acceleration", count)
    labelled = int(np.count_nonzero(fast[1]))
    t.check(labelled == expected_parts, f"{name} camera: pixels showing a part", labelled)
t.finish()
