"""A small pipeline through `import lfd`: built-in fish -> synthetic capture
-> light-field renderer, then deformed: part boxes -> swim pose -> the same
renderer through the cage. Asserts the classes are exposed, the captured
label set is exact, the novel view shows the three parts, and the swim moves
the head and the tail more than the body (measured 2.7, 5.1 and 1.0 pixels)."""

import lfdtesting as t
import numpy as np
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

for name in ("vtkLightField", "vtkCameraRig", "vtkLightFieldAlgorithm", "vtkLightFieldReader", "vtkLightFieldWriter",
             "vtkMiddleburyImporter", "vtkLightFieldScene", "vtkProceduralObjectSource",
             "vtkLightFieldCapture", "vtkLabelCellsByBoxes", "vtkLightFieldRenderer",
             "vtkLeaveOneOutEvaluator", "vtkImageFileReader", "vtkImageFileWriter",
             "vtkDeformationCage", "vtkCageTransform", "vtkKeyframeInterpolator",
             "vtkPartCageSource", "vtkCagePoseFilter", "vtkGroundTruthEvaluator",
             "vtkLatticeCageFilter", "vtkLightFieldMapper", "vtkLightFieldActor", "vtkLabelPalette",
             "vtkProjectorSegmentation", "vtkScanlineSplit", "vtkLabelPropagation",
             "vtkBoxCoverageCheck"):
    t.check(hasattr(lfd, name), f"lfd.{name} exposed", hasattr(lfd, name))

fish = lfd.vtkProceduralObjectSource()
fish.SetObjectToFish()
capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(fish.GetOutputPort())
capture.SetViewsPerRing(24)
capture.SetNumberOfRows(1)
capture.SetWidth(96)
capture.SetHeight(96)
capture.Update()
lf = capture.GetOutput()
t.check(lf.GetNumberOfViews() == 24, "views captured", lf.GetNumberOfViews())
labels = np.unique(t.vtk_to_numpy(lf.GetPass(lfd.vtkLightField.LABEL)))
t.check(list(labels) == [0, 1, 2, 3], "labels in the Label pass", list(labels))

rig = lf.GetRig()
camera = vtkCamera()
center = rig.GetCenter()
camera.SetFocalPoint(center)
camera.SetPosition(center[0] + 0.3 * rig.GetRadius(), center[1] + 0.1 * rig.GetRadius(),
                   center[2] + 1.2 * rig.GetRadius())
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(30)

renderer = lfd.vtkLightFieldRenderer()
renderer.SetInputConnection(capture.GetOutputPort())
renderer.SetCamera(camera)
renderer.SetWidth(128)
renderer.SetHeight(128)
renderer.Update()
image = renderer.GetOutput()
t.check(image.GetDimensions() == (128, 128, 1), "image size", image.GetDimensions())
rendered = t.image_array(image, "Label")[..., 0]
parts = {int(v): int((rendered == v).sum()) for v in np.unique(rendered)}
t.check(set(parts) == {0, 1, 2, 3}, "labels seen in the novel view", parts)
t.check(all(parts[p] > 50 for p in (1, 2, 3)), "every part covers > 50 pixels", parts)

# Deform: a box per part, posed swimming, rendered through the cage.
boxes = lfd.vtkPartCageSource()
boxes.SetInputConnection(fish.GetOutputPort())
pose = lfd.vtkCagePoseFilter()
pose.SetInputConnection(boxes.GetOutputPort())
pose.SetModeToSwim()
pose.SetAngle(25.0)
pose.SetTurnAxis(0, 0, 1)
pose.SetPhase(1.0)
renderer.SetCageConnection(pose.GetOutputPort())
renderer.Update()
swimming = t.image_array(renderer.GetOutput(), "Label")[..., 0]


def centroid(labels, part):
    ys, xs = np.nonzero(labels == part)
    return np.array([xs.mean(), ys.mean()])


moves = {p: round(float(np.linalg.norm(centroid(swimming, p) - centroid(rendered, p))), 2)
         for p in (1, 2, 3)}
t.check(moves[1] > 2.0 * moves[2] and moves[3] > 2.0 * moves[2] and moves[3] > 1.5,
        "the swim moves the tail and the head more than the body (pixels)", moves)
t.check(set(np.unique(swimming)) == {0, 1, 2, 3}, "every part still seen", sorted(np.unique(swimming)))
t.finish()
