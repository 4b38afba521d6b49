// Internal to DeepShadow::Scenes: checks of a NIfTI file (.nii, .nii.gz; NIfTI-1 or -2, either
// byte order) made before VTK's reader sees it. VTK 9.1's vtkNIFTIImageReader trusts the
// header: an unknown datatype (1536, float128) sends it past the end of its type table
// (SIGSEGV), a bit count that is not the datatype's is read as the datatype's, and data
// declared past the end of the file is filled with zeros without a word. The file is read
// through zlib, which reads an uncompressed file as it is: gzip data named .nii are read
// too. Each check returns "" when it finds nothing wrong, else the problem in words.
#ifndef deepshadow_NiftiFileChecks_h
#define deepshadow_NiftiFileChecks_h

#include <string>

namespace deepshadow
{
namespace volumefile
{

/**
 * The header: its size field (348 or 540) and magic of a single-file NIfTI ("n+1", "n+2"),
 * 1 to 7 dimensions of positive sizes within VTK's int, a datatype VTK reads with its own
 * bit count, and the data offset after the header.
 */
std::string CheckNiftiHeader(const std::string& fileName);

/**
 * The data: the first volume (its three dimensions, every vector component) is in the file
 * after the data offset, counting uncompressed bytes (a cut gzip stream is read up to where
 * it breaks).
 */
std::string CheckNiftiData(const std::string& fileName);

}
}
#endif
