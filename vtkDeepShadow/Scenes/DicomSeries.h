// Internal to DeepShadow::Scenes: DICOM series read with GDCM, the field's library. A folder's
// regular files are grouped by SeriesInstanceUID; a series' slices are sorted by their
// ImagePositionPatient projected on the normal of ImageOrientationPatient, the spacing taken
// from those positions (not SliceThickness), and the volume placed in DICOM's patient
// coordinates (LPS): origin the first slice's position, direction the orientation's row,
// column and normal, so that index (i, j, k) is column i, row j of slice k. Pixels are
// decoded by GDCM (every transfer syntax it reads: JPEG, JPEG-LS, JPEG 2000, RLE, deflate,
// big endian) and rescaled to the modality's units (Hounsfield units for CT). A single
// multi-frame file is one volume. Slices sheared off their normal (gantry tilt) are placed
// each at its own position, the third axis following them (said). What cannot be one volume
// is refused, said in words: slices of several sizes or orientations, uneven spacing, slices
// off one line, two slices at one position, Siemens mosaics (a volume tiled in each file).
#ifndef deepshadow_DicomSeries_h
#define deepshadow_DicomSeries_h

#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkImageData;

namespace deepshadow
{
namespace dicom
{

/**
 * The regular files of `directory` (paths, sorted), not its subdirectories. Any other entry
 * (a named pipe, a device, a broken link) sets `problem` (when given) to a one-line reason:
 * a DICOM reader opens every entry, and a pipe with no writer blocks it for ever.
 */
std::vector<std::string> RegularFiles(const std::string& directory, std::string* problem = nullptr);

/** One series of a folder, as its files' headers describe it. */
struct SeriesInfo
{
  std::string UID;
  std::string Number; // SeriesNumber, as written ("" if absent)
  std::string Description;
  std::string Modality;
  int Rows = 0, Columns = 0;
  std::vector<std::string> Files;
  std::uint64_t Frames = 0; // slices: one a file, or a multi-frame file's frames
};

/**
 * The series of `files` (those GDCM reads a DICOM header of; the others are skipped), by
 * SeriesNumber then UID. Empty, with `problem`, when no file is DICOM.
 */
std::vector<SeriesInfo> ListSeries(const std::vector<std::string>& files, std::string& problem);

/** One line on a series: "3 (MR, 'T1 axial', 7 slices of 16x16, UID 1.2.3...)". */
std::string Describe(const SeriesInfo& series);

/**
 * The series `choice` names: its SeriesNumber, or its UID; "" picks the only one. Null with
 * `problem` (listing the series to choose from) otherwise.
 */
const SeriesInfo* Choose(const std::vector<SeriesInfo>& series, const std::string& choice, std::string& problem);

/** A series as one volume, from its headers alone (sorted, checked, placed). */
struct Geometry
{
  std::vector<std::string> Files; // in slice order (one multi-frame file: itself)
  int Dimensions[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  // Row-major; its columns: the row and column directions and the slice axis (the normal,
  // or the direction the slices step in when they are sheared).
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  int ScalarType = 0; // VTK type of the rescaled values
  std::string Modality;
  std::string Warning; // what the reader says of a series it reads (a gantry tilt)
};

/**
 * Sorts and checks the series' slices and places the volume. False with `problem` when it is
 * not one volume GDCM can read.
 */
bool ReadGeometry(const SeriesInfo& series, Geometry& geometry, std::string& problem);

/**
 * Decodes every slice into `image` (which the caller set up with the geometry's extent and
 * scalar type), rescaled to the modality's units. False with `problem` for a file GDCM cannot
 * decode or whose image differs from its header.
 */
bool ReadPixels(const Geometry& geometry, vtkImageData* image, std::string& problem);

/**
 * The narrowest VTK integer type that holds every value of an integer array as read
 * (unsigned char, short, unsigned short, int), else the array's own type.
 */
int NarrowestType(vtkDataArray* values);

/** Whether `path` is a file that starts with DICOM's preamble ("DICM" at byte 128). */
bool IsDicomFile(const std::string& path);

}
}
#endif
