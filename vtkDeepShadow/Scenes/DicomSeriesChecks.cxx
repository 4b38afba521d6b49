#include "DicomSeriesChecks.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <vector>

namespace deepshadow
{
namespace volumefile
{
namespace
{
using vtksys::SystemTools;

// Headers are read from the first bytes only: the pixel data, most of a file, is not read.
constexpr std::uint64_t HeaderBytes = 4 << 20;

struct DicomHeader
{
  std::string Problem; // "" when the header was read
  bool Unknown = false; // the header goes on past HeaderBytes: not checked
  std::string TransferSyntax;
  std::string SeriesUID;
  int Rows = 0, Columns = 0, BitsAllocated = 0, SamplesPerPixel = 1;
  std::uint64_t PixelOffset = 0, PixelLength = 0;
  bool HasPixels = false;
};

std::uint16_t U16(const std::vector<unsigned char>& b, std::uint64_t at)
{
  return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}

std::uint32_t U32(const std::vector<unsigned char>& b, std::uint64_t at)
{
  return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
    (static_cast<std::uint32_t>(b[at + 2]) << 16) | (static_cast<std::uint32_t>(b[at + 3]) << 24);
}

std::string Text(const std::vector<unsigned char>& b, std::uint64_t at, std::uint32_t length)
{
  std::string text(b.begin() + static_cast<std::ptrdiff_t>(at),
    b.begin() + static_cast<std::ptrdiff_t>(at + length));
  while (!text.empty() && (text.back() == '\0' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

// The elements the checks need. Undefined-length sequences are skipped to their delimiter.
DicomHeader ReadHeader(const std::string& path)
{
  DicomHeader h;
  const std::uint64_t fileSize = SystemTools::FileLength(path);
  std::vector<unsigned char> b(static_cast<size_t>(std::min(fileSize, HeaderBytes)));
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(b.size()));
  b.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  const std::uint64_t size = b.size();
  const bool whole = size == fileSize;
  std::uint64_t at = 132;
  bool explicitVR = true;
  while (at + 8 <= size)
  {
    const std::uint16_t group = U16(b, at), element = U16(b, at + 2);
    if (group != 0x0002 && h.TransferSyntax == "1.2.840.10008.1.2")
    {
      explicitVR = false;
    }
    std::uint32_t length;
    std::uint64_t value;
    const char vr[3] = { static_cast<char>(b[at + 4]), static_cast<char>(b[at + 5]), 0 };
    const bool longForm = std::string("OB OW OF SQ UT UN OD OL UC UR").find(vr) != std::string::npos;
    if (group == 0xFFFE) // item and delimiters: no VR
    {
      length = U32(b, at + 4);
      value = at + 8;
    }
    else if (explicitVR && longForm)
    {
      if (at + 12 > size)
      {
        break;
      }
      length = U32(b, at + 8);
      value = at + 12;
    }
    else if (explicitVR)
    {
      length = U16(b, at + 6);
      value = at + 8;
    }
    else
    {
      length = U32(b, at + 4);
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
      if (whole)
      {
        h.Problem = "its header is cut short";
      }
      h.Unknown = !whole;
      return h;
    }
    if (group == 0x0002 && element == 0x0010)
    {
      h.TransferSyntax = Text(b, value, length);
    }
    else if (group == 0x0020 && element == 0x000E)
    {
      h.SeriesUID = Text(b, value, length);
    }
    else if (group == 0x0028 && length == 2 &&
      (element == 0x0010 || element == 0x0011 || element == 0x0100 || element == 0x0002))
    {
      const int v = U16(b, value);
      (element == 0x0010 ? h.Rows : element == 0x0011 ? h.Columns
        : element == 0x0100 ? h.BitsAllocated : h.SamplesPerPixel) = v;
    }
    at = value + length;
  }
  h.Unknown = !whole; // the header runs past what was read
  return h;
}

bool HasPreamble(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char magic[4] = { 0, 0, 0, 0 };
  return in.seekg(128) && in.read(magic, 4) && std::string(magic, 4) == "DICM";
}
}

std::string CheckDicomDirectory(const std::string& directory)
{
  vtksys::Directory listing;
  if (!listing.Load(directory))
  {
    return "cannot list the directory";
  }
  std::vector<std::string> files;
  unsigned long others = 0;
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    const std::string path = directory + "/" + name;
    if (name == "." || name == ".." || SystemTools::FileIsDirectory(path))
    {
      continue;
    }
    if (HasPreamble(path))
    {
      files.push_back(name);
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
    if (h.Unknown)
    {
      continue; // a header over HeaderBytes: left to VTK's reader
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
