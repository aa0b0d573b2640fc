"""Deformed light-field rendering (paper Sec. 5-6) against ground truth: the
source mesh deformed by the same cage map and rendered with the same coaxial
light from the same camera (vtkGroundTruthEvaluator). Checks identity (a
cage at rest changes no pixel), the swimming fish (Fig. 13), the twisted
and the bent figure (Fig. 1; bending goes beyond the paper), and occlusion
between parts: turning the head towards or away from the camera shows as
much of it as the ground truth does. The fish is rendered through the
paper's focal plane and through its Depth pass as a per-pixel proxy focal
surface (render.focal: proxy), also from a camera between two rows; its
rows cover the eye as the swimming boxes see their rest contents
(vtkLightFieldCapture::AppendRestEyes). Every capture and its ground truth
are prefiltered (vtkLightFieldCapture::SetSupersample). Thresholds sit under
the measured figures (README results table)."""

import math

import lfdtesting as t
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

SIZE = 256
# Samples per pixel along each axis of the captures and their ground truth
# (vtkLightFieldCapture::SetSupersample): prefiltered, as a camera integrates
# over its pixels, so the figure's fine texture is not aliased.
PREFILTER = 2
# (PSNR dB, SSIM, IoU) thresholds, just under the measured figures, with
# the widened camera search, anti-aliased silhouettes and prefiltered
# captures (2 x 2 samples per pixel); the fish from 5 rows covering the rest
# eyes: swim through the plane 30.63 / 0.972 / 0.990 (point-sampled, 3 rows
# about the camera: 26.28 / 0.947 / 0.986); twist 18.36 / 0.820 / 0.944,
# bend 20.34 / 0.884 / 0.958 (point-sampled: 16.81 / 0.748 / 0.944, 18.37 /
# 0.809 / 0.958); head turns: label agreement 0.943 and 0.959.
SWIM = (30.4, 0.969, 0.987)
# Proxy focal surface (the fish's Depth pass): swim 33.11 / 0.985 / 0.991
# (32.89 before a moved box showed the slices of neighbouring parts the
# proxy puts inside it, lfd::detail::ShownPart; issue 11's target: 30 dB;
# prefiltered from the default 3 rows 29.23, point-sampled 28.05); undeformed
# from between two rows 32.64 / 0.991 / 0.991 (point-sampled, 3 rows: 30.43 /
# 0.986).
SWIM_PROXY = (32.9, 0.982, 0.988)
BETWEEN_ROWS_PROXY = (32.4, 0.988, 0.989)
ROW_HEIGHTS = [-0.109, -0.054, 0.0, 0.054, 0.109]
PLANE, PROXY = 1, 2
# The figure, captured with its Depth pass (k = 1, proxy): twist 45 21.32 /
# 0.865 / 0.964, bend 30 24.58 / 0.919 / 0.973 (through the plane, without
# the Depth pass: 18.36 / 0.820 / 0.944 and 20.34 / 0.884 / 0.958). The
# figure's torso reaches 3 cm above its slab face, into the head's box:
# before lfd::detail::ShownPart the label test hid that slice once the head moved
# (twist 45 at 512 x 512: 21.23 -> 29.68 dB, see the README).
TWIST = (21.0, 0.86, 0.96)
BEND = (24.3, 0.91, 0.97)
OCCLUSION_AGREEMENT = 0.93


def render(lf, cage, camera):
    renderer = lfd.vtkLightFieldRenderer()
    renderer.SetInputData(lf)
    renderer.SetCageData(cage)
    renderer.SetCamera(camera)
    renderer.SetWidth(SIZE)
    renderer.SetHeight(SIZE)
    renderer.Update()
    return t.image_array(renderer.GetOutput()).astype(int)


