"""A medical-style pipeline to copy: a CT volume from a file, a transfer function in
Hounsfield units, a key light, deep shadow maps, a floor that receives the shadows, a PNG.

    python3 MedicalVolume.py [volume.vti|.mhd|.mha|.nrrd|.nhdr] [out.png]

With no file it writes the module's CT-like head phantom to head-phantom.mhd first and reads
that, so the script runs anywhere; give your own CT to see yours.
"""
import os
import sys
import tempfile

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkMetaImageWriter, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkLight,
                                         vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkdeepshadow import (vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowPass,
                           vtkDeepShadowPolyDataMapper, vtkDeepShadowStandardScene,
                           vtkDeepShadowVolumeMapper, vtkDeepShadowVolumeReader)


def phantom_file():
    """Writes the head phantom (short, Hounsfield units) as MetaImage; returns its path."""
    scene = vtkDeepShadowStandardScene()
    scene.SetScene("head")
    path = os.path.join(tempfile.mkdtemp(prefix="deepshadow-"), "head-phantom.mhd")
    writer = vtkMetaImageWriter()
    writer.SetInputData(scene.GetVolume())
    writer.SetFileName(path)
    writer.Write()
    return path


path = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1] else phantom_file()
out = sys.argv[2] if len(sys.argv) > 2 else "MedicalVolume.png"

# The reader checks the file against its header before VTK's reader sees it: a bad file is
# one error line (reader.GetLastError()) and an empty output, never a crash.
reader = vtkDeepShadowVolumeReader()
reader.SetFileName(path)
reader.Update()
if reader.GetLastError():
    sys.exit("cannot read the volume: " + reader.GetLastError())

# CT transfer function: air and fat transparent, soft tissue faint, bone opaque and white.
# (Or in one call, a preset ParaView and 3D Slicer users know, or a ParaView preset file:
#  vtkDeepShadowVolumePresets().Apply("CT-Bone", volume_property).)
opacity = vtkPiecewiseFunction()
for hu, alpha in ((-1000, 0.0), (-100, 0.0), (20, 0.015), (150, 0.04), (500, 0.4), (1500, 0.85)):
    opacity.AddPoint(hu, alpha)
color = vtkColorTransferFunction()
for hu, rgb in ((-1000, (0.0, 0.0, 0.0)), (20, (0.75, 0.45, 0.35)), (150, (0.85, 0.6, 0.45)),
                (300, (0.95, 0.9, 0.8)), (1500, (1.0, 1.0, 1.0))):
    color.AddRGBPoint(hu, *rgb)
volume_property = vtkVolumeProperty()
volume_property.SetScalarOpacity(opacity)
volume_property.SetColor(color)
volume_property.SetInterpolationTypeToLinear()
volume_property.ShadeOn()
volume_property.SetAmbient(0.2)
volume_property.SetDiffuse(0.8)

# Deep shadow maps (Lokovic and Veach): the head shadows itself and the floor.
technique = vtkDeepShadowDeepShadowMapTechnique()
technique.SetMapSize(512)
mapper = vtkDeepShadowVolumeMapper()
mapper.SetInputConnection(reader.GetOutputPort())
mapper.SetShadowTechnique(technique)
mapper.JitterOn()  # trades wood-grain rings of the fixed sample positions for fine noise
volume = vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(volume_property)

renderer = vtkRenderer()
renderer.SetBackground(0.08, 0.09, 0.12)
renderer.AddVolume(volume)

# A floor under the volume. vtkDeepShadowPass draws the meshes and the volume together, so
# the volume's shadows fall on meshes drawn by vtkDeepShadowPolyDataMapper.
xmin, xmax, ymin, ymax, zmin, zmax = volume.GetBounds()
dx, dy = xmax - xmin, ymax - ymin
floor = vtkPlaneSource()
floor.SetOrigin(xmin - dx, ymin - dy, zmin - 0.05 * (zmax - zmin))
floor.SetPoint1(xmax + dx, ymin - dy, zmin - 0.05 * (zmax - zmin))
floor.SetPoint2(xmin - dx, ymax + dy, zmin - 0.05 * (zmax - zmin))
floor_mapper = vtkDeepShadowPolyDataMapper()
floor_mapper.SetInputConnection(floor.GetOutputPort())
floor_actor = vtkActor()
floor_actor.SetMapper(floor_mapper)
floor_actor.GetProperty().SetColor(0.8, 0.8, 0.8)
renderer.AddActor(floor_actor)
renderer.SetPass(vtkDeepShadowPass())

# The key light, above and to the side; shadows come from scene lights.
cx, cy, cz = volume.GetCenter()
size = max(dx, dy, zmax - zmin)
light = vtkLight()
light.SetLightTypeToSceneLight()
light.SetPositional(False)
light.SetFocalPoint(cx, cy, cz)
light.SetPosition(cx + 0.6 * size, cy - 0.5 * size, cz + 1.2 * size)
renderer.AddLight(light)

camera = renderer.GetActiveCamera()
camera.SetFocalPoint(cx, cy, cz)
camera.SetPosition(cx + 0.4 * size, cy - 2.2 * size, cz + 0.9 * size)
camera.SetViewUp(0.0, 0.0, 1.0)
renderer.ResetCamera(xmin, xmax, ymin, ymax, zmin, zmax)
camera.Zoom(1.3)
renderer.ResetCameraClippingRange()

window = vtkRenderWindow()  # headless with no display
window.SetSize(512, 512)
window.AddRenderer(renderer)
window.Render()
if mapper.GetLastError():
    sys.exit("cannot render: " + mapper.GetLastError())

grab = vtkWindowToImageFilter()
grab.SetInput(window)
png = vtkPNGWriter()
png.SetInputConnection(grab.GetOutputPort())
png.SetFileName(out)
png.Write()
print("read", path, "-> rendered with", window.GetClassName(), "->", out)
