#include "MeshFileChecks.h"

#include "HeaderText.h"
#include "vtkDeepShadowMemoryBudget.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace deepshadow
{
namespace meshfile
{
namespace
{

// Bytes of a PLY scalar type, 0 if unknown.
int PLYTypeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "uchar", 1 },
    { "int8", 1 }, { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 },
    { "uint16", 2 }, { "int", 4 }, { "uint", 4 }, { "int32", 4 }, { "uint32", 4 },
    { "float", 4 }, { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

bool IsFloatType(const std::string& type)
{
  return type == "float" || type == "float32" || type == "double" || type == "float64";
}

bool IsSignedType(const std::string& type)
{
  return type == "char" || type == "int8" || type == "short" || type == "int16" ||
    type == "int" || type == "int32";
}

struct Property
{
  std::string Name;
  std::string Type;      // of the value, or of a list's items
  std::string CountType; // empty unless a list
};

struct Element
{
  std::string Name;
  std::uint64_t Count = 0;
  std::vector<Property> Properties;
};

std::vector<std::string> Words(const std::string& line)
{
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string word;
  while (in >> word)
  {
    words.push_back(word);
  }
  return words;
}

// A list count (or an index) as the file stores it, binary in its byte order; true when it is
// a whole number >= 0.
bool ListCount(const unsigned char* bytes, const std::string& type, bool bigEndian, double& count)
{
  const int size = PLYTypeSize(type);
  unsigned char b[8];
  for (int i = 0; i < size; ++i)
  {
    b[i] = bytes[bigEndian ? size - 1 - i : i];
  }
  std::uint64_t u = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    u = (u << 8) | b[i];
  }
  if (type == "float" || type == "float32")
  {
    float f;
    std::uint32_t w = static_cast<std::uint32_t>(u);
    std::memcpy(&f, &w, 4);
    count = f;
  }
  else if (type == "double" || type == "float64")
  {
    std::memcpy(&count, &u, 8);
  }
  else if (IsSignedType(type))
  {
    const int shift = 64 - 8 * size;
    count = static_cast<double>(static_cast<std::int64_t>(u << shift) >> shift);
  }
  else
  {
    count = static_cast<double>(u);
  }
  return std::isfinite(count) && count >= 0.0 && count == std::floor(count);
}

// Whether a list property holds point ids that VTK's reader follows without checking (face
// and tristrip corners); tristrips separate strips with -1.
bool IsIndexList(const Element& element, const Property& property)
{
  return !property.CountType.empty() && (element.Name == "face" || element.Name == "tristrips") &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}

std::string BadIndex(const Element& element, std::uint64_t e, double value, std::uint64_t vertices)
{
  std::ostringstream problem;
  problem << element.Name << " " << e << " refers to the vertex " << value << " of "
          << vertices << " (out of range)";
  return problem.str();
}

// One value as the file stores it (binary, its byte order), as a double.
double BinaryValue(const unsigned char* bytes, const std::string& type, bool bigEndian)
{
  double value = 0.0;
  ListCount(bytes, type, bigEndian, value); // any integer (or float) decodes; the check is the caller's
  return value;
}

// The vertex indices of an ASCII index list (the `count` words after its count at `next`):
// whole numbers within the vertices (tristrips: -1 too, which separates strips).
std::string CheckAsciiIndices(const Element& element, std::uint64_t e,
  const std::vector<std::string>& words, size_t next, double count, std::uint64_t vertices)
{
  const double lowest = element.Name == "tristrips" ? -1.0 : 0.0;
  for (size_t k = next + 1; k <= next + static_cast<size_t>(count); ++k)
  {
    char* end = nullptr;
    const double index = std::strtod(words[k].c_str(), &end);
    if (*end != '\0' || !(index >= lowest) || !(index < static_cast<double>(vertices)) ||
      index != std::floor(index))
    {
      return BadIndex(element, e, index, vertices);
    }
  }
  return "";
}

// The words of the ASCII line of element `e` against its properties: a value for each, and
// each list's count matching the values after it.
std::string CheckAsciiValues(const Element& element, std::uint64_t e,
  const std::vector<std::string>& words, std::uint64_t vertices)
{
  size_t next = 0;
  for (const Property& property : element.Properties)
  {
    if (next >= words.size())
    {
      return element.Name + " " + std::to_string(e) + " has fewer values than its properties";
    }
    if (!property.CountType.empty())
    {
      char* end = nullptr;
      const double count = std::strtod(words[next].c_str(), &end);
      if (*end != '\0' || !(count >= 0.0) || count != std::floor(count) ||
        count > static_cast<double>(words.size() - next - 1))
      {
        return element.Name + " " + std::to_string(e) + "'s " + property.Name +
          " list count '" + words[next] + "' does not match its values";
      }
      if (IsIndexList(element, property))
      {
        const std::string problem = CheckAsciiIndices(element, e, words, next, count, vertices);
        if (!problem.empty())
        {
          return problem;
        }
      }
      next += static_cast<size_t>(count);
    }
    ++next;
  }
  return "";
}

// An ASCII body: a whole line of text for each element, its values as its properties say.
std::string CheckAsciiBody(
  std::ifstream& in, const std::vector<Element>& elements, std::uint64_t vertices)
{
  std::string line;
  for (const Element& element : elements)
  {
    for (std::uint64_t e = 0; e < element.Count; ++e)
    {
      if (!std::getline(in, line))
      {
        return "it ends after " + std::to_string(e) + " of its " + std::to_string(element.Count) +
          " " + element.Name + " lines (truncated?)";
      }
      if (!IsHeaderText(line))
      {
        return element.Name + " " + std::to_string(e) + "'s line holds bytes that are not text";
      }
      if (in.eof())
      {
        // VTK's reader frees twice at an end of file inside a line.
        return "it ends inside the line of " + element.Name + " " + std::to_string(e) + " (truncated?)";
      }
      const std::string problem = CheckAsciiValues(element, e, Words(line), vertices);
      if (!problem.empty())
      {
        return problem;
      }
    }
  }
  return "";
}

// A walk through a binary body: the file (at the next value), its byte order, the bytes of
// data after the header and how many of them were used, and the vertices indices refer to.
struct BinaryWalk
{
  BinaryWalk(std::ifstream& in, bool bigEndian, std::uint64_t dataBytes, std::uint64_t vertices)
    : In(in)
    , BigEndian(bigEndian)
    , DataBytes(dataBytes)
    , Vertices(vertices)
  {
  }

  std::ifstream& In;
  const bool BigEndian;
  const std::uint64_t DataBytes, Vertices;
  std::uint64_t Used = 0;
  std::vector<unsigned char> Buffer = std::vector<unsigned char>(8);
};

// Elements without lists are of a fixed size: their total is known without reading them, so
// the walk checks it against the data left and skips them.
std::string SkipFixedElements(BinaryWalk& walk, const Element& element, std::uint64_t fixed)
{
  const std::uint64_t bytes = SaturatingProduct(element.Count, fixed);
  if (bytes > walk.DataBytes - walk.Used)
  {
    return "its header declares " + std::to_string(element.Count) + " " + element.Name +
      " elements (" + std::to_string(bytes) + " bytes) but " +
      std::to_string(walk.DataBytes - walk.Used) + " bytes of data are left (truncated?)";
  }
  walk.Used += bytes;
  walk.In.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
  return "";
}

// The `count` vertex indices of an index list, the file at its first: whole numbers within
// the vertices (tristrips: -1 too, which separates strips).
std::string CheckBinaryIndices(BinaryWalk& walk, const Element& element, std::uint64_t e,
  const Property& property, double count)
{
  const int itemSize = PLYTypeSize(property.Type);
  const double lowest = element.Name == "tristrips" ? -1.0 : 0.0;
  for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(count); ++k)
  {
    walk.In.read(reinterpret_cast<char*>(walk.Buffer.data()), itemSize);
    const double index = BinaryValue(walk.Buffer.data(), property.Type, walk.BigEndian);
    if (!(index >= lowest) || !(index < static_cast<double>(walk.Vertices)) || index != std::floor(index))
    {
      return BadIndex(element, e, index, walk.Vertices);
    }
  }
  return "";
}

// A list whose count (in the walk's buffer) was just read: a whole count of items within the
// data left, then its items, checked when they are vertex indices, skipped otherwise.
std::string CheckBinaryList(
  BinaryWalk& walk, const Element& element, std::uint64_t e, const Property& property)
{
  double count = 0.0;
  if (!ListCount(walk.Buffer.data(), property.CountType, walk.BigEndian, count))
  {
    return element.Name + " " + std::to_string(e) + "'s " + property.Name +
      " list has a count that is not a whole number >= 0";
  }
  const int itemSize = PLYTypeSize(property.Type);
  if (count > static_cast<double>((walk.DataBytes - walk.Used) / static_cast<std::uint64_t>(itemSize)))
  {
    return element.Name + " " + std::to_string(e) + "'s " + property.Name + " list of " +
      std::to_string(static_cast<std::uint64_t>(count)) + " items runs past the end of the file (truncated?)";
  }
  const std::uint64_t items = static_cast<std::uint64_t>(count) * static_cast<std::uint64_t>(itemSize);
  walk.Used += items;
  if (!IsIndexList(element, property))
  {
    walk.In.seekg(static_cast<std::streamoff>(items), std::ios::cur);
    return "";
  }
  return CheckBinaryIndices(walk, element, e, property, count);
}

// Element `e` of an element with lists, value by value: each within the data left.
std::string CheckBinaryElement(BinaryWalk& walk, const Element& element, std::uint64_t e)
{
  for (const Property& property : element.Properties)
  {
    const bool list = !property.CountType.empty();
    const int size = PLYTypeSize(list ? property.CountType : property.Type);
    if (static_cast<std::uint64_t>(size) > walk.DataBytes - walk.Used ||
      !walk.In.read(reinterpret_cast<char*>(walk.Buffer.data()), size))
    {
      return "it ends inside " + element.Name + " " + std::to_string(e) + " of " +
        std::to_string(element.Count) + " (truncated?)";
    }
    walk.Used += static_cast<std::uint64_t>(size);
    if (!list)
    {
      continue;
    }
    const std::string problem = CheckBinaryList(walk, element, e, property);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return "";
}

// A binary body: every element within the data after the header (`dataBytes`).
std::string CheckBinaryBody(std::ifstream& in, const std::vector<Element>& elements,
  bool bigEndian, std::uint64_t dataBytes, std::uint64_t vertices)
{
  BinaryWalk walk(in, bigEndian, dataBytes, vertices);
  for (const Element& element : elements)
  {
    std::uint64_t fixed = 0; // bytes of the scalar properties
    bool lists = false;
    for (const Property& property : element.Properties)
    {
      fixed += property.CountType.empty() ? PLYTypeSize(property.Type) : 0;
      lists = lists || !property.CountType.empty();
    }
    if (!lists)
    {
      const std::string problem = SkipFixedElements(walk, element, fixed);
      if (!problem.empty())
      {
        return problem;
      }
      continue;
    }
    for (std::uint64_t e = 0; e < element.Count; ++e)
    {
      const std::string problem = CheckBinaryElement(walk, element, e);
      if (!problem.empty())
      {
        return problem;
      }
    }
  }
  return "";
}

std::string CheckBody(std::ifstream& in, const std::vector<Element>& elements, bool ascii,
  bool bigEndian, std::uint64_t dataBytes, std::uint64_t vertices)
{
  return ascii ? CheckAsciiBody(in, elements, vertices)
               : CheckBinaryBody(in, elements, bigEndian, dataBytes, vertices);
}

// What a PLY header declares, filled in as its lines are read.
struct PLYHeader
{
  std::vector<Element> Elements;
  bool Ascii = false, BigEndian = false, FormatSeen = false, Ended = false;
};

// A "format" line: the only one, of one of PLY's three formats.
std::string ParseFormat(const std::vector<std::string>& words, int number, PLYHeader& header)
{
  if (header.FormatSeen || words.size() != 3 ||
    (words[1] != "ascii" && words[1] != "binary_little_endian" && words[1] != "binary_big_endian"))
  {
    return "its header line " + std::to_string(number) + " is not a PLY format line";
  }
  header.FormatSeen = true;
  header.Ascii = words[1] == "ascii";
  header.BigEndian = words[1] == "binary_big_endian";
  return "";
}

// An "element NAME COUNT" line, its count a whole number up to 2^31 - 1.
std::string ParseElement(const std::vector<std::string>& words, int number, PLYHeader& header)
{
  char* end = nullptr;
  const double count = words.size() == 3 ? std::strtod(words[2].c_str(), &end) : -1.0;
  if (words.size() != 3 || *end != '\0' || !(count >= 0.0) || count != std::floor(count) ||
    count > 2147483647.0)
  {
    return "its header line " + std::to_string(number) + " is not 'element NAME COUNT' with a count up to 2^31 - 1";
  }
  header.Elements.push_back({ words[1], static_cast<std::uint64_t>(count), {} });
  return "";
}

// A "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME" line of the last element, of
// known types; a list's count of an integer type.
std::string ParseProperty(const std::vector<std::string>& words, int number, PLYHeader& header)
{
  const bool list = words.size() == 5 && words[1] == "list";
  if (header.Elements.empty() || (!list && words.size() != 3) ||
    PLYTypeSize(words[list ? 3 : 1]) == 0 || (list && PLYTypeSize(words[2]) == 0))
  {
    return "its header line " + std::to_string(number) +
      " is not a property of known type after an element";
  }
  if (list && IsFloatType(words[2]))
  {
    return "its header line " + std::to_string(number) + " counts a list with a floating-point type";
  }
  header.Elements.back().Properties.push_back(
    { words[list ? 4 : 2], words[list ? 3 : 1], list ? words[2] : std::string() });
  return "";
}

// Header line `number` (from 1): "ply" first, then keyword lines up to end_header.
std::string ParseHeaderLine(const std::string& line, int number, PLYHeader& header)
{
  if (line.size() > 1000 || !IsHeaderText(line))
  {
    return "its header line " + std::to_string(number) +
      (IsHeaderText(line) ? " is longer than 1000 characters" : " holds bytes that are not text");
  }
  const std::vector<std::string> words = Words(line);
  const std::string key = words.empty() ? "" : words[0];
  if (number == 1)
  {
    if (key != "ply" || words.size() != 1)
    {
      return "it does not start with 'ply'";
    }
  }
  else if (key == "format")
  {
    return ParseFormat(words, number, header);
  }
  else if (key == "element")
  {
    return ParseElement(words, number, header);
  }
  else if (key == "property")
  {
    return ParseProperty(words, number, header);
  }
  else if (key == "end_header")
  {
    header.Ended = true;
  }
  else if (key != "comment" && key != "obj_info" && !key.empty())
  {
    return "its header line " + std::to_string(number) + " starts with the unknown keyword '" + key + "'";
  }
  return "";
}

// Reads the header up to its end_header, leaving `in` at the body.
std::string ReadHeader(std::ifstream& in, PLYHeader& header)
{
  std::string line;
  // vtkPLY reads header lines into fixed buffers and words into a fixed table.
  for (int number = 1; !header.Ended && std::getline(in, line); ++number)
  {
    const std::string problem = ParseHeaderLine(line, number, header);
    if (!problem.empty())
    {
      return problem;
    }
  }
  if (!header.FormatSeen || !header.Ended)
  {
    return !header.FormatSeen ? "its header has no format line" : "its header does not end (no end_header)";
  }
  if (header.Elements.size() > 100)
  {
    return "its header declares more than 100 elements";
  }
  return "";
}

// An element's properties: names unique, vertex indices of an integer type. Counts its scalar
// x, y and z in `xyz`, and its vertex index lists in `lists`.
std::string CheckProperties(const Element& element, int& xyz, int& lists)
{
  for (size_t p = 0; p < element.Properties.size(); ++p)
  {
    const Property& property = element.Properties[p];
    for (size_t q = 0; q < p; ++q)
    {
      if (element.Properties[q].Name == property.Name)
      {
        return "its element " + element.Name + " declares the property " + property.Name + " twice";
      }
    }
    xyz += property.CountType.empty() && (property.Name == "x" || property.Name == "y" || property.Name == "z");
    if (IsIndexList(element, property))
    {
      if (IsFloatType(property.Type))
      {
        return "its element " + element.Name + " lists vertex indices of a floating-point type";
      }
      ++lists;
    }
  }
  return "";
}

// What VTK's reader assumes without checking (it crashes or frees twice otherwise): element
// and property names unique, a vertex element with scalar x, y and z, and faces and strips
// with an integer list of vertex indices. `vertices`: the vertex element's count.
std::string CheckElements(const std::vector<Element>& elements, std::uint64_t& vertices)
{
  bool haveVertex = false;
  for (size_t i = 0; i < elements.size(); ++i)
  {
    const Element& element = elements[i];
    for (size_t j = 0; j < i; ++j)
    {
      if (elements[j].Name == element.Name)
      {
        return "its header declares the element " + element.Name + " twice";
      }
    }
    // VTK's PLY reader frees a pointer it never set for an element without properties.
    if (element.Properties.empty())
    {
      return "its element " + element.Name + " has no properties";
    }
    int xyz = 0, lists = 0;
    const std::string problem = CheckProperties(element, xyz, lists);
    if (!problem.empty())
    {
      return problem;
    }
    if (element.Name == "vertex")
    {
      if (xyz != 3)
      {
        return "its vertex element lacks the scalar properties x, y and z";
      }
      haveVertex = true;
      vertices = element.Count;
    }
    if ((element.Name == "face" || element.Name == "tristrips") && lists != 1)
    {
      return "its element " + element.Name + " has no list property vertex_indices";
    }
  }
  if (!haveVertex)
  {
    return "its header declares no vertex element";
  }
  return "";
}

// Adds to `bytes` what VTK allocates for each element, element by element (a refused element
// leaves the sum of those before it): at most 100 properties an element.
std::string AddElementBytes(const std::vector<Element>& elements, std::uint64_t& bytes)
{
  for (const Element& element : elements)
  {
    if (element.Properties.size() > 100)
    {
      return "its element " + element.Name + " has more than 100 properties";
    }
    // VTK keeps each value of each element as at most 8 bytes (lists: their items too, read
    // below within the file's size).
    bytes += SaturatingProduct(element.Count, 8 * (element.Properties.size() + 1));
  }
  return "";
}
}

std::string CheckPLY(const std::string& fileName, std::uint64_t& bytes)
{
  bytes = 0;
  std::ifstream in(fileName, std::ios::binary);
  PLYHeader header;
  std::uint64_t vertices = 0;
  std::string problem = ReadHeader(in, header);
  if (problem.empty())
  {
    problem = CheckElements(header.Elements, vertices);
  }
  if (problem.empty())
  {
    problem = AddElementBytes(header.Elements, bytes);
  }
  if (!problem.empty())
  {
    return problem;
  }
  const std::uint64_t size = vtksys::SystemTools::FileLength(fileName);
  const std::uint64_t headerEnd = static_cast<std::uint64_t>(in.tellg());
  return CheckBody(in, header.Elements, header.Ascii, header.BigEndian,
    size > headerEnd ? size - headerEnd : 0, vertices);
}

std::string CheckOBJ(const std::string& fileName, std::uint64_t& bytes)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  std::uint64_t points = 0, textures = 0, normals = 0, corners = 0;
  for (std::uint64_t number = 1; std::getline(in, line); ++number)
  {
    if (!IsHeaderText(line))
    {
      return "its line " + std::to_string(number) + " holds bytes that are not text";
    }
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "v")
    {
      // VTK's OBJ reader reads "nan" as 0 and a missing coordinate as 0: the mesh then had
      // points the file never gave.
      ++points;
      std::string word;
      int coordinates = 0;
      for (; coordinates < 3 && words >> word; ++coordinates)
      {
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        if (*end != '\0' || !std::isfinite(value))
        {
          return "line " + std::to_string(number) + " gives the vertex coordinate '" +
            word.substr(0, 30) + "', not a finite number";
        }
      }
      if (coordinates < 3)
      {
        return "line " + std::to_string(number) + " gives a vertex fewer than 3 coordinates";
      }
    }
    else if (key == "vt")
    {
      ++textures;
    }
    else if (key == "vn")
    {
      ++normals;
    }
    else if (key == "f" || key == "l" || key == "p")
    {
      std::string corner;
      while (words >> corner)
      {
        ++corners;
        // v, v/vt, v//vn or v/vt/vn, 1-based, within what was declared before.
        const std::uint64_t counts[3] = { points, textures, normals };
        const char* names[3] = { "vertex", "texture coordinate", "normal" };
        size_t start = 0;
        for (int part = 0; part < 3 && start <= corner.size(); ++part)
        {
          const size_t slash = corner.find('/', start);
          const std::string text = corner.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
          start = slash == std::string::npos ? corner.size() + 1 : slash + 1;
          if (text.empty() && part > 0)
          {
            continue;
          }
          char* end = nullptr;
          const long long index = std::strtoll(text.c_str(), &end, 10);
          if (text.empty() || *end != '\0' || index < 1 || static_cast<std::uint64_t>(index) > counts[part])
          {
            return "line " + std::to_string(number) + " refers to the " + names[part] + " '" + text +
              "' of " + std::to_string(counts[part]) + " declared before it (out of range)";
          }
        }
      }
    }
  }
  bytes = SaturatingProduct(points + textures + normals, 24) + SaturatingProduct(corners, 16);
  return "";
}

