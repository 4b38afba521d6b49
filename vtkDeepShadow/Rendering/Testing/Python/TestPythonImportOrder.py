"""Headless from Python whatever the import order, with both backends.

Python loads extension modules with RTLD_LOCAL and binds them at load, so after `import vtk`
VTK's OpenGL libraries call libOpenGL/libGLEW directly and the module's GL entry points do not
win by symbol order as in a linked program; the headless window then points those imports at
its entry points (vtkDeepShadowRenderWindow.GetRewrittenGLImports() counts them). Each order
and backend runs in a fresh interpreter with no DISPLAY and must give the same picture."""
import hashlib
import json
import os
import subprocess
import sys

from vtkmodules.test import Testing

IMPORTS = {
    "vtk-first": "import vtk\nimport vtkdeepshadow\n",
    "vtkdeepshadow-first": "import vtkdeepshadow\nimport vtk\n",
    "vtkmodules-only": "import vtkmodules.vtkRenderingOpenGL2\n"
                       "import vtkmodules.vtkRenderingVolumeOpenGL2\n"
                       "from vtkmodules.vtkRenderingCore import vtkRenderWindow\n"
                       "import vtkdeepshadow\n",
    "vtkmodules-after": "import vtkdeepshadow\n"
                        "import vtkmodules.vtkRenderingOpenGL2\n"
                        "import vtkmodules.vtkRenderingVolumeOpenGL2\n",
}

RENDER = """
import hashlib, json
from vtkdeepshadow import vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowRenderWindow
from DeepShadowPythonTesting import RodsScene, foreground
scene = RodsScene(size=96, technique=vtkDeepShadowDeepShadowMapTechnique())
picture = scene.render()
print(json.dumps({
    "window": scene.window.GetClassName(),
    "context": scene.window.GetContextDescription() if scene.window.IsA("vtkDeepShadowRenderWindow") else "",
    "rewritten": vtkDeepShadowRenderWindow.GetRewrittenGLImports(),
    "covered": float(foreground(picture).mean()),
    "md5": hashlib.md5(picture.tobytes()).hexdigest(),
    "error": scene.mapper.GetLastError()}))
"""


LATE_IMPORT = """
import json
import vtkdeepshadow
from DeepShadowPythonTesting import RodsScene, foreground
scene = RodsScene(size=96)
first = foreground(scene.render()).mean()
# Imported after the window has its context: VTK's own GPU volume mapper in the same window.
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
mapper = vtkOpenGLGPUVolumeRayCastMapper()
mapper.SetInputData(scene.scene.GetVolume())
scene.volume.SetMapper(mapper)
print(json.dumps({"first": float(first), "late": float(foreground(scene.render()).mean())}))
"""


def run(order, backend, rebind=True, check=True):
    environment = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="", VTK_DEEPSHADOW_BACKEND=backend,
                       VTK_DEEPSHADOW_NO_REBIND="0" if rebind else "1")
    code = LATE_IMPORT if order == "late-import" else IMPORTS[order] + RENDER
    result = subprocess.run([sys.executable, "-c", code], env=environment,
                            capture_output=True, text=True, timeout=300)
    if not check:
        return result
    if result.returncode != 0:
        raise AssertionError("%s/%s exited %d:\n%s" % (order, backend, result.returncode,
                                                       result.stderr[-2000:]))
    return json.loads(result.stdout.strip().splitlines()[-1])


class TestPythonImportOrder(Testing.vtkTest):
    def testEveryOrderAndBackend(self):
        for backend, context in (("osmesa", "OSMesa"), ("egl", "EGL")):
            pictures = {}
            for order in IMPORTS:
                outcome = run(order, backend)
                print(backend, order, outcome)
                self.assertEqual(outcome["window"], "vtkDeepShadowRenderWindow", order)
                self.assertIn(context, outcome["context"], order)
                self.assertEqual(outcome["error"], "", order)
                self.assertGreater(outcome["covered"], 0.05, "%s/%s drew nothing" % (order, backend))
                pictures[order] = outcome["md5"]
                if order == "vtk-first":
                    # VTK's GL libraries were bound first: their imports had to be redirected.
                    self.assertGreater(outcome["rewritten"], 0)
            self.assertEqual(len(set(pictures.values())), 1,
                             "%s: the import order changed the picture: %s" % (backend, pictures))

    def testLibrariesImportedAfterTheFirstFrame(self):
        # Each frame rewrites the GL imports of libraries loaded since the last (without it,
        # VTK's mapper imported after the first frame drew nothing with OSMesa).
        for backend in ("osmesa", "egl"):
            outcome = run("late-import", backend)
            print(backend, "late import", outcome)
            self.assertGreater(outcome["first"], 0.05)
            self.assertGreater(outcome["late"], 0.05, backend + ": VTK's mapper drew nothing")

    def testWithoutTheRewriteVtkFirstFails(self):
        # What this test guards against, seen once here so that it can fail: without the
        # rewrite, `import vtk` first crashes with OSMesa (GLEW: "Missing GL version") and
        # draws a wrong picture with EGL, silently.
        good = run("vtkdeepshadow-first", "egl")["md5"]
        for backend in ("osmesa", "egl"):
            result = run("vtk-first", backend, rebind=False, check=False)
            if result.returncode == 0:
                outcome = json.loads(result.stdout.strip().splitlines()[-1])
                self.assertNotEqual(outcome["md5"], good, backend + ": the rewrite is not needed?")


if __name__ == "__main__":
    Testing.main([(TestPythonImportOrder, "test")])
