"""`lfd camera-sim` (issue 12, item 2): the simulated rig camera served by the
lfd tool as a separate process on 127.0.0.1, started and stopped here by pid.
A frame acquired over GigE Vision with lfd.vtkAravisCamera at gantry angle
150 degrees under the projector's flood light (the projector is at 180
degrees) matches view 5 (150 degrees) of
the synthetic light field it simulates; Ctrl-C stops the camera cleanly; a
light that does not exist is one error line. (A second camera on the same
address and an address that is not local: TestAravisCameraErrors.)"""
import os
import shutil
import signal
import subprocess

import lfd
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData

import lfdtesting as t

folder = t.temp_path("camera-sim", "fish.lf")
shutil.rmtree(folder, ignore_errors=True)
synth = subprocess.run([t.LFD, "synth", "--object", "fish", "--views", "12", "--rows", "1",
                        "--width", "64", "--height", "64", "--projectors", "1", "--no-depth",
                        "--out", folder], capture_output=True, text=True)
t.check(synth.returncode == 0, "lfd synth of a 12-view ring", synth.returncode or "ok")

server = subprocess.Popen([t.LFD, "camera-sim", "--lightfield", folder, "--light", "flood",
                           "--angle", "150", "--seconds", "120"],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
try:
    banner = server.stdout.readline().strip()
    t.check(banner.startswith("Serving the GigE Vision camera LFD-SIM on 127.0.0.1"),
            "camera-sim serves", banner)

    camera = lfd.vtkAravisCamera()
    camera.SetAddress("127.0.0.1")
    errors = t.error_observer(camera)
    frame = vtkImageData()
    acquired = camera.Open() and camera.Acquire(frame)
    t.check(acquired, "a frame acquired over GigE Vision", errors.GetErrorMessage() or "ok")
    camera.Close()
    if acquired:
        got = vtk_to_numpy(frame.GetPointData().GetScalars()).reshape(64, 64, 3)  # top row first
        reader = lfd.vtkLightFieldReader()
        reader.SetFileName(folder)
        reader.Update()
        flood = reader.GetOutput().GetPass(lfd.vtkLightField.FLOOD)
        view = vtk_to_numpy(flood).reshape(12, 64, 64, 3)[5][::-1]
        t.check(np.count_nonzero(view.max(axis=2) > 20) > 200, "view 5 Flood shows the object",
                np.count_nonzero(view.max(axis=2) > 20))
        psnr = t.psnr(got, view)
        t.check(psnr > 45.0, "PSNR of the frame at 150 degrees against view 5 Flood (dB)", psnr)
        wrong = t.psnr(got, vtk_to_numpy(flood).reshape(12, 64, 64, 3)[4][::-1])
        t.check(wrong < 30.0, "PSNR against view 4 Flood (dB, a different view)", wrong)
finally:
    server.send_signal(signal.SIGINT)
    out, err = server.communicate(timeout=30)
t.check(server.returncode == 0 and out.strip().endswith("Stopped after 1 frames."),
        "Ctrl-C stops the camera after its one frame", (server.returncode, out.strip()[-40:]))

bad = subprocess.run([t.LFD, "camera-sim", "--lightfield", folder, "--light", "sparkle"],
                     capture_output=True, text=True)
t.check(bad.returncode == 1 and bad.stderr.strip() ==
        "lfd: error: --light 'sparkle': expected coaxial, coded, flood or none",
        "an unknown light is one error", bad.stderr.strip())
t.finish()
