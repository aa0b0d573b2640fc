"""`lfd capture --simulate` (issue 12, item 4) end to end: the gantry
simulator (Modbus TCP, a free port) and the simulated rig camera (GigE
Vision, 127.0.0.1) served by the lfd process, 12 positions x 3 passes of a
36-view ring of `lfd synth` with 2 projectors. The process is killed with
SIGKILL mid-capture: the dataset then lists only complete views, every listed
image is whole; resumed and stopped with Ctrl-C (SIGINT) after the current
view; `--resume` completes it with no view lost or duplicated
(each image once, no temporary left). The capture matches `lfd synth`'s
views of the same positions (PSNR) and `lfd split projector` labels it. The
coaxial lamp is switched on coil 5 of the simulator over Modbus
(--coaxial-coil), the simulated camera sees that coil: the Coaxial pass lit
and the others dark prove it followed the passes. Bad input: an unreachable
gantry, and --coaxial-lamp with --simulate, are one error each naming them."""
import glob
import json
import os
import shutil
import signal
import subprocess
import time

import lfd
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import lfdtesting as t

folder = t.temp_path("capture-command")
shutil.rmtree(folder, ignore_errors=True)
os.makedirs(folder)
ref, out = os.path.join(folder, "ref.lf"), os.path.join(folder, "cap.lf")
synth = subprocess.run([t.LFD, "synth", "--object", "fish", "--views", "36", "--rows", "1",
                        "--width", "48", "--height", "48", "--projectors", "2", "--no-depth",
                        "--out", ref], capture_output=True, text=True)
t.check(synth.returncode == 0, "lfd synth of a 36-view ring with 2 projectors",
        synth.returncode or "ok")
capture = [t.LFD, "capture", "--simulate", "--gantry", "127.0.0.1:0", "--rig", ref,
           "--views", "12", "--projectors", "2", "--out", out,
           "--velocity", "600", "--acceleration", "6000", "--coaxial-coil", "5"]


def listed_views():
    try:
        with open(os.path.join(out, "lightfield.json")) as f:
            return len(json.load(f)["views"])
    except (OSError, ValueError, KeyError):
        return 0


# Killed once 3 views are complete.
process = subprocess.Popen(capture, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
deadline = time.time() + 60
while listed_views() < 3 and process.poll() is None and time.time() < deadline:
    time.sleep(0.05)
process.send_signal(signal.SIGKILL)
process.communicate()
killed_at = listed_views()
t.check(3 <= killed_at < 12, "killed mid-capture: views listed", killed_at)
images = sorted(glob.glob(os.path.join(out, "*", "view_*.png")))
reader = lfd.vtkLightFieldReader()
reader.SetFileName(out)
errors = t.error_observer(reader)
reader.Update()
t.check(not errors.GetErrorMessage() and reader.GetOutput().GetNumberOfViews() == killed_at,
        "the killed capture reads back with its listed views",
        errors.GetErrorMessage() or reader.GetOutput().GetNumberOfViews())

# Resumed, then Ctrl-C once a view more is complete: stops after the view
# being taken.
process = subprocess.Popen(capture + ["--resume"], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
deadline = time.time() + 60
while listed_views() <= killed_at and process.poll() is None and time.time() < deadline:
    time.sleep(0.05)
process.send_signal(signal.SIGINT)
_, err = process.communicate(timeout=60)
interrupted_at = listed_views()
t.check(process.returncode == 1 and killed_at < interrupted_at < 12 and
        f"lfd: error: interrupted: {interrupted_at} of 12 views complete in '{out}'; continue "
        "with --resume" in err, "Ctrl-C stops after the current view",
        err.strip().splitlines()[-1:])

resumed = subprocess.run(capture + ["--resume"], capture_output=True, text=True)
t.check(resumed.returncode == 0 and
        f"Captured 12 views x 3 passes into {out} ({12 - interrupted_at} of them now; "
        f"{interrupted_at} were complete)" in resumed.stdout,
        "--resume completes the capture", resumed.stdout.strip() or resumed.stderr.strip())
print(resumed.stdout.strip())
names = sorted(os.path.relpath(p, out) for p in glob.glob(os.path.join(out, "**", "*"),
                                                             recursive=True)
               if os.path.isfile(p))
expected = sorted([f"{p}/view_{v:04d}.png" for p in ("coaxial", "coded", "flood")
                   for v in range(12)] +
                  ["capture.json", "lightfield.json", "projectors/mask_0000.png",
                   "projectors/mask_0001.png"])
t.check(names == expected, "each view's 3 images once, no temporary, nothing else",
        [n for n in names if n not in expected] + [n for n in expected if n not in names])

# The capture against lfd synth's views 0, 3, ..., 33 of the same rig.
reader.Modified()
reader.Update()
captured = reader.GetOutput()
synthetic = lfd.vtkLightFieldReader()
synthetic.SetFileName(ref)
synthetic.Update()
for pass_ in (lfd.vtkLightField.COAXIAL, lfd.vtkLightField.CODED, lfd.vtkLightField.FLOOD):
    got = vtk_to_numpy(captured.GetPass(pass_)).reshape(12, 48, 48, 3)
    want = vtk_to_numpy(synthetic.GetOutput().GetPass(pass_)).reshape(36, 48, 48, 3)[::3]
    psnr = t.psnr(got, want)
    t.check(psnr > 40.0, "PSNR of the captured %s against lfd synth (dB)"
            % lfd.vtkLightField.GetPassName(pass_), psnr)

split = subprocess.run([t.LFD, "split", "projector", out, "--out",
                        os.path.join(folder, "split.lf")],
                       capture_output=True, text=True)
t.check(split.returncode == 0, "lfd split projector of the capture",
        split.returncode or split.stdout.strip().splitlines()[-1:])
# A gantry that is not there: one error naming it, nothing written.
refused = subprocess.run([t.LFD, "capture", "--gantry", "127.0.0.1:1", "--camera", "127.0.0.1",
                          "--rig", ref, "--views", "12", "--out",
                          os.path.join(folder, "refused.lf")], capture_output=True, text=True)
error_lines = [line for line in refused.stderr.splitlines() if "error" in line]
t.check(refused.returncode == 1 and error_lines == [
    "lfd: error: preparing the gantry: gantry 127.0.0.1:1: cannot connect: Connection refused "
    "(3 attempts)"] and not os.path.exists(os.path.join(folder, "refused.lf")),
    "an unreachable gantry: one error naming it, nothing written", error_lines)
# The simulated lamp is on the simulator's coil: no other lamp device.
lamp = subprocess.run([t.LFD, "capture", "--simulate", "--gantry", "127.0.0.1:0", "--rig", ref,
                       "--views", "12", "--out", os.path.join(folder, "lamp.lf"),
                       "--coaxial-coil", "5", "--coaxial-lamp", "127.0.0.1:502"],
                      capture_output=True, text=True)
t.check(lamp.returncode == 1 and [line for line in lamp.stderr.splitlines() if "error" in line] == [
    "lfd: error: --coaxial-lamp '127.0.0.1:502': not with --simulate (the simulated lamp is on "
    "a coil of the gantry simulator)"] and not os.path.exists(os.path.join(folder, "lamp.lf")),
    "--coaxial-lamp with --simulate: one error", lamp.stderr.strip())
t.finish()
