"""Leave-one-out PSNR on a synthetic ring of the textured figure (120 views,
one row, 256x256): every 10th view is re-rendered from all the others and
compared with its capture, point-sampled and prefiltered (2 x 2 samples per
pixel, vtkLightFieldCapture::SetSupersample: the figure's fine texture is
aliased otherwise). Thresholds sit just under the measured figures (see the
README's results table), so a regression in sampling fails."""

import lfdtesting as t

import lfd

MEAN_PSNR = 26.0  # measured 26.48 dB (README results table)
MEAN_OBJECT_PSNR = 17.5  # measured 18.06 dB

PREFILTERED_MEAN_PSNR = 28.0  # measured 28.40 dB with 2 x 2 samples per pixel
PREFILTERED_MEAN_OBJECT_PSNR = 19.8  # measured 20.15 dB

figure = lfd.vtkProceduralObjectSource()
figure.SetObjectToFigure()


def leave_one_out(supersample, mean_psnr, mean_object_psnr):
    capture = lfd.vtkLightFieldCapture()
    capture.SetInputConnection(figure.GetOutputPort())
    capture.SetTextureConnection(figure.GetOutputPort(1))
    capture.SetNumberOfRows(1)
    capture.CaptureDepthOff()
    capture.SetSupersample(supersample)
    loo = lfd.vtkLeaveOneOutEvaluator()
    loo.SetInputConnection(capture.GetOutputPort())
    loo.SetStride(10)
    loo.Update()
    table = loo.GetOutput()
    print(f"{supersample} x {supersample} samples per pixel")
    for row in range(table.GetNumberOfRows()):
        print("view %3d  PSNR %6.2f  object PSNR %6.2f" % (table.GetValue(row, 0).ToInt(),
              table.GetValue(row, 1).ToDouble(), table.GetValue(row, 2).ToDouble()))
    t.check(table.GetNumberOfRows() == 12, "views evaluated", table.GetNumberOfRows())
    t.check(loo.GetMeanPSNR() > mean_psnr, f"{supersample}x{supersample}: mean PSNR > {mean_psnr} dB",
            loo.GetMeanPSNR())
    t.check(loo.GetMeanObjectPSNR() > mean_object_psnr,
            f"{supersample}x{supersample}: mean object PSNR > {mean_object_psnr} dB",
            loo.GetMeanObjectPSNR())


leave_one_out(1, MEAN_PSNR, MEAN_OBJECT_PSNR)
leave_one_out(2, PREFILTERED_MEAN_PSNR, PREFILTERED_MEAN_OBJECT_PSNR)
t.finish()
