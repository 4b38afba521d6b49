#!/usr/bin/env python3
"""Shadow-edge error of pictures against an exact one.

    edge-error.py EXACT.png UNSHADOWED.png PICTURE.png...

The RMSE, over RGB in [0, 1], of each picture against EXACT on the pixels within 2 of a
shadow edge on a receiver: where EXACT's luminance steps by more than 0.1 between
neighbours, and UNSHADOWED's (the same view without shadows) does not step by more than
0.03 within 3 pixels (object silhouettes and texture are no shadow edges)."""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def load(path):
    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        sys.exit("edge-error: cannot read " + path)
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3] / 255.0


def steps(image, threshold):
    lum = image.mean(axis=2)
    step = np.zeros_like(lum)
    step[1:-1, 1:-1] = np.maximum(np.abs(lum[2:, 1:-1] - lum[:-2, 1:-1]), np.abs(lum[1:-1, 2:] - lum[1:-1, :-2]))
    return step > threshold


def grow(mask, radius):
    grown = mask.copy()
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            grown |= np.roll(np.roll(mask, dy, 0), dx, 1)
    return grown


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    exact, unshadowed = load(sys.argv[1]), load(sys.argv[2])
    edges = grow(steps(exact, 0.1), 2) & ~grow(steps(unshadowed, 0.03), 3)
    for path in sys.argv[3:]:
        picture = load(path)
        if picture.shape != exact.shape:
            sys.exit("edge-error: %s is not the size of %s" % (path, sys.argv[1]))
        rmse = np.sqrt(((picture - exact)[edges] ** 2).mean())
        print("%-40s edge RMSE %.4f over %d pixels" % (path.split("/")[-1], rmse, edges.sum()))


main()
