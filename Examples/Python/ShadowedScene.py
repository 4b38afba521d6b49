"""The smallest vtkDeepShadow script: a standard scene with deep shadow maps, written to a PNG.

    python3 ShadowedScene.py [out.png]

Runs with no display: with none, vtkRenderWindow() is the headless vtkDeepShadowRenderWindow
(OSMesa; VTK_DEEPSHADOW_BACKEND=egl for EGL). See Documentation/Python.md for PYTHONPATH.
"""
import sys

from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkLight, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (VTK's OpenGL classes, as in any VTK script)
from vtkdeepshadow import (vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowStandardScene,
                           vtkDeepShadowVolumeMapper)

scene = vtkDeepShadowStandardScene()  # a procedural volume, its transfer function and view
scene.SetScene("rods")

mapper = vtkDeepShadowVolumeMapper()
mapper.SetInputData(scene.GetVolume())
mapper.SetShadowTechnique(vtkDeepShadowDeepShadowMapTechnique())  # deep shadow maps
# Lit as the deepshadow tool lights it. The default is VTK's own volume shading (what a mapper
# swapped into a VTK script must draw), which under a scene light has no ambient light: the
# rods' unlit sides and their shadows would be black.
mapper.SetShadingModelToBlinnPhong()

volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(scene.GetVolumeProperty())

renderer = vtkRenderer()
renderer.SetBackground(0.08, 0.09, 0.12)
renderer.AddVolume(volume)
scene.ApplyCamera(renderer.GetActiveCamera())
renderer.ResetCameraClippingRange()

light = vtkLight()  # shadows need a scene light: the scene suggests where it is
light.SetLightTypeToSceneLight()
light.SetPositional(False)
center = volume.GetCenter()
direction = scene.GetLightDirection()
light.SetFocalPoint(center)
light.SetPosition([c + d for c, d in zip(center, direction)])
renderer.AddLight(light)

window = vtkRenderWindow()
window.SetSize(300, 300)
window.AddRenderer(renderer)
window.Render()
if mapper.GetLastError():
    sys.exit("cannot render: " + mapper.GetLastError())

grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(sys.argv[1] if len(sys.argv) > 1 else "ShadowedScene.png")
writer.Write()
print("rendered with", window.GetClassName(), "->", writer.GetFileName())
