#include "VolumeFileChecks.h"
#include "DicomSeries.h"
#include "NiftiFileChecks.h"
#include "XMLFileChecks.h"

#include "HeaderText.h"
#include "vtkDeepShadowMemoryBudget.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>
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

}

Format FormatOf(const std::string& fileName)
{
  if (SystemTools::FileIsDirectory(fileName) || dicom::IsDicomFile(fileName))
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
  if (format == Format::Meta || format == Format::Nrrd)
  {
    // The data files too: VTK's readers expand a file pattern with sprintf as they read the
    // header (a "%n" in it aborted the process).
    const std::string header = format == Format::Meta ? CheckMetaHeader(fileName) : CheckNrrdHeader(fileName);
    return header.empty() ? CheckDataLayout(format, fileName) : header;
  }
  return format == Format::Nifti ? CheckNiftiHeader(fileName)
    : format == Format::XML     ? xmlfile::CheckStructure(fileName)
                                : std::string(); // DICOM: checked as it is read (DicomSeries.h)
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

namespace
{
// Where a MetaImage or NRRD header keeps its data: after the header in the same file (local),
// in one file it names, or in a list or numbered pattern of files (one 2D slice each).
struct DataLayout
{
  bool Local = true;
  bool Raw = true;          // uncompressed: sizes can be checked
  bool Skips = false;       // byte or line skips, a header size: sizes not checked
  std::uint64_t HeaderEnd = 0;
  std::vector<std::string> Files; // resolved paths of the files named (none when local)
  bool Several = false;     // a list or pattern: one slice a file
  std::uint64_t Slices = 0; // the last size (DimSize / sizes), for several files
  std::string Problem;      // a list or pattern VTK would misread
};

// Files a data file pattern names: "NAME%03d.raw MIN MAX STEP", one integer conversion.
std::vector<std::string> PatternFiles(const std::vector<std::string>& words, const std::string& base,
  std::string& problem)
{
  long long first = 0, last = 0, step = 0;
  if (words.size() < 4 || !IsInteger(words[1], -2147483647, 2147483647, &first) ||
    !IsInteger(words[2], -2147483647, 2147483647, &last) || !IsInteger(words[3], 1, 2147483647, &step) ||
    last < first)
  {
    problem = "its data file pattern '" + words[0] + "' is not followed by first, last and step";
    return {};
  }
  // VTK passes the pattern to sprintf: exactly one integer conversion, no other '%'.
  const std::string& pattern = words[0];
  int conversions = 0;
  for (size_t i = 0; i < pattern.size(); ++i)
  {
    if (pattern[i] != '%')
    {
      continue;
    }
    size_t j = i + 1;
    while (j < pattern.size() && std::strchr("0-+ #", pattern[j]))
    {
      ++j;
    }
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])))
    {
      ++j;
    }
    if (j - i > 6 || j >= pattern.size() || !std::strchr("diuxXo", pattern[j]))
    {
      problem = "its data file pattern '" + pattern + "' is not a name with one %d";
      return {};
    }
    ++conversions;
    i = j;
  }
  const long long count = (last - first) / step + 1;
  if (conversions != 1 || count > MaxDataFiles)
  {
    problem = conversions != 1
      ? "its data file pattern '" + pattern + "' is not a name with one %d"
      : "its data file pattern names " + std::to_string(count) + " files, more than " +
        std::to_string(MaxDataFiles);
    return {};
  }
  std::vector<std::string> files;
  for (long long n = first; n <= last; n += step)
  {
    char name[4096];
    std::snprintf(name, sizeof(name), pattern.c_str(), static_cast<int>(n));
    files.push_back(SystemTools::CollapseFullPath(name, base));
  }
  return files;
}

