"""The README's before/after pictures of deformed rendering (issue 11 item 5),
written to docs/images/:

- figure_twist.png: the figure twisted 45 degrees (TestDeformedRendering's
  camera, 256x256), captured at 512x512 prefiltered (2 x 2 samples per
  pixel; its ground truth 4 x 4 per pixel) with its Depth pass, 3 rows of 120
  views: its ground truth | the paper's render
  (one straight warped ray per box, k = 1, hard label edges, the focal
  plane) | subdivision auto, anti-aliased silhouettes and the proxy focal
  surface (the defaults of this version: auto from the scene's
  "subdivision": "auto"); the object PSNR of each is printed (the figure at
  rest, from between two rows and bent: lfd-TestFigureGroundTruth);
- temple_twist.png (when the templeRing data is found): the real
  templeRing in one box (`lfd demo --scene temple`), undeformed | its top
  twisted 35 degrees as the paper renders it (focal plane, k = 1, hard
  label edges) | the same focused on the estimated proxy (`lfd proxy
  --threshold 60`, a few minutes), subdivision auto and anti-aliased
  silhouettes.

Run from the build directory under xvfb-run, with the package and the lfd
tool of the build:
  PYTHONPATH=lib/python3/dist-packages LFD_EXECUTABLE=bin/lfd \\
    xvfb-run -a /usr/bin/python3 ../Utilities/readme_pictures.py [TEMPLERING_DIR]
(TEMPLERING_DIR: the folder of templeR_par.txt; default: $LFD_TEMPLERING_DIR)
"""

import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Testing", "Python"))

import lfdtesting as t  # noqa: E402  (the capture, camera and pose helpers)
from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGWriter  # noqa: E402

import lfd  # noqa: E402

OUT = os.path.join(HERE, "..", "docs", "images")
SIZE = 256


def write_png(path, panels):
    """The panels (H, W, 3 uint8, top row first) side by side, 2 pixels apart."""
    gap = np.full((panels[0].shape[0], 2, 3), 255, np.uint8)
    strip = np.concatenate([p for panel in panels for p in (panel, gap)][:-1], axis=1)
    image = vtkImageData()
    image.SetDimensions(strip.shape[1], strip.shape[0], 1)
    image.GetPointData().SetScalars(
        numpy_to_vtk(np.ascontiguousarray(strip[::-1]).reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
    print(f"wrote {os.path.normpath(path)}")


def figure_twist():
    # Captured at twice the pictures' resolution (lfdtesting.fine_figure, the
    # capture of lfd-TestFigureGroundTruth, which checks the figures printed).
    source, lf, parts, camera, _ = t.fine_figure(SIZE)
    twist = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.TWIST, 45.0).GetOutput()
    panels = []
    for name, subdivision, anti_aliasing, focal in (("twist k=1 hard plane", 1, False, 1),
                                                    ("twist auto aa proxy", 0, True, 2)):
        ev = t.evaluate(name, source, lf, twist, camera, subdivision, SIZE,
                        anti_aliasing=anti_aliasing, focal=focal)
        if not panels:
            panels.append(t.image_array(ev.GetOutput(1)))
        panels.append(t.image_array(ev.GetOutput(0)))
    write_png(os.path.join(OUT, "figure_twist.png"), panels)


def temple_twist(data_dir):
    if not os.path.isfile(os.path.join(data_dir, "templeR_par.txt")):
        print(f"templeRing not found in {data_dir}: temple_twist.png skipped")
        return
    with tempfile.TemporaryDirectory() as work:
        demo = os.path.join(work, "temple")
        subprocess.run([t.LFD, "demo", "--scene", "temple", "--data", data_dir, "--frames", "1",
                        "--size", str(SIZE), "--out", demo], check=True, capture_output=True)
        proxy = os.path.join(work, "temple-proxy.lf")
        subprocess.run([t.LFD, "proxy", os.path.join(demo, "temple.lf"), "--threshold", "60",
                        "--out", proxy], check=True, capture_output=True)
        scene = lfd.vtkLightFieldScene()
        scene.Read(os.path.join(demo, "temple.json"))
        reader = lfd.vtkLightFieldReader()
        scene.ConfigureReader(reader)
        reader.SetFileName(proxy)
        reader.Update()
        rest = lfd.vtkDeformationCage()
        rest.InitializeFromGrid(scene.GetCage())
        pose = lfd.vtkCagePoseFilter()
        pose.SetInputData(rest)
        pose.SetModeToTwist()
        pose.SetAxis(1)
        pose.SetAngle(35.0)
        pose.Update()
        panels = []
        plane, proxy = lfd.vtkLightFieldRenderer.FOCAL_PLANE, lfd.vtkLightFieldRenderer.FOCAL_PROXY
        for cage, subdivision, anti_aliasing, focal in ((rest, 1, False, proxy),
                                                        (pose.GetOutput(), 1, False, plane),
                                                        (pose.GetOutput(), 0, True, proxy)):
            renderer = lfd.vtkLightFieldRenderer()
            renderer.SetInputConnection(reader.GetOutputPort())
            renderer.SetCageData(cage)
            renderer.SetCamera(scene.GetCamera())
            renderer.SetWidth(SIZE)
            renderer.SetHeight(SIZE)
            renderer.SetObjectThreshold(scene.GetObjectThreshold())
            renderer.SetSubdivision(subdivision)
            renderer.SetAntiAliasing(anti_aliasing)
            renderer.SetFocalSurface(focal)
            renderer.Update()
            panels.append(t.image_array(renderer.GetOutput()))
            print(f"temple: k = {renderer.GetLastMaximumSubdivision()}, anti-aliasing "
                  f"{anti_aliasing}, focal surface {'plane' if focal == plane else 'proxy'}")
        write_png(os.path.join(OUT, "temple_twist.png"), panels)


os.makedirs(OUT, exist_ok=True)
figure_twist()
temple_twist(sys.argv[1] if len(sys.argv) > 1 else t.TEMPLERING_DIR)
