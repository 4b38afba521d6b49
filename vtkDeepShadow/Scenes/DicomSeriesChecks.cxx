#include "DicomSeriesChecks.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sys/stat.h>
#include <vector>

namespace deepshadow
{
namespace volumefile
{
namespace
{
using vtksys::SystemTools;

struct DicomHeader
{
  std::string Problem; // "" when the header was read
  std::string TransferSyntax;
  std::string SeriesUID;
  int Rows = 0, Columns = 0, BitsAllocated = 0, SamplesPerPixel = 1;
  std::uint64_t PixelOffset = 0, PixelLength = 0;
  bool HasPixels = false;
};

std::uint32_t Little(const unsigned char* b, int bytes)
{
  std::uint32_t value = 0;
  for (int i = bytes - 1; i >= 0; --i)
  {
    value = (value << 8) | b[i];
  }
  return value;
}

std::string Text(std::ifstream& in, std::uint32_t length)
{
  std::string text(length, '\0');
  in.read(&text[0], length);
  while (!text.empty() && (text.back() == '\0' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

// The elements the checks need, read element by element from the file (values the checks do
// not need are skipped, whatever their size: a header of any length is read whole, never
// more of it than its elements' tags). Undefined-length sequences are walked into.
DicomHeader ReadHeader(const std::string& path)
{
  DicomHeader h;
  const std::uint64_t size = SystemTools::FileLength(path);
  std::ifstream in(path, std::ios::binary);
  std::uint64_t at = 132;
  bool explicitVR = true;
  unsigned char tag[12];
  while (at + 8 <= size)
  {
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(tag), 8))
    {
      break;
    }
    const std::uint32_t group = Little(tag, 2), element = Little(tag + 2, 2);
    if (group != 0x0002 && h.TransferSyntax == "1.2.840.10008.1.2")
    {
      explicitVR = false;
    }
    std::uint32_t length;
    std::uint64_t value;
    const char vr[3] = { static_cast<char>(tag[4]), static_cast<char>(tag[5]), 0 };
    const bool longForm = std::string("OB OW OF SQ UT UN OD OL UC UR").find(vr) != std::string::npos;
    if (group == 0xFFFE) // item and delimiters: no VR
    {
      length = Little(tag + 4, 4);
      value = at + 8;
    }
    else if (explicitVR && longForm)
    {
      if (at + 12 > size || !in.read(reinterpret_cast<char*>(tag + 8), 4))
      {
        break;
      }
      length = Little(tag + 8, 4);
      value = at + 12;
    }
    else if (explicitVR)
    {
      length = Little(tag + 6, 2);
      value = at + 8;
    }
    else
    {
      length = Little(tag + 4, 4);
      value = at + 8;
    }
    if (group == 0x7FE0 && element == 0x0010)
    {
      h.HasPixels = true;
      h.PixelOffset = value;
      h.PixelLength = length;
      return h;
    }
    if (length == 0xFFFFFFFFu || (group == 0xFFFE && element == 0xE000))
    {
      at = value; // walk into the sequence or item; its elements follow
      continue;
    }
    if (value + length > size)
    {
      h.Problem = "its header is cut short";
      return h;
    }
    in.seekg(static_cast<std::streamoff>(value));
    if (group == 0x0002 && element == 0x0010)
    {
      h.TransferSyntax = Text(in, length);
    }
    else if (group == 0x0020 && element == 0x000E)
    {
      h.SeriesUID = Text(in, std::min<std::uint32_t>(length, 256));
    }
    else if (group == 0x0028 && length == 2 &&
      (element == 0x0010 || element == 0x0011 || element == 0x0100 || element == 0x0002))
    {
      unsigned char word[2];
      in.read(reinterpret_cast<char*>(word), 2);
      const int v = static_cast<int>(Little(word, 2));
      (element == 0x0010 ? h.Rows : element == 0x0011 ? h.Columns
        : element == 0x0100 ? h.BitsAllocated : h.SamplesPerPixel) = v;
    }
    at = value + length;
  }
  return h;
}

bool HasPreamble(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char magic[4] = { 0, 0, 0, 0 };
  return in.seekg(128) && in.read(magic, 4) && std::string(magic, 4) == "DICM";
}
}

std::vector<std::string> DicomDirectoryFiles(const std::string& directory, std::string* problem)
{
  vtksys::Directory listing;
  std::vector<std::string> files;
  if (!listing.Load(directory))
  {
    if (problem)
    {
      *problem = "cannot list the directory";
    }
    return files;
  }
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    const std::string path = directory + "/" + name;
    struct stat info;
    if (name == "." || name == ".." || (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)))
    {
      continue;
    }
    if (stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
    {
      // VTK's reader opens every entry: a named pipe with no writer blocks it for ever.
      if (problem && problem->empty())
      {
        *problem = "'" + name + "' in the directory is not a regular file (a pipe, device or "
          "broken link; the reader would open it and could wait for ever)";
      }
      continue;
    }
    files.push_back(path);
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string CheckDicomDirectory(const std::string& directory)
{
  std::string problem;
  const std::vector<std::string> entries = DicomDirectoryFiles(directory, &problem);
  if (!problem.empty())
  {
    return problem;
  }
  std::vector<std::string> files;
  unsigned long others = 0;
  for (const std::string& path : entries)
  {
    if (HasPreamble(path))
    {
      files.push_back(path.substr(directory.size() + 1));
    }
    else
    {
      ++others;
    }
  }
  if (files.empty())
  {
    return "no DICOM files in the directory (" + std::to_string(others) +
      " files, none with DICOM's \"DICM\" preamble)";
  }
  std::sort(files.begin(), files.end());
  DicomHeader first;
  std::string firstName; // of the first file whose header was read whole
  for (size_t f = 0; f < files.size(); ++f)
  {
    const std::string path = directory + "/" + files[f];
    const DicomHeader h = ReadHeader(path);
    const std::string where = "'" + files[f] + "'";
    if (!h.Problem.empty())
    {
      return where + ": " + h.Problem;
    }
    const std::string& ts = h.TransferSyntax;
    if (ts != "1.2.840.10008.1.2" && ts != "1.2.840.10008.1.2.1")
    {
      return where + ": transfer syntax " + (ts.empty() ? std::string("(none)") : ts) +
        " (compressed or big endian); VTK's DICOM reader reads uncompressed little endian only";
    }
    if (h.Rows <= 0 || h.Columns <= 0 || (h.BitsAllocated != 8 && h.BitsAllocated != 16) ||
      h.SamplesPerPixel != 1)
    {
      return where + ": not a single-channel 8- or 16-bit image (rows " + std::to_string(h.Rows) +
        ", columns " + std::to_string(h.Columns) + ", bits " + std::to_string(h.BitsAllocated) +
        ", samples " + std::to_string(h.SamplesPerPixel) + ")";
    }
    const std::uint64_t needed = static_cast<std::uint64_t>(h.Rows) * h.Columns * (h.BitsAllocated / 8);
    const std::uint64_t size = SystemTools::FileLength(path);
    if (!h.HasPixels || h.PixelLength < needed || h.PixelOffset + needed > size)
    {
      return where + ": its pixel data is missing or cut short (" +
        std::to_string(h.HasPixels && size > h.PixelOffset ? size - h.PixelOffset : 0) +
        " of the " + std::to_string(needed) + " bytes a " + std::to_string(h.Columns) + "x" +
        std::to_string(h.Rows) + " image needs)";
    }
    if (firstName.empty())
    {
      first = h;
      firstName = files[f];
      continue;
    }
    if (h.SeriesUID != first.SeriesUID)
    {
      return "the directory mixes series: '" + firstName + "' and " + where +
        " have different series instance UIDs; give one series per directory";
    }
    if (h.Rows != first.Rows || h.Columns != first.Columns || h.BitsAllocated != first.BitsAllocated)
    {
      return "the directory mixes image sizes: '" + firstName + "' is " +
        std::to_string(first.Columns) + "x" + std::to_string(first.Rows) + ", " + where + " " +
        std::to_string(h.Columns) + "x" + std::to_string(h.Rows);
    }
  }
  return "";
}

}
}
