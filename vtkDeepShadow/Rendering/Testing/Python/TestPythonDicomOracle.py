"""DICOM series read by vtkDeepShadowVolumeReader (GDCM) against an independent oracle: Debian's
dcm2niix converts each series to NIfTI, and every voxel of every slice must hold the same
value at the same point of DICOM's patient space (LPS) in both. Also against pydicom: each
file's pixels must be the slice placed at that file's ImagePositionPatient (a series read
mirrored along its slices put slice k's pixels at slice n-1-k's position).

Series: the real axial CT of pydicom's test files (5 slices stored in descending order), and
the Colin27 brain MRI written as sagittal, coronal and axial (descending) series by
DicomSeriesWriter (no real sagittal or coronal series is packaged here: nibabel's two real MR
files are Siemens mosaics, refused). Skipped where dcm2niix, pydicom or the data are not
installed."""
import glob
import os
import shutil
import subprocess
import tempfile

import numpy
from vtkmodules.test import Testing
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkdeepshadow import vtkDeepShadowVolumeReader

PYDICOM_CT = "/usr/lib/python3/dist-packages/pydicom/data/test_files/dicomdirtests/98892001/CT5N"
NIBABEL_MR = "/usr/lib/python3/dist-packages/nibabel/tests/data"


def read(path, **settings):
    reader = vtkDeepShadowVolumeReader()
    reader.SetFileName(path)
    for key, value in settings.items():
        getattr(reader, "Set" + key)(value)
    reader.Update()
    return reader


def voxels(image):
    """Values as an array indexed [k, j, i], and the index -> LPS matrix (4x4)."""
    nx, ny, nz = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(nz, ny, nx).astype(float)
    m = image.GetIndexToPhysicalMatrix()
    matrix = numpy.array([[m.GetElement(r, c) for c in range(4)] for r in range(4)])
    return values, matrix


