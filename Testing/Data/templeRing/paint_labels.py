"""Paints the templeRing label images used by the propagation tests.

A stand-in for a user's brush, kept so the committed PNGs can be remade:
in a view of the Middlebury templeRing the cameras are rolled ~90 degrees
(views 0-28 one way, 29-46 the other), so the ring's axis is the image's x
axis, pointing left or right. The temple is the pixels brighter than 60
(mean RGB), painted in three bands of its extent along that axis: label 1
(the first 22 %), label 2 (up to 62 %) and label 3 (the rest), counted from
the same end of the temple in every view. The tests apply the same rule to
every view to measure how consistent the propagated labels are. Usage,
from a build tree:

    lfd import middlebury .../templeR_par.txt --out temple.lf
    python3 paint_labels.py temple.lf 0 16 32
"""
import json
import sys

import numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.util.numpy_support import vtk_to_numpy, numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData

THRESHOLD = 60
BANDS = (0.22, 0.62)


def axis_signs(dataset):
    """Per view, +1 or -1: the direction of the ring's axis along image x."""
    views = json.load(open(f"{dataset}/lightfield.json"))["views"]
    rotations = [np.array(v["R"]).reshape(3, 3) for v in views]
    centres = np.array([-R.T @ np.array(v["t"]) for R, v in zip(rotations, views)])
    normal = np.linalg.svd(centres - centres.mean(axis=0))[2][2]
    return [1.0 if R.T[:, 0] @ normal < 0.0 else -1.0 for R in rotations]


def paint(rgb, sign):
    """Label image (VTK row order) of one RGB view (VTK row order)."""
    grey = rgb.mean(axis=2)
    mask = grey > THRESHOLD
    columns = np.nonzero(mask.sum(axis=0) > 2)[0]
    left, right = columns.min(), columns.max()
    x = (np.arange(rgb.shape[1]) - left) / float(right - left)
    x = x if sign > 0 else 1.0 - x
    band = np.where(x < BANDS[0], 1, np.where(x < BANDS[1], 2, 3))
    return np.where(mask, band[None, :], 0).astype(np.uint8)


def main(dataset, views):
    signs = axis_signs(dataset)
    for view in views:
        reader = vtkPNGReader()
        reader.SetFileName(f"{dataset}/coaxial/view_{view:04d}.png")
        reader.Update()
        image = reader.GetOutput()
        w, h, _ = image.GetDimensions()
        rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[..., :3]
        labels = paint(rgb.astype(float), signs[view])
        out = vtkImageData()
        out.SetDimensions(w, h, 1)
        out.GetPointData().SetScalars(numpy_to_vtk(labels.ravel(), deep=True))
        writer = vtkPNGWriter()
        writer.SetInputData(out)
        writer.SetFileName(f"painted_view_{view:04d}.png")
        writer.Write()


if __name__ == "__main__":
    main(sys.argv[1], [int(v) for v in sys.argv[2:]])
