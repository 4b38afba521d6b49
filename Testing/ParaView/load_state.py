"""pvbatch: loads the DeepShadow plugin, then a ParaView state file, prints the Wavelet's
representation and technique, and saves the view. Arguments: PLUGIN STATE.pvsm OUT.png"""
import sys

from paraview.simple import FindSource, GetActiveView, GetDisplayProperties, LoadPlugin, LoadState, SaveScreenshot

plugin, state, output = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())
LoadState(state)
view = GetActiveView()
display = GetDisplayProperties(FindSource("Wavelet1"), view)
print(f"state: representation {display.Representation}, technique {display.ShadowTechnique}")
SaveScreenshot(output, view)
