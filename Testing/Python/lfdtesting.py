"""Helpers shared by the end-to-end tests: paths from the CTest environment,
numpy views of VTK arrays and exact-result checks."""

import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy

BASELINE_DIR = os.environ.get("LFD_BASELINE_DIR", "")
TEMP_DIR = os.environ.get("LFD_TEMP_DIR", "/tmp")
SHARED_DATA_DIR = os.environ.get("LFD_SHARED_DATA_DIR", "")
LFD = os.environ.get("LFD_EXECUTABLE", "lfd")

failures = []


def check(condition, what, value):
    """Prints the measured value and records a failure."""
    print(("ok   " if condition else "FAIL ") + f"{what}: {value}")
    if not condition:
        failures.append(what)


def finish():
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")


def image_array(image, name=None):
    """(H, W, C) numpy view of an image's scalars (or named array), top row first."""
    data = image.GetPointData()
    array = data.GetArray(name) if name else data.GetScalars()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(array).reshape(h, w, -1)[::-1]


def temp_path(*parts):
    path = os.path.join(TEMP_DIR, *parts)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    return path
