"""A small pipeline through `import lfd`: built-in fish -> synthetic capture
-> light-field renderer. Asserts the classes are exposed, the captured label
set is exact and the novel view shows the three parts."""

import lfdtesting as t
import numpy as np
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

for name in ("vtkLightField", "vtkCameraRig", "vtkLightFieldAlgorithm", "vtkLightFieldReader", "vtkLightFieldWriter",
             "vtkMiddleburyImporter", "vtkLightFieldScene", "vtkProceduralObjectSource",
             "vtkLightFieldCapture", "vtkLabelCellsByBoxes", "vtkLightFieldRenderer",
             "vtkLeaveOneOutEvaluator", "vtkImageFileReader", "vtkImageFileWriter",
             "vtkDeformationCage", "vtkCageTransform", "vtkKeyframeInterpolator",
             "vtkPartCageSource", "vtkCagePoseFilter", "vtkGroundTruthEvaluator"):
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
t.finish()