# The fish's rig, framed as the default capture frames it (a probe: 3 views
# of 8 x 8 pixels), places the side camera; the swim's boxes turn its rays
# up to 0.2 radius above it in rest space, so the fish is captured (with its
# Depth pass: the proxy) in 5 rows at that radius that cover the eye as each
# swimming box sees its rest contents (vtkLightFieldCapture::AppendRestEyes;
# from the default 3 rows about the camera the swim through the proxy
# scored 29.23 dB), prefiltered (2 x 2 samples per pixel, and so is its
# ground truth): identity, swim.
fish, probe = t.capture(lfd.vtkProceduralObjectSource.FISH, ViewsPerRing=3, Width=8, Height=8)
rig = probe.GetRig()
camera = t.side_camera(rig)
parts = lfd.vtkPartCageSource()
parts.SetInputConnection(fish.GetOutputPort())
parts.Update()
rest = parts.GetOutput()
swim = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.SWIM, 20.0, (0, 0, 1), 1.0).GetOutput()
eyes = vtkPoints()
eyes.InsertNextPoint(camera.GetPosition())
swim_cage = lfd.vtkDeformationCage()
swim_cage.InitializeFromGrid(swim)
lfd.vtkLightFieldCapture.AppendRestEyes(swim_cage, camera.GetPosition(), eyes)
_, fish_lf = t.capture(lfd.vtkProceduralObjectSource.FISH, depth=True, Supersample=PREFILTER,
                       Eyes=eyes, NumberOfRows=5, Radius=rig.GetRadius(), Center=rig.GetCenter())
heights = [round(fish_lf.GetRig().GetRowHeight(r) / rig.GetRadius(), 3)
           for r in range(fish_lf.GetRig().GetNumberOfRows())]
t.check(heights == ROW_HEIGHTS, "rows covering the rest eyes (heights / radius)", heights)
why = rest.Validate(fish_lf)
t.check(why == "", "fish cage validates", why or "ok")
difference = np.abs(render(fish_lf, None, camera) - render(fish_lf, rest, camera))
t.check(difference.max() == 0, "a cage at rest renders the undeformed light field exactly",
        int(difference.max()))

# The ground truth is prefiltered as the capture was (its provenance says
# how): from a captured view's own camera, render and truth are that photo.
t.check(lfd.vtkGroundTruthEvaluator.GetCaptureSupersample(fish_lf) == PREFILTER,
        "the evaluator reads the capture's supersampling",
        lfd.vtkGroundTruthEvaluator.GetCaptureSupersample(fish_lf))
# The truth is sampled at least as densely as the capture: a camera with
# half view 0's focal length in pixels gets 4 x 4 samples, one with view
# 0's (or the side camera's, 22 degrees against the capture's 30) 2 x 2.
focal0 = 0.5 * SIZE / math.tan(math.radians(0.5 * fish_lf.GetRig().GetViewAngle(0)))
truth_samples = [lfd.vtkGroundTruthEvaluator.GetTruthSupersample(fish_lf, f)
                 for f in (0.5 * focal0, focal0, 0.5 * SIZE / math.tan(math.radians(11.0)))]
t.check(truth_samples == [4, 2, 2], "truth samples per pixel from the capture's density",
        truth_samples)
at_view = vtkCamera()
fish_lf.GetRig().ApplyToCamera(0, at_view)
same = t.evaluate("view 0", fish, fish_lf, None, at_view, focal=PLANE)
t.check(same.GetPSNR() == 100.0, "from view 0's camera: render = prefiltered truth (PSNR 100)",
        same.GetPSNR())

widened = t.evaluate("fish swim", fish, fish_lf, swim, camera, focal=PLANE)
t.expect("fish swim", widened, *SWIM)
# The widened camera search (paper Sec. 8, on by default) fills regions the
# swim uncovers: better than the nearby cameras alone.
nearby = t.evaluate("swim, nearby", fish, fish_lf, swim, camera, widen=0, focal=PLANE)
# (Anti-aliased silhouettes soften the edges of the holes it fills too:
# +0.09 dB, +0.16 with hard edges.)
t.check(widened.GetPSNR() > nearby.GetPSNR() + 0.05 and widened.GetIoU() > nearby.GetIoU(),
        "widened camera search improves the swim (PSNR dB, IoU: widened vs nearby cameras only)",
        (round(widened.GetPSNR(), 2), round(nearby.GetPSNR(), 2), round(widened.GetIoU(), 4),
         round(nearby.GetIoU(), 4)))

# The proxy focal surface: every ray focused on the Depth pass's surface,
# blended from the nearest views in angle that see it (beyond the paper).
t.expect("fish swim, proxy", t.evaluate("swim, proxy", fish, fish_lf, swim, camera, focal=PROXY),
         *SWIM_PROXY)
between = t.side_camera(rig)
between.SetPosition(rig.GetCenter()[0] + 0.35 * rig.GetRadius(),
                    rig.GetCenter()[1] + 0.025 * rig.GetRadius(),
                    rig.GetCenter()[2] + 0.95 * rig.GetRadius())
