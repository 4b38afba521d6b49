"""Run by the paraview GUI (--script): loads the DeepShadow plugin as Tools > Manage Plugins
would, shows a Wavelet as a "Shadowed Volume" above a Plane shown as "Shadowed Surface", and
writes what the application sees to the file named by DEEPSHADOW_GUI_REPORT: the
representations and the volume's shadow properties. With DEEPSHADOW_GUI_SHOW=panel the volume
is selected instead, with a cached technique and a parameter, so that its Properties panel
shows the technique menu and the parameter form."""
import os

from paraview.simple import (ColorBy, GetOpacityTransferFunction, LoadPlugin, Plane, Render, ResetCamera,
                             SetActiveSource, Show, Wavelet)

LoadPlugin(os.environ["DEEPSHADOW_PARAVIEW_PLUGIN"], remote=False, ns=globals())
wavelet = Wavelet()
display = Show(wavelet)
display.Representation = "Shadowed Volume"
ColorBy(display, ("POINTS", "RTData"))
GetOpacityTransferFunction("RTData").Points = [37, 0.0, 0.5, 0.0, 150, 0.0, 0.5, 0.0, 276, 0.8, 0.5, 0.0]
display.Shade = 1
display.ShadowTechnique = "dsm"
# Below the volume in ParaView's default view (+Y up), receiving its shadow.
ground = Plane(Origin=[-20, -11, -20], Point1=[20, -11, -20], Point2=[-20, -11, 20])
surface = Show(ground)
surface.Representation = "Shadowed Surface"
panel = os.environ.get("DEEPSHADOW_GUI_SHOW") == "panel"
if panel:
    display.ShadowTechnique = "dsm-cached"
    display.ShadowParameters = "epsilon=0.05"
SetActiveSource(wavelet if panel else ground)
ResetCamera()
Render()
with open(os.environ["DEEPSHADOW_GUI_REPORT"], "w") as report:
    report.write(f"representation {display.Representation}\n")
    report.write(f"technique {display.ShadowTechnique}\n")
    report.write(f"lights {display.ShadowLights}\n")
    report.write(f"surface {surface.Representation}\n")
    report.write(f"parameters '{display.ShadowParameters}'\n")
