"""A medical pipeline to copy, start to end: a CT or MR volume from a file or a DICOM folder,
placed in the patient's coordinates (DICOM's LPS), a look chosen by its modality, deep shadow
maps from a key light, a floor that receives the shadows, a PNG.

    python3 MedicalVolume.py [FILE|DICOM_FOLDER] [out.png] [SERIES]

FILE: .nii/.nii.gz, .vti, .mhd/.mha, .nrrd/.nhdr or a multi-frame .dcm; a DICOM folder is read
with GDCM (any transfer syntax it decodes), its slices sorted by position, rescaled to
Hounsfield units for CT. SERIES picks one series of a folder of several, by its number or UID.
With no volume it reads the Colin27 brain MRI (Debian's mricron-data) when it is installed,
else it writes the module's CT-like head phantom and reads that, so the script runs anywhere.
"""
import os
import sys
import tempfile

from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkMetaImageWriter, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
from vtkdeepshadow import (vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowPass,
                           vtkDeepShadowPolyDataMapper, vtkDeepShadowStandardScene,
                           vtkDeepShadowVolumeMapper, vtkDeepShadowVolumePresets,
                           vtkDeepShadowVolumeReader)

COLIN27 = "/usr/share/mricron/templates/ch2.nii.gz"


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


path = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1] else None
path = path or (COLIN27 if os.path.exists(COLIN27) else phantom_file())
out = sys.argv[2] if len(sys.argv) > 2 else "MedicalVolume.png"

# The reader checks the file (or each DICOM file) before it is decoded: a bad one is one
# error line (GetLastError()) and an empty output, never a crash. A DICOM folder of several
# series is an error that lists them; SetSeries picks one.
reader = vtkDeepShadowVolumeReader()
reader.SetFileName(path)
if len(sys.argv) > 3:
    reader.SetSeries(sys.argv[3])
reader.Update()
if reader.GetLastError():
    sys.exit("cannot read the volume: " + reader.GetLastError())
image = reader.GetOutput()

# The look by modality: CT-Bone for CT (Hounsfield units), MR-Default windowed from the data's
# histogram for MR (whose intensities have no fixed scale). A named preset, or a ParaView
# preset file, is one call too: vtkDeepShadowVolumePresets().Apply("CT-Skin", volume_property).
volume_property = vtkVolumeProperty()
look = vtkDeepShadowVolumePresets().ApplyDefault(reader.GetModality(), image, volume_property)
spacing = image.GetSpacing()
volume_property.SetScalarOpacityUnitDistance(min(abs(s) for s in spacing))

# Deep shadow maps (Lokovic and Veach): the anatomy shadows itself and the floor. With only
# VTK's automatic headlight, the mapper lights the scene from a key light above and to the
# side of the camera, and fills from the eye (SetHeadlightKeyLight): a headlight's shadows
# fall straight behind what it lights, where no one sees them.
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

# A floor under the volume (inferior: -z in LPS). vtkDeepShadowPass draws the meshes and the
# volume together, so the volume's shadows fall on meshes drawn by vtkDeepShadowPolyDataMapper.
xmin, xmax, ymin, ymax, zmin, zmax = volume.GetBounds()
dx, dy, dz = xmax - xmin, ymax - ymin, zmax - zmin
floor = vtkPlaneSource()
floor.SetOrigin(xmin - dx, ymin - dy, zmin - 0.05 * dz)
floor.SetPoint1(xmax + dx, ymin - dy, zmin - 0.05 * dz)
floor.SetPoint2(xmin - dx, ymax + dy, zmin - 0.05 * dz)
floor_mapper = vtkDeepShadowPolyDataMapper()
floor_mapper.SetInputConnection(floor.GetOutputPort())
floor_actor = vtkActor()
floor_actor.SetMapper(floor_mapper)
floor_actor.GetProperty().SetColor(0.8, 0.8, 0.8)
renderer.AddActor(floor_actor)
renderer.SetPass(vtkDeepShadowPass())

# Radiology's anterior view (the camera in front of the patient, anterior being -y in LPS,
# head up: the patient's left on the viewer's right), turned a little for depth.
cx, cy, cz = volume.GetCenter()
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(cx, cy, cz)
camera.SetPosition(cx, cy - 1.0, cz)
camera.SetViewUp(0.0, 0.0, 1.0)
renderer.ResetCamera(xmin, xmax, ymin, ymax, zmin, zmax)
camera.Azimuth(-30)
camera.Elevation(15)
camera.OrthogonalizeViewUp()
camera.Zoom(1.2)
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
modality = reader.GetModality() or "no modality"
print("read", path, "(%s), look %s -> rendered with %s -> %s" % (modality, look, window.GetClassName(), out))
