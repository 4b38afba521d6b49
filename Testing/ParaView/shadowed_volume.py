"""pvbatch: a Wavelet drawn by the DeepShadow plugin's "Shadowed Volume" representation (or
ParaView's own "Volume"), shaded, saved to a PNG. Arguments: PLUGIN OUTPUT.png
REPRESENTATION [TECHNIQUE [SHADOW_LIGHTS [cells] [ground] [bad-key] [unshaded] [gather]]]: "cells"
colours by the Wavelet's values as cell data, "ground" adds the representation's shadow ground
below it (-Z), "bad-key" gives the technique a parameter no technique has, "unshaded" leaves
Shade off (ParaView's default), "gather" has the ranks gather their shadows instead of
scanning them. Under mpirun every rank holds a brick of it."""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetOpacityTransferFunction,
                             LoadPlugin, PointDatatoCellData, Render, ResetCamera, SaveScreenshot, Show,
                             Wavelet)

plugin, output, representation = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())
wavelet = Wavelet()
wavelet.WholeExtent = [-24, 24, -24, 24, -24, 24]
cells = "cells" in sys.argv[6:]
ground = "ground" in sys.argv[6:]
bad_key = "bad-key" in sys.argv[6:]
unshaded = "unshaded" in sys.argv[6:]
gather = "gather" in sys.argv[6:]
source = PointDatatoCellData(Input=wavelet) if cells else wavelet
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [240, 240]
view.OrientationAxesVisibility = 0
display = Show(source, view)
display.Representation = representation
ColorBy(display, ("CELLS" if cells else "POINTS", "RTData"))
display.Shade = 0 if unshaded else 1
# Clear below 150, denser towards the peak: a lobed ball that shadows itself.
GetOpacityTransferFunction("RTData").Points = [37, 0.0, 0.5, 0.0, 150, 0.0, 0.5, 0.0, 276, 0.8, 0.5, 0.0]
if representation == "Shadowed Volume":
    display.ShadowTechnique = sys.argv[4] if len(sys.argv) > 4 else "dsm"
    display.ShadowLights = int(sys.argv[5]) if len(sys.argv) > 5 else 0
    display.ShadowGround = "-Z" if ground else "None"
    if bad_key:
        display.ShadowParameters = "no-such-key=1"
    display.ShadowExchangeScan = 0 if gather else 1
view.CameraPosition = [0, -100, 50]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
SaveScreenshot(output, view)
if representation == "Shadowed Volume":
    # What the ranks' shadows moved between them in the screenshot's frame (the most any rank
    # received; 0 on one rank): gathered over the ranks at the next render's start.
    Render(view)
    display.UpdatePropertyInformation()
    print("shadow exchange: %d bytes in %d messages, %.2f ms per frame (largest of any rank)" %
          (display.GetPropertyValue("ShadowExchangeBytes"), display.GetPropertyValue("ShadowExchangeMessages"),
           display.GetPropertyValue("ShadowExchangeMilliseconds")))
    print("shadow statistics: %s" % display.GetPropertyValue("ShadowStatistics"))
