"""Leave-one-out PSNR on real data: the Middlebury templeRing (Seitz, Curless,
Diebel, Scharstein and Szeliski, CVPR 2006), 47 views on the Stanford
Spherical Gantry. Every view is re-rendered from the others (its
near-duplicates excluded too) with the real, imperfect calibration."""


import lfdtesting as t

import lfd

MEAN_PSNR = 22.5  # measured 22.91 dB (README results table)
MEAN_OBJECT_PSNR = 18.5  # measured 18.86 dB

importer = t.templering("templeRing leave-one-out")
if importer:
    loo = lfd.vtkLeaveOneOutEvaluator()
    loo.SetInputConnection(importer.GetOutputPort())
    loo.Update()
    table = loo.GetOutput()
    for row in range(table.GetNumberOfRows()):
        print("view %3d  PSNR %6.2f  object PSNR %6.2f  object px %6d" % (
            table.GetValue(row, 0).ToInt(), table.GetValue(row, 1).ToDouble(),
            table.GetValue(row, 2).ToDouble(), table.GetValue(row, 3).ToInt()))
    t.check(table.GetNumberOfRows() == 47, "views evaluated", table.GetNumberOfRows())
    t.check(loo.GetMeanPSNR() > MEAN_PSNR, f"mean PSNR > {MEAN_PSNR} dB", loo.GetMeanPSNR())
    t.check(loo.GetMeanObjectPSNR() > MEAN_OBJECT_PSNR, f"mean object PSNR > {MEAN_OBJECT_PSNR} dB",
            loo.GetMeanObjectPSNR())
t.finish()