DataLayout ReadLayout(Format format, const std::string& fileName)
{
  DataLayout layout;
  std::ifstream in(fileName, std::ios::binary);
  const std::string base = SystemTools::GetFilenamePath(fileName);
  std::string line, dataFile;
  long long dimension = 0;
  std::vector<std::string> sizes;
  while (std::getline(in, line))
  {
    if (format == Format::Nrrd && Trim(line).empty())
    {
      layout.HeaderEnd = static_cast<std::uint64_t>(in.tellg());
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
    if (key == "encoding")
    {
      layout.Raw = lower == "raw";
    }
    else if (key == "compresseddata")
    {
      layout.Raw = lower != "true";
    }
    else if (key == "byte skip" || key == "byteskip" || key == "line skip" || key == "lineskip" ||
      key == "headersize")
    {
      layout.Skips = true;
    }
    else if (key == "sizes" || key == "dimsize")
    {
      sizes = Words(value);
    }
    else if (key == "data file" || key == "datafile" || key == "elementdatafile")
    {
      dataFile = value;
      layout.HeaderEnd = static_cast<std::uint64_t>(in.tellg());
      if (format == Format::Meta)
      {
        break; // the last field; a .mha's data follow
      }
    }
  }
  // No data file named (or a header that cannot be read): the data would follow the header.
  layout.Local = dataFile.empty() || (format == Format::Meta && SystemTools::LowerCase(dataFile) == "local");
  if (layout.Local)
  {
    return layout;
  }
  const std::vector<std::string> words = Words(dataFile);
  layout.Several = words.size() > 1 || SystemTools::LowerCase(words.front()) == "list";
  if (!sizes.empty())
  {
    IsInteger(sizes.back(), 1, 2147483647, &dimension);
    layout.Slices = static_cast<std::uint64_t>(std::max(dimension, 0LL));
  }
  if (SystemTools::LowerCase(words.front()) == "list")
  {
    // The file names follow, one a line, to the end of the header file.
    in.clear();
    in.seekg(static_cast<std::streamoff>(layout.HeaderEnd));
    while (std::getline(in, line) && layout.Files.size() <= MaxDataFiles)
    {
      if (!Trim(line).empty())
      {
        layout.Files.push_back(SystemTools::CollapseFullPath(Trim(line), base));
      }
    }
    if (layout.Files.size() > MaxDataFiles)
    {
      layout.Problem = "its list names more than " + std::to_string(MaxDataFiles) + " data files";
    }
  }
  else if (layout.Several)
  {
    layout.Files = PatternFiles(words, base, layout.Problem);
  }
  else
  {
    layout.Files.push_back(SystemTools::CollapseFullPath(dataFile, base));
  }
  return layout;
}
}

std::vector<std::string> DataFiles(Format format, const std::string& fileName)
{
  return format == Format::Meta || format == Format::Nrrd ? ReadLayout(format, fileName).Files
                                                          : std::vector<std::string>();
}

std::string CheckDataLayout(Format format, const std::string& fileName)
{
  return ReadLayout(format, fileName).Problem;
}

std::string CheckDataFile(Format format, const std::string& fileName, std::uint64_t needed)
{
  const DataLayout layout = ReadLayout(format, fileName);
  if (!layout.Problem.empty())
  {
    return layout.Problem;
  }
  if (layout.Several && layout.Files.size() != layout.Slices)
  {
    // VTK reads one slice a file and past its list otherwise (a list of 2 for 16 slices crashed it).
    return "its data file list names " + std::to_string(layout.Files.size()) + " files for " +
      std::to_string(layout.Slices) + " slices (one slice a file)";
  }
  for (const std::string& path : layout.Files)
  {
    if (!SystemTools::FileExists(path, true))
    {
      return "its data file '" + path + "' does not exist";
    }
    struct stat info;
    if (stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
    {
      return "its data file '" + path + "' is not a regular file";
    }
  }
  if (!layout.Raw || layout.Skips)
  {
    return "";
  }
  // Raw data: each file (or the data after the header) holds its share of the image.
  const std::uint64_t share = layout.Files.empty() ? needed : needed / layout.Files.size();
  for (const std::string& path : layout.Local ? std::vector<std::string>{ fileName } : layout.Files)
  {
    const std::uint64_t size = SystemTools::FileLength(path);
    const std::uint64_t available = layout.Local ? (size > layout.HeaderEnd ? size - layout.HeaderEnd : 0) : size;
    if (available < share)
    {
      std::ostringstream problem;
      problem << "its raw data " << (layout.Local ? "" : "file '" + path + "' ") << "holds " << available
              << " bytes where the image needs " << share << " (truncated?)";
      return problem.str();
    }
  }
  return "";
}

}
}
