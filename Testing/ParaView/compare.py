"""Compares PNGs written by the ParaView tests (system python3, VTK 9.1's PNG reader).
  compare.py diff A.png B.png MAX_RMSE MAX_FRACTION   difference within bounds (beyond 8/255)
  compare.py darker SHADOWED.png LIT.png FACTOR       the foreground's mean at most FACTOR of LIT's
  compare.py drawn PICTURE.png FRACTION               at least FRACTION of its pixels differ from the corner's
  compare.py darker-in X0 Y0 X1 Y1 SHADOWED.png LIT.png FACTOR
                                                      the same in a box (fractions of the width and height,
                                                      from the top left), every pixel of it
Prints the figures; exit 1 when the bound is not met."""
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def load(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(float) / 255.0


def main():
    if sys.argv[1] == "darker-in":
        x0, y0, x1, y1 = (float(v) for v in sys.argv[2:6])
        a, b, factor = sys.argv[6], sys.argv[7], float(sys.argv[8])
        first, second = load(a)[::-1], load(b)[::-1]  # rows from the top
        height, width, _ = first.shape
        box = (slice(int(y0 * height), int(y1 * height)), slice(int(x0 * width), int(x1 * width)))
        shadowed, lit = float(first[box].mean()), float(second[box].mean())
        ok = shadowed <= factor * lit
        print(f"{a}: box {x0}-{x1} x {y0}-{y1} mean {shadowed:.4f} against {lit:.4f} (<= {factor} of it): "
              f"{'ok' if ok else 'FAILED'}")
        sys.exit(0 if ok else 1)
    if sys.argv[1] == "drawn":
        picture, fraction = load(sys.argv[2]), float(sys.argv[3])
        drawn = float(numpy.mean(numpy.abs(picture - picture[0, 0]).max(axis=2) > 8.0 / 255.0))
        ok = drawn >= fraction
        print(f"{sys.argv[2]}: {100 * drawn:.1f}% of pixels drawn (>= {100 * fraction:.1f}%): {'ok' if ok else 'FAILED'}")
        sys.exit(0 if ok else 1)
    mode, a, b = sys.argv[1:4]
    first, second = load(a), load(b)
    if mode == "diff":
        max_rmse, max_fraction = float(sys.argv[4]), float(sys.argv[5])
        difference = numpy.abs(first - second)
        rmse = float(numpy.sqrt(numpy.mean(difference ** 2)))
        fraction = float(numpy.mean(difference.max(axis=2) > 8.0 / 255.0))
        ok = rmse <= max_rmse and fraction <= max_fraction
        print(f"{a} vs {b}: RMSE {rmse:.4f} (<= {max_rmse}), {100 * fraction:.2f}% of pixels beyond 8/255 "
              f"(<= {100 * max_fraction:.2f}%), largest {difference.max() * 255:.0f}/255: {'ok' if ok else 'FAILED'}")
    else:
        factor = float(sys.argv[4])
        background = second[0, 0]
        foreground = numpy.abs(second - background).max(axis=2) > 8.0 / 255.0
        shadowed, lit = float(first[foreground].mean()), float(second[foreground].mean())
        ok = foreground.mean() > 0.05 and shadowed <= factor * lit
        print(f"{a}: foreground ({100 * foreground.mean():.1f}% of pixels) mean {shadowed:.4f} against {lit:.4f} "
              f"unshadowed (<= {factor} of it): {'ok' if ok else 'FAILED'}")
    sys.exit(0 if ok else 1)


main()
