"""Issue 11's figure targets against ground truth (vtkGroundTruthEvaluator,
object pixels of 256x256 renders): the figure twisted 45 degrees and bent 30
degrees (target 26 dB), and at rest from a camera between two rows (target
30 dB), rendered with the defaults of this version (the Depth pass as the
focal surface, subdivision auto, anti-aliased silhouettes) from the capture
of lfdtesting.fine_figure: 512x512 views, prefiltered, so that resampling
the views does not bound the figure's fine texture. The paper's render
(focal plane, k = 1, hard label edges) of the twist is measured too, the
"before" of the README's picture. Thresholds sit just under the measured
figures (README results table)."""

import lfdtesting as t

import lfd

SIZE = 256
# (PSNR dB, SSIM, IoU), measured 2026-11-26: rest 31.57 / 0.985 / 0.982;
# between rows 30.26 / 0.983 / 0.991; bend 30 31.86 / 0.986 / 0.983; twist 45
# 31.14 / 0.981 / 0.970; the paper's twist (plane, k = 1, hard edges) 18.55 /
# 0.839 / 0.944.
REST = (31.3, 0.982, 0.979)
BETWEEN_ROWS = (30.0, 0.980, 0.988)
BEND = (31.6, 0.983, 0.980)
TWIST = (30.9, 0.978, 0.967)
PAPER_TWIST_GAP = 5.0  # the defaults gain more than this over the paper's render

source, lf, parts, camera, between = t.fine_figure(SIZE)
t.expect("rest", t.evaluate("rest", source, lf, None, camera, 0, SIZE), *REST)
t.expect("between rows", t.evaluate("between rows", source, lf, None, between, 0, SIZE),
         *BETWEEN_ROWS)
bend = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.BEND, 30.0, (0, 0, 1)).GetOutput()
t.expect("bend 30", t.evaluate("bend 30 auto", source, lf, bend, camera, 0, SIZE), *BEND)
twist = t.pose(parts.GetOutputPort(), lfd.vtkCagePoseFilter.TWIST, 45.0).GetOutput()
defaults = t.evaluate("twist 45 auto", source, lf, twist, camera, 0, SIZE)
t.expect("twist 45", defaults, *TWIST)
paper = t.evaluate("twist 45 paper", source, lf, twist, camera, 1, SIZE, anti_aliasing=False,
                   focal=lfd.vtkLightFieldRenderer.FOCAL_PLANE)
t.check(defaults.GetPSNR() > paper.GetPSNR() + PAPER_TWIST_GAP,
        f"the defaults gain > {PAPER_TWIST_GAP} dB over the paper's render of the twist",
        (defaults.GetPSNR(), paper.GetPSNR()))
t.finish()
