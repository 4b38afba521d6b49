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

std::string CheckBody(std::ifstream& in, const std::vector<Element>& elements, bool ascii,
  bool bigEndian, std::uint64_t dataBytes, std::uint64_t vertices)
{
  if (ascii)
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
        const std::vector<std::string> words = Words(line);
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
              const double lowest = element.Name == "tristrips" ? -1.0 : 0.0;
              for (size_t k = next + 1; k <= next + static_cast<size_t>(count); ++k)
              {
                const double index = std::strtod(words[k].c_str(), &end);
                if (*end != '\0' || !(index >= lowest) || !(index < static_cast<double>(vertices)) ||
                  index != std::floor(index))
                {
                  return BadIndex(element, e, index, vertices);
                }
              }
            }
            next += static_cast<size_t>(count);
          }
          ++next;
        }
      }
    }
    return "";
  }
  std::uint64_t used = 0;
  std::vector<unsigned char> buffer(8);
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
      // Fixed-size elements: their total is known without reading them.
      const std::uint64_t bytes = SaturatingProduct(element.Count, fixed);
      if (bytes > dataBytes - used)
      {
        return "its header declares " + std::to_string(element.Count) + " " + element.Name +
          " elements (" + std::to_string(bytes) + " bytes) but " +
          std::to_string(dataBytes - used) + " bytes of data are left (truncated?)";
      }
      used += bytes;
      in.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
      continue;
    }
    for (std::uint64_t e = 0; e < element.Count; ++e)
    {
      for (const Property& property : element.Properties)
      {
        const bool list = !property.CountType.empty();
        const int size = PLYTypeSize(list ? property.CountType : property.Type);
        if (static_cast<std::uint64_t>(size) > dataBytes - used ||
          !in.read(reinterpret_cast<char*>(buffer.data()), size))
        {
          return "it ends inside " + element.Name + " " + std::to_string(e) + " of " +
            std::to_string(element.Count) + " (truncated?)";
        }
        used += static_cast<std::uint64_t>(size);
        if (!list)
        {
          continue;
        }
        double count = 0.0;
        if (!ListCount(buffer.data(), property.CountType, bigEndian, count))
        {
          return element.Name + " " + std::to_string(e) + "'s " + property.Name +
            " list has a count that is not a whole number >= 0";
        }
        const int itemSize = PLYTypeSize(property.Type);
        if (count > static_cast<double>((dataBytes - used) / static_cast<std::uint64_t>(itemSize)))
        {
          return element.Name + " " + std::to_string(e) + "'s " + property.Name + " list of " +
            std::to_string(static_cast<std::uint64_t>(count)) + " items runs past the end of the file (truncated?)";
        }
        const std::uint64_t items = static_cast<std::uint64_t>(count) * static_cast<std::uint64_t>(itemSize);
        used += items;
        if (!IsIndexList(element, property))
        {
          in.seekg(static_cast<std::streamoff>(items), std::ios::cur);
          continue;
        }
        const double lowest = element.Name == "tristrips" ? -1.0 : 0.0;
        for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(count); ++k)
        {
          in.read(reinterpret_cast<char*>(buffer.data()), itemSize);
          const double index = BinaryValue(buffer.data(), property.Type, bigEndian);
          if (!(index >= lowest) || !(index < static_cast<double>(vertices)) || index != std::floor(index))
          {
            return BadIndex(element, e, index, vertices);
          }
        }
      }
    }
  }
  return "";
}
}

std::string CheckPLY(const std::string& fileName, std::uint64_t& bytes)
{
  bytes = 0;
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  std::vector<Element> elements;
  bool ascii = false, bigEndian = false, formatSeen = false, ended = false;
  // vtkPLY reads header lines into fixed buffers and words into a fixed table.
  for (int number = 1; !ended && std::getline(in, line); ++number)
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
      if (formatSeen || words.size() != 3 ||
        (words[1] != "ascii" && words[1] != "binary_little_endian" && words[1] != "binary_big_endian"))
      {
        return "its header line " + std::to_string(number) + " is not a PLY format line";
      }
      formatSeen = true;
      ascii = words[1] == "ascii";
      bigEndian = words[1] == "binary_big_endian";
    }
    else if (key == "element")
    {
      char* end = nullptr;
      const double count = words.size() == 3 ? std::strtod(words[2].c_str(), &end) : -1.0;
      if (words.size() != 3 || *end != '\0' || !(count >= 0.0) || count != std::floor(count) ||
        count > 2147483647.0)
      {
        return "its header line " + std::to_string(number) + " is not 'element NAME COUNT' with a count up to 2^31 - 1";
      }
      elements.push_back({ words[1], static_cast<std::uint64_t>(count), {} });
    }
    else if (key == "property")
    {
      const bool list = words.size() == 5 && words[1] == "list";
      if (elements.empty() || (!list && words.size() != 3) ||
        PLYTypeSize(words[list ? 3 : 1]) == 0 || (list && PLYTypeSize(words[2]) == 0))
      {
        return "its header line " + std::to_string(number) +
          " is not a property of known type after an element";
      }
      if (list && IsFloatType(words[2]))
      {
        return "its header line " + std::to_string(number) + " counts a list with a floating-point type";
      }
      elements.back().Properties.push_back(
        { words[list ? 4 : 2], words[list ? 3 : 1], list ? words[2] : std::string() });
    }
    else if (key == "end_header")
    {
      ended = true;
    }
    else if (key != "comment" && key != "obj_info" && !key.empty())
    {
      return "its header line " + std::to_string(number) + " starts with the unknown keyword '" + key + "'";
    }
  }
  if (!formatSeen || !ended)
  {
    return !formatSeen ? "its header has no format line" : "its header does not end (no end_header)";
  }
  if (elements.size() > 100)
  {
    return "its header declares more than 100 elements";
  }
  // What VTK's reader assumes without checking (it crashes or frees twice otherwise): element
  // and property names unique, a vertex element with scalar x, y and z, and faces and strips
  // with an integer list of vertex indices.
  std::uint64_t vertices = 0;
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
    int xyz = 0, lists = 0;
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
  const std::uint64_t size = vtksys::SystemTools::FileLength(fileName);
  const std::uint64_t headerEnd = static_cast<std::uint64_t>(in.tellg());
  return CheckBody(in, elements, ascii, bigEndian, size > headerEnd ? size - headerEnd : 0, vertices);
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
