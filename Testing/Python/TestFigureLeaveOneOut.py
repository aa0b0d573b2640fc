"""Leave-one-out PSNR on a synthetic ring of the textured figure (120 views,
one row, 256x256): every 10th view is re-rendered from all the others and
compared with its capture. Thresholds sit just under the measured figures
(see the README's results table), so a regression in sampling fails."""

import lfdtesting as t

import lfd

MEAN_PSNR = 26.0  # measured 26.48 dB (README results table)
MEAN_OBJECT_PSNR = 17.5  # measured 18.06 dB

figure = lfd.vtkProceduralObjectSource()
figure.SetObjectToFigure()
capture = lfd.vtkLightFieldCapture()
capture.SetInputConnection(figure.GetOutputPort())
capture.SetTextureConnection(figure.GetOutputPort(1))
capture.SetNumberOfRows(1)
capture.CaptureDepthOff()

loo = lfd.vtkLeaveOneOutEvaluator()
loo.SetInputConnection(capture.GetOutputPort())
loo.SetStride(10)
loo.Update()
table = loo.GetOutput()
for row in range(table.GetNumberOfRows()):
    print("view %3d  PSNR %6.2f  object PSNR %6.2f" % (table.GetValue(row, 0).ToInt(),
          table.GetValue(row, 1).ToDouble(), table.GetValue(row, 2).ToDouble()))
t.check(table.GetNumberOfRows() == 12, "views evaluated", table.GetNumberOfRows())
t.check(loo.GetMeanPSNR() > MEAN_PSNR, f"mean PSNR > {MEAN_PSNR} dB", loo.GetMeanPSNR())
t.check(loo.GetMeanObjectPSNR() > MEAN_OBJECT_PSNR, f"mean object PSNR > {MEAN_OBJECT_PSNR} dB",
        loo.GetMeanObjectPSNR())
t.finish()
