"""Two-plane light fields through the command line and Python: a 3 x 3 grid
folder named like the Stanford archive (a textured plane at depth 4, drawn
analytically) -> `lfd import twoplane` -> `lfd render --focal-depth
--aperture` at a camera between the grid's, against the analytic image; the
same render from Python (vtkLightFieldRenderer.SetFocalDepth / SetAperture)
gives the same pixels, and focused at infinity (the default) it is worse;
--aperture on a ring and a misnamed image are each one error line."""

import json
import math
import os
import shutil

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

WORK = t.temp_path("twoplane", "x")[:-2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
SIZE, FOCAL, SPACING, DEPTH = 32, 32.0, 0.25, 4.0


def plane_image(centre):
    """The textured plane z = DEPTH seen from `centre` looking along +Z (R = I,
    f = FOCAL, principal point at the image centre), top row first."""
    y, x = np.mgrid[0:SIZE, 0:SIZE].astype(float)
    px = centre[0] + DEPTH * (x - (SIZE - 1) / 2) / FOCAL
    py = centre[1] + DEPTH * (y - (SIZE - 1) / 2) / FOCAL
    rgb = np.stack([128 + 100 * np.sin(3 * px) * np.cos(2 * py),
                    128 + 100 * np.cos(4 * px + 1),
                    128 + 100 * np.sin(2 * py - px)], axis=-1)
    return np.round(rgb).astype(np.uint8)


def write_png(path, rgb):
    image = vtkImageData()
    image.SetDimensions(SIZE, SIZE, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(rgb[::-1].reshape(-1, 3).copy()))
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return t.image_array(reader.GetOutput())[:, :, :3]


grid = os.path.join(WORK, "grid")
os.makedirs(grid)
for r in range(3):
    for c in range(3):
        write_png(os.path.join(grid, f"out_{r:02d}_{c:02d}_{-381.6 + r:.1f}_{100.5 * c:.1f}_.png"),
                  plane_image((c * SPACING, r * SPACING)))

lf = os.path.join(WORK, "grid.lf")
code, out, err = t.run_lfd("import", "twoplane", grid, "--spacing", str(SPACING),
                           "--focal-length", str(FOCAL), "--out", lf)
t.check(code == 0 and "imported 9 views" in out, "lfd import twoplane: 9 views", out + err)
reader = lfd.vtkLightFieldReader()
reader.SetFileName(lf)
reader.Update()
rig = reader.GetOutput().GetRig()
t.check(rig.IsTwoPlane(), "the dataset read back is a two-plane rig", rig.IsTwoPlane())

# A camera on the plane between four of the grid's, image up = -Y.
eye = (0.3, 0.2)
view_angle = 2 * math.degrees(math.atan(SIZE / 2 / FOCAL))
scene = os.path.join(WORK, "scene.json")
with open(scene, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "grid.lf",
               "camera": {"position": [eye[0], eye[1], 0], "focal_point": [eye[0], eye[1], DEPTH],
                          "view_up": [0, -1, 0], "view_angle": view_angle,
                          "width": SIZE, "height": SIZE}}, f)
truth = plane_image(eye)
focused = os.path.join(WORK, "focused.png")
code, out, err = t.run_lfd("render", scene, "--focal-depth", str(DEPTH), "--aperture", "0.3",
                           "--out", focused)
t.check(code == 0, "lfd render --focal-depth 4 --aperture 0.3", out + err)
sharp = t.psnr(read_png(focused), truth) if code == 0 else 0.0
# The plane is at the focal depth: every camera of the aperture agrees.
# (Measured 42.7 dB; at infinity 36.2.)
t.check(sharp > 40.0, "focused on the plane, PSNR against the analytic image > 40 dB", sharp)
# The same render from Python.
camera = vtkCamera()
camera.SetPosition(eye[0], eye[1], 0)
camera.SetFocalPoint(eye[0], eye[1], DEPTH)
camera.SetViewUp(0, -1, 0)
camera.SetViewAngle(view_angle)
renderer = lfd.vtkLightFieldRenderer()
renderer.SetInputConnection(reader.GetOutputPort())
renderer.SetCamera(camera)
renderer.SetWidth(SIZE)
renderer.SetHeight(SIZE)
renderer.SetFocalDepth(DEPTH)
renderer.SetAperture(0.3)
renderer.Update()
same = t.psnr(t.image_array(renderer.GetOutput()), read_png(focused))
t.check(same == 100.0, "Python's SetFocalDepth / SetAperture render = the command line's", same)
renderer.SetFocalDepth(0.0)  # the default: at infinity
renderer.SetAperture(0.0)
renderer.Update()
far = t.psnr(t.image_array(renderer.GetOutput()), truth)
t.check(far < sharp - 5.0, "focused at infinity (the default): at least 5 dB lower", far)

# Refocusing options on a ring: refused in one line.
ring = lfd.vtkLightField()
ring.SetLayout(16, 16, 8)
ring.GetRig().MakeCylinder((0, 0, 0), (0, 1, 0), 4.0, 8, 1, (0.0,), 16, 16, 30.0)
ring.AllocatePass(lfd.vtkLightField.COAXIAL).Fill(0)
writer = lfd.vtkLightFieldWriter()
writer.SetInputData(ring)
writer.SetDirectory(os.path.join(WORK, "ring.lf"))
writer.Write()
with open(os.path.join(WORK, "ring.json"), "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "ring.lf",
               "camera": {"position": [0, 0, 6], "focal_point": [0, 0, 0], "width": 16,
                          "height": 16}}, f)
code, _, err = t.run_lfd("render", os.path.join(WORK, "ring.json"), "--aperture", "1",
                         "--out", os.path.join(WORK, "ring.png"))
lines = [line for line in err.splitlines() if line.startswith("lfd: error:")]
t.check(code == 1 and len(lines) == 1 and "refocus two-plane light fields" in lines[0],
        "--aperture on a ring: one error", err.strip())

# A misnamed image: one error line naming it, no dataset written.
write_png(os.path.join(grid, "view_a.png"), truth)
bad = os.path.join(WORK, "bad.lf")
code, _, err = t.run_lfd("import", "twoplane", grid, "--focal-length", "32", "--out", bad)
lines = [line for line in err.splitlines() if line.startswith("lfd: error:")]
t.check(code == 1 and len(lines) == 1 and "view_a.png: the name has no row and column" in lines[0]
        and not os.path.exists(bad), "a misnamed image: one error naming it", err.strip())
t.finish()
