#include "XMLFileChecks.h"

#include "vtkDeepShadowMemoryBudget.h"

#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace deepshadow
{
namespace xmlfile
{
namespace
{
using vtksys::SystemTools;

// Reads a file one character at a time through its stream buffer, counting them.
class CharStream
{
public:
  explicit CharStream(const std::string& fileName)
    : In(fileName, std::ios::binary)
  {
  }
  bool Good() const { return static_cast<bool>(this->In); }
  int Get()
  {
    const int c = this->In.rdbuf()->sbumpc();
    return c;
  }
  // Skips to just past `end` (e.g. "-->"); false at the end of the file.
  bool SkipPast(const char* end)
  {
    const size_t length = std::strlen(end);
    size_t matched = 0;
    for (int c = this->Get(); c != EOF; c = this->Get())
    {
      matched = c == end[matched] ? matched + 1 : (c == end[0] ? 1 : 0);
      if (matched == length)
      {
        return true;
      }
    }
    return false;
  }

private:
  std::ifstream In;
};

// Bytes of a VTK XML data array type, 0 if not a numeric type.
std::uint64_t TypeSize(const std::string& type)
{
  static const std::map<std::string, std::uint64_t> sizes = { { "Int8", 1 }, { "UInt8", 1 },
    { "Int16", 2 }, { "UInt16", 2 }, { "Int32", 4 }, { "UInt32", 4 }, { "Int64", 8 },
    { "UInt64", 8 }, { "Float32", 4 }, { "Float64", 8 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

// A header word (4 or 8 bytes, the file's byte order) at `bytes`.
std::uint64_t Word(const unsigned char* bytes, int size, bool bigEndian)
{
  std::uint64_t value = 0;
  for (int b = 0; b < size; ++b)
  {
    value |= static_cast<std::uint64_t>(bytes[bigEndian ? size - 1 - b : b]) << (8 * b);
  }
  return value;
}

int Base64Value(int c)
{
  return c >= 'A' && c <= 'Z' ? c - 'A'
    : c >= 'a' && c <= 'z'    ? c - 'a' + 26
    : c >= '0' && c <= '9'    ? c - '0' + 52
    : c == '+'                ? 62
    : c == '/'                ? 63
                              : -1;
}

std::uint64_t Base64Length(std::uint64_t bytes)
{
  return (bytes + 2) / 3 * 4;
}

// The array's data in the file, as VTK's XML writer lays it out after '_': raw, a byte-count
// word then the bytes, or (compressed) the block count, block size, last block size, each
// block's compressed size, then the blocks; base64, the same bytes encoded (uncompressed: the
// word and the data in one run of characters; compressed: the header words, padded, then the
// blocks). Reads only the header words.
class AppendedData
{
public:
  AppendedData(const std::string& fileName, std::uint64_t start, bool base64, int word, bool bigEndian)
    : In(fileName, std::ios::binary)
    , FileSize(SystemTools::FileLength(fileName))
    , Start(start)
    , Base64(base64)
    , WordSize(word)
    , BigEndian(bigEndian)
  {
  }

  // Checks one array at `offset` needing `needed` bytes: "" or the problem.
  std::string Check(std::uint64_t offset, std::uint64_t needed, bool compressed, const std::string& name)
  {
    const std::uint64_t at = this->Start + offset;
    const std::string truncated =
      "the file ends inside the appended data of its array '" + name + "' (truncated?)";
    std::vector<unsigned char> header;
    if (!this->Read(at, 0, this->WordSize, header))
    {
      return truncated;
    }
    const std::uint64_t first = Word(header.data(), this->WordSize, this->BigEndian);
    std::uint64_t payload = 0, stored = 0; // bytes decoded, bytes in the file after the header
    std::uint64_t headerBytes = static_cast<std::uint64_t>(this->WordSize);
    if (!compressed)
    {
      payload = stored = first;
    }
    else
    {
      const std::uint64_t blocks = first;
      headerBytes = SaturatingProduct(blocks + 3, static_cast<std::uint64_t>(this->WordSize));
      if (headerBytes > this->FileSize || !this->Read(at, 0, headerBytes, header))
      {
        return truncated;
      }
      const std::uint64_t blockSize = Word(&header[this->WordSize], this->WordSize, this->BigEndian);
      const std::uint64_t lastSize = Word(&header[2 * this->WordSize], this->WordSize, this->BigEndian);
      for (std::uint64_t b = 0; b < blocks; ++b)
      {
        stored = std::min(stored + Word(&header[(3 + b) * this->WordSize], this->WordSize,
          this->BigEndian), this->FileSize + 1);
      }
      payload = blocks == 0 ? 0 : SaturatingProduct(blocks - 1, blockSize) + (lastSize ? lastSize : blockSize);
    }
    if (payload < needed)
    {
      std::ostringstream problem;
      problem << "its array '" << name << "' " << (compressed ? "decompresses to " : "holds ")
              << payload << " bytes where the image needs " << needed;
      return problem.str();
    }
    // Uncompressed data need only what the image does; compressed blocks all of theirs.
    const std::uint64_t body = compressed ? stored : needed;
    const std::uint64_t span = !this->Base64 ? headerBytes + body
      : compressed ? Base64Length(headerBytes) + Base64Length(body)
                   : Base64Length(headerBytes + body);
    if (at > this->FileSize || span > this->Available(at))
    {
      return truncated;
    }
    return "";
  }

private:
  // Decodes `count` bytes from `skip` bytes into the array's run at `at`; false past the end.
  bool Read(std::uint64_t at, std::uint64_t skip, std::uint64_t count, std::vector<unsigned char>& out)
  {
    out.assign(static_cast<size_t>(count), 0);
    this->In.clear();
    if (!this->Base64)
    {
      this->In.seekg(static_cast<std::streamoff>(at + skip));
      return at + skip + count <= this->FileSize &&
        static_cast<bool>(this->In.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(count)));
    }
    this->In.seekg(static_cast<std::streamoff>(at));
    std::uint64_t produced = 0, bits = 0;
    int held = 0;
    while (produced < skip + count)
    {
      const int value = Base64Value(this->In.get());
      if (value < 0)
      {
        return false;
      }
      bits = (bits << 6) | static_cast<std::uint64_t>(value);
      held += 6;
      if (held >= 8)
      {
        held -= 8;
        if (produced >= skip)
        {
          out[static_cast<size_t>(produced - skip)] = static_cast<unsigned char>((bits >> held) & 0xFF);
        }
        ++produced;
      }
    }
    return true;
  }

  // Bytes (raw) or base64 characters (base64) from `at` to the end of the run.
  std::uint64_t Available(std::uint64_t at)
  {
    if (!this->Base64)
    {
      return this->FileSize - at;
    }
    this->In.clear();
    this->In.seekg(static_cast<std::streamoff>(at));
    std::uint64_t count = 0;
    for (int c = this->In.get(); c != EOF && (Base64Value(c) >= 0 || c == '='); c = this->In.get())
    {
      ++count;
    }
    return count;
  }

  std::ifstream In;
  std::uint64_t FileSize;
  std::uint64_t Start;
  bool Base64;
  int WordSize;
  bool BigEndian;
};

using Extent = std::array<int, 6>;

// Points of the whole extent that no piece covers (VTK leaves them unset), counted exactly
// over the grid the pieces' bounds cut it into (at most 64 pieces; more: by their sizes).
std::uint64_t UncoveredPoints(const Extent& whole, const std::vector<Extent>& pieces)
{
  auto points = [](const Extent& e) {
    std::uint64_t n = 1;
    for (int a = 0; a < 3; ++a)
    {
      n = SaturatingProduct(n, static_cast<std::uint64_t>(static_cast<std::int64_t>(e[2 * a + 1]) - e[2 * a] + 1));
    }
    return n;
  };
  const std::uint64_t total = points(whole);
  if (pieces.size() > 64)
  {
    std::uint64_t covered = 0;
    for (const Extent& piece : pieces)
    {
      covered += points(piece);
    }
    return covered >= total ? 0 : total - covered;
  }
  // Cell c of axis a spans [cuts[c], cuts[c + 1]) in point indices.
  std::array<std::vector<std::int64_t>, 3> cuts;
  for (int a = 0; a < 3; ++a)
  {
    std::set<std::int64_t> at = { whole[2 * a], static_cast<std::int64_t>(whole[2 * a + 1]) + 1 };
    for (const Extent& piece : pieces)
    {
      at.insert(piece[2 * a]);
      at.insert(static_cast<std::int64_t>(piece[2 * a + 1]) + 1);
    }
    cuts[a].assign(at.begin(), at.end());
  }
  std::uint64_t uncovered = 0;
  for (size_t i = 0; i + 1 < cuts[0].size(); ++i)
  {
    for (size_t j = 0; j + 1 < cuts[1].size(); ++j)
    {
      for (size_t k = 0; k + 1 < cuts[2].size(); ++k)
      {
        const std::int64_t lo[3] = { cuts[0][i], cuts[1][j], cuts[2][k] };
        const bool covered = std::any_of(pieces.begin(), pieces.end(), [&](const Extent& p) {
          return lo[0] >= p[0] && lo[0] <= p[1] && lo[1] >= p[2] && lo[1] <= p[3] && lo[2] >= p[4] &&
            lo[2] <= p[5];
        });
        if (!covered)
        {
          uncovered += static_cast<std::uint64_t>((cuts[0][i + 1] - cuts[0][i]) *
            (cuts[1][j + 1] - cuts[1][j]) * (cuts[2][k + 1] - cuts[2][k]));
        }
      }
    }
  }
  return uncovered;
}
}

std::string CheckStructure(const std::string& fileName)
{
  CharStream in(fileName);
  if (!in.Good())
  {
    return "it cannot be opened";
  }
  int depth = 0;
  std::uint64_t elements = 0;
  for (int c = in.Get(); c != EOF; c = in.Get())
  {
    if (c != '<')
    {
      continue;
    }
    c = in.Get();
    if (c == '!')
    {
      // A comment, CDATA or a declaration (a DOCTYPE's internal subset in brackets).
      const int second = in.Get(), third = in.Get();
      bool closed = true;
      if (second == '-' && third == '-')
      {
        closed = in.SkipPast("-->");
      }
      else if (second == '[')
      {
        closed = in.SkipPast("]]>");
      }
      else
      {
        int brackets = second == '[' ? 1 : 0;
        brackets += third == '[' ? 1 : third == ']' ? -1 : 0;
        int d = third;
        for (; d != EOF && !(d == '>' && brackets <= 0); d = in.Get())
        {
          brackets += d == '[' ? 1 : d == ']' ? -1 : 0;
        }
        closed = d != EOF;
      }
      if (!closed)
      {
        return "its XML ends inside a comment or declaration (truncated?)";
      }
      continue;
    }
    if (c == '?')
    {
      if (!in.SkipPast("?>"))
      {
        return "its XML ends inside a processing instruction (truncated?)";
      }
      continue;
    }
    const bool end = c == '/';
    std::string name;
    for (c = end ? in.Get() : c; c != EOF && c != '>' && c != '/' && !std::isspace(c); c = in.Get())
    {
      name += static_cast<char>(c);
    }
    // The rest of the tag, quoted attribute values included ('>' may appear in them).
    int quote = 0, last = 0;
    for (; c != EOF && !(c == '>' && !quote); c = in.Get())
    {
      quote = quote ? (c == quote ? 0 : quote) : (c == '"' || c == '\'' ? c : 0);
      last = c;
    }
    if (c == EOF)
    {
      return "its XML ends inside the tag <" + name.substr(0, 40) + "> (truncated?)";
    }
    if (end)
    {
      --depth;
      continue;
    }
    if (++elements > MaxElements)
    {
      return "it holds more than " + std::to_string(MaxElements) +
        " XML elements (a VTK XML file needs a few per piece and array)";
    }
    if (name == "AppendedData")
    {
      return ""; // raw bytes follow: not XML
    }
    if (last != '/' && ++depth > MaxDepth)
    {
      return "its XML elements nest more than " + std::to_string(MaxDepth) +
        " deep (a VTK XML file needs about 7 levels)";
    }
  }
  return "";
}

std::string CheckImage(vtkXMLDataParser* parser, const std::string& fileName)
{
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* image = root ? root->FindNestedElementWithName("ImageData") : nullptr;
  if (!image)
  {
    return "";
  }
  // Every piece within the whole extent (VTK copies a piece into the image by its extent,
  // unchecked: a piece from -2^31 crashed it), and all of it covered (VTK leaves the rest
  // of the image unset: half a volume drawn, no word).
  Extent whole;
  if (image->GetVectorAttribute("WholeExtent", 6, whole.data()) != 6)
  {
    return "its ImageData has no WholeExtent of six numbers";
  }
  std::vector<Extent> pieces;
  for (int p = 0; p < image->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = image->GetNestedElement(p);
    Extent extent;
    if (std::string(piece->GetName()) != "Piece")
    {
      continue;
    }
    if (piece->GetVectorAttribute("Extent", 6, extent.data()) != 6)
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
    pieces.push_back(extent);
  }
  const std::uint64_t uncovered = UncoveredPoints(whole, pieces);
  if (uncovered > 0 && whole[0] <= whole[1] && whole[2] <= whole[3] && whole[4] <= whole[5])
  {
    std::ostringstream problem;
    problem << "its pieces leave " << uncovered << " points of its WholeExtent without data "
            << "(the image would be drawn partly empty)";
    return problem.str();
  }

  vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
  if (!appended)
  {
    return ""; // no appended data: inline data that the XML parser checks
  }
  const char* encoding = appended->GetAttribute("encoding");
  const bool base64 = encoding && std::string(encoding) == "base64";
  if (!base64 && (!encoding || std::string(encoding) != "raw"))
  {
    return std::string("its appended data's encoding '") + (encoding ? encoding : "") +
      "' is neither raw nor base64";
  }
  const char* headerType = root->GetAttribute("header_type");
  const int word = headerType && std::string(headerType) == "UInt64" ? 8 : 4;
  const char* byteOrder = root->GetAttribute("byte_order");
  const bool bigEndian = byteOrder && std::string(byteOrder) == "BigEndian";
  const bool compressed = root->GetAttribute("compressor") != nullptr;
  AppendedData data(fileName, static_cast<std::uint64_t>(parser->GetAppendedDataPosition()), base64, word, bigEndian);
  for (int p = 0; p < image->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = image->GetNestedElement(p);
    Extent extent;
    if (std::string(piece->GetName()) != "Piece" || piece->GetVectorAttribute("Extent", 6, extent.data()) != 6)
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
          SaturatingProduct(tuples, static_cast<std::uint64_t>(std::max(components, 1))), TypeSize(type));
        const std::string problem = data.Check(offset, needed, compressed, name);
        if (!problem.empty())
        {
          return problem;
        }
      }
    }
  }
  return "";
}

}
}
