"""Helpers shared by the end-to-end tests: paths from the CTest environment,
numpy views of VTK arrays, exact-result checks, and the captures, cameras
and ground-truth evaluations of the deformed-rendering tests."""

import os
import subprocess
import sys

import numpy as np

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkCamera
from vtkmodules.vtkTestingRendering import vtkTesting

import lfd

BASELINE_DIR = os.environ.get("LFD_BASELINE_DIR", "")
TEMP_DIR = os.environ.get("LFD_TEMP_DIR", "/tmp")
# The real templeRing (templeR_par.txt + 47 PNGs), resolved by ExternalData
# (CMake/lfdTestData.cmake); empty of data on a clone without it.
TEMPLERING_DIR = os.environ.get("LFD_TEMPLERING_DIR", "")
LFD = os.environ.get("LFD_EXECUTABLE", "lfd")
# ctest reports a test that exits with this code as skipped (SKIP_RETURN_CODE).
SKIP_RETURN_CODE = 125

failures = []
skipped = []


def check(condition, what, value):
    """Prints the measured value and records a failure."""
    print(("ok   " if condition else "FAIL ") + f"{what}: {value}")
    if not condition:
        failures.append(what)


def error_observer(*objects):
    """A vtkLightFieldErrorObserver observing `objects` (and the executives of
    those that are algorithms): their errors are recorded, not printed;
    GetErrorMessage() is the first one, without VTK's location prefix."""
    observer = lfd.vtkLightFieldErrorObserver()
    for obj in objects:
        observer.Observe(obj)
    return observer


def templering(what):
    """The real templeRing imported (an updated vtkMiddleburyImporter), or
    None when its data is missing: `what` (the part of the test that needs it)
    is then recorded as skipped. A failed import ends the test as failed
    rather than letting it use an empty output."""
    par = os.path.join(TEMPLERING_DIR, "templeR_par.txt")
    if not os.path.isfile(par):
        print(f"skipped: {what}: {par} not found "
              "(templeRing data: see the README's Tests section)")
        skipped.append(what)
        return None
    importer = lfd.vtkMiddleburyImporter()
    errors = error_observer(importer)
    importer.SetFileName(par)
    importer.Update()
    views = importer.GetOutput().GetNumberOfViews()
    check(importer.GetErrorCode() == 0 and views == 47, "templeRing imported: 47 views",
          views or errors.GetErrorMessage())
    if failures:
        finish()
    return importer


def matches_baseline(name, source=None, window=None, threshold=10.0):
    """vtkTesting's regression test of an algorithm's output image (`source`)
    or of a render window against Data/Baseline/<name>.png; on a mismatch the
    candidate and difference images are left in TEMP_DIR."""
    testing = vtkTesting()
    for arg in ("-V", os.path.join(BASELINE_DIR, name + ".png"), "-T", TEMP_DIR):
        testing.AddArgument(arg)
    if window is not None:
        testing.SetRenderWindow(window)
        return testing.RegressionTest(threshold) == vtkTesting.PASSED
    return testing.RegressionTest(source, threshold) == vtkTesting.PASSED


def finish():
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    if skipped:
        print(f"all checks passed, skipped for want of data: {', '.join(skipped)}")
        sys.exit(SKIP_RETURN_CODE)
    print("all checks passed")


def image_array(image, name=None):
    """(H, W, C) numpy view of an image's scalars (or named array), top row first."""
    data = image.GetPointData()
    array = data.GetArray(name) if name else data.GetScalars()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(array).reshape(h, w, -1)[::-1]


def top_over_bottom(image):
    """Mean brightness of the checkerboard's white squares in the top half of
    an image over the bottom half (paper Figs. 4 and 5)."""
    luminance = image_array(image).astype(float).mean(axis=2)
    white = luminance > 0.5 * luminance.max()
    half = luminance.shape[0] // 2
    return luminance[:half][white[:half]].mean() / luminance[half:][white[half:]].mean()


def psnr(a, b, mask=None):
    """PSNR in dB of two 8-bit images (arrays), over `mask` when given; 100 dB
    for identical images, as vtkLeaveOneOutEvaluator::ComputePSNR."""
    difference = np.asarray(a, float) - np.asarray(b, float)
    if mask is not None:
        difference = difference[mask]
    mse = float((difference ** 2).mean())
    return 100.0 if mse == 0.0 else 10.0 * np.log10(255.0 ** 2 / mse)


def temp_path(*parts):
    path = os.path.join(TEMP_DIR, *parts)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    return path


