"""Writes DICOM series of real anatomy for the reader tests: slices of a NIfTI volume (the
Colin27 brain MRI of Debian's mricron-data) in a chosen orientation, with pydicom, as a
scanner would lay them out (ImagePositionPatient, ImageOrientationPatient, PixelSpacing,
rescale). What a reader makes of them is then checked against dcm2niix's conversion."""
import os

import numpy
import nibabel
import pydicom
from pydicom.dataset import FileDataset, FileMetaDataset
from pydicom.uid import ExplicitVRLittleEndian, generate_uid

COLIN27 = "/usr/share/mricron/templates/ch2.nii.gz"

# Row and column directions in DICOM's patient axes (LPS: +x left, +y posterior, +z superior).
ORIENTATIONS = {
    "axial": ((1, 0, 0), (0, 1, 0)),      # rows run to the patient's left, columns posterior
    "sagittal": ((0, 1, 0), (0, 0, -1)),  # rows posterior, columns inferior
    "coronal": ((1, 0, 0), (0, 0, -1)),   # rows left, columns inferior
}


def lps_volume(path=COLIN27):
    """The NIfTI volume resampled onto a grid whose axes are LPS's (1 mm here: only flips),
    as (values[x, y, z], origin of index 0 in LPS, spacing)."""
    image = nibabel.load(path)
    ornt = nibabel.orientations.io_orientation(image.affine)
    lps = nibabel.orientations.axcodes2ornt(("L", "P", "S"))
    transform = nibabel.orientations.ornt_transform(ornt, lps)
    data = nibabel.orientations.apply_orientation(numpy.asanyarray(image.dataobj), transform)
    affine = image.affine @ nibabel.orientations.inv_ornt_aff(transform, image.shape)
    ras_to_lps = numpy.diag([-1.0, -1.0, 1.0, 1.0])
    affine = ras_to_lps @ affine
    spacing = numpy.abs(numpy.diag(affine)[:3])
    return numpy.asarray(data), affine[:3, 3], spacing


def new_dataset(sop_class):
    """An empty explicit-little-endian dataset of `sop_class` with a new instance UID."""
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = sop_class
    meta.MediaStorageSOPInstanceUID = generate_uid()
    meta.TransferSyntaxUID = ExplicitVRLittleEndian
    ds = FileDataset(None, {}, file_meta=meta, preamble=b"\0" * 128)
    ds.is_little_endian, ds.is_implicit_VR = True, False
    ds.SOPClassUID, ds.SOPInstanceUID = meta.MediaStorageSOPClassUID, meta.MediaStorageSOPInstanceUID
    return ds


