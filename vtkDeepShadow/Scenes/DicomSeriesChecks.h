// Internal to DeepShadow::Scenes: a DICOM series directory checked before VTK's
// vtkDICOMImageReader reads it. That reader takes every file of a directory as one series:
// it stacks slices of different series or sizes, fills a cut file's missing pixels, and
// cannot decode compressed transfer syntaxes, and opens every entry of the directory (a named
// pipe blocks it). Each file's header is read here (the elements
// the checks need, little endian, implicit or explicit VR) without VTK.
#ifndef deepshadow_DicomSeriesChecks_h
#define deepshadow_DicomSeriesChecks_h

#include <string>
#include <vector>

namespace deepshadow
{
namespace volumefile
{

/**
 * The regular files of `directory` (paths, sorted), not its subdirectories. Any other entry
 * (a named pipe, a device, a broken link) sets `problem` (when given) to a one-line reason.
 */
std::vector<std::string> DicomDirectoryFiles(const std::string& directory, std::string* problem = nullptr);

/**
 * "" when `directory` holds one readable series: at least one DICOM file (the "DICM"
 * preamble), all of one series and one size, uncompressed little endian, each with all its
 * pixel data. Else the problem in words, naming the file.
 */
std::string CheckDicomDirectory(const std::string& directory);

}
}
#endif
