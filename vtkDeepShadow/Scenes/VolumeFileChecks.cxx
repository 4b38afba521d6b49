#include "VolumeFileChecks.h"
#include "DicomSeriesChecks.h"

#include "vtk_zlib.h"

#include "HeaderText.h"
#include "vtkDeepShadowMemoryBudget.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace deepshadow
{
namespace volumefile
{
namespace
{
using vtksys::SystemTools;

std::string Trim(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
  {
    return "";
  }
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> Words(const std::string& text)
{
  std::vector<std::string> words;
  std::istringstream in(text);
  std::string word;
  while (in >> word)
  {
    words.push_back(word);
  }
  return words;
}

bool IsInteger(const std::string& word, long long lo, long long hi, long long* value = nullptr)
{
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(word.c_str(), &end, 10);
  if (word.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
  {
    return false;
  }
  if (value)
  {
    *value = v;
  }
  return true;
}

bool IsFinite(const std::string& word)
{
  char* end = nullptr;
  const double v = std::strtod(word.c_str(), &end);
  return !word.empty() && *end == '\0' && std::isfinite(v);
}


// "KEY = value" lines of a MetaImage header, keys lower case, up to ElementDataFile (the
// last key; binary data may follow it in a .mha). A line that is not text: the key "".
std::map<std::string, std::string> MetaFields(const std::string& fileName)
{
  std::map<std::string, std::string> fields;
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  for (int lines = 0; lines < 1000 && std::getline(in, line); ++lines)
  {
    if (!IsHeaderText(line))
    {
      fields[""] = line;
      break;
    }
    const size_t at = line.find('=');
    if (at == std::string::npos)
    {
      continue;
    }
    const std::string key = SystemTools::LowerCase(Trim(line.substr(0, at)));
    fields[key] = Trim(line.substr(at + 1));
    if (key == "elementdatafile")
    {
      break;
    }
  }
  return fields;
}

std::string CheckMetaHeader(const std::string& fileName)
{
  const auto fields = MetaFields(fileName);
  auto field = [&](const char* key) -> const std::string* {
    const auto it = fields.find(key);
    return it == fields.end() ? nullptr : &it->second;
  };
  if (field(""))
  {
    return "its header holds bytes that are not text before ElementDataFile";
  }
  long long dims = 0;
  if (const std::string* text = field("ndims"))
  {
    if (!IsInteger(*text, 1, 10, &dims))
    {
      return "its header's NDims = " + *text + " is not a whole number from 1 to 10";
    }
  }
  else
  {
    return ""; // MetaIO says what is missing
  }
  if (const std::string* text = field("dimsize"))
  {
    const auto words = Words(*text);
    if (static_cast<long long>(words.size()) != dims)
    {
      return "its header's DimSize = " + *text + " does not have NDims = " +
        std::to_string(dims) + " sizes";
    }
    for (const auto& word : words)
    {
      if (!IsInteger(word, 1, 2147483647))
      {
        return "its header's DimSize = " + *text + " is not a list of positive whole numbers";
      }
    }
  }
  if (const std::string* text = field("elementtype"))
  {
    static const std::set<std::string> types = { "MET_CHAR", "MET_UCHAR", "MET_SHORT",
      "MET_USHORT", "MET_INT", "MET_UINT", "MET_LONG", "MET_ULONG", "MET_LONG_LONG",
      "MET_ULONG_LONG", "MET_FLOAT", "MET_DOUBLE" };
    if (!types.count(*text))
    {
      return "its header's ElementType = " + *text +
        " is not a MetaImage scalar type (MET_UCHAR, MET_SHORT, MET_FLOAT, ...)";
    }
  }
  if (const std::string* text = field("elementnumberofchannels"))
  {
    if (!IsInteger(*text, 1, 1024))
    {
      return "its header's ElementNumberOfChannels = " + *text + " is not a whole number from 1 to 1024";
    }
  }
  // Numbers per key: the geometry must be finite, spacings also non-zero.
  const std::pair<const char*, long long> vectors[] = { { "elementspacing", dims },
    { "elementsize", dims }, { "offset", dims }, { "origin", dims }, { "position", dims },
    { "transformmatrix", dims * dims }, { "rotation", dims * dims },
    { "orientation", dims * dims } };
  for (const auto& vector : vectors)
  {
    if (const std::string* text = field(vector.first))
    {
      const auto words = Words(*text);
      bool good = static_cast<long long>(words.size()) >= vector.second;
      for (const auto& word : words)
      {
        good = good && IsFinite(word);
      }
      if (good && (std::string(vector.first) == "elementspacing" || std::string(vector.first) == "elementsize"))
      {
        for (const auto& word : words)
        {
          good = good && std::strtod(word.c_str(), nullptr) != 0.0;
        }
      }
      if (!good)
      {
        return "its header's " + std::string(vector.first) + " = " + *text + " is not " +
          std::to_string(vector.second) + " finite numbers" +
          (std::string(vector.first).find("element") == 0 ? " (non-zero)" : "");
      }
    }
  }
  if (const std::string* text = field("compresseddatasize"))
  {
    if (!IsInteger(*text, 0, std::numeric_limits<long long>::max()))
    {
      return "its header's CompressedDataSize = " + *text + " is not a byte count";
    }
  }
  if (const std::string* text = field("headersize"))
  {
    if (!IsInteger(*text, -1, std::numeric_limits<long long>::max()))
    {
      return "its header's HeaderSize = " + *text + " is not a byte count";
    }
  }
  return "";
}

std::string CheckNrrdHeader(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  std::map<std::string, std::string> fields;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r')
  {
    line.pop_back();
  }
  if (line.size() != 8 || line.compare(0, 7, "NRRD000") != 0 || line[7] < '1' || line[7] > '5')
  {
    // VTK's reader checks "NRRD" only, and hung on a NUL byte later in that line.
    return "its first line is not the magic NRRD0001 to NRRD0005";
  }
  for (int lines = 0; lines < 1000 && std::getline(in, line) && !Trim(line).empty(); ++lines)
  {
    if (in.eof())
    {
      // Seen here: VTK 9.1's NRRD reader waits forever for the rest of that line.
      return "its header ends inside a line (no line break after '" + line.substr(0, 40) + "')";
    }
    if (!IsHeaderText(line))
    {
      return "its header line " + std::to_string(lines + 2) + " holds bytes that are not text";
    }
    // A field is "name: value" (colon and space, as VTK's reader splits it: "sizes:16" is no
    // field to it, and the image then had no size); "key:=value" pairs and comments are not.
    const size_t at = line.find(": ");
    if (line[0] == '#' || at == std::string::npos || line.find(":=") < at)
    {
      continue;
    }
    fields[SystemTools::LowerCase(Trim(line.substr(0, at)))] = Trim(line.substr(at + 2));
  }
  for (const char* required : { "type", "dimension", "sizes", "encoding" })
  {
    // VTK's reader reads past its buffers without them.
    if (!fields.count(required))
    {
      return std::string("its header lacks the required field '") + required + "'";
    }
  }
  long long dims = 0;
  const auto dimension = fields.find("dimension");
  if (!IsInteger(dimension->second, 1, 16, &dims))
  {
    return "its header's dimension: " + dimension->second + " is not a whole number from 1 to 16";
  }
  const auto sizes = fields.find("sizes");
  if (sizes != fields.end())
  {
    const auto words = Words(sizes->second);
    if (static_cast<long long>(words.size()) != dims)
    {
      return "its header's sizes: " + sizes->second + " does not have dimension: " +
        std::to_string(dims) + " sizes";
    }
    for (const auto& word : words)
    {
      if (!IsInteger(word, 1, 2147483647))
      {
        return "its header's sizes: " + sizes->second + " is not a list of positive whole numbers";
      }
    }
  }
  const auto encoding = fields.find("encoding");
  if (encoding != fields.end())
  {
    const std::string e = SystemTools::LowerCase(encoding->second);
    if (e == "ascii" || e == "text" || e == "txt")
    {
      // Seen here: a ball written as ASCII reads as stripes (uchar) or nothing (short, float).
      return "its data are ASCII-encoded, which VTK 9.1's NRRD reader misreads (the picture "
             "would be wrong); write it with encoding raw or gzip";
    }
  }
  const auto spacings = fields.find("spacings");
  if (spacings != fields.end())
  {
    const auto words = Words(spacings->second);
    if (static_cast<long long>(words.size()) != dims)
    {
      return "its header's spacings: " + spacings->second + " does not have dimension: " +
        std::to_string(dims) + " values";
    }
  }
  return "";
}

// Bytes of a VTK XML data array type, 0 if not a numeric type.
std::uint64_t XMLTypeSize(const std::string& type)
{
  static const std::map<std::string, std::uint64_t> sizes = { { "Int8", 1 }, { "UInt8", 1 },
    { "Int16", 2 }, { "UInt16", 2 }, { "Int32", 4 }, { "UInt32", 4 }, { "Int64", 8 },
    { "UInt64", 8 }, { "Float32", 4 }, { "Float64", 8 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// Reads one header word (4 or 8 bytes, the file's byte order); false past the end.
bool ReadWord(std::ifstream& in, int size, bool bigEndian, std::uint64_t& value)
{
  unsigned char bytes[8] = { 0 };
  if (!in.read(reinterpret_cast<char*>(bytes), size))
  {
    return false;
  }
  value = 0;
  for (int b = 0; b < size; ++b)
  {
    value |= static_cast<std::uint64_t>(bytes[bigEndian ? size - 1 - b : b]) << (8 * b);
  }
  return true;
}
}

Format FormatOf(const std::string& fileName)
{
  if (SystemTools::FileIsDirectory(fileName))
  {
    return Format::Dicom;
  }
  const std::string ext =
    SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(fileName));
  if (ext == ".vti")
  {
    return Format::XML;
  }
  if (ext == ".mhd" || ext == ".mha")
  {
    return Format::Meta;
  }
  if (ext == ".nrrd" || ext == ".nhdr")
  {
    return Format::Nrrd;
  }
  const std::string lower = SystemTools::LowerCase(fileName);
  if (ext == ".nii" || (ext == ".gz" && lower.size() > 7 && lower.rfind(".nii.gz") == lower.size() - 7))
  {
    return Format::Nifti;
  }
  return Format::Unknown;
}

std::string CheckHeader(Format format, const std::string& fileName)
{
  return format == Format::Meta ? CheckMetaHeader(fileName)
    : format == Format::Nrrd    ? CheckNrrdHeader(fileName)
    : format == Format::Dicom   ? CheckDicomDirectory(fileName)
                                : std::string();
}

std::uint64_t ScalarBytes(vtkInformation* info)
{
  vtkInformation* scalars = vtkDataObject::GetActiveFieldInformation(
    info, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  if (!scalars || !scalars->Has(vtkDataObject::FIELD_ARRAY_TYPE()) ||
    !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return 0;
  }
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const int components = scalars->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
    ? scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
    : 1;
  std::uint64_t bytes = SaturatingProduct(static_cast<std::uint64_t>(std::max(components, 1)),
    static_cast<std::uint64_t>(
      vtkDataArray::GetDataTypeSize(scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE()))));
  for (int a = 0; a < 3; ++a)
  {
    const std::int64_t n = static_cast<std::int64_t>(extent[2 * a + 1]) - extent[2 * a] + 1;
    bytes = SaturatingProduct(bytes, static_cast<std::uint64_t>(std::max<std::int64_t>(n, 0)));
  }
  return bytes;
}

std::string CheckInformation(vtkInformation* info, std::uint64_t budget)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (!info->Has(SDDP::WHOLE_EXTENT()))
  {
    return "the file holds no image extent";
  }
  int extent[6];
  info->Get(SDDP::WHOLE_EXTENT(), extent);
  if (extent[1] < extent[0] || extent[3] < extent[2] || extent[5] < extent[4])
  {
    return "the image in the file is empty";
  }
  auto finite = [](const double* v, int n) {
    for (int i = 0; i < n; ++i)
    {
      if (!std::isfinite(v[i]))
      {
        return false;
      }
    }
    return true;
  };
  if (info->Has(vtkDataObject::SPACING()))
  {
    const double* spacing = info->Get(vtkDataObject::SPACING());
    if (!finite(spacing, 3) || spacing[0] == 0.0 || spacing[1] == 0.0 || spacing[2] == 0.0)
    {
      std::ostringstream problem;
      problem << "its spacing (" << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
              << ") is not finite and non-zero";
      return problem.str();
    }
  }
  if (info->Has(vtkDataObject::ORIGIN()) && !finite(info->Get(vtkDataObject::ORIGIN()), 3))
  {
    return "its origin is not finite";
  }
  if (info->Has(vtkDataObject::DIRECTION()))
  {
    const double* d = info->Get(vtkDataObject::DIRECTION());
    const double det = d[0] * (d[4] * d[8] - d[5] * d[7]) - d[1] * (d[3] * d[8] - d[5] * d[6]) +
      d[2] * (d[3] * d[7] - d[4] * d[6]);
    if (!finite(d, 9) || !(std::abs(det) > 1e-12))
    {
      return "its direction matrix is not finite and invertible";
    }
  }
  std::ostringstream image;
  image << "the image (" << (extent[1] - extent[0] + 1LL) << "x" << (extent[3] - extent[2] + 1LL)
        << "x" << (extent[5] - extent[4] + 1LL) << ")";
  return CheckMemoryBudget(image.str(), ScalarBytes(info), budget);
}

// NRRD and MetaImage data files that are missing, or raw (uncompressed) data shorter than the
// image: VTK's readers only print a warning (MetaIO writes to std::cerr) and may return
// garbage, so this is checked from the header before reading. Returns "" when the data look
// complete or the layout is one this check does not cover (compressed or ASCII sizes, skips,
// lists of files).
namespace
{
// NIfTI: the data after a header of at least 348 bytes (352 with its extension flag) must be
// in the file; gzip's trailer holds the uncompressed size modulo 2^32.
std::string CheckNiftiSize(const std::string& fileName, std::uint64_t needed)
{
  const std::uint64_t header = 352;
  const std::uint64_t bytes = SystemTools::FileLength(fileName);
  const bool gzipped = SystemTools::LowerCase(fileName).rfind(".gz") == fileName.size() - 3;
  std::uint64_t holds = bytes;
  if (gzipped)
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
    while (holds < header + needed &&
      (got = gzread(in, buffer.data(), static_cast<unsigned>(buffer.size()))) > 0)
    {
      holds += static_cast<std::uint64_t>(got);
    }
    int code = Z_OK;
    const char* text = gzerror(in, &code);
    const std::string message = text && *text ? text : "zlib error"; // gzclose frees it
    gzclose(in);
    if (holds < header + needed && code != Z_OK && code != Z_STREAM_END)
    {
      return "its gzip stream is broken (" + message + ") after " + std::to_string(holds) +
        " bytes (truncated?)";
    }
  }
  if (holds < header + needed)
  {
    std::ostringstream problem;
    problem << "the file holds " << holds << (gzipped ? " uncompressed" : "")
            << " bytes, its header and data need at least " << header + needed
            << " (truncated?)";
    return problem.str();
  }
  return "";
}
}

std::string CheckDataFile(Format format, const std::string& fileName, std::uint64_t needed)
{
  if (format == Format::Nifti)
  {
    return CheckNiftiSize(fileName, needed);
  }
  std::ifstream in(fileName, std::ios::binary);
  std::string line, dataFile;
  std::uint64_t headerEnd = 0;
  bool raw = true;
  while (std::getline(in, line))
  {
    if (format == Format::Nrrd && Trim(line).empty())
    {
      headerEnd = static_cast<std::uint64_t>(in.tellg());
      break;
    }
    const size_t at = line.find(format == Format::Nrrd ? ':' : '=');
    if (at == std::string::npos)
    {
      continue;
    }
    const std::string key = SystemTools::LowerCase(Trim(line.substr(0, at)));
    const std::string value = Trim(line.substr(at + 1));
    const std::string lower = SystemTools::LowerCase(value);
    if (format == Format::Nrrd)
    {
      if (key == "encoding")
      {
        raw = lower == "raw";
      }
      else if (key == "data file" || key == "datafile")
      {
        dataFile = value;
      }
      else if (key == "byte skip" || key == "byteskip" || key == "line skip" || key == "lineskip")
      {
        return "";
      }
    }
    else
    {
      if (key == "compresseddata")
      {
        raw = lower != "true";
      }
      else if (key == "headersize")
      {
        return "";
      }
      else if (key == "elementdatafile")
      {
        dataFile = value;
        headerEnd = static_cast<std::uint64_t>(in.tellg());
        break;
      }
    }
  }
  const bool local =
    format == Format::Nrrd ? dataFile.empty() : SystemTools::LowerCase(dataFile) == "local";
  if (!local &&
    (dataFile.empty() || SystemTools::LowerCase(dataFile) == "list" ||
      dataFile.find_first_of(" %") != std::string::npos))
  {
    return ""; // no data file named, or a list or pattern of files
  }
  std::string path = fileName;
  if (!local)
  {
    path = SystemTools::CollapseFullPath(dataFile, SystemTools::GetFilenamePath(fileName));
    if (!SystemTools::FileExists(path, true))
    {
      return "its data file '" + path + "' does not exist";
    }
  }
  if (!raw)
  {
    return "";
  }
  const std::uint64_t size = SystemTools::FileLength(path);
  const std::uint64_t available = local ? (size > headerEnd ? size - headerEnd : 0) : size;
  if (available >= needed)
  {
    return "";
  }
  std::ostringstream problem;
  problem << "its raw data " << (local ? "" : "file '" + path + "' ") << "holds " << available
          << " bytes where the image needs " << needed << " (truncated?)";
  return problem.str();
}

std::string CheckXMLImage(vtkXMLDataParser* parser, const std::string& fileName)
{
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* image = root ? root->FindNestedElementWithName("ImageData") : nullptr;
  if (!image)
  {
    return "";
  }
  // Every piece within the whole extent (VTK copies a piece into the image by its extent,
  // unchecked: a piece from -2^31 crashed it).
  int whole[6];
  if (image->GetVectorAttribute("WholeExtent", 6, whole) != 6)
  {
    return "its ImageData has no WholeExtent of six numbers";
  }
  for (int p = 0; p < image->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = image->GetNestedElement(p);
    int extent[6];
    if (std::string(piece->GetName()) != "Piece")
    {
      continue;
    }
    if (piece->GetVectorAttribute("Extent", 6, extent) != 6)
    {
      return "its piece " + std::to_string(p) + " has no Extent of six numbers";
    }
    for (int a = 0; a < 3; ++a)
    {
      if (extent[2 * a] < whole[2 * a] || extent[2 * a + 1] > whole[2 * a + 1] ||
        extent[2 * a] > extent[2 * a + 1])
      {
        return "its piece " + std::to_string(p) + "'s extent is not within its WholeExtent";
      }
    }
  }
  vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
  if (!appended)
  {
    return ""; // no appended data: inline data that the XML parser checks
  }
  const char* encoding = appended->GetAttribute("encoding");
  if (!encoding || std::string(encoding) != "raw")
  {
    return ""; // base64: not covered
  }
  const char* headerType = root->GetAttribute("header_type");
  const int word = headerType && std::string(headerType) == "UInt64" ? 8 : 4;
  const char* byteOrder = root->GetAttribute("byte_order");
  const bool bigEndian = byteOrder && std::string(byteOrder) == "BigEndian";
  const bool compressed = root->GetAttribute("compressor") != nullptr;
  const std::uint64_t fileSize = SystemTools::FileLength(fileName);
  const std::uint64_t start = static_cast<std::uint64_t>(parser->GetAppendedDataPosition());
  std::ifstream in(fileName, std::ios::binary);
  for (int p = 0; p < image->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = image->GetNestedElement(p);
    int extent[6];
    if (std::string(piece->GetName()) != "Piece" || piece->GetVectorAttribute("Extent", 6, extent) != 6)
    {
      continue;
    }
    for (int g = 0; g < piece->GetNumberOfNestedElements(); ++g)
    {
      vtkXMLDataElement* group = piece->GetNestedElement(g);
      const std::string groupName = group->GetName();
      if (groupName != "PointData" && groupName != "CellData")
      {
        continue;
      }
      const int cell = groupName == "CellData" ? 1 : 0;
      std::uint64_t tuples = 1;
      for (int a = 0; a < 3; ++a)
      {
        const std::int64_t n = std::max<std::int64_t>(
          static_cast<std::int64_t>(extent[2 * a + 1]) - extent[2 * a] + 1 - cell, cell ? 1 : 0);
        tuples = SaturatingProduct(tuples, static_cast<std::uint64_t>(std::max<std::int64_t>(n, 0)));
      }
      for (int d = 0; d < group->GetNumberOfNestedElements(); ++d)
      {
        vtkXMLDataElement* array = group->GetNestedElement(d);
        const char* format = array->GetAttribute("format");
        const char* type = array->GetAttribute("type");
        unsigned long long offset = 0;
        if (!format || std::string(format) != "appended" || !type ||
          !array->GetScalarAttribute("offset", offset))
        {
          continue;
        }
        int components = 1;
        array->GetScalarAttribute("NumberOfComponents", components);
        const std::string name = array->GetAttribute("Name") ? array->GetAttribute("Name") : "?";
        const std::uint64_t needed = SaturatingProduct(
          SaturatingProduct(tuples, static_cast<std::uint64_t>(std::max(components, 1))),
          XMLTypeSize(type));
        const std::uint64_t at = start + offset;
        std::uint64_t header = 0, data = 0, blocks = 0;
        in.clear();
        in.seekg(static_cast<std::streamoff>(std::min<std::uint64_t>(at, fileSize)));
        bool complete = at < fileSize && ReadWord(in, word, bigEndian, blocks);
        if (complete && !compressed)
        {
          header = word;
          data = blocks; // the one word is the byte count
        }
        else if (complete)
        {
          // Blocks, block size, last block size, then each block's compressed size.
          std::uint64_t blockSize = 0, lastSize = 0;
          complete = ReadWord(in, word, bigEndian, blockSize) && ReadWord(in, word, bigEndian, lastSize) &&
            SaturatingProduct(blocks + 3, static_cast<std::uint64_t>(word)) <= fileSize - at;
          header = (blocks + 3) * static_cast<std::uint64_t>(word);
          for (std::uint64_t b = 0; complete && b < blocks; ++b)
          {
            std::uint64_t size = 0;
            complete = ReadWord(in, word, bigEndian, size);
            data = std::min(data + size, fileSize);
          }
          const std::uint64_t raw = blocks == 0 ? 0
            : SaturatingProduct(blocks - 1, blockSize) + (lastSize ? lastSize : blockSize);
          if (complete && raw < needed)
          {
            std::ostringstream problem;
            problem << "its array '" << name << "' decompresses to " << raw
                    << " bytes where the image needs " << needed;
            return problem.str();
          }
        }
        if (complete && !compressed && data < needed)
        {
          std::ostringstream problem;
          problem << "its array '" << name << "' holds " << data << " bytes where the image needs "
                  << needed;
          return problem.str();
        }
        if (!complete || header + data > fileSize - std::min(at, fileSize))
        {
          return "the file ends inside the appended data of its array '" + name + "' (truncated?)";
        }
      }
    }
  }
  return "";
}

}
}