def capture(obj, depth=False, **settings):
    """A built-in object (vtkProceduralObjectSource) and its light field
    (default rig; no Depth pass unless asked). `settings` are
    vtkLightFieldCapture setters without "Set", e.g. ViewsPerRing=90."""
    source = lfd.vtkProceduralObjectSource()
    source.SetObject(obj)
    source.Update()
    cap = lfd.vtkLightFieldCapture()
    cap.SetInputConnection(source.GetOutputPort())
    cap.SetTextureConnection(source.GetOutputPort(1))
    cap.SetCaptureDepth(depth)
    for name, value in settings.items():
        getattr(cap, "Set" + name)(value)
    cap.Update()
    return source, cap.GetOutput()


def pose(cage_port, mode, angle, turn_axis=(0, 1, 0), phase=0.0):
    """vtkCagePoseFilter (twist, swim or bend) of the cage on `cage_port`, updated."""
    posed = lfd.vtkCagePoseFilter()
    posed.SetInputConnection(cage_port)
    posed.SetMode(mode)
    posed.SetAngle(angle)
    posed.SetTurnAxis(*turn_axis)
    posed.SetPhase(phase)
    posed.Update()
    return posed


def side_camera(rig, azimuth=0.35, angle=22.0):
    """A camera at the ring's height, between captured views, outside the ring."""
    camera = vtkCamera()
    c, r = rig.GetCenter(), rig.GetRadius()
    camera.SetFocalPoint(c)
    camera.SetPosition(c[0] + azimuth * r, c[1] + 0.01 * r, c[2] + 0.95 * r)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(angle)
    return camera


def fine_figure(size=256):
    """The figure captured for issue 11's figure targets, seen in `size` x
    `size` renders: views of 2 size x 2 size pixels, prefiltered (2 x 2
    samples per pixel: 4 x 4 per render pixel, and so is its ground truth,
    vtkGroundTruthEvaluator::GetTruthSupersample), with its Depth pass, the
    default 3 rows of 120 views. From views of `size` x `size`, bilinear
    resampling alone bounds the figure's fine texture at about 25.8 dB (the
    30-degree capture resampled onto the 26-degree camera's pixels).
    Returns (source, light field, part cage source, the twist camera, a
    camera between two rows)."""
    source, lf = capture(lfd.vtkProceduralObjectSource.FIGURE, depth=True, Supersample=2,
                         Width=2 * size, Height=2 * size)
    parts = lfd.vtkPartCageSource()
    parts.SetInputConnection(source.GetOutputPort())
    parts.Update()
    rig = lf.GetRig()
    camera = side_camera(rig, azimuth=0.2, angle=26.0)
    between = side_camera(rig)
    c, r = rig.GetCenter(), rig.GetRadius()
    between.SetPosition(c[0] + 0.35 * r, c[1] + 0.025 * r, c[2] + 0.95 * r)
    return source, lf, parts, camera, between


def evaluate(name, source, lf, cage, camera, subdivision=1, size=256, widen=2,
             anti_aliasing=True, ambient=0.1, focal=0):
    """vtkGroundTruthEvaluator of the light field deformed by `cage` (None:
    undeformed) against the source mesh deformed by the same cage (its
    coaxial light's ambient `ambient`: the light field's own); prints the
    figures. `focal`: vtkLightFieldRenderer's focal surface (0 automatic: the
    proxy when `lf` has a Depth pass, 1 plane, 2 proxy)."""
    ev = lfd.vtkGroundTruthEvaluator()
    ev.SetFocalSurface(focal)
    ev.SetInputData(lf)
    ev.SetMeshConnection(source.GetOutputPort())
    ev.SetTextureConnection(source.GetOutputPort(1))
    if cage is not None:
        ev.SetCageData(cage)
    ev.SetCamera(camera)
    ev.SetSubdivision(subdivision)
    ev.SetWidenedSearch(widen)
    ev.SetAntiAliasing(anti_aliasing)
    ev.SetAmbient(ambient)
    ev.SetWidth(size)
    ev.SetHeight(size)
    ev.Update()
    print(f"{name:12s} PSNR {ev.GetPSNR():6.2f}  SSIM {ev.GetSSIM():.3f}  IoU {ev.GetIoU():.3f}"
          f"  label agreement {ev.GetLabelAgreement():.3f}")
    return ev


def expect(name, ev, psnr, ssim, iou):
    """Checks the evaluation's object PSNR, SSIM and silhouette IoU."""
    check(ev.GetPSNR() > psnr, f"{name}: object PSNR > {psnr} dB", ev.GetPSNR())
    check(ev.GetSSIM() > ssim, f"{name}: object SSIM > {ssim}", ev.GetSSIM())
    check(ev.GetIoU() > iou, f"{name}: silhouette IoU > {iou}", ev.GetIoU())


def run_lfd(*args):
    """Runs the `lfd` executable: (exit status, stdout, stderr)."""
    result = subprocess.run([LFD, *args], capture_output=True, text=True, timeout=600)
    return result.returncode, result.stdout, result.stderr
