"""A volume with deep shadows in ParaView, as a pvbatch (or pvpython) script.

    . /opt/deepshadow-pvsdk/env.sh       # ParaView's SDK, from scripts/setup-paraview.sh
    DISPLAY=:140 pvbatch Examples/ParaView/shadowed_volume.py [VOLUME_FILE] [OUT.png]

Loads the DeepShadow plugin (DEEPSHADOW_PARAVIEW_PLUGIN, or the build tree's), reads the
volume (a file ParaView has a reader for: .vti, .mha, .vtk, ...; none: a Wavelet), shows it as a
"Shadowed Volume" with a deep shadow map cast by the view's key light, and saves a
screenshot. Under `mpirun -np N pvbatch` each rank draws its piece (shadows per piece).

shadowed_volume.pvsm beside it is the same scene as a ParaView state: load the plugin first
(Tools > Manage Plugins, or LoadPlugin), then File > Load State (or LoadState in a script).
"""
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetOpacityTransferFunction, LoadPlugin,
                             OpenDataFile, ResetCamera, SaveScreenshot, Show, Wavelet)

here = os.path.dirname(os.path.abspath(__file__))
plugin = os.environ.get("DEEPSHADOW_PARAVIEW_PLUGIN", os.path.join(
    here, "..", "..", "build-paraview", "lib", "paraview-5.11", "plugins", "DeepShadow", "DeepShadow.so"))
LoadPlugin(plugin, remote=False, ns=globals())

arguments = sys.argv[1:]
source = Wavelet()
if arguments and not arguments[0].endswith(".png"):
    path = arguments.pop(0)
    try:
        source = OpenDataFile(path)
    except RuntimeError:
        source = None
    if source is None or not (source.PointData.keys() or source.CellData.keys()):
        print(f"shadowed_volume: ParaView cannot read a volume from {path}")
        sys.exit(2)
output = arguments[0] if arguments else "shadowed_volume.png"

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [600, 600]
view.OrientationAxesVisibility = 0
display = Show(source, view)
display.Representation = "Shadowed Volume"
array = source.PointData.keys()[0] if source.PointData.keys() else source.CellData.keys()[0]
ColorBy(display, ("POINTS" if source.PointData.keys() else "CELLS", array))
low, high = source.GetDataInformation().GetPointDataInformation().GetArrayInformation(array).GetComponentRange(0) \
    if source.PointData.keys() else source.CellData[array].GetRange()
# Clear below the middle of the range, denser towards the top: something that casts.
middle = 0.5 * (low + high)
GetOpacityTransferFunction(array).Points = [low, 0.0, 0.5, 0.0, middle, 0.0, 0.5, 0.0, high, 0.8, 0.5, 0.0]
display.Shade = 1
display.ShadowTechnique = "dsm"             # none, rays, shadowmap, dsm, dsm-color, dsm3, cssm, ...-cached
display.ShadowParameters = "epsilon=0.02"  # KEY=VALUE pairs: the deepshadow tool's options
display.ShadowLights = 0                   # 0: the key light, 1: every light (at most four)
view.CameraPosition = [0, -3, 1.5]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
SaveScreenshot(output, view)
print("saved", output)
