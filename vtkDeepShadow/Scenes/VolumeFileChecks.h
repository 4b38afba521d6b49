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

class vtkInformation;
class vtkXMLDataParser;

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
  Dicom  // a directory of one DICOM series
};

/** The format chosen by the file name's extension (case-insensitive); a directory: DICOM. */
Format FormatOf(const std::string& fileName);

/**
 * The header fields VTK's MetaImage and NRRD readers misread without a word: counts that do
 * not match the number of dimensions, numbers that are not numbers, unknown element types,
 * and NRRD's ASCII encoding (VTK 9.1 reads it wrong).
 */
std::string CheckHeader(Format format, const std::string& fileName);

/**
 * The image a delegate announced in its output information: a whole extent, finite spacing
 * (non-zero), origin and direction (invertible), and its bytes within `budget`.
 */
std::string CheckInformation(vtkInformation* info, std::uint64_t budget);

/** Bytes of the point scalars the information announces (saturating), 0 if unknown. */
std::uint64_t ScalarBytes(vtkInformation* info);

/**
 * NRRD and MetaImage: a data file that is missing, or raw data shorter than `needed` bytes.
 * NIfTI: a file shorter than its header and `needed` bytes (for .nii.gz, the uncompressed
 * size gzip records).
 */
std::string CheckDataFile(Format format, const std::string& fileName, std::uint64_t needed);

/**
 * VTK XML image data: every piece's extent within the whole extent, and with appended data
 * (raw, compressed or not) every array's block within the file and holding the bytes its
 * piece's extent needs. `parser` is the delegate's, after its information was read.
 */
std::string CheckXMLImage(vtkXMLDataParser* parser, const std::string& fileName);

}
}
#endif
