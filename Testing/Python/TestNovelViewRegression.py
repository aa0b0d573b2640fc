"""Regression image of a rendered novel view: the textured figure captured on
a small rig, rendered from a camera between captured views, compared with
the committed baseline (vtkTesting, as VTK's own tests do)."""


import lfdtesting as t
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

figure = lfd.vtkProceduralObjectSource()
figure.SetObjectToFigure()
capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(figure.GetOutputPort())
capture.SetTextureConnection(figure.GetOutputPort(1))
capture.SetViewsPerRing(60)
capture.SetNumberOfRows(2)
capture.SetWidth(128)
capture.SetHeight(128)
capture.CaptureDepthOff()
capture.Update()
rig = capture.GetOutput().GetRig()

camera = vtkCamera()
c = rig.GetCenter()
r = rig.GetRadius()
camera.SetFocalPoint(c)
camera.SetPosition(c[0] + 0.3 * r, c[1] + 0.05 * r, c[2] + 0.6 * r)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(32)

renderer = lfd.vtkLightFieldRenderer()
renderer.SetInputConnection(capture.GetOutputPort())
renderer.SetCamera(camera)
renderer.SetWidth(256)
renderer.SetHeight(256)
renderer.SetBackground(0.1, 0.1, 0.2)

passed = t.matches_baseline("TestNovelViewRegression", renderer)
t.check(passed, "novel view matches the baseline", "passed" if passed else "differs (see {})".format(t.TEMP_DIR))
t.finish()
