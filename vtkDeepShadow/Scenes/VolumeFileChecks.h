// Internal to DeepShadow::Scenes: checks of volume files made before VTK's readers read their
// data, because those readers trust the headers. They accept a truncated file (zero-filled
// or garbage data, or a crash), allocate whatever a header declares (std::bad_alloc for
// 100000^3), misread a broken header (an unknown MetaImage element type read as a 1x1x1
// image) and hang on a NRRD header line cut short or holding a NUL byte. Each check returns
// "" when it finds nothing wrong (or does not cover the file's layout), else the problem in
// words, for vtkDeepShadowVolumeReader's one line.
#ifndef deepshadow_VolumeFileChecks_h
#define deepshadow_VolumeFileChecks_h

#include <cstdint>
#include <string>
#include <vector>

class vtkInformation;

namespace deepshadow
{
namespace volumefile
{

enum class Format
{
  Unknown,
  XML,
  Meta,
  Nrrd,
  Nifti, // .nii, .nii.gz
  Dicom  // a directory of DICOM series, or one DICOM file (DicomSeries.h)
};

/**
 * The format chosen by the file name's extension (case-insensitive); a directory, or a file
 * with DICOM's preamble: DICOM.
 */
Format FormatOf(const std::string& fileName);

/**
 * The header fields VTK's MetaImage and NRRD readers misread without a word: counts that do
 * not match the number of dimensions, numbers that are not numbers, unknown element types,
 * and NRRD's ASCII encoding (VTK 9.1 reads it wrong); NIfTI's header (NiftiFileChecks.h);
 * VTK XML's structure (XMLFileChecks.h). DICOM is checked as it is read (DicomSeries.h).
 */
std::string CheckHeader(Format format, const std::string& fileName);

/**
 * The image a delegate announced in its output information: a whole extent, finite spacing
 * (non-zero), origin and direction (invertible), and its bytes within `budget`.
 */
std::string CheckInformation(vtkInformation* info, std::uint64_t budget);

/** Bytes of the point scalars the information announces (saturating), 0 if unknown. */
std::uint64_t ScalarBytes(vtkInformation* info);

/** Data files a list or pattern may name (VTK reads one slice from each). */
constexpr std::uint64_t MaxDataFiles = 65536;

/**
 * MetaImage and NRRD: the detached data files the header names (one, a LIST of them, or a
 * numbered pattern), resolved against the header's folder; none for data in the same file.
 */
std::vector<std::string> DataFiles(Format format, const std::string& fileName);

/**
 * MetaImage and NRRD, with the header (CheckHeader runs it): a file pattern VTK would pass
 * to sprintf unsafely (anything but one integer conversion), or a list of too many files.
 */
std::string CheckDataLayout(Format format, const std::string& fileName);

/**
 * MetaImage and NRRD, before the data are read: a data file that is missing or not a regular
 * file, a list or pattern that does not name one file a slice, or raw data (each file of a
 * list its share) shorter than `needed` bytes.
 */
std::string CheckDataFile(Format format, const std::string& fileName, std::uint64_t needed);

}
}
#endif