t.expect("fish between rows, proxy",
         t.evaluate("rows, proxy", fish, fish_lf, None, between, focal=PROXY), *BETWEEN_ROWS_PROXY)

# Occlusion: the head box turned by 55 degrees towards, then away from, the
# camera. The head covers as many pixels as in the ground truth, and the
# turn that shows more head in the ground truth shows more head here too.
head_pixels = {}
for degrees in (55.0, -55.0):
    cage = lfd.vtkDeformationCage()
    cage.DeepCopy(rest)
    n = cage.GetNumberOfPoints()
    hinge = [0.0] * 3
    cage.GetRestPoint(n - 8, hinge)
    theta = math.radians(degrees)
    for pid in range(n - 4, n):
        r = [0.0] * 3
        cage.GetRestPoint(pid, r)
        dx, dz = r[0] - hinge[0], r[2]
        cage.SetDeformedPoint(pid, [hinge[0] + dx * math.cos(theta) - dz * math.sin(theta), r[1],
                                    dz * math.cos(theta) + dx * math.sin(theta)])
    why = cage.Validate(fish_lf)
    t.check(why == "", f"head turned {degrees:+.0f} validates", why or "ok")
    ev = t.evaluate(f"head {degrees:+.0f}", fish, fish_lf, cage, camera, focal=PLANE)
    labels = t.image_array(ev.GetOutput(0), "Label")[..., 0]
    truth = t.image_array(ev.GetOutput(1), "Label")[..., 0]
    head_pixels[degrees] = ((labels == 1).sum(), (truth == 1).sum())
    t.check(ev.GetLabelAgreement() > OCCLUSION_AGREEMENT,
            f"head {degrees:+.0f}: label agreement > {OCCLUSION_AGREEMENT}",
            ev.GetLabelAgreement())
t.check((head_pixels[-55.0][0] > head_pixels[55.0][0]) ==
        (head_pixels[-55.0][1] > head_pixels[55.0][1]),
        "the turn showing more head in the ground truth shows more head here",
        head_pixels)

# The figure (with its Depth pass: the proxy): twisted and bent.
figure, figure_lf = t.capture(lfd.vtkProceduralObjectSource.FIGURE, depth=True, Supersample=PREFILTER)
figure_parts = lfd.vtkPartCageSource()
figure_parts.SetInputConnection(figure.GetOutputPort())
figure_parts.Update()
camera = t.side_camera(figure_lf.GetRig(), azimuth=0.2, angle=26.0)
twist = t.pose(figure_parts.GetOutputPort(), lfd.vtkCagePoseFilter.TWIST, 45.0).GetOutput()
t.expect("figure twist", t.evaluate("figure twist", figure, figure_lf, twist, camera), *TWIST)
# Tessellation (beyond the paper): a 90-degree twist bends the inverse images
# of view rays; splitting the boxes into 2^3 sub-boxes (or the automatic
# choice, from the measured warp deviation) follows them better (measured,
# on the proxy: 17.56 -> 23.58 dB, SSIM 0.751 -> 0.916 at k = 2; 23.73 dB,
# SSIM 0.920 automatic; through the plane 16.42 -> 19.62, auto 19.79 dB).
strong = t.pose(figure_parts.GetOutputPort(), lfd.vtkCagePoseFilter.TWIST, 90.0).GetOutput()
plain = t.evaluate("twist 90 k=1", figure, figure_lf, strong, camera, 1)
split = t.evaluate("twist 90 k=2", figure, figure_lf, strong, camera, 2)
automatic = t.evaluate("twist 90 auto", figure, figure_lf, strong, camera, 0)
t.check(split.GetPSNR() > plain.GetPSNR() + 5.5, "subdivision 2 gains > 5.5 dB on a 90-degree twist",
        split.GetPSNR() - plain.GetPSNR())
t.check(split.GetSSIM() > plain.GetSSIM() + 0.15, "subdivision 2 gains > 0.15 SSIM",
        split.GetSSIM() - plain.GetSSIM())
t.check(automatic.GetPSNR() > plain.GetPSNR() + 5.5, "automatic subdivision gains > 5.5 dB",
        automatic.GetPSNR() - plain.GetPSNR())
bend = t.pose(figure_parts.GetOutputPort(), lfd.vtkCagePoseFilter.BEND, 30.0, (0, 0, 1)).GetOutput()
t.expect("figure bend", t.evaluate("figure bend", figure, figure_lf, bend, camera), *BEND)
t.finish()
