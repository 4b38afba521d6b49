#include "NiftiFileChecks.h"

#include "vtkDeepShadowMemoryBudget.h"

#include "vtk_zlib.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace deepshadow
{
namespace volumefile
{
namespace
{
// What the checks need of a NIfTI-1 or NIfTI-2 header, in the machine's byte order.
struct NiftiHeader
{
  std::string Problem; // "" when read
  int Version = 0;
  std::int64_t Dim[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  int DataType = 0;
  int BitPix = 0;
  double VoxOffset = 0.0;
  bool Gzipped = false;
};

template <class T>
T Field(const unsigned char* bytes, bool swap)
{
  unsigned char copy[sizeof(T)];
  for (size_t b = 0; b < sizeof(T); ++b)
  {
    copy[b] = bytes[swap ? sizeof(T) - 1 - b : b];
  }
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

NiftiHeader ReadHeader(const std::string& fileName)
{
  NiftiHeader h;
  unsigned char bytes[540] = { 0 };
  gzFile in = gzopen(fileName.c_str(), "rb");
  if (!in)
  {
    h.Problem = "it cannot be opened";
    return h;
  }
  const int got = gzread(in, bytes, sizeof(bytes));
  h.Gzipped = gzdirect(in) == 0;
  gzclose(in);
  if (got < 348)
  {
    h.Problem = "it is shorter than a NIfTI header (348 bytes)";
    return h;
  }
  const std::int32_t size = Field<std::int32_t>(bytes, false);
  const bool swap = size != 348 && size != 540;
  const std::int32_t declared = swap ? Field<std::int32_t>(bytes, true) : size;
  if (declared == 348)
  {
    h.Version = 1;
    for (int i = 0; i < 8; ++i)
    {
      h.Dim[i] = Field<std::int16_t>(bytes + 40 + 2 * i, swap);
    }
    h.DataType = Field<std::int16_t>(bytes + 70, swap);
    h.BitPix = Field<std::int16_t>(bytes + 72, swap);
    h.VoxOffset = Field<float>(bytes + 108, swap);
    if (std::memcmp(bytes + 344, "n+1\0", 4) != 0)
    {
      h.Problem = std::memcmp(bytes + 344, "ni1\0", 4) == 0
        ? "it is the header of a .hdr/.img pair (magic ni1), not a single-file .nii"
        : "its magic is not NIfTI-1's n+1";
    }
  }
  else if (declared == 540 && got == 540)
  {
    h.Version = 2;
    h.DataType = Field<std::int16_t>(bytes + 12, swap);
    h.BitPix = Field<std::int16_t>(bytes + 14, swap);
    for (int i = 0; i < 8; ++i)
    {
      h.Dim[i] = Field<std::int64_t>(bytes + 16 + 8 * i, swap);
    }
    h.VoxOffset = static_cast<double>(Field<std::int64_t>(bytes + 168, swap));
    if (std::memcmp(bytes + 4, "n+2\0\r\n\032\n", 8) != 0)
    {
      h.Problem = "its magic is not NIfTI-2's n+2";
    }
  }
  else
  {
    h.Problem = "its header size field is " + std::to_string(declared) +
      ", neither NIfTI-1's 348 nor NIfTI-2's 540";
  }
  return h;
}

// Datatypes VTK 9.1's reader maps to VTK types, with the bits a voxel takes.
int BitsOf(int datatype)
{
  switch (datatype)
  {
    case 2:    // uint8
    case 256:  // int8
      return 8;
    case 4:    // int16
    case 512:  // uint16
      return 16;
    case 128:  // RGB24
      return 24;
    case 8:    // int32
    case 16:   // float32
    case 768:  // uint32
    case 2304: // RGBA32
      return 32;
    case 32:   // complex64
    case 64:   // float64
    case 1024: // int64
    case 1280: // uint64
      return 64;
    case 1792: // complex128
      return 128;
    default:
      return 0;
  }
}

const char* KnownName(int datatype)
{
  switch (datatype)
  {
    case 1:
      return " (binary)";
    case 1536:
      return " (float128)";
    case 2048:
      return " (complex256)";
    default:
      return "";
  }
}

// Bytes of the image the header declares (saturating).
std::uint64_t DataBytes(const NiftiHeader& h)
{
  std::uint64_t bytes = static_cast<std::uint64_t>(h.BitPix / 8);
  for (std::int64_t i = 1; i <= h.Dim[0]; ++i)
  {
    bytes = SaturatingProduct(bytes, static_cast<std::uint64_t>(h.Dim[i]));
  }
  return bytes;
}
}

std::string CheckNiftiHeader(const std::string& fileName)
{
  const NiftiHeader h = ReadHeader(fileName);
  if (!h.Problem.empty())
  {
    return h.Problem;
  }
  if (h.Dim[0] < 1 || h.Dim[0] > 7)
  {
    return "its header declares " + std::to_string(h.Dim[0]) + " dimensions (NIfTI has 1 to 7)";
  }
  for (std::int64_t i = 1; i <= h.Dim[0]; ++i)
  {
    if (h.Dim[i] < 1 || h.Dim[i] > 2147483647)
    {
      return "its header's dimension " + std::to_string(i) + " is " + std::to_string(h.Dim[i]) +
        " (a size from 1 to 2^31 - 1)";
    }
  }
  const int bits = BitsOf(h.DataType);
  if (bits == 0)
  {
    return "its datatype " + std::to_string(h.DataType) + KnownName(h.DataType) +
      " is not one VTK's NIfTI reader reads (8- to 64-bit integers, float32, float64, "
      "complex, RGB24, RGBA32)";
  }
  if (h.BitPix != bits)
  {
    return "its bitpix " + std::to_string(h.BitPix) + " is not the " + std::to_string(bits) +
      " bits of its datatype " + std::to_string(h.DataType);
  }
  const double header = h.Version == 1 ? 352.0 : 544.0;
  if (!(h.VoxOffset >= header) || h.VoxOffset != std::floor(h.VoxOffset) || h.VoxOffset > 1e15)
  {
    std::ostringstream problem;
    problem << "its vox_offset " << h.VoxOffset << " is not a whole byte offset after the "
            << header << "-byte header";
    return problem.str();
  }
  return "";
}

std::string CheckNiftiData(const std::string& fileName)
{
  const NiftiHeader h = ReadHeader(fileName);
  if (!h.Problem.empty())
  {
    return h.Problem;
  }
  const std::uint64_t needed = static_cast<std::uint64_t>(h.VoxOffset) + DataBytes(h);
  std::uint64_t holds = vtksys::SystemTools::FileLength(fileName);
  if (h.Gzipped)
  {
    // Decompressed up to what is needed: gzip's trailer cannot be trusted in a cut file, and
    // VTK's reader fills what a cut stream lacks with zeros without a word.
    gzFile in = gzopen(fileName.c_str(), "rb");
    if (!in)
    {
      return "the gzip stream cannot be opened";
    }
    std::vector<char> buffer(1 << 20);
    holds = 0;
    int got = 0;
    while (holds < needed && (got = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0)
    {
      holds += static_cast<std::uint64_t>(got);
    }
    int code = Z_OK;
    const char* text = gzerror(in, &code);
    const std::string message = text && *text ? text : "zlib error"; // gzclose frees it
    gzclose(in);
    if (holds < needed && code != Z_OK && code != Z_STREAM_END)
    {
      return "its gzip stream is broken (" + message + ") after " + std::to_string(holds) +
        " bytes (truncated?)";
    }
  }
  if (holds < needed)
  {
    std::ostringstream problem;
    problem << "the file holds " << holds << (h.Gzipped ? " uncompressed" : "")
            << " bytes, its header and data need " << needed << " (truncated?)";
    return problem.str();
  }
  return "";
}

}
}