def write_series(folder, orientation="axial", descending=False, step=1, modality="MR",
                 slope=1.0, intercept=0.0, series_number=1, description=None, crop=None,
                 shear=0.0, volume=None):
    """Writes one slice per file of the Colin27 volume in `orientation`, every `step`-th slice
    (`crop`: (x0, x1, y0, y1, z0, z1) voxels of the LPS grid first). `descending`: files and
    instance numbers run against the normal. `shear`: each slice's position moved along the
    column direction by that many mm per mm along the normal (a gantry tilt of atan(shear)).
    `volume`: (values[x, y, z], origin, spacing) on an LPS grid instead of Colin27's.
    Returns the folder."""
    values, origin, spacing = volume if volume is not None else lps_volume()
    if crop:
        x0, x1, y0, y1, z0, z1 = crop
        values = values[x0:x1, y0:y1, z0:z1]
        origin = origin + spacing * numpy.array([x0, y0, z0])
    row, column = (numpy.array(v, dtype=float) for v in ORIENTATIONS[orientation])
    normal = numpy.cross(row, column)
    axis = lambda v: int(numpy.argmax(numpy.abs(v)))  # noqa: E731
    # Pixel (r, c) of slice k lies at IPP_k + c * row + r * column: grid axes by direction.
    ra, ca, na = axis(row), axis(column), axis(normal)
    n = values.shape[na]
    os.makedirs(folder, exist_ok=True)
    series_uid, study_uid = generate_uid(), generate_uid()
    ks = list(range(0, n, step))
    order = ks[::-1] if descending else ks
    for instance, k in enumerate(order, start=1):
        # The grid index of pixel (0, 0) of slice k, along each direction's sign.
        index = [0, 0, 0]
        index[ra] = 0 if row[ra] > 0 else values.shape[ra] - 1
        index[ca] = 0 if column[ca] > 0 else values.shape[ca] - 1
        index[na] = k if normal[na] > 0 else values.shape[na] - 1 - k
        position = origin + spacing * numpy.array(index)
        position = position + shear * spacing[na] * k * column
        plane = numpy.take(values, index[na], axis=na)
        # plane's axes are the two remaining grid axes in order; rows of the image run along
        # `column` (r), columns along `row` (c).
        remaining = [a for a in range(3) if a != na]
        image = plane if remaining.index(ca) == 0 else plane.T
        if row[ra] < 0:
            image = image[:, ::-1]
        if column[ca] < 0:
            image = image[::-1, :]
        stored = numpy.round((image.astype(float) - intercept) / slope).astype(numpy.uint16)
        ds = new_dataset(pydicom.uid.MRImageStorage)
        ds.Modality, ds.PatientName, ds.PatientID = modality, "Colin27", "colin27"
        ds.StudyInstanceUID, ds.SeriesInstanceUID = study_uid, series_uid
        ds.SeriesNumber, ds.InstanceNumber = series_number, instance
        ds.SeriesDescription = description or "Colin27 %s" % orientation
        ds.ImagePositionPatient = [float(v) for v in position]
        ds.ImageOrientationPatient = [float(v) for v in list(row) + list(column)]
        ds.PixelSpacing = [float(spacing[ca]), float(spacing[ra])]
        ds.SliceThickness = float(spacing[na] * step)
        ds.Rows, ds.Columns = stored.shape
        ds.SamplesPerPixel, ds.PhotometricInterpretation = 1, "MONOCHROME2"
        ds.BitsAllocated, ds.BitsStored, ds.HighBit, ds.PixelRepresentation = 16, 16, 15, 0
        ds.RescaleSlope, ds.RescaleIntercept = slope, intercept
        ds.PixelData = numpy.ascontiguousarray(stored).tobytes()
        ds.save_as(os.path.join(folder, "IM%04d.dcm" % instance), write_like_original=False)
    return folder


def write_multiframe(path, orientation="axial", crop=None, slope=1.0, intercept=0.0):
    """The series write_series writes, as one Enhanced MR file: every slice a frame, placed by
    its per-frame PlanePositionSequence, the orientation, pixel spacing and rescale shared."""
    from pydicom.sequence import Sequence
    from pydicom.dataset import Dataset
    folder = path + ".slices"
    write_series(folder, orientation, crop=crop, slope=slope, intercept=intercept)
    slices = sorted((pydicom.dcmread(os.path.join(folder, f)) for f in os.listdir(folder)),
                    key=lambda d: d.InstanceNumber)
    first = slices[0]
    ds = new_dataset(pydicom.uid.EnhancedMRImageStorage)
    for key in ("Modality", "PatientName", "PatientID", "StudyInstanceUID", "SeriesInstanceUID",
                "SeriesNumber", "SeriesDescription", "Rows", "Columns", "SamplesPerPixel",
                "PhotometricInterpretation", "BitsAllocated", "BitsStored", "HighBit",
                "PixelRepresentation"):
        setattr(ds, key, getattr(first, key))
    ds.InstanceNumber, ds.NumberOfFrames = 1, len(slices)
    shared = Dataset()
    orient, measures, rescale = Dataset(), Dataset(), Dataset()
    orient.ImageOrientationPatient = first.ImageOrientationPatient
    measures.PixelSpacing = first.PixelSpacing
    measures.SliceThickness = first.SliceThickness
    measures.SpacingBetweenSlices = first.SliceThickness
    rescale.RescaleSlope, rescale.RescaleIntercept = slope, intercept
    rescale.RescaleType = "US"
    shared.PlaneOrientationSequence = Sequence([orient])
    shared.PixelMeasuresSequence = Sequence([measures])
    shared.PixelValueTransformationSequence = Sequence([rescale])
    ds.SharedFunctionalGroupsSequence = Sequence([shared])
    frames = []
    for d in slices:
        frame, position = Dataset(), Dataset()
        position.ImagePositionPatient = d.ImagePositionPatient
        frame.PlanePositionSequence = Sequence([position])
        frames.append(frame)
    ds.PerFrameFunctionalGroupsSequence = Sequence(frames)
    ds.PixelData = b"".join(d.PixelData for d in slices)
    ds.save_as(path, write_like_original=False)
    return folder
