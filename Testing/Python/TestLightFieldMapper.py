"""vtkLightFieldActor / vtkLightFieldMapper in a vtkRenderer: the swimming
fish drawn with its cage outline (regression image, as VTK's tests do), depth
compositing with ordinary actors (a plane in front of the fish hides it, one
behind does not), the true depth of the proxy focal surface (a small sphere
inside the fish's body is hidden by it; through the focal plane it shows;
regression image), and progressive refinement (a quarter of the resolution
while the window renders at an interactive rate, full resolution when
still)."""


import lfdtesting as t
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkFiltersExtraction import vtkExtractEdges
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

import lfd

fish = lfd.vtkProceduralObjectSource()
fish.SetObjectToFish()
capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(fish.GetOutputPort())
capture.SetNumberOfRows(1)
capture.SetViewsPerRing(60)
capture.SetWidth(128)
capture.SetHeight(128)
# The Depth pass is the proxy of the sphere test below; the rest of the
# test renders through the focal plane.
# The mapper's bounds come from its inputs as they are (GetBounds runs no
# pipeline): update the capture before the clipping range is reset.
capture.Update()
parts = lfd.vtkPartCageSource()
parts.SetInputConnection(fish.GetOutputPort())
pose = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.SWIM, 20.0, (0, 0, 1), 1.0)

mapper = lfd.vtkLightFieldMapper()
mapper.SetInputConnection(capture.GetOutputPort())
mapper.SetCageConnection(pose.GetOutputPort())
mapper.GetLightFieldRenderer().SetFocalSurfaceToPlane()
actor = lfd.vtkLightFieldActor()
actor.SetMapper(mapper)
edges = vtkExtractEdges()
edges.SetInputConnection(pose.GetOutputPort())
outline_mapper = vtkPolyDataMapper()
outline_mapper.SetInputConnection(edges.GetOutputPort())
outline = vtkActor()
outline.SetMapper(outline_mapper)
outline.GetProperty().SetColor(1.0, 0.2, 0.2)
outline.GetProperty().SetLineWidth(2)

renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.AddActor(outline)
renderer.SetBackground(0.1, 0.1, 0.2)
window = vtkRenderWindow()
window.SetSize(300, 300)
window.SetMultiSamples(0)
window.AddRenderer(renderer)
camera = renderer.GetActiveCamera()
camera.SetPosition(0.6, 0.05, 3.0)
camera.SetFocalPoint(0, 0, 0)
camera.SetViewUp(0, 1, 0)
camera.SetViewAngle(30)
renderer.ResetCameraClippingRange()
window.Render()
t.check(tuple(mapper.GetLastImageSize()) == (300, 300), "still render at full resolution",
        mapper.GetLastImageSize())

# The depth the mapper wrote (GetDepthImage) is the window's z-buffer where
# the fish is: same convention and row order (the cage outline, drawn over
# some fish pixels, is the only difference).
depth = t.image_array(mapper.GetDepthImage())[..., 0]
zbuffer = vtkFloatArray()
window.GetZbufferData(0, 0, 299, 299, zbuffer)
zbuffer = numpy_support.vtk_to_numpy(zbuffer).reshape(300, 300)[::-1]  # top row first, as image_array
fish_mask = depth < 1.0
same = float((abs(depth - zbuffer)[fish_mask] < 1e-6).mean())
print("depth image: {} fish pixels, {:.3f} equal to the z-buffer".format(int(fish_mask.sum()), same))
t.check(depth.shape == (300, 300) and fish_mask.sum() > 4000, "a depth image of the viewport's size with the fish in it",
        (depth.shape, int(fish_mask.sum())))
t.check(same > 0.95, "the depth image is the z-buffer where the fish is", same)
t.check(bool((depth[~fish_mask] == 1.0).all()), "no fish: depth 1", float(depth[~fish_mask].min()))

passed = t.matches_baseline("TestLightFieldMapper", window=window)
t.check(passed, "fish and cage outline match the baseline", "passed" if passed else "differs (see {})".format(t.TEMP_DIR))


