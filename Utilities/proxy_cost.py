"""The proxy's cost against the plane (README, "Focal surface: a per-pixel
proxy"): `lfd bench`'s fish light field (with its Depth pass), its orbit
camera, 256x256, at rest and swimming, rendered through the focal plane and
the proxy in turn, so that the machine's load falls on both alike; the
figure is the process's CPU time (all threads), which a loaded machine
does not stretch as it stretches the wall clock. Prints the median of N
renders each and the ratio.

  xvfb-run -a bin/lfd synth --object fish --views 120 --rows 3 --out fish3.lf
  PYTHONPATH=lib/python3/dist-packages /usr/bin/python3 ../Utilities/proxy_cost.py fish3.lf [N]
"""

import statistics
import sys
import time

from vtkmodules.vtkRenderingCore import vtkCamera

import lfd

repeat = int(sys.argv[2]) if len(sys.argv) > 2 else 9
reader = lfd.vtkLightFieldReader()
reader.SetFileName(sys.argv[1])
reader.Update()
rig = reader.GetOutput().GetRig()
camera = vtkCamera()
lfd.vtkLightFieldSceneLogic.OrbitCamera(rig, 0.37, 1.2, 0.0, rig.GetViewAngle(0), camera)
source = lfd.vtkProceduralObjectSource()
source.SetObjectToFish()
parts = lfd.vtkPartCageSource()
parts.SetInputConnection(source.GetOutputPort())
swim = lfd.vtkCagePoseFilter()  # lfd bench's swim
swim.SetInputConnection(parts.GetOutputPort())
swim.SetModeToSwim()
swim.SetAngle(20.0)
swim.SetPhase(1.0)
swim.SetTurnAxis(0.0, 0.0, 1.0)
swim.Update()
focal = {"plane": lfd.vtkLightFieldRenderer.FOCAL_PLANE,
         "proxy": lfd.vtkLightFieldRenderer.FOCAL_PROXY}
renderers = {}
for surface in focal:
    for pose in ("rest", "swim"):
        renderer = lfd.vtkLightFieldRenderer()
        renderer.SetInputConnection(reader.GetOutputPort())
        renderer.SetCamera(camera)
        renderer.SetWidth(256)
        renderer.SetHeight(256)
        renderer.SetFocalSurface(focal[surface])
        if pose == "swim":
            renderer.SetCageData(swim.GetOutput())
        renderer.Update()  # the proxy's bounds and tiles are built once, not timed
        renderers[(surface, pose)] = renderer
times = {key: [] for key in renderers}
for _ in range(repeat):
    for key, renderer in renderers.items():
        renderer.Modified()
        start = time.process_time()
        renderer.Update()
        times[key].append(time.process_time() - start)
ms = {key: 1000.0 * statistics.median(values) for key, values in times.items()}
for pose in ("rest", "swim"):
    print(f"{pose}: plane {ms[('plane', pose)]:.1f} ms, proxy {ms[('proxy', pose)]:.1f} ms CPU, "
          f"{ms[('proxy', pose)] / ms[('plane', pose)]:.2f}x")