class TestPythonDicomOracle(Testing.vtkTest):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="dicom-oracle-")

    def tearDown(self):
        shutil.rmtree(self.work, ignore_errors=True)

    def require(self, *paths):
        for path in paths:
            if not os.path.exists(path):
                self.skipTest(path + " is not installed")
        if not shutil.which("dcm2niix"):
            self.skipTest("dcm2niix is not installed")

    def series(self, name, source):
        """A copy of the DICOM files of `source` (a folder, or a list of files)."""
        folder = os.path.join(self.work, name)
        os.makedirs(folder)
        for path in (source if isinstance(source, list) else glob.glob(source + "/*")):
            shutil.copy(path, folder)
        return folder

    def against_dcm2niix(self, folder):
        """Every voxel of the series against the same LPS point of dcm2niix's NIfTI; returns
        the DICOM reader."""
        out = os.path.join(self.work, "nifti-" + os.path.basename(folder))
        os.makedirs(out)
        subprocess.run(["dcm2niix", "-o", out, "-f", "volume", folder], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        dicom = read(folder)
        self.assertEqual(dicom.GetLastError(), "", folder)
        nifti = read(os.path.join(out, "volume.nii"))
        self.assertEqual(nifti.GetLastError(), "")
        a, to_world = voxels(dicom.GetOutput())
        b, nifti_to_world = voxels(nifti.GetOutput())
        nz, ny, nx = a.shape
        k, j, i = numpy.meshgrid(numpy.arange(nz), numpy.arange(ny), numpy.arange(nx), indexing="ij")
        points = numpy.stack([i.ravel(), j.ravel(), k.ravel(), numpy.ones(i.size)])
        index = numpy.linalg.inv(nifti_to_world) @ (to_world @ points)
        nearest = numpy.round(index[:3]).astype(int)
        self.assertLess(numpy.abs(index[:3] - nearest).max(), 1e-3, "the grids are not the same")
        bz, by, bx = b.shape
        self.assertTrue(((nearest >= 0).all() and (nearest[0] < bx).all() and (nearest[1] < by).all()
                         and (nearest[2] < bz).all()), "a DICOM voxel lies outside dcm2niix's volume")
        other = b[nearest[2], nearest[1], nearest[0]]
        mismatches = int(numpy.count_nonzero(other != a.ravel()))
        self.assertEqual(mismatches, 0, "%d of %d voxels differ from dcm2niix's" % (mismatches, a.size))
        self.assertEqual(a.size, b.size, "dcm2niix's volume holds other voxels too")
        return dicom

    def against_pydicom(self, folder, dicom):
        """Each file's pixels (rescaled) are the slice at that file's position."""
        import pydicom
        values, to_world = voxels(dicom.GetOutput())
        to_index = numpy.linalg.inv(to_world)
        for path in glob.glob(folder + "/*"):
            ds = pydicom.dcmread(path)
            position = to_index @ numpy.array([float(v) for v in ds.ImagePositionPatient] + [1.0])
            k = int(round(position[2]))
            self.assertLess(numpy.abs(position[:3] - [0, 0, k]).max(), 1e-3, path + " is off the grid")
            pixels = ds.pixel_array * float(ds.get("RescaleSlope", 1)) + float(ds.get("RescaleIntercept", 0))
            self.assertTrue(numpy.array_equal(values[k], pixels), path + ": its pixels are not slice %d's" % k)

    def testRealAxialCTStoredDescending(self):
        self.require(PYDICOM_CT)
        folder = self.series("ct", PYDICOM_CT)
        dicom = self.against_dcm2niix(folder)
        self.against_pydicom(folder, dicom)
        self.assertEqual(dicom.GetModality(), "CT")
        self.assertEqual(dicom.GetOutput().GetDimensions(), (16, 16, 5))

    def testShearedSlicesAreEachAtTheirPosition(self):
        """A gantry tilt of 11.3 degrees: each slice at its own ImagePositionPatient (dcm2niix
        places them along the normal instead, so only pydicom is the oracle here)."""
        from DicomSeriesWriter import COLIN27, write_series
        self.require(COLIN27)
        folder = write_series(os.path.join(self.work, "tilted"), "axial", shear=0.2,
                              crop=(60, 120, 70, 150, 60, 120))
        dicom = read(folder)
        self.assertEqual(dicom.GetLastError(), "")
        self.against_pydicom(folder, dicom)

    def testCompressedTransferSyntaxesDecodeAlike(self):
        """The real CT re-encoded by gdcmconv (GDCM's own tool): JPEG-LS, JPEG 2000, RLE and
        lossless JPEG read voxel for voxel as the uncompressed series (VTK's reader refused
        them all)."""
        self.require(PYDICOM_CT)
        if not shutil.which("gdcmconv"):
            self.skipTest("gdcmconv (libgdcm-tools) is not installed")
        plain = self.series("plain", PYDICOM_CT)
        reference, _ = voxels(read(plain).GetOutput())
        for flag in ("--jpegls", "--j2k", "--rle", "--jpeg"):
            folder = os.path.join(self.work, flag.strip("-"))
            os.makedirs(folder)
            for path in glob.glob(plain + "/*"):
                subprocess.run(["gdcmconv", flag, path, os.path.join(folder, os.path.basename(path))], check=True)
            reader = read(folder)
            self.assertEqual(reader.GetLastError(), "", flag)
            values, _ = voxels(reader.GetOutput())
            self.assertTrue(numpy.array_equal(values, reference), flag + " decodes other values")

    def testEnhancedMultiFrameFileIsTheSeries(self):
        from DicomSeriesWriter import COLIN27, write_multiframe
        self.require(COLIN27)
        path = os.path.join(self.work, "enhanced.dcm")
        folder = write_multiframe(path, "coronal", crop=(60, 120, 70, 150, 60, 120))
        series, frames = read(folder), read(path)
        self.assertEqual(frames.GetLastError(), "")
        a, to_world = voxels(series.GetOutput())
        b, frames_to_world = voxels(frames.GetOutput())
        self.assertTrue(numpy.array_equal(a, b), "the frames hold other values than the slices")
        self.assertLess(numpy.abs(to_world - frames_to_world).max(), 1e-6, "placed elsewhere")

    def testPatientsLeftIsOnTheViewersRightSeenFromTheFront(self):
        """A marker in the patient's upper left, written as a sagittal series: seen from the
        front (camera anterior, head up: radiology's convention), it must be on the right of
        the picture and at its top. A series read mirrored, or LPS taken for RAS, moves it."""
        from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow, vtkVolume, vtkVolumeProperty
        from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
        from vtkdeepshadow import vtkDeepShadowVolumeMapper
        from DicomSeriesWriter import write_series
        from DeepShadowPythonTesting import pixels
        values = numpy.zeros((32, 32, 32), numpy.uint16)
        values[24:30, 10:20, 24:30] = 1000  # +x: the patient's left; +z: superior
        folder = write_series(os.path.join(self.work, "marker"), "sagittal",
                              volume=(values, numpy.array([-15.5, -15.5, -15.5]), numpy.ones(3)))
        reader = read(folder)
        self.assertEqual(reader.GetLastError(), "")
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(0, 0.0)
        opacity.AddPoint(1000, 1.0)
        prop = vtkVolumeProperty()
        prop.SetScalarOpacity(opacity)
        mapper = vtkDeepShadowVolumeMapper()
        mapper.SetInputConnection(reader.GetOutputPort())
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        renderer = vtkRenderer()
        renderer.AddVolume(volume)
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(0, -100, 0)  # in front of the patient (anterior is -y in LPS)
        camera.SetViewUp(0, 0, 1)
        renderer.ResetCamera()
        window = vtkRenderWindow()
        window.SetSize(64, 64)
        window.AddRenderer(renderer)
        window.Render()
        picture = pixels(window).astype(float).sum(axis=2)  # VTK's rows: from the bottom
        rows, columns = numpy.nonzero(picture > picture.mean() + 3 * picture.std())
        self.assertGreater(len(columns), 10, "the marker is not drawn")
        self.assertGreater(columns.mean(), 32, "the patient's left is not on the viewer's right")
        self.assertGreater(rows.mean(), 32, "the patient's head is not up")

    def testSiemensMosaicsAreRefused(self):
        self.require(NIBABEL_MR + "/0.dcm")
        folder = self.series("mosaic", [NIBABEL_MR + "/0.dcm", NIBABEL_MR + "/1.dcm"])
        self.assertIn("Siemens mosaic", read(folder).GetLastError())

    def testColin27InThreeOrientations(self):
        from DicomSeriesWriter import COLIN27, write_series
        self.require(COLIN27)
        for orientation, descending in (("sagittal", False), ("coronal", False), ("axial", True)):
            folder = write_series(os.path.join(self.work, orientation), orientation, descending=descending,
                                  crop=(60, 120, 70, 150, 60, 120), slope=1.5, intercept=-10)
            self.against_pydicom(folder, self.against_dcm2niix(folder))


if __name__ == "__main__":
    Testing.main([(TestPythonDicomOracle, "test")])
