"""Runs an example script (RunExample.py EXAMPLE.py OUT.png) the way a user does, in a fresh
interpreter, and checks the picture it wrote: there, and not a blank or one-colour image."""
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

example, out = sys.argv[1], sys.argv[2]
if os.path.exists(out):
    os.remove(out)
arguments = [sys.executable, example] + (["", out] if "MedicalVolume" in example else [out])
result = subprocess.run(arguments, capture_output=True, text=True, timeout=600)
sys.stdout.write(result.stdout)
sys.stderr.write(result.stderr)
if result.returncode != 0:
    sys.exit("%s exited %d" % (example, result.returncode))
if not os.path.exists(out):
    sys.exit("%s wrote no %s" % (example, out))
reader = vtkPNGReader()
reader.SetFileName(out)
reader.Update()
pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3]
corner = pixels[0]
share = (abs(pixels.astype(int) - corner).sum(axis=1) > 6).mean()
colours = len({tuple(p) for p in pixels[::7]})
print("%s: %.1f %% of the pixels differ from the corner's, %d colours" % (out, 100 * share, colours))
if share < 0.05 or colours < 50:
    sys.exit("%s is blank or nearly so" % out)