def fish_pixels_left():
    """Pixels of the left half that show the fish (not background, not plane)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = t.image_array(grab.GetOutput())[:, :140, :3].astype(int)
    background = (abs(rgb[..., 0] - 26) < 4) & (abs(rgb[..., 2] - 51) < 4)
    green_plane = (rgb[..., 1] > 200) & (rgb[..., 0] < 60)
    return int((~background & ~green_plane).sum())


renderer.RemoveActor(outline)
plane = vtkPlaneSource()
plane.SetOrigin(-3.0, -1.5, 0.0)
plane.SetPoint1(0.1, -1.5, 0.0)
plane.SetPoint2(-3.0, 1.5, 0.0)
plane_mapper = vtkPolyDataMapper()
plane_mapper.SetInputConnection(plane.GetOutputPort())
plane_actor = vtkActor()
plane_actor.SetMapper(plane_mapper)
plane_actor.GetProperty().SetColor(0.0, 1.0, 0.0)
plane_actor.GetProperty().LightingOff()
renderer.AddActor(plane_actor)
visible = {}
for name, z in (("in front", 0.6), ("behind", -0.6)):
    plane_actor.SetPosition(0.0, 0.0, z)
    renderer.ResetCameraClippingRange()
    window.Render()
    visible[name] = fish_pixels_left()
print("fish pixels in the left half:", visible)
t.check(visible["in front"] < 50, "a plane in front of the fish hides it", visible["in front"])
t.check(visible["behind"] > 2000, "a plane behind the fish does not", visible["behind"])
renderer.RemoveActor(plane_actor)

# A small red sphere inside the fish's body (an ellipsoid of semi-axes 0.36,
# 0.20, 0.12 about the origin), the cage at rest: through the focal plane
# (depth: the plane through the rig axis) its front half shows through the
# fish; with the proxy (the Depth pass) the fish's surface hides it.
sphere = vtkSphereSource()
sphere.SetRadius(0.08)
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(24)
sphere_mapper = vtkPolyDataMapper()
sphere_mapper.SetInputConnection(sphere.GetOutputPort())
sphere_actor = vtkActor()
sphere_actor.SetMapper(sphere_mapper)
sphere_actor.GetProperty().SetColor(1.0, 0.0, 0.0)
sphere_actor.GetProperty().LightingOff()
renderer.AddActor(sphere_actor)
mapper.SetCageConnection(parts.GetOutputPort())


def red_pixels():
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    rgb = t.image_array(grab.GetOutput())[..., :3].astype(int)
    return int(((rgb[..., 0] > 200) & (rgb[..., 1] < 40) & (rgb[..., 2] < 40)).sum())


red = {}
for name in ("plane", "proxy"):
    getattr(mapper.GetLightFieldRenderer(), "SetFocalSurfaceTo" + name.capitalize())()
    renderer.ResetCameraClippingRange()
    window.Render()
    red[name] = red_pixels()
print("red sphere pixels through the fish:", red)
t.check(red["plane"] > 300, "focal plane depth: the sphere inside the body shows through", red["plane"])
t.check(red["proxy"] == 0, "proxy depth: the fish hides the sphere inside its body", red["proxy"])
passed = t.matches_baseline("TestLightFieldMapperProxyDepth", window=window)
t.check(passed, "fish hiding the sphere matches the baseline",
        "passed" if passed else "differs (see {})".format(t.TEMP_DIR))
renderer.RemoveActor(sphere_actor)
mapper.SetCageConnection(pose.GetOutputPort())
mapper.GetLightFieldRenderer().SetFocalSurfaceToPlane()

window.SetDesiredUpdateRate(15.0)
window.Render()
t.check(tuple(mapper.GetLastImageSize()) == (75, 75), "interactive render at a quarter resolution",
        mapper.GetLastImageSize())
t.check(tuple(mapper.GetDepthImage().GetDimensions()) == (75, 75, 1), "and so is its depth image",
        mapper.GetDepthImage().GetDimensions())
# Adaptive: a frame budget no computation fits (1 microsecond) takes the
# coarsest subsampling, 64; one any fits (1 s) keeps InteractiveSubsampling.
mapper.AdaptiveSubsamplingOn()
window.SetDesiredUpdateRate(1e6)
camera.Azimuth(1.0)
window.Render()
t.check(tuple(mapper.GetLastImageSize()) == (4, 4), "adaptive: 1/64 when the budget is tiny",
        mapper.GetLastImageSize())
window.SetDesiredUpdateRate(1.0)
camera.Azimuth(1.0)
window.Render()
t.check(tuple(mapper.GetLastImageSize()) == (75, 75), "adaptive: 1/4 when it fits",
        mapper.GetLastImageSize())
mapper.AdaptiveSubsamplingOff()
window.SetDesiredUpdateRate(0.0001)
window.Render()
t.check(tuple(mapper.GetLastImageSize()) == (300, 300), "back to full resolution when still",
        mapper.GetLastImageSize())
t.finish()
