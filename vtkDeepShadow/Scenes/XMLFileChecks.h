// Internal to DeepShadow::Scenes: checks of VTK XML files (.vti, .vtp) made before VTK's
// XML readers see them. VTK 9.1's parser keeps every element of the document in memory and
// frees them recursively (150,000 nested elements overflowed the stack: SIGSEGV), copies a
// piece into the image by its extent unchecked, and reads appended data shorter than its
// arrays without a word (the rest of the volume left empty). Each check returns "" when it
// finds nothing wrong, else the problem in words.
#ifndef deepshadow_XMLFileChecks_h
#define deepshadow_XMLFileChecks_h

#include <cstdint>
#include <string>

class vtkXMLDataParser;

namespace deepshadow
{
namespace xmlfile
{

/** Elements may nest this deep: a VTK XML file needs about 7 levels. */
constexpr int MaxDepth = 256;
/** Elements a file may hold before its appended data: a few per piece and array. */
constexpr std::uint64_t MaxElements = 100000;

/**
 * The XML markup up to the appended data (whose raw bytes are not XML): elements nested at
 * most MaxDepth deep, at most MaxElements of them, and every tag, comment and declaration
 * closed before the file ends. Read as a stream, in one pass.
 */
std::string CheckStructure(const std::string& fileName);

/**
 * VTK XML image data, after its information was read by `parser` (the delegate's): every
 * piece's extent within the whole extent, the pieces covering all of it, and each array's
 * appended data (raw or base64, compressed or not) within the file and holding the bytes
 * its piece's extent needs.
 */
std::string CheckImage(vtkXMLDataParser* parser, const std::string& fileName);

}
}
#endif
