"""pvbatch: frame times of a volume rotated as a ParaView user drags it, with ParaView's default
light kit (which follows the camera). Arguments: PLUGIN VOLUME.vti REPRESENTATION TECHNIQUE LAG
[FRAMES [DEGREES]] (VOLUME "wavelet": ParaView's Wavelet source): REPRESENTATION "Volume" (ParaView's) or "Shadowed Volume"; TECHNIQUE and
LAG (ShadowInteractiveLag, degrees) are the latter's. Each frame turns the camera by DEGREES
(default 2.5) and renders it as an interactive render (what ParaView's GUI does while the
mouse moves); then still renders, each after a turn (what it does when the mouse is let go).
Prints one line: representation, technique, lag, interactive and still milliseconds (means),
the shadow builds counted over each, and the maps' size after each (ShadowInteractiveSubsampling
N rebuilds them N times coarser while interacting). SHADE=1 in the environment shades the volume;
SUBSAMPLING=N sets ShadowInteractiveSubsampling (default: the representation's); FRAME_TIMES=1
also prints each interactive frame's milliseconds."""
import os
import sys
import time

from paraview.simple import (ColorBy, GetActiveViewOrCreate, LoadPlugin, Render, ResetCamera, Show, Wavelet,
                             XMLImageDataReader)

plugin, volume, representation, technique, lag = sys.argv[1:6]
frames = int(sys.argv[6]) if len(sys.argv) > 6 else 36
degrees = float(sys.argv[7]) if len(sys.argv) > 7 else 2.5
LoadPlugin(plugin, remote=False, ns=globals())
reader = Wavelet() if volume == "wavelet" else XMLImageDataReader(FileName=[volume])
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [500, 500]
view.OrientationAxesVisibility = 0
view.LODThreshold = 1e9  # never the outline: every frame draws the volume
display = Show(reader, view)
display.Representation = representation
ColorBy(display, ("POINTS", reader.PointData.keys()[0]))
display.Shade = int(os.environ.get("SHADE", "0"))  # ParaView's default: unshaded
if representation == "Shadowed Volume":
    display.ShadowTechnique = technique
    display.ShadowInteractiveLag = float(lag)
    if "SUBSAMPLING" in os.environ:
        display.ShadowInteractiveSubsampling = int(os.environ["SUBSAMPLING"])
view.CameraPosition = [0, -400, 150]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
for _ in range(2):  # compile, upload, first build
    Render(view)
camera = view.GetActiveCamera()


def builds():
    if representation != "Shadowed Volume":
        return 0
    display.UpdatePropertyInformation()
    return int(display.GetPropertyValue("ShadowBuilds"))


def map_size():
    """The light-space maps' texels a side (the technique's statistic map_size), or 0."""
    if representation != "Shadowed Volume":
        return 0
    display.UpdatePropertyInformation()
    pairs = dict(p.split("=", 1) for p in str(display.GetPropertyValue("ShadowStatistics")).split() if "=" in p)
    return int(float(pairs.get("map_size", 0)))


def timed(render):
    start = time.perf_counter()
    render()
    return 1000.0 * (time.perf_counter() - start)


first = builds()
interactive = []
for _ in range(frames):
    camera.Azimuth(degrees)
    interactive.append(timed(view.InteractiveRender))
built = builds() - first
if os.environ.get("FRAME_TIMES"):
    print("frames:", " ".join("%.0f" % t for t in interactive))
interactive_maps = map_size()
still = []
first = builds()
for _ in range(5):
    camera.Azimuth(degrees)
    still.append(timed(view.StillRender))
still_built = builds() - first
still_maps = map_size()
print("%s %s lag %s%s: interactive %.1f ms, still %.1f ms; shadow builds: %d in %d interactive frames of %g degrees, "
      "%d in 5 still frames; maps %d texels a side after them, %d after the still ones" % (
          representation, technique if representation != "Volume" else "-", lag if representation != "Volume" else "-",
          ", subsampling %d" % display.ShadowInteractiveSubsampling if representation != "Volume" else "",
          sum(interactive) / len(interactive), sum(still) / len(still), built, frames, degrees, still_built,
          interactive_maps, still_maps))
