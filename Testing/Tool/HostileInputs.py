#!/usr/bin/env python3
"""Writes the hostile inputs of issue 45 ("Hostile input II") into a folder, for
TestHostileInputII.sh. Each file is broken in one way that VTK's readers or the tool once
took badly (a signal, a hang, memory without bound, a wrong picture with exit 0, or a wrong
reason); the test says what each must give now. Deterministic: the same bytes every run.

Usage: HostileInputs.py FOLDER
Needs Debian's python3-vtk9 (the well-formed files are written by VTK's own writers)."""
import gzip
import json
import os
import struct
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLPolyDataWriter
from vtkmodules.util.numpy_support import numpy_to_vtk
import numpy


def write(folder, name, data):
    with open(os.path.join(folder, name), "wb") as out:
        out.write(data if isinstance(data, bytes) else data.encode())


def ramp_volume(n=16, dtype=numpy.uint8, constant=None):
    """An n^3 image of a ramp (or one value), spacing 2, centred near the origin."""
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(2, 2, 2)
    image.SetOrigin(-n + 1, -n + 1, -n + 1)
    k, j, i = numpy.meshgrid(numpy.arange(n), numpy.arange(n), numpy.arange(n), indexing="ij")
    values = (i + j + k) * 255 // (3 * (n - 1)) if constant is None else numpy.full(i.shape, constant)
    array = numpy_to_vtk(values.astype(dtype).ravel(), deep=True)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    return image


def write_vti(path, image, appended=True, encode=False, compress=False):
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    if appended:
        writer.SetDataModeToAppended()
        writer.SetEncodeAppendedData(1 if encode else 0)
    else:
        writer.SetDataModeToBinary()
    if not compress:
        writer.SetCompressorTypeToNone()
    writer.Write()


def nested_xml(kind, depth):
    """A VTK XML file whose elements nest `depth` deep (VTK frees them recursively)."""
    head = ('<?xml version="1.0"?>\n<VTKFile type="%s" version="0.1" byte_order="LittleEndian">\n'
            % kind)
    return head + "<a>" * depth + "</a>" * depth + "\n</VTKFile>\n"


