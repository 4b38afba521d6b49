"""Frame time from Python against the C++ tool, same scene, technique and size:
    PYTHONPATH=build/lib/python3/dist-packages python3 scripts/python-vs-tool.py \
        [--scene rods] [--technique dsm] [--size 512] [--frames 9] [--rounds 3]
Each round runs `deepshadow render` and then the same scene from Python (the shadow structure
built in the first frame, then --frames frames of the same view, each Render() followed by
WaitForCompletion(), as the tool times them); prints the medians and their ratio."""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderer, vtkVolume
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkdeepshadow import (vtkDeepShadowRenderWindow, vtkDeepShadowStandardScene,
                           vtkDeepShadowTechnique, vtkDeepShadowVolumeMapper)

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
parser = argparse.ArgumentParser()
parser.add_argument("--scene", default="rods")
parser.add_argument("--technique", default="dsm")
parser.add_argument("--size", type=int, default=512)
parser.add_argument("--frames", type=int, default=9)
parser.add_argument("--rounds", type=int, default=3)
parser.add_argument("--tool", default=os.path.join(root, "build", "bin", "deepshadow"))
options = parser.parse_args()


def python_frames():
    scene = vtkDeepShadowStandardScene()
    scene.SetScene(options.scene)
    mapper = vtkDeepShadowVolumeMapper()
    mapper.SetInputData(scene.GetVolume())
    mapper.SetShadowTechnique(vtkDeepShadowTechnique.NewFromName(options.technique))
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(scene.GetVolumeProperty())
    renderer = vtkRenderer()
    renderer.SetBackground(0.08, 0.09, 0.12)
    renderer.AddVolume(volume)
    scene.ApplyCamera(renderer.GetActiveCamera())
    renderer.ResetCameraClippingRange()
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    center = volume.GetCenter()
    light.SetFocalPoint(center)
    light.SetPosition([c + d for c, d in zip(center, scene.GetLightDirection())])
    renderer.AddLight(light)
    window = vtkDeepShadowRenderWindow()
    window.SetSize(options.size, options.size)
    window.AddRenderer(renderer)
    window.Render()
    times = []
    for _ in range(options.frames):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
    window.Finalize()
    return times


def tool_frames():
    with tempfile.TemporaryDirectory() as directory:
        stats = os.path.join(directory, "stats.json")
        subprocess.run([options.tool, "render", "--scene", options.scene, "--technique",
                        options.technique, "--size", "%dx%d" % (options.size, options.size),
                        "--frames", str(options.frames), "--out",
                        os.path.join(directory, "out.png"), "--json", stats],
                       check=True, capture_output=True, env=dict(os.environ, DISPLAY=""))
        with open(stats) as file:
            return json.load(file)["render_ms_frames"]


tool, python = [], []
for _ in range(options.rounds):
    tool += tool_frames()
    python += python_frames()
tool_median, python_median = statistics.median(tool), statistics.median(python)
print("%s, %s, %dx%d, %d frames x %d rounds: tool median %.1f ms, Python median %.1f ms, "
      "Python / tool %.3f" % (options.scene, options.technique, options.size, options.size,
                              options.frames, options.rounds, tool_median, python_median,
                              python_median / tool_median))
