"""The geometric proxy (issue 11 item 3): vtkLightFieldProxy estimates a
Depth pass from a light field without one (visual hull + plane sweep); it is
checked against the capture's true depth, and the renderer's proxy focal
surface through it is checked against the plane on a view left out. `lfd
proxy` writes it; `lfd render --focal proxy` refuses a light field without
a depth pass in one line; a recorded Depth pass is kept."""

import json
import os
import shutil

import lfdtesting as t
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import lfd

# Measured: 80.8 % of the object pixels within 2 % of the true depth after
# the plane sweep, 71.5 % from the visual hull alone (the fish is nearly
# convex); leave-one-out of 4 views, object PSNR: plane 16.16 dB, estimated
# proxy 19.20 dB, true depth 18.56 dB.
WITHIN = 0.79
SWEEP_GAIN = 0.07
GAIN = 2.5

WORK = t.temp_path("proxy", "x")
shutil.rmtree(os.path.dirname(WORK), ignore_errors=True)
os.makedirs(os.path.dirname(WORK))

fish, truth = t.capture(lfd.vtkProceduralObjectSource.FISH, depth=True, NumberOfRows=1,
                        ViewsPerRing=36, Width=96, Height=96)
true_depth = vtk_to_numpy(truth.GetPass(lfd.vtkLightField.DEPTH))
plain = lfd.vtkLightField()
plain.ShallowCopy(truth)
plain.GetPointData().RemoveArray("Depth")


def estimate(steps):
    proxy = lfd.vtkLightFieldProxy()
    proxy.SetInputData(plain)
    proxy.SetSweepSteps(steps)
    proxy.Update()
    return proxy


def within(proxy, fraction):
    """Fraction of the object pixels (true depth > 0) whose estimate is
    within `fraction` of the true depth."""
    estimated = vtk_to_numpy(proxy.GetOutput().GetPass(lfd.vtkLightField.DEPTH))
    mask = true_depth > 0
    return float((np.abs(estimated[mask] - true_depth[mask]) < fraction * true_depth[mask]).mean())


hull = within(estimate(1), 0.02)
proxy = estimate(24)
swept = within(proxy, 0.02)
t.check(swept > WITHIN, f"plane sweep: > {WITHIN} of the object pixels within 2 % of the true depth",
        round(swept, 4))
t.check(swept > hull + SWEEP_GAIN, f"the sweep adds > {SWEEP_GAIN} to the hull's fraction",
        (round(swept, 4), round(hull, 4)))

# Leave-one-out through the plane, the estimated proxy and the true depth.
psnr = {}
for name, lf, focal in (("plane", plain, 1), ("estimated", proxy.GetOutput(), 2),
                        ("true depth", truth, 2)):
    loo = lfd.vtkLeaveOneOutEvaluator()
    loo.SetInputData(lf)
    loo.SetFocalSurface(focal)
    loo.SetStride(9)
    loo.Update()
    psnr[name] = round(loo.GetMeanObjectPSNR(), 2)
print("leave-one-out object PSNR:", psnr)
t.check(psnr["estimated"] > psnr["plane"] + GAIN,
        f"the estimated proxy gains > {GAIN} dB over the plane", psnr)

# A recorded Depth pass is the proxy, unchanged.
kept = lfd.vtkLightFieldProxy()
kept.SetInputData(truth)
kept.Update()
t.check(kept.GetOutput().GetPass(lfd.vtkLightField.DEPTH) is truth.GetPass(lfd.vtkLightField.DEPTH),
        "a recorded Depth pass is kept", "same array")

# The command line: lfd proxy writes the depth pass; render --focal proxy
# needs one.
source = os.path.join(os.path.dirname(WORK), "fish.lf")
writer = lfd.vtkLightFieldWriter()
writer.SetInputData(plain)
writer.SetDirectory(source)
writer.Write()
out = os.path.join(os.path.dirname(WORK), "fish-proxy.lf")
code, stdout, stderr = t.run_lfd("proxy", source, "--out", out, "--sweep-steps", "8")
manifest = json.load(open(os.path.join(out, "lightfield.json"))) if code == 0 else {}
t.check(code == 0 and "depth" in manifest.get("passes", {}) and "estimated" in stdout,
        "lfd proxy writes the depth pass", (code, stdout.strip(), stderr.strip()[-200:]))
scene = os.path.join(os.path.dirname(WORK), "scene.json")
with open(scene, "w") as f:
    json.dump({"format": "lfd-scene", "version": 1, "lightfield": "fish.lf",
               "camera": {"position": [0.3, 0.0, 2.0], "focal_point": [0, 0, 0],
                          "view_up": [0, 1, 0], "width": 32, "height": 32},
               "render": {"focal": "proxy"}}, f)
code, _, stderr = t.run_lfd("render", scene, "--out", os.path.join(os.path.dirname(WORK), "a.png"))
errors = [line for line in stderr.splitlines() if line.startswith("lfd: error:")]
t.check(code == 1 and len(errors) == 1 and "no float Depth pass: compute one with `lfd proxy`" in errors[0],
        "render.focal proxy without a depth pass: one error line", errors)
code, stdout, stderr = t.run_lfd("render", scene, "--focal", "plane", "--out",
                                 os.path.join(os.path.dirname(WORK), "a.png"))
t.check(code == 0, "--focal plane overrides the scene's render.focal", (code, stderr.strip()[-200:]))
code, _, stderr = t.run_lfd("render", scene, "--focal", "plane", "--antialiasing", "maybe",
                            "--out", os.path.join(os.path.dirname(WORK), "a.png"))
t.check(code != 0 and "--antialiasing: maybe not in {on,off}" in stderr,
        "--antialiasing takes on or off", (code, stderr.strip()[-200:]))

# lfd eval loo --focal: the evaluator's focal surface, as vtkLeaveOneOutEvaluator above.
loo_psnr = {}
for focal in ("plane", "proxy"):
    code, stdout, stderr = t.run_lfd("eval", "loo", out, "--stride", "9", "--focal", focal)
    mean = [line.split() for line in stdout.splitlines() if line.startswith("mean")]
    loo_psnr[focal] = float(mean[0][2]) if code == 0 and mean else stderr.strip()[-200:]
t.check(all(isinstance(v, float) for v in loo_psnr.values()) and
        loo_psnr["plane"] == psnr["plane"] and loo_psnr["proxy"] > psnr["plane"] + 1.0,
        "lfd eval loo --focal plane is the evaluator's plane; --focal proxy gains > 1 dB",
        (loo_psnr, psnr["plane"]))
t.finish()