def nifti(datatype, bitpix, dims, vox_offset=352.0, data=None, magic=b"n+1\0"):
    """A NIfTI-1 single file (.nii): header, 4 extension bytes, then `data` (zeros of the
    declared size by default)."""
    header = bytearray(348)
    struct.pack_into("<i", header, 0, 348)
    dim = [len(dims)] + list(dims) + [1] * (7 - len(dims))
    struct.pack_into("<8h", header, 40, *dim)
    struct.pack_into("<hh", header, 70, datatype, bitpix)
    struct.pack_into("<8f", header, 76, 1.0, 1.0, 1.0, 1.0, 0, 0, 0, 0)
    struct.pack_into("<f", header, 108, vox_offset)
    struct.pack_into("<f", header, 112, 1.0)  # scl_slope
    header[344:348] = magic
    if data is None:
        count = 1
        for d in dims[:3]:
            count *= d
        data = bytes(count * max(bitpix // 8, 1))
    return bytes(header) + b"\0\0\0\0" + data


def dicom_element(group, element, vr, value):
    if len(value) % 2:
        value += b"\0" if vr in (b"UI", b"OB") else b" "
    if vr in (b"OB", b"OW", b"SQ", b"UN", b"UT"):
        return struct.pack("<HH2sHI", group, element, vr, 0, len(value)) + value
    return struct.pack("<HH2sH", group, element, vr, len(value)) + value


def dicom_slice(series, instance, rows, columns, z, private_bytes=0):
    """One CT slice, explicit VR little endian, 16-bit, with an optional private OB element
    of `private_bytes` before the image elements (a header that long)."""
    ts = b"1.2.840.10008.1.2.1"
    sop = ("1.2.826.0.1.3680043.2.1143.45.%d" % instance).encode()
    meta_body = (dicom_element(0x0002, 0x0001, b"OB", b"\0\1") +
                 dicom_element(0x0002, 0x0002, b"UI", b"1.2.840.10008.5.1.4.1.1.2") +
                 dicom_element(0x0002, 0x0003, b"UI", sop) +
                 dicom_element(0x0002, 0x0010, b"UI", ts))
    meta = dicom_element(0x0002, 0x0000, b"UL", struct.pack("<I", len(meta_body))) + meta_body
    body = (dicom_element(0x0008, 0x0016, b"UI", b"1.2.840.10008.5.1.4.1.1.2") +
            dicom_element(0x0008, 0x0018, b"UI", sop) +
            dicom_element(0x0008, 0x0060, b"CS", b"CT") +
            dicom_element(0x0009, 0x0010, b"LO", b"HOSTILE") +
            (dicom_element(0x0009, 0x1001, b"OB", bytes(private_bytes)) if private_bytes else b"") +
            dicom_element(0x0020, 0x000D, b"UI", b"1.2.826.0.1.3680043.2.1143.45") +
            dicom_element(0x0020, 0x000E, b"UI", series) +
            dicom_element(0x0020, 0x0013, b"IS", str(instance).encode()) +
            dicom_element(0x0020, 0x0032, b"DS", ("0\\0\\%g" % z).encode()) +
            dicom_element(0x0020, 0x0037, b"DS", b"1\\0\\0\\0\\1\\0") +
            dicom_element(0x0028, 0x0002, b"US", struct.pack("<H", 1)) +
            dicom_element(0x0028, 0x0004, b"CS", b"MONOCHROME2") +
            dicom_element(0x0028, 0x0010, b"US", struct.pack("<H", rows)) +
            dicom_element(0x0028, 0x0011, b"US", struct.pack("<H", columns)) +
            dicom_element(0x0028, 0x0030, b"DS", b"1\\1") +
            dicom_element(0x0028, 0x0100, b"US", struct.pack("<H", 16)) +
            dicom_element(0x0028, 0x0101, b"US", struct.pack("<H", 16)) +
            dicom_element(0x0028, 0x0102, b"US", struct.pack("<H", 15)) +
            dicom_element(0x0028, 0x0103, b"US", struct.pack("<H", 0)))
    pixels = numpy.fromfunction(lambda r, c: (r + c + instance) * 7, (rows, columns)).astype("<u2")
    body += dicom_element(0x7FE0, 0x0010, b"OW", pixels.tobytes())
    return bytes(128) + b"DICM" + meta + body


def closed_cylinder(corners):
    """A closed cylinder as legacy VTK poly data: two caps of `corners` corners each, and
    quads around (a "not closed" refusal would be wrong)."""
    angles = numpy.arange(corners) * (2 * numpy.pi / corners)
    ring = numpy.stack([10 * numpy.cos(angles), 10 * numpy.sin(angles)], axis=1)
    lines = ["# vtk DataFile Version 4.2", "closed cylinder", "ASCII", "DATASET POLYDATA",
             "POINTS %d double" % (2 * corners)]
    for z in (-8.0, 8.0):
        lines += ["%.17g %.17g %.17g" % (x, y, z) for x, y in ring]
    quads = ["4 %d %d %d %d" % (i, (i + 1) % corners, corners + (i + 1) % corners, corners + i)
             for i in range(corners)]
    bottom = "%d " % corners + " ".join(str(i) for i in reversed(range(corners)))
    top = "%d " % corners + " ".join(str(corners + i) for i in range(corners))
    lines.append("POLYGONS %d %d" % (corners + 2, 5 * corners + 2 * (corners + 1)))
    lines += quads + [bottom, top]
    return "\n".join(lines) + "\n"


def cube_obj(half):
    corners = [(x, y, z) for x in (-half, half) for y in (-half, half) for z in (-half, half)]
    faces = [(1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)]
    return "".join("v %.17g %.17g %.17g\n" % c for c in corners) + \
        "".join("f %d %d %d %d\n" % f for f in faces)


def camera(position, focal=(0, 0, 0), up=(0, 0, 1), angle=30.0):
    return json.dumps({"camera": {"position": list(position), "focal_point": list(focal),
                                  "view_up": list(up), "view_angle": angle}})


def main(folder):
    os.makedirs(folder, exist_ok=True)
    # XML nested deeper than VTK's recursive element destructor survives, and too many elements.
    write(folder, "deep.vti", nested_xml("ImageData", 150000))
    write(folder, "deep.vtp", nested_xml("PolyData", 150000))
    write(folder, "wide.vti", '<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1">'
          + "<a/>" * 2000000 + "</VTKFile>\n")

    # NIfTI headers VTK's reader trusts: float128 (it walked off its type table), a bit count
    # that is not the type's, data declared past the end, a wrong magic.
    write(folder, "float128.nii", nifti(1536, 128, (32, 32, 32)))
    write(folder, "bitpix.nii", nifti(2, 16, (32, 32, 32)))
    write(folder, "voxoffset.nii", nifti(2, 8, (32, 32, 32), vox_offset=1e9))
    write(folder, "dims.nii", nifti(2, 8, (32, -4, 32), data=bytes(32 * 32)))
    ramp = ramp_volume(16).GetPointData().GetScalars()
    ramp_bytes = bytes(numpy.array([ramp.GetValue(i) for i in range(ramp.GetNumberOfValues())],
                                   dtype=numpy.uint8))
    good_nifti = nifti(2, 8, (16, 16, 16), data=ramp_bytes)
    write(folder, "ramp.nii", good_nifti)
    write(folder, "gzipped-as.nii", gzip.compress(good_nifti, mtime=0))

    # VTK XML image data that VTK reads half of without a word.
    half = ramp_volume(16)
    write_vti(os.path.join(folder, "ramp.vti"), half)
    write_vti(os.path.join(folder, "ramp-base64.vti"), half, encode=True)
    with open(os.path.join(folder, "ramp.vti"), "rb") as f:
        text = f.read()
    # One piece of half the whole extent (z 0..7 of 0..15), its data cut to match.
    head, _, rest = text.partition(b"<AppendedData")
    head = head.replace(b'<Piece Extent="0 15 0 15 0 15"', b'<Piece Extent="0 15 0 15 0 7"')
    marker = rest.index(b"_") + 1
    size = struct.unpack("<I", rest[marker:marker + 4])[0]
    data = rest[marker + 4:marker + 4 + size // 2]
    write(folder, "half-piece.vti", head + b"<AppendedData" + rest[:marker] +
          struct.pack("<I", size // 2) + data + b"\n  </AppendedData>\n</VTKFile>\n")
    with open(os.path.join(folder, "ramp-base64.vti"), "rb") as f:
        encoded = f.read()
    write(folder, "base64-cut.vti", encoded[:len(encoded) - (len(encoded) - encoded.index(b"_")) // 2])
    write_vti(os.path.join(folder, "constant.vti"), ramp_volume(16, constant=7))

    # A NRRD header naming a list of data files that do not exist.
    write(folder, "list.nhdr", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 16 16 16\n"
          "encoding: raw\ndata file: LIST\nmissing-0.raw\nmissing-1.raw\n")
    # 2^32 points along x.
    write(folder, "extent.mhd", "ObjectType = Image\nNDims = 3\nDimSize = 4294967296 1 1\n"
          "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n")

    # DICOM: a folder with a named pipe beside two good slices (opened, it blocks), and a
    # series whose headers run past 4 MiB, mixing two image sizes.
    series = b"1.2.826.0.1.3680043.2.1143.45.1"
    os.makedirs(os.path.join(folder, "dicom-fifo"), exist_ok=True)
    for k in range(2):
        write(folder, "dicom-fifo/slice%d.dcm" % k, dicom_slice(series, k + 1, 16, 16, 2.0 * k))
    fifo = os.path.join(folder, "dicom-fifo", "pipe.dcm")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
    os.makedirs(os.path.join(folder, "dicom-bigheader"), exist_ok=True)
    write(folder, "dicom-bigheader/slice0.dcm", dicom_slice(series, 1, 16, 16, 0.0, 5 << 20))
    write(folder, "dicom-bigheader/slice1.dcm", dicom_slice(series, 2, 32, 8, 2.0, 5 << 20))
    os.makedirs(os.path.join(folder, "dicom-bigheader-good"), exist_ok=True)
    for k in range(3):
        write(folder, "dicom-bigheader-good/slice%d.dcm" % k,
              dicom_slice(series, k + 1, 16, 16, 2.0 * k, 5 << 20))

    # Meshes.
    write(folder, "nan.obj", "v nan nan nan\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n"
          "f 1 4 2\nf 2 4 3\n")
    write(folder, "cylinder.vtk", closed_cylinder(20000))
    write(folder, "cylinder-256.vtk", closed_cylinder(256))
    write(folder, "cube-1e300.obj", cube_obj(1e300))
    write(folder, "cube.obj", cube_obj(20.0))
    sphere = vtkSphereSource()
    sphere.SetRadius(12)
    sphere.SetThetaResolution(101)
    sphere.SetPhiResolution(101)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.SetFileName(os.path.join(folder, "sphere-20k.vtp"))
    writer.Write()

    # Transfer functions: 200000 nodes within the 16 MiB limit; nodes at +-1.7e308 (their
    # distance overflows a double); the same grey ramp over a range a double spans.
    count = 200000
    xs = numpy.linspace(0, 255, count)
    nodes = numpy.stack([xs, xs / 255, xs / 255, xs / 255], axis=1).ravel()
    write(folder, "tf-200k.json", json.dumps([{"Name": "many", "RGBPoints": [round(v, 6) for v in nodes]}]))
    write(folder, "tf-overflow.json", json.dumps([{"Name": "wide", "RGBPoints":
          [-1.7e308, 0, 0, 0, 1.7e308, 1, 1, 1], "Points": [-1.7e308, 0.05, 0.5, 0, 1.7e308, 0.05, 0.5, 0]}]))
    write(folder, "tf-grey.json", json.dumps([{"Name": "grey", "RGBPoints":
          [-1e3, 0.5, 0.5, 0.5, 1e3, 0.5, 0.5, 0.5], "Points": [-1e3, 0.05, 0.5, 0, 1e3, 0.05, 0.5, 0]}]))

    # Cameras: a view angle given as a string, one of 1e-300 degrees, one 1e15 away framing
    # the volume, one looking away from it.
    write(folder, "camera-string.json", camera((0, -100, 0), angle="5"))
    write(folder, "camera-tiny-angle.json", camera((0, -100, 0), angle=1e-300))
    write(folder, "camera-far.json", camera((0, -1e15, 0), angle=30.0 * 100 / 1e15))
    write(folder, "camera-away.json", camera((0, -100, 0), focal=(0, -200, 0)))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