std::string CheckLegacyVTK(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string version, title, format;
  std::getline(in, version);
  std::getline(in, title);
  std::getline(in, format);
  // Versions VTK 9.1 writes and reads; it takes anything else for an old layout and read a
  // 5.1 file with a garbled version past its buffers.
  static const char* const known[] = { "1.0", "2.0", "3.0", "4.0", "4.1", "4.2", "5.1" };
  const std::string prefix = "# vtk DataFile Version ";
  bool good = version.compare(0, prefix.size(), prefix) == 0;
  const std::vector<std::string> words = good ? Words(version.substr(prefix.size())) : std::vector<std::string>();
  const std::string number = words.empty() ? "" : words.front();
  good = good && std::any_of(std::begin(known), std::end(known), [&](const char* v) { return number == v; });
  if (!good)
  {
    return "its first line is not '# vtk DataFile Version N' with a version VTK 9.1 reads (1.0 to 5.1)";
  }
  if (!IsHeaderText(title))
  {
    return "its title line holds bytes that are not text";
  }
  const std::vector<std::string> formatWords = Words(format);
  format = formatWords.empty() ? "" : formatWords.front();
  if (format != "ASCII" && format != "BINARY")
  {
    return "its third line is not ASCII or BINARY";
  }
  return "";
}

