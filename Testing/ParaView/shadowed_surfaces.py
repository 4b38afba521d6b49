"""pvbatch: ParaView surfaces in the shadow of a Wavelet drawn as "Shadowed Volume" (as in
shadowed_volume.py, shaded, the key light casting), saved to a PNG. Arguments: PLUGIN OUTPUT.png
TECHNIQUE SURFACE RECEIVER: SURFACE is the representation of the receiver ("Surface" or
"Shadowed Surface"); RECEIVER is "plane" (a Plane where the volume's own ground would be: on
its -Z side, a twentieth of its box below it, half the box wider on every side, in the
ground's colour) or "contour" (a Contour of the Wavelet at 200, moved 40 below the volume and
coloured by its Normals' Z, so that colouring by an array goes through) or "caster" (a Plane
above the volume, between it and the key light, that casts into it)."""
import sys

from paraview.simple import (ColorBy, Contour, GetActiveViewOrCreate, GetOpacityTransferFunction, LoadPlugin,
                             Plane, ResetCamera, SaveScreenshot, Show, Transform, Wavelet)

plugin, output, technique, surface, receiver = sys.argv[1:6]
LoadPlugin(plugin, remote=False, ns=globals())
wavelet = Wavelet()
wavelet.WholeExtent = [-24, 24, -24, 24, -24, 24]
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [240, 240]
view.OrientationAxesVisibility = 0
volume = Show(wavelet, view)
volume.Representation = "Shadowed Volume"
ColorBy(volume, ("POINTS", "RTData"))
volume.Shade = 1
GetOpacityTransferFunction("RTData").Points = [37, 0.0, 0.5, 0.0, 150, 0.0, 0.5, 0.0, 276, 0.8, 0.5, 0.0]
volume.ShadowTechnique = technique
if receiver == "caster":
    # A Plane above the volume, between it and the key light: it casts into the volume.
    plane = Plane(Origin=[-20, -20, 40], Point1=[20, -20, 40], Point2=[-20, 20, 40])
    shown = Show(plane, view)
    shown.Representation = surface
    ColorBy(shown, ("POINTS", None))
elif receiver == "plane":
    level = -24 - 0.05 * 48
    plane = Plane(Origin=[-48, -48, level], Point1=[48, -48, level], Point2=[-48, 48, level])
    shown = Show(plane, view)
    shown.Representation = surface
    ColorBy(shown, ("POINTS", None))
    shown.AmbientColor = shown.DiffuseColor = [0.85, 0.85, 0.8]
else:
    blob = Transform(Input=Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[200],
                                   ComputeNormals=1))
    blob.Transform.Translate = [0, 0, -40]
    shown = Show(blob, view)
    shown.Representation = surface
    ColorBy(shown, ("POINTS", "Normals", "Z"))
view.CameraPosition = [0, -100, 50]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
SaveScreenshot(output, view)