std::string CheckVTP(const std::string& fileName, std::uint64_t& bytes)
{
  // The counts are attributes of the Piece elements, in the XML before any appended data.
  std::ifstream in(fileName, std::ios::binary);
  std::string head(1 << 20, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  head = head.substr(0, head.find("<AppendedData"));
  bytes = 0;
  for (size_t at = head.find("NumberOf"); at != std::string::npos; at = head.find("NumberOf", at + 8))
  {
    const size_t quote = head.find('"', at);
    const size_t end = quote == std::string::npos ? quote : head.find('"', quote + 1);
    if (end == std::string::npos || head.find('=', at) > quote)
    {
      continue;
    }
    const std::string name = head.substr(at, head.find('=', at) - at);
    const std::string value = head.substr(quote + 1, end - quote - 1);
    char* stop = nullptr;
    const double count = std::strtod(value.c_str(), &stop);
    if (*stop != '\0' || !(count >= 0.0) || count != std::floor(count) || count > 2147483647.0)
    {
      return "its " + name + "=\"" + value.substr(0, 30) + "\" is not a count from 0 to 2^31 - 1";
    }
    bytes += static_cast<std::uint64_t>(count) * 32;
  }
  return "";
}

std::string CheckSTL(const std::string& fileName, std::uint64_t& bytes)
{
  std::ifstream in(fileName, std::ios::binary);
  char head[256] = { 0 };
  in.read(head, sizeof(head));
  const std::streamsize got = in.gcount();
  bool text = got >= 5 && std::string(head, 5) == "solid";
  for (std::streamsize i = 0; text && i < got; ++i)
  {
    text = static_cast<unsigned char>(head[i]) < 128;
  }
  const std::uint64_t size = vtksys::SystemTools::FileLength(fileName);
  bytes = size * 4; // ASCII: far fewer points than characters; binary: below
  if (text)
  {
    return "";
  }
  if (got < 84)
  {
    return "it is shorter than a binary STL header (84 bytes)";
  }
  std::uint32_t triangles = 0;
  for (int b = 3; b >= 0; --b)
  {
    triangles = (triangles << 8) | static_cast<unsigned char>(head[80 + b]);
  }
  const std::uint64_t needed = 84 + 50 * static_cast<std::uint64_t>(triangles);
  bytes = SaturatingProduct(triangles, 3 * 3 * 8 + 32);
  if (size < needed)
  {
    return "its header declares " + std::to_string(triangles) + " triangles (" +
      std::to_string(needed) + " bytes) but the file holds " + std::to_string(size) +
      " bytes (truncated?)";
  }
  return "";
}

}
}
