// SPDX-License-Identifier: BSD-3-Clause
#include "MeshFileChecks.h"

#include "XmlMarkupScan.h"

#include "vtkBase64Utilities.h"
#include "vtkNew.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

namespace meshfiles
{
namespace
{
std::uintmax_t FileSize(const std::string& path)
{
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  return error ? 0 : size;
}

/// A whole decimal integer, nothing around it (a leading '+' allowed).
bool ParseInteger(const std::string& text, long long& value)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
  {
    ++begin;
  }
  const std::from_chars_result parsed = std::from_chars(begin, end, value);
  return begin != end && parsed.ec == std::errc() && parsed.ptr == end;
}

bool ParseCount(const std::string& text, long long& value)
{
  return ParseInteger(text, value) && value >= 0;
}

/// A whole number as strtod reads it (nan and inf included).
bool IsNumber(const std::string& text)
{
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+')
  {
    ++begin;
  }
  double value;
  const std::from_chars_result parsed = std::from_chars(begin, end, value);
  return begin != end && parsed.ptr == end &&
    (parsed.ec == std::errc() || parsed.ec == std::errc::result_out_of_range);
}

/// A word for a message: quoted, at most 40 characters, unprintable bytes as '?'.
std::string Quote(const std::string& word)
{
  std::string shown = word.substr(0, 40);
  for (char& c : shown)
  {
    c = std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return "'" + shown + (word.size() > 40 ? "...'" : "'");
}

std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/// The words of a line split at blanks (isspace).
std::vector<std::string> SplitBlanks(const std::string& line)
{
  std::vector<std::string> words;
  std::size_t at = 0;
  while (true)
  {
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at])))
    {
      ++at;
    }
    if (at == line.size())
    {
      return words;
    }
    const std::size_t begin = at;
    while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at])))
    {
      ++at;
    }
    words.push_back(line.substr(begin, at - begin));
  }
}

/// The largest magnitude among a file's finite vertex coordinates, for a reader that stores
/// them as floats (VTK's PLY reader): beyond float's range they become infinite; below its
/// normal range (FLT_MIN) they lose precision against the mesh's own size, to 0 at 1e-46.
struct CoordinateScale
{
  double Largest = 0.0;

  void Add(double value)
  {
    if (std::isfinite(value))
    {
      this->Largest = std::max(this->Largest, std::abs(value));
    }
  }

  std::string Problem(const char* reader) const
  {
    if (this->Largest <= FLT_MAX && (this->Largest == 0.0 || this->Largest >= FLT_MIN))
    {
      return "";
    }
    char largest[32];
    std::snprintf(largest, sizeof(largest), "%g", this->Largest);
    return std::string("the largest vertex coordinate, ") + largest + ", is " +
      (this->Largest > FLT_MAX ? "beyond" : "below") + " the single precision range " + reader +
      " stores coordinates in";
  }
};

// ----------------------------------------------------------------------------------------- PLY
namespace ply
{
/// VTK's reader reads lines into 4096-byte buffers and cuts longer ones.
constexpr std::size_t MaximumLine = 4000;
/// Its face record holds at most 255 corners (an unsigned char count, a 256-entry buffer).
constexpr long long MaximumCorners = 255;

enum class Encoding
{
  Ascii,
  LittleEndian,
  BigEndian
};

/// A type's facts, read once from its name (the body's records do not parse names again).
struct TypeFacts
{
  int Size = 0; // bytes, 0 for an unknown name
  bool Signed = false;
  long long Maximum = 0; // the largest value an integer type holds
};

struct Property
{
  std::string Name;
  std::string Type;      // of the value, or of a list's items
  std::string CountType; // of a list's length; empty for a scalar
  TypeFacts Item, Count; // of Type and CountType
  bool IsList() const { return !this->CountType.empty(); }
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;
};

struct Header
{
  Encoding Format = Encoding::Ascii;
  bool HasFormat = false;
  std::vector<Element> Elements;
};

/// Bytes of a PLY type, 0 for an unknown name.
int TypeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "uchar", 1 }, { "int8", 1 },
    { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 }, { "int", 4 },
    { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

bool IsIntegerType(const std::string& type)
{
  return TypeSize(type) > 0 && type.find("float") == std::string::npos && type != "double";
}

bool IsSignedType(const std::string& type)
{
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
    type == "int32";
}

TypeFacts FactsOf(const std::string& type)
{
  TypeFacts facts;
  facts.Size = TypeSize(type);
  facts.Signed = IsSignedType(type);
  const int bits = 8 * facts.Size - (facts.Signed ? 1 : 0);
  facts.Maximum = bits >= 63 ? std::numeric_limits<long long>::max() : (1LL << bits) - 1;
  return facts;
}

/// A line's words as VTK's reader splits it: "vertex_index" renamed "vertex_indices" (the rest
/// of the line cut, as its strcpy does), words separated by blanks, tabs and carriage returns.
std::vector<std::string> Words(std::string line)
{
  const std::size_t renamed = line.find("vertex_index");
  if (renamed != std::string::npos)
  {
    line = line.substr(0, renamed) + "vertex_indices";
  }
  std::vector<std::string> words(1);
  for (char c : line)
  {
    if (c != ' ' && c != '\t' && c != '\r')
    {
      words.back() += c;
    }
    else if (!words.back().empty())
    {
      words.emplace_back();
    }
  }
  if (words.back().empty())
  {
    words.pop_back();
  }
  return words;
}

const Property* Find(const Element& element, const std::string& name)
{
  for (const Property& property : element.Properties)
  {
    if (property.Name == name)
    {
      return &property;
    }
  }
  return nullptr;
}

std::string ParseFormat(const std::vector<std::string>& words, Header& header)
{
  if (header.HasFormat)
  {
    return "a second format line";
  }
  if (words.size() != 3)
  {
    return "the format line is not 'format <encoding> <version>'";
  }
  if (words[1] == "ascii")
  {
    header.Format = Encoding::Ascii;
  }
  else if (words[1] == "binary_little_endian")
  {
    header.Format = Encoding::LittleEndian;
  }
  else if (words[1] == "binary_big_endian")
  {
    header.Format = Encoding::BigEndian;
  }
  else
  {
    return "unknown format " + Quote(words[1]);
  }
  header.HasFormat = true;
  return "";
}

std::string ParseElement(const std::vector<std::string>& words, Header& header)
{
  long long count = 0;
  if (words.size() != 3)
  {
    return "the element line is not 'element <name> <count>'";
  }
  if (!ParseCount(words[2], count) || count > INT_MAX)
  {
    return "element '" + words[1] + "' has count " + Quote(words[2]) +
      ", not an integer from 0 to 2^31 - 1";
  }
  for (const Element& element : header.Elements)
  {
    if (element.Name == words[1])
    {
      return "a second element '" + words[1] + "'";
    }
  }
  header.Elements.push_back({ words[1], count, {} });
  return "";
}

std::string ParseProperty(const std::vector<std::string>& words, Header& header)
{
  if (header.Elements.empty())
  {
    return "a property before any element";
  }
  Property property;
  if (words.size() == 5 && words[1] == "list")
  {
    property = { words[4], words[3], words[2] };
    if (!IsIntegerType(property.CountType))
    {
      return "list '" + property.Name + "' has length type " + Quote(property.CountType);
    }
  }
  else if (words.size() == 3 && words[1] != "list")
  {
    property = { words[2], words[1], "" };
  }
  else
  {
    return "the property line is not 'property <type> <name>' or "
           "'property list <length type> <type> <name>'";
  }
  property.Item = FactsOf(property.Type);
  property.Count = FactsOf(property.CountType);
  if (property.Item.Size == 0)
  {
    return "property '" + property.Name + "' has unknown type " + Quote(property.Type);
  }
  Element& element = header.Elements.back();
  if (Find(element, property.Name))
  {
    return "a second property '" + property.Name + "' in element '" + element.Name + "'";
  }
  element.Properties.push_back(property);
  return "";
}

/// Reads the header up to and including the end_header line.
std::string ReadHeader(std::istream& in, Header& header)
{
  std::string line;
  if (!std::getline(in, line) || Words(line).empty() || Words(line)[0] != "ply")
  {
    return "the first line is not 'ply'";
  }
  for (long long number = 2; std::getline(in, line); ++number)
  {
    const std::string where = "header line " + std::to_string(number);
    if (line.size() > MaximumLine)
    {
      return where + " is longer than 4000 characters";
    }
    const std::vector<std::string> words = Words(line);
    if (words.empty())
    {
      return where + " is blank (VTK's reader would end the header there)";
    }
    std::string problem;
    if (words[0] == "end_header")
    {
      return header.HasFormat ? "" : "no format line";
    }
    if (words[0] == "format")
    {
      problem = ParseFormat(words, header);
    }
    else if (words[0] == "element")
    {
      problem = ParseElement(words, header);
    }
    else if (words[0] == "property")
    {
      problem = ParseProperty(words, header);
    }
    else if (words[0] != "comment" && words[0] != "obj_info")
    {
      problem = "unknown keyword " + Quote(words[0]);
    }
    if (!problem.empty())
    {
      return where + ": " + problem;
    }
  }
  return "no end_header line";
}

/// VTK's reader reads the elements in file order but only 'vertex' and 'face', and stores the
/// properties it knows in fixed fields: a list where it expects a number (or the reverse)
/// overwrites its record.
std::string CheckLayout(const Header& header)
{
  static const char* const vertexScalars[] = { "x", "y", "z", "u", "v", "texture_u", "texture_v",
    "nx", "ny", "nz", "red", "green", "blue", "alpha", "diffuse_red", "diffuse_green",
    "diffuse_blue" };
  static const char* const faceScalars[] = { "intensity", "red", "green", "blue", "alpha" };
  static const char* const faceLists[] = { "vertex_indices", "texcoord" };
  if (header.Elements.empty() || header.Elements[0].Name != "vertex")
  {
    return "the first element is not 'vertex' (VTK's reader reads no element before it)";
  }
  if (header.Elements.size() < 2 || header.Elements[1].Name != "face")
  {
    return "no 'element face' right after the vertices";
  }
  const Element& vertex = header.Elements[0];
  const Element& face = header.Elements[1];
  for (const char* axis : { "x", "y", "z" })
  {
    if (!Find(vertex, axis))
    {
      return std::string("the vertices have no property '") + axis + "'";
    }
  }
  for (const char* name : vertexScalars)
  {
    const Property* property = Find(vertex, name);
    if (property && property->IsList())
    {
      return std::string("vertex property '") + name + "' is a list";
    }
  }
  for (const char* name : faceScalars)
  {
    const Property* property = Find(face, name);
    if (property && property->IsList())
    {
      return std::string("face property '") + name + "' is a list";
    }
  }
  for (const char* name : faceLists)
  {
    const Property* property = Find(face, name);
    if (property && !property->IsList())
    {
      return std::string("face property '") + name + "' is not a list";
    }
  }
  const Property* corners = Find(face, "vertex_indices");
  if (!corners)
  {
    return "the faces have no vertex_indices list";
  }
  if (!IsIntegerType(corners->Type))
  {
    return "vertex_indices holds " + Quote(corners->Type) + " values, not integers";
  }
  return "";
}

/// "face 12 of 5804", for messages.
std::string Record(const Element& element, long long record)
{
  return element.Name + " " + std::to_string(record + 1) + " of " + std::to_string(element.Count);
}

bool IsCornerList(const Element& element, const Property& property)
{
  return element.Name == "face" && property.Name == "vertex_indices";
}

bool IsCoordinate(const Element& element, const Property& property)
{
  return element.Name == "vertex" && !property.IsList() &&
    (property.Name == "x" || property.Name == "y" || property.Name == "z");
}

/// Binary coordinates of a double type may leave the float range VTK's reader stores them in.
bool HasDoubleCoordinates(const Element& element)
{
  return std::any_of(element.Properties.begin(), element.Properties.end(),
    [&element](const Property& property) {
      return IsCoordinate(element, property) && property.Item.Size == 8;
    });
}

/// A list's length: an integer its type holds, at most 255 corners.
std::string CheckListLength(long long length, const std::string& word, const Element& element, const Property& property)
{
  if (length < 0 || length > property.Count.Maximum)
  {
    return "list '" + property.Name + "' has length " + Quote(word);
  }
  if (IsCornerList(element, property) && length > MaximumCorners)
  {
    return std::to_string(length) + " corners, more than VTK's 255";
  }
  return "";
}

/// A list's length from its word (see CheckListLength).
std::string ListLength(const std::string& word, const Element& element, const Property& property,
  long long& length)
{
  return ParseCount(word, length) ? CheckListLength(length, word, element, property)
                                  : "list '" + property.Name + "' has length " + Quote(word);
}

/// One ASCII record: enough words, numbers where numbers belong, corners naming vertices.
std::string CheckAsciiRecord(const std::vector<std::string>& words, const Element& element,
  long long vertices, CoordinateScale& scale)
{
  std::size_t next = 0;
  for (const Property& property : element.Properties)
  {
    long long length = 1;
    if (property.IsList())
    {
      if (next == words.size())
      {
        return "too few values";
      }
      const std::string problem = ListLength(words[next++], element, property, length);
      if (!problem.empty())
      {
        return problem;
      }
    }
    for (long long k = 0; k < length; ++k, ++next)
    {
      long long corner = -1;
      if (next == words.size())
      {
        return "too few values";
      }
      if (!IsCornerList(element, property) && !IsNumber(words[next]))
      {
        return Quote(words[next]) + " is not a number";
      }
      if (IsCoordinate(element, property))
      {
        scale.Add(std::strtod(words[next].c_str(), nullptr));
      }
      if (IsCornerList(element, property) &&
        (!ParseInteger(words[next], corner) || corner < 0 || corner >= vertices))
      {
        return "corner " + Quote(words[next]) + " is no index of the " +
          std::to_string(vertices) + " vertices";
      }
    }
  }
  return "";
}

/// The vertex and face records of an ASCII file, one line each; VTK's reader reads no further.
/// Without other elements nothing but blank lines may follow the faces (more faces than the
/// header declares would be lost).
std::string CheckAsciiBody(std::istream& in, const Header& header)
{
  const long long vertices = header.Elements[0].Count;
  CoordinateScale scale;
  std::string line;
  for (std::size_t e = 0; e < 2; ++e)
  {
    const Element& element = header.Elements[e];
    for (long long record = 0; record < element.Count; ++record)
    {
      if (!std::getline(in, line))
      {
        return "the file ends before " + Record(element, record);
      }
      if (in.eof())
      {
        return Record(element, record) + " does not end with a newline (VTK's reader loses it)";
      }
      if (line.size() > MaximumLine)
      {
        return Record(element, record) + " is longer than 4000 characters";
      }
      const std::string problem = CheckAsciiRecord(Words(line), element, vertices, scale);
      if (!problem.empty())
      {
        return Record(element, record) + ": " + problem;
      }
    }
  }
  while (header.Elements.size() == 2 && std::getline(in, line))
  {
    if (!SplitBlanks(line).empty())
    {
      return "data follow the last of the " + std::to_string(header.Elements[1].Count) +
        " faces the header declares";
    }
  }
  return scale.Problem("VTK's PLY reader");
}

/// The bytes after the header, read in the file's byte order.
class BinaryReader
{
public:
  BinaryReader(std::istream& in, bool bigEndian, std::uintmax_t remaining)
    : In(in)
    , BigEndian(bigEndian)
    , Remaining(remaining)
    , Buffer(1 << 16)
  {
  }

  bool Skip(std::uintmax_t bytes)
  {
    if (bytes > this->Remaining)
    {
      return false;
    }
    this->Remaining -= bytes;
    const std::uintmax_t buffered = this->End - this->At;
    if (bytes <= buffered)
    {
      this->At += static_cast<std::size_t>(bytes);
      return true;
    }
    this->At = this->End = 0;
    this->In.seekg(static_cast<std::streamoff>(bytes - buffered), std::ios::cur);
    return static_cast<bool>(this->In);
  }

  bool ReadInteger(const TypeFacts& type, long long& value)
  {
    const int size = type.Size;
    std::uint64_t raw = 0;
    if (!this->ReadBits(size, raw))
    {
      return false;
    }
    const bool negative = type.Signed && (raw >> (8 * size - 1)) != 0;
    value = static_cast<long long>(raw) - (negative ? 1LL << (8 * size) : 0);
    return true;
  }

  bool ReadDouble(double& value)
  {
    std::uint64_t raw = 0;
    if (!this->ReadBits(8, raw))
    {
      return false;
    }
    std::memcpy(&value, &raw, 8);
    return true;
  }

  std::uintmax_t Left() const { return this->Remaining; }

private:
  /// The next size bytes as an unsigned number in the file's byte order.
  bool ReadBits(int size, std::uint64_t& raw)
  {
    if (static_cast<std::uintmax_t>(size) > this->Remaining || !this->Have(size))
    {
      return false;
    }
    unsigned char bytes[8] = {};
    std::copy_n(this->Buffer.data() + this->At, size, bytes);
    this->At += size;
    this->Remaining -= size;
    if (this->BigEndian)
    {
      std::reverse(bytes, bytes + size);
    }
    raw = 0;
    for (int k = size - 1; k >= 0; --k)
    {
      raw = raw << 8 | bytes[k];
    }
    return true;
  }

  /// Whether size bytes are buffered, reading the next block of the file when they are not.
  bool Have(std::size_t size)
  {
    if (this->End - this->At >= size)
    {
      return true;
    }
    std::copy(this->Buffer.begin() + this->At, this->Buffer.begin() + this->End, this->Buffer.begin());
    this->End -= this->At;
    this->At = 0;
    const std::uintmax_t unread = this->Remaining - this->End;
    const std::size_t wanted = static_cast<std::size_t>(std::min<std::uintmax_t>(this->Buffer.size() - this->End, unread));
    this->In.read(reinterpret_cast<char*>(this->Buffer.data() + this->End), static_cast<std::streamsize>(wanted));
    this->End += static_cast<std::size_t>(this->In.gcount());
    return this->End - this->At >= size;
  }

  std::istream& In;
  bool BigEndian;
  std::uintmax_t Remaining; // bytes not yet consumed, the buffered ones included
  std::vector<unsigned char> Buffer;
  std::size_t At = 0, End = 0; // the buffered bytes not yet consumed: [At, End)
};

/// One binary record with lists or double coordinates: list lengths, the corners naming
/// vertices, the coordinates' scale.
std::string CheckBinaryRecord(
  BinaryReader& bytes, const Element& element, long long vertices, CoordinateScale& scale)
{
  for (const Property& property : element.Properties)
  {
    long long length = 0;
    double coordinate = 0.0;
    if (!property.IsList())
    {
      const bool read = IsCoordinate(element, property) && property.Item.Size == 8
        ? bytes.ReadDouble(coordinate)
        : bytes.Skip(property.Item.Size);
      if (!read)
      {
        return "the file ends inside it";
      }
      scale.Add(coordinate);
      continue;
    }
    if (!bytes.ReadInteger(property.Count, length))
    {
      return "the file ends inside it";
    }
    const std::string problem = length >= 0 && length <= MaximumCorners
      ? std::string() // within every count type and VTK's limit: no message to make
      : CheckListLength(length, std::to_string(length), element, property);
    if (!problem.empty())
    {
      return problem;
    }
    if (!IsCornerList(element, property))
    {
      if (!bytes.Skip(static_cast<std::uintmax_t>(length) * property.Item.Size))
      {
        return "the file ends inside it";
      }
      continue;
    }
    for (long long k = 0; k < length; ++k)
    {
      long long corner = 0;
      if (!bytes.ReadInteger(property.Item, corner))
      {
        return "the file ends inside it";
      }
      if (corner < 0 || corner >= vertices)
      {
        return "corner " + std::to_string(corner) + " is no index of the " +
          std::to_string(vertices) + " vertices";
      }
    }
  }
  return "";
}

/// The vertex and face records of a binary file: records of floats and integers by their size,
/// records with lists or double coordinates one by one. Without other elements the faces end the
/// file.
std::string CheckBinaryBody(std::istream& in, const Header& header, std::uintmax_t remaining)
{
  BinaryReader bytes(in, header.Format == Encoding::BigEndian, remaining);
  const long long vertices = header.Elements[0].Count;
  CoordinateScale scale;
  for (std::size_t e = 0; e < 2; ++e)
  {
    const Element& element = header.Elements[e];
    std::uintmax_t stride = 0;
    bool hasList = false;
    for (const Property& property : element.Properties)
    {
      stride += property.Item.Size;
      hasList = hasList || property.IsList();
    }
    if (!hasList && !HasDoubleCoordinates(element))
    {
      const std::uintmax_t needed = stride * static_cast<std::uintmax_t>(element.Count);
      if (!bytes.Skip(needed))
      {
        return "the " + std::to_string(element.Count) + " " + element.Name + " records need " +
          std::to_string(needed) + " bytes, " + std::to_string(bytes.Left()) + " follow";
      }
      continue;
    }
    for (long long record = 0; record < element.Count; ++record)
    {
      const std::string problem = CheckBinaryRecord(bytes, element, vertices, scale);
      if (!problem.empty())
      {
        return Record(element, record) + ": " + problem;
      }
    }
  }
  if (header.Elements.size() == 2 && bytes.Left() > 0)
  {
    return std::to_string(bytes.Left()) + " bytes follow the last of the " +
      std::to_string(header.Elements[1].Count) + " faces the header declares";
  }
  return scale.Problem("VTK's PLY reader");
}
} // namespace ply

// ----------------------------------------------------------------------------------------- STL
std::string CheckBinarySTL(const std::string& path)
{
  const std::uintmax_t size = FileSize(path);
  if (size < 84)
  {
    return "a binary STL starts with 84 header bytes, the file has " + std::to_string(size);
  }
  std::ifstream in(path, std::ios::binary);
  unsigned char count[4] = {};
  in.seekg(80);
  in.read(reinterpret_cast<char*>(count), 4);
  const std::uintmax_t triangles = static_cast<std::uintmax_t>(count[0]) | count[1] << 8 |
    count[2] << 16 | static_cast<std::uintmax_t>(count[3]) << 24;
  const std::uintmax_t expected = 84 + 50 * triangles;
  if (size != expected)
  {
    return "a binary STL of " + std::to_string(triangles) + " triangles takes " +
      std::to_string(expected) + " bytes, the file has " + std::to_string(size);
  }
  return "";
}

std::string CheckAsciiSTL(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  bool solid = false;
  long long facets = 0, vertices = 0;
  while (std::getline(in, line))
  {
    const std::vector<std::string> words = SplitBlanks(line);
    const std::string keyword = words.empty() ? "" : Lower(words[0]);
    if (keyword.empty())
    {
      continue;
    }
    if (!solid && keyword != "solid")
    {
      return "an ASCII STL starts with 'solid', not " + Quote(words[0]);
    }
    solid = true;
    facets += keyword == "facet";
    vertices += keyword == "vertex";
  }
  if (facets == 0 || vertices < 3)
  {
    return "an ASCII STL without facet and vertex lines";
  }
  return "";
}

// ----------------------------------------------------------------------------------------- OBJ
namespace obj
{
/// vtkOBJReader's line buffer (fgets into 256 KiB) and material name buffer (sscanf %s into
/// 100 bytes).
constexpr std::size_t MaximumLine = 256 * 1024 - 2;
constexpr std::size_t MaximumName = 99;

/// One kind of entry faces refer to (vertices, texture coordinates, normals): how many lines
/// vtkOBJReader has read so far (for relative indices), how many there are in all when known
/// beforehand, else the largest index named, to compare once all are read.
struct Entries
{
  const char* Name;
  long long Read = 0;
  long long Total = -1;
  long long Largest = -1;
  long long LargestLine = 0;
};

struct Kinds
{
  Entries Vertices{ "vertex" };
  Entries TextureCoordinates{ "texture coordinate" };
  Entries Normals{ "normal" };
};

/// A line's command (first word) and where its arguments start, as vtkOBJReader splits it.
std::string Command(const std::string& line, std::size_t& arguments)
{
  std::size_t begin = 0;
  while (begin < line.size() && std::isspace(static_cast<unsigned char>(line[begin])))
  {
    ++begin;
  }
  std::size_t end = begin;
  while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end])))
  {
    ++end;
  }
  arguments = std::min(end + 1, line.size());
  return line.substr(begin, end - begin);
}

/// The reader's first pass: it reads every texture coordinate ahead; NUL bytes, over-long lines
/// and material names it would overflow on are refused.
std::string FirstPass(std::istream& in, Kinds& kinds)
{
  std::string line;
  kinds.TextureCoordinates.Total = 0;
  for (long long number = 1; std::getline(in, line); ++number)
  {
    const std::string where = "line " + std::to_string(number);
    std::size_t arguments = 0;
    if (line.find('\0') != std::string::npos)
    {
      return where + " holds a NUL byte";
    }
    if (line.size() > MaximumLine)
    {
      return where + " is longer than vtkOBJReader's 256 KiB";
    }
    const std::string command = Command(line, arguments);
    kinds.TextureCoordinates.Total += command == "vt";
    const std::vector<std::string> name = SplitBlanks(line.substr(arguments));
    if (command == "usemtl" && !name.empty() && name[0].size() > MaximumName)
    {
      return where + ": a material name longer than vtkOBJReader's 99 characters";
    }
  }
  return "";
}

/// An index of a face corner resolved as vtkOBJReader resolves it: from 1, or back from the
/// last entry read when negative.
std::string CheckIndex(Entries& entries, int index, long long line)
{
  const long long at = index < 0 ? entries.Read + index : index - 1LL;
  if (at < 0 || (entries.Total >= 0 && at >= entries.Total))
  {
    return "a face corner names " + std::string(entries.Name) + " " + std::to_string(index) +
      " of " + std::to_string(entries.Total >= 0 ? entries.Total : entries.Read);
  }
  if (at > entries.Largest)
  {
    entries.Largest = at;
    entries.LargestLine = line;
  }
  return "";
}

/// One corner as vtkOBJReader 9.2 parses it: sscanf with v/t/n, v//n, v/t and v in turn (%d
/// skips blanks, so "1/ 2/ 3/" is the corner 1/2/3). False when none matches.
bool CheckCorner(const char* text, Kinds& kinds, long long line, std::string& problem)
{
  int v = 0, t = 0, n = 0;
  if (std::sscanf(text, "%d/%d/%d", &v, &t, &n) == 3)
  {
    problem = CheckIndex(kinds.Vertices, v, line) +
      CheckIndex(kinds.TextureCoordinates, t, line) + CheckIndex(kinds.Normals, n, line);
  }
  else if (std::sscanf(text, "%d//%d", &v, &n) == 2)
  {
    problem = CheckIndex(kinds.Vertices, v, line) + CheckIndex(kinds.Normals, n, line);
  }
  else if (std::sscanf(text, "%d/%d", &v, &t) == 2)
  {
    problem =
      CheckIndex(kinds.Vertices, v, line) + CheckIndex(kinds.TextureCoordinates, t, line);
  }
  else if (std::sscanf(text, "%d", &v) == 1)
  {
    problem = CheckIndex(kinds.Vertices, v, line);
  }
  else
  {
    return false;
  }
  return true;
}

/// The rest of an f, l or p line from arguments on, word by word as vtkOBJReader walks it: a
/// backslash at the end continues on the next line (consumed here, as by the reader). Face
/// corners are checked; at the first word the reader cannot parse, it reports and stops.
std::string CheckElement(std::istream& in, std::string line, std::size_t arguments,
  long long& number, bool isFace, Kinds& kinds)
{
  const long long first = number;
  line += in.eof() ? "" : "\n"; // fgets keeps it, and the continuation test needs it
  const char* at = line.c_str() + arguments;
  const char* end = line.c_str() + line.size();
  while (at < end)
  {
    while (at < end && std::isspace(static_cast<unsigned char>(*at)))
    {
      ++at;
    }
    std::string problem;
    int index = 0;
    if (at == end)
    {
      break;
    }
    if (std::strcmp(at, "\\\n") == 0)
    {
      if (!std::getline(in, line))
      {
        return "";
      }
      ++number;
      line += in.eof() ? "" : "\n";
      at = line.c_str();
      end = at + line.size();
      continue;
    }
    const bool parsed =
      isFace ? CheckCorner(at, kinds, first, problem) : std::sscanf(at, "%d", &index) == 1;
    if (!parsed || !problem.empty())
    {
      return problem;
    }
    while (at < end && !std::isspace(static_cast<unsigned char>(*at)))
    {
      ++at;
    }
  }
  return "";
}

/// A vertex line's coordinates: vtkOBJReader reads nan and inf as other, finite numbers.
std::string CheckCoordinates(const std::string& arguments)
{
  const std::vector<std::string> words = SplitBlanks(arguments);
  for (std::size_t k = 0; k < std::min<std::size_t>(3, words.size()); ++k)
  {
    if (IsNumber(words[k]) && !std::isfinite(std::strtod(words[k].c_str(), nullptr)))
    {
      return "vertex coordinate " + Quote(words[k]) +
        " is not a finite number (vtkOBJReader would read another number)";
    }
  }
  return "";
}

/// The reader's second pass: vertices, normals and elements in order, every face corner
/// checked; vertex and normal indices beyond those read so far, once all are read.
std::string SecondPass(std::istream& in, Kinds& kinds)
{
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number)
  {
    const long long first = number;
    std::size_t arguments = 0;
    const std::string command = Command(line, arguments);
    kinds.Vertices.Read += command == "v";
    kinds.TextureCoordinates.Read += command == "vt";
    kinds.Normals.Read += command == "vn";
    std::string problem;
    if (command == "v")
    {
      problem = CheckCoordinates(line.substr(arguments));
    }
    else if (command == "f" || command == "l" || command == "p")
    {
      problem = CheckElement(in, line, arguments, number, command == "f", kinds);
    }
    if (!problem.empty())
    {
      return "line " + std::to_string(first) + ": " + problem;
    }
  }
  for (const Entries* entries : { &kinds.Vertices, &kinds.Normals })
  {
    if (entries->Largest >= entries->Read)
    {
      return "line " + std::to_string(entries->LargestLine) + ": a face corner names " +
        entries->Name + " " + std::to_string(entries->Largest + 1) + " of " +
        std::to_string(entries->Read);
    }
  }
  return "";
}
} // namespace obj

// ----------------------------------------------------------------------------------------- VTP
namespace vtp
{
/// How the file stores binary data.
struct XmlFile
{
  std::ifstream In;
  std::uintmax_t Size = 0;
  std::size_t HeaderWord = 4; // header_type UInt32 or UInt64
  bool BigEndian = false;
  std::string Compressor; // empty: none
  std::int64_t AppendedPosition = -1;
  bool AppendedBase64 = false;
  double Version = 0.0; // the VTKFile element's
};

/// Where an array's binary data are: a run of bytes, or of base64 characters, of some length.
struct DataRun
{
  std::int64_t Position = 0;
  bool Base64 = false;
  std::uintmax_t Length = 0; // characters up to the next '<' or blank, or bytes to the end
};

/// The largest expansion of a block by each compressor (deflate 1032:1, LZ4 255:1, xz about
/// 7000:1), with room to spare: more, and the block header lies.
std::uintmax_t MaximumRatio(const std::string& compressor)
{
  if (compressor == "vtkZLibDataCompressor")
  {
    return 1100;
  }
  if (compressor == "vtkLZ4DataCompressor")
  {
    return 300;
  }
  return 10000;
}

int TypeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "Int8", 1 }, { "UInt8", 1 }, { "Int16", 2 },
    { "UInt16", 2 }, { "Int32", 4 }, { "UInt32", 4 }, { "Int64", 8 }, { "UInt64", 8 },
    { "Float32", 4 }, { "Float64", 8 } };
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

/// Characters from position up to the next '<' or blank (base64 holds neither).
std::uintmax_t RunLength(XmlFile& file, std::int64_t position)
{
  file.In.clear();
  file.In.seekg(position);
  std::uintmax_t length = 0;
  char c = 0;
  while (file.In.get(c) && c != '<' && !std::isspace(static_cast<unsigned char>(c)))
  {
    ++length;
  }
  return length;
}

/// Bytes [offset, offset + count) of a run, decoded from base64 if it is encoded.
bool ReadRun(XmlFile& file, const DataRun& run, std::uintmax_t offset, std::size_t count,
  std::vector<unsigned char>& bytes)
{
  const std::uintmax_t first = run.Base64 ? offset / 3 * 4 : offset;
  const std::uintmax_t last = run.Base64 ? (offset + count + 2) / 3 * 4 : offset + count;
  bytes.clear();
  if (count == 0)
  {
    return true;
  }
  if (last > run.Length)
  {
    return false;
  }
  std::vector<unsigned char> raw(last - first);
  file.In.clear();
  file.In.seekg(run.Position + static_cast<std::int64_t>(first));
  if (!file.In.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size())))
  {
    return false;
  }
  if (!run.Base64)
  {
    bytes = raw;
    return true;
  }
  std::vector<unsigned char> decoded(raw.size() / 4 * 3);
  const std::size_t size =
    vtkBase64Utilities::DecodeSafely(raw.data(), raw.size(), decoded.data(), decoded.size());
  const std::size_t skip = offset % 3;
  if (size < skip + count)
  {
    return false;
  }
  bytes.assign(decoded.begin() + skip, decoded.begin() + skip + count);
  return true;
}

/// An unsigned value of size bytes, in the file's byte order.
std::uint64_t Unsigned(const XmlFile& file, const unsigned char* bytes, std::size_t size)
{
  std::uint64_t value = 0;
  for (std::size_t k = 0; k < size; ++k)
  {
    value = value << 8 | bytes[file.BigEndian ? k : size - 1 - k];
  }
  return value;
}

/// count header words from word first on.
bool ReadWords(XmlFile& file, const DataRun& run, std::uintmax_t first, std::uintmax_t count,
  std::vector<std::uint64_t>& words)
{
  std::vector<unsigned char> bytes;
  if (!ReadRun(file, run, first * file.HeaderWord, count * file.HeaderWord, bytes))
  {
    return false;
  }
  words.clear();
  for (std::size_t k = 0; k < count; ++k)
  {
    words.push_back(Unsigned(file, bytes.data() + k * file.HeaderWord, file.HeaderWord));
  }
  return true;
}

/// Bytes a run can hold after its first skip characters (or bytes).
std::uintmax_t Capacity(const DataRun& run, std::uintmax_t skip)
{
  const std::uintmax_t left = run.Length > skip ? run.Length - skip : 0;
  return run.Base64 ? left / 4 * 3 : left;
}

/// The data size an uncompressed array's header declares, if the run holds it.
std::string MeasureUncompressed(XmlFile& file, const DataRun& run, std::uintmax_t& bytes)
{
  std::vector<std::uint64_t> words;
  if (!ReadWords(file, run, 0, 1, words))
  {
    return "its data end before their size";
  }
  bytes = words[0];
  const std::uintmax_t capacity = Capacity(run, 0) - file.HeaderWord;
  if (bytes > capacity)
  {
    return "its header declares " + std::to_string(bytes) + " bytes, " +
      std::to_string(capacity) + " follow";
  }
  return "";
}

/// The data size a compressed array's header declares (blocks of BlockSize bytes, the last
/// one of LastSize if not 0, each stored in its compressed size), if its blocks fit in the run
/// and none claims to expand beyond what the compressor can.
std::string MeasureCompressed(XmlFile& file, const DataRun& run, std::uintmax_t& bytes)
{
  std::vector<std::uint64_t> words;
  if (!ReadWords(file, run, 0, 3, words))
  {
    return "its data end inside the compression header";
  }
  const std::uint64_t blocks = words[0], blockSize = words[1], lastSize = words[2];
  if (blocks > Capacity(run, 0) / file.HeaderWord)
  {
    return "its compression header declares " + std::to_string(blocks) + " blocks";
  }
  if (blocks > 0 && (blockSize == 0 || lastSize > blockSize))
  {
    return "its compression header has blocks of " + std::to_string(blockSize) +
      " bytes, the last of " + std::to_string(lastSize);
  }
  if (!ReadWords(file, run, 3, blocks, words))
  {
    return "its data end inside the compression header";
  }
  const std::uintmax_t headerBytes = (3 + blocks) * file.HeaderWord;
  const std::uintmax_t headerLength = run.Base64 ? (headerBytes + 2) / 3 * 4 : headerBytes;
  const std::uintmax_t capacity = Capacity(run, headerLength);
  std::uintmax_t stored = 0;
  bytes = 0;
  for (std::uint64_t b = 0; b < blocks; ++b)
  {
    const std::uintmax_t size = b + 1 == blocks && lastSize ? lastSize : blockSize;
    if (words[b] > capacity || size > MaximumRatio(file.Compressor) * words[b] + 64)
    {
      return "its block " + std::to_string(b) + " of " + std::to_string(words[b]) +
        " compressed bytes cannot hold " + std::to_string(size);
    }
    stored += words[b];
    bytes += size;
  }
  if (stored > capacity)
  {
    return "its blocks take " + std::to_string(stored) + " bytes, " + std::to_string(capacity) +
      " follow";
  }
  return "";
}

/// The first byte of an element's inline data, found as vtkXMLDataParser finds it: after the
/// start tag's '>' and any blanks.
std::int64_t InlinePosition(XmlFile& file, vtkXMLDataElement* element)
{
  file.In.clear();
  file.In.seekg(element->GetXMLByteIndex());
  char c = 0;
  while (file.In.get(c) && c != '>')
  {
  }
  while (file.In.get(c) && std::isspace(static_cast<unsigned char>(c)))
  {
  }
  return file.In ? static_cast<std::int64_t>(file.In.tellg()) - 1 : -1;
}

/// Numbers of an ASCII array: words up to the next '<'.
std::uintmax_t CountAsciiValues(XmlFile& file, std::int64_t position)
{
  file.In.clear();
  file.In.seekg(position);
  std::uintmax_t values = 0;
  bool inWord = false;
  char c = 0;
  while (file.In.get(c) && c != '<')
  {
    const bool blank = std::isspace(static_cast<unsigned char>(c)) != 0;
    values += !blank && !inWord;
    inWord = !blank;
  }
  return values;
}

/// Where a binary array's data run, inline or appended.
std::string FindRun(XmlFile& file, vtkXMLDataElement* array, const std::string& format,
  DataRun& run)
{
  long long offset = 0;
  if (format == "binary")
  {
    run.Position = InlinePosition(file, array);
    run.Base64 = true;
    run.Length = run.Position < 0 ? 0 : RunLength(file, run.Position);
    return "";
  }
  const char* text = array->GetAttribute("offset");
  if (!text || !ParseCount(text, offset) || file.AppendedPosition < 0)
  {
    return "its appended data offset is " + Quote(text ? text : "missing");
  }
  if (static_cast<std::uintmax_t>(offset) >= file.Size - static_cast<std::uintmax_t>(file.AppendedPosition))
  {
    return "its appended data offset " + std::to_string(offset) + " is beyond the file";
  }
  run.Position = file.AppendedPosition + offset;
  run.Base64 = file.AppendedBase64;
  run.Length = run.Base64 ? RunLength(file, run.Position) : file.Size - run.Position;
  return "";
}

/// Values an array holds: numbers of an ASCII array, the declared data size of a binary one
/// (if its header is sound) divided by the value size.
std::string MeasureArray(XmlFile& file, vtkXMLDataElement* array, std::uintmax_t& values)
{
  const char* formatText = array->GetAttribute("format");
  const std::string format = formatText ? formatText : "";
  const int size = TypeSize(array->GetAttribute("type") ? array->GetAttribute("type") : "");
  if (format == "ascii")
  {
    values = CountAsciiValues(file, InlinePosition(file, array));
    return "";
  }
  if (format != "binary" && format != "appended")
  {
    return "unknown format " + Quote(format);
  }
  DataRun run;
  std::uintmax_t bytes = 0;
  std::string problem = FindRun(file, array, format, run);
  if (problem.empty())
  {
    problem = file.Compressor.empty() ? MeasureUncompressed(file, run, bytes)
                                      : MeasureCompressed(file, run, bytes);
  }
  values = bytes / size;
  return problem;
}

/// The value at index of an uncompressed integer array (the last cell offset), if readable.
bool ReadIntegerValue(XmlFile& file, vtkXMLDataElement* array, std::uintmax_t index,
  long long& value)
{
  const std::string format = array->GetAttribute("format") ? array->GetAttribute("format") : "";
  const std::string type = array->GetAttribute("type") ? array->GetAttribute("type") : "";
  const int size = TypeSize(type);
  if (format == "ascii")
  {
    file.In.clear();
    file.In.seekg(InlinePosition(file, array));
    std::string word;
    for (std::uintmax_t k = 0; k <= index && file.In >> word; ++k)
    {
    }
    return ParseInteger(word, value);
  }
  DataRun run;
  std::vector<unsigned char> bytes;
  if (!file.Compressor.empty() || type.find("Int") == std::string::npos ||
    !FindRun(file, array, format, run).empty() ||
    !ReadRun(file, run, file.HeaderWord + index * size, size, bytes))
  {
    return false;
  }
  const std::uint64_t raw = Unsigned(file, bytes.data(), size);
  const bool negative = type[0] == 'I' && (raw >> (8 * size - 1)) != 0;
  value = negative ? -1 : static_cast<long long>(std::min<std::uint64_t>(raw, LLONG_MAX));
  return true;
}

/// "array 'Normals'" for messages, or "the array" when it has no name.
std::string Name(vtkXMLDataElement* array)
{
  const char* name = array->GetAttribute("Name");
  return name ? std::string("array '") + name + "'" : std::string("the array");
}

/// One array: a known type, components, format and data for tuples tuples (-1: any).
std::string CheckArray(XmlFile& file, vtkXMLDataElement* array, long long tuples)
{
  const std::string type = array->GetAttribute("type") ? array->GetAttribute("type") : "";
  const char* componentsText = array->GetAttribute("NumberOfComponents");
  long long components = 1;
  if (type == "String" || type == "Bit")
  {
    // No fixed size: only counts no compressed file of this size could hold are refused.
    return tuples > 0 && static_cast<std::uintmax_t>(tuples) / 80000 > file.Size
      ? Name(array) + " declares " + std::to_string(tuples) + " values"
      : "";
  }
  if (TypeSize(type) == 0)
  {
    return Name(array) + " has unknown type " + Quote(type);
  }
  if (componentsText && (!ParseCount(componentsText, components) || components < 1 ||
                          components > INT_MAX))
  {
    return Name(array) + " has NumberOfComponents " + Quote(componentsText);
  }
  std::uintmax_t values = 0;
  const std::string problem = MeasureArray(file, array, values);
  if (!problem.empty())
  {
    return Name(array) + ": " + problem;
  }
  if (tuples >= 0 && static_cast<std::uintmax_t>(tuples) > values / components)
  {
    return Name(array) + " holds " + std::to_string(values) + " values, not " +
      std::to_string(tuples) + " x " + std::to_string(components);
  }
  return "";
}

/// The arrays of a Points, PointData, CellData or FieldData element, of tuples tuples each
/// (-1: as many as an array's NumberOfTuples says, as in field data).
std::string CheckArrays(XmlFile& file, vtkXMLDataElement* parent, long long tuples)
{
  for (int i = 0; parent && i < parent->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* array = parent->GetNestedElement(i);
    const char* count = array->GetAttribute("NumberOfTuples");
    long long own = tuples;
    std::string problem;
    if (tuples < 0 && count && !ParseCount(count, own))
    {
      problem = Name(array) + " has NumberOfTuples " + Quote(count);
    }
    else if (std::strcmp(array->GetName(), "DataArray") == 0 ||
      std::strcmp(array->GetName(), "Array") == 0)
    {
      problem = CheckArray(file, array, own);
    }
    if (!problem.empty())
    {
      return std::string(parent->GetName()) + ": " + problem;
    }
  }
  return "";
}

/// A Verts, Lines, Strips or Polys element: offsets for its cells, connectivity up to the last
/// offset (when that can be read without decompressing).
std::string CheckCells(XmlFile& file, vtkXMLDataElement* cells, long long count)
{
  auto array = [cells](const char* name) {
    return cells ? cells->FindNestedElementWithNameAndAttribute("DataArray", "Name", name)
                 : nullptr;
  };
  vtkXMLDataElement* offsets = array("offsets");
  vtkXMLDataElement* connectivity = array("connectivity");
  if (count == 0 || !offsets || !connectivity)
  {
    return ""; // nothing to read, or the reader reports the missing array
  }
  std::string problem = CheckArray(file, offsets, count);
  std::uintmax_t values = 0;
  if (problem.empty() && MeasureArray(file, offsets, values).empty() &&
    values > static_cast<std::uintmax_t>(count))
  {
    // VTK 9.2 reads as many cells as the count says (file version 2's leading 0 included).
    problem = "holds " + std::to_string(values) + " offsets for the " + std::to_string(count) +
      " cells it declares" +
      (file.Version >= 2 ? " (VTK 9.2 misreads the offsets of VTK files of version 2)" : "");
  }
  long long last = -1;
  if (problem.empty() && ReadIntegerValue(file, offsets, count - 1, last) && last < 0)
  {
    problem = "the last offset is negative";
  }
  if (problem.empty())
  {
    problem = CheckArray(file, connectivity, last);
  }
  return problem.empty() ? "" : std::string(cells->GetName()) + ": " + problem;
}

/// A Piece's counts, and every array it holds.
std::string CheckPiece(XmlFile& file, vtkXMLDataElement* piece)
{
  static const char* const kinds[] = { "Verts", "Lines", "Strips", "Polys" };
  long long points = 0, counts[4] = {}, cells = 0;
  for (int k = -1; k < 4; ++k)
  {
    const std::string attribute = std::string("NumberOf") + (k < 0 ? "Points" : kinds[k]);
    const char* text = piece->GetAttribute(attribute.c_str());
    long long& count = k < 0 ? points : counts[k];
    if (text && (!ParseCount(text, count) || static_cast<std::uintmax_t>(count) > file.Size))
    {
      return "a Piece has " + attribute + " " + Quote(text);
    }
    cells += k < 0 ? 0 : count;
  }
  std::string problem = CheckArrays(file, piece->FindNestedElementWithName("Points"), points);
  if (problem.empty())
  {
    problem = CheckArrays(file, piece->FindNestedElementWithName("PointData"), points);
  }
  if (problem.empty())
  {
    problem = CheckArrays(file, piece->FindNestedElementWithName("CellData"), cells);
  }
  for (int k = 0; k < 4 && problem.empty(); ++k)
  {
    problem = CheckCells(file, piece->FindNestedElementWithName(kinds[k]), counts[k]);
  }
  return problem;
}

/// The VTKFile element's byte order, header type and compressor, and the appended data.
std::string ReadFileAttributes(XmlFile& file, vtkXMLDataElement* root, vtkXMLDataParser* parser)
{
  const char* order = root->GetAttribute("byte_order");
  const char* header = root->GetAttribute("header_type");
  const char* compressor = root->GetAttribute("compressor");
  if (!order || (std::strcmp(order, "LittleEndian") != 0 && std::strcmp(order, "BigEndian") != 0))
  {
    return "byte_order is " + Quote(order ? order : "missing");
  }
  if (header && std::strcmp(header, "UInt32") != 0 && std::strcmp(header, "UInt64") != 0)
  {
    return "header_type is " + Quote(header);
  }
  file.Compressor = compressor ? compressor : "";
  if (!file.Compressor.empty() && file.Compressor != "vtkZLibDataCompressor" &&
    file.Compressor != "vtkLZ4DataCompressor" && file.Compressor != "vtkLZMADataCompressor")
  {
    return "unknown compressor " + Quote(file.Compressor);
  }
  file.BigEndian = std::strcmp(order, "BigEndian") == 0;
  file.Version = root->GetAttribute("version") ? std::atof(root->GetAttribute("version")) : 0.0;
  file.HeaderWord = header && std::strcmp(header, "UInt64") == 0 ? 8 : 4;
  vtkXMLDataElement* appended = root->FindNestedElementWithName("AppendedData");
  const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
  file.AppendedPosition = appended ? parser->GetAppendedDataPosition() : -1;
  file.AppendedBase64 = !encoding || std::strcmp(encoding, "raw") != 0;
  return "";
}
} // namespace vtp

// ----------------------------------------------------------------------------------------- VTK
namespace legacy
{
/// Bytes a value of a legacy type takes at least: its size in a binary file (bits packed),
/// a digit and a blank in an ASCII one.
double ValueBytes(bool binary, const std::string& type)
{
  static const std::map<std::string, double> sizes = { { "bit", 0.125 }, { "char", 1 },
    { "unsigned_char", 1 }, { "short", 2 }, { "unsigned_short", 2 }, { "int", 4 },
    { "unsigned_int", 4 }, { "long", 4 }, { "unsigned_long", 4 }, { "float", 4 },
    { "double", 8 }, { "vtkIdType", 4 }, { "vtktypeint8", 1 }, { "vtktypeuint8", 1 },
    { "vtktypeint16", 2 }, { "vtktypeuint16", 2 }, { "vtktypeint32", 4 },
    { "vtktypeuint32", 4 }, { "vtktypeint64", 8 }, { "vtktypeuint64", 8 } };
  const auto found = sizes.find(type);
  return !binary ? 2 : found == sizes.end() ? 1 : found->second;
}

bool IsType(const std::string& type)
{
  return ValueBytes(true, type) != 1 || type == "char" || type == "unsigned_char" ||
    type == "vtktypeint8" || type == "vtktypeuint8" || type == "string" ||
    type == "utf8_string" || type == "variant";
}

struct Scan
{
  bool Binary = false;
  int Version = 0; // 10 * major + minor
  std::uintmax_t Size = 0;
  long long Tuples = -1; // of the current POINT_DATA or CELL_DATA
  // In an ASCII FIELD block: the arrays still to come, the current array's values still to
  // come, and whether a METADATA block (ended by an empty line) is being skipped.
  long long FieldArrays = 0;
  long long FieldValues = 0;
  bool InMetadata = false;
};

bool IsCellSection(const std::string& keyword)
{
  const std::string lower = Lower(keyword);
  return lower == "vertices" || lower == "lines" || lower == "polygons" ||
    lower == "triangle_strips";
}

/// The next integer of the data: a word of an ASCII file, a big-endian int32 of a binary one.
bool ReadInteger(std::istream& in, bool binary, long long& value)
{
  std::string word;
  unsigned char bytes[4] = {};
  if (!binary)
  {
    return (in >> word) && ParseInteger(word, value);
  }
  if (!in.read(reinterpret_cast<char*>(bytes), 4))
  {
    return false;
  }
  value = static_cast<std::int32_t>(
    static_cast<std::uint32_t>(bytes[0]) << 24 | bytes[1] << 16 | bytes[2] << 8 | bytes[3]);
  return true;
}

/// The cells of a file before version 5: size integers, each cell its point count then its
/// point ids, filling size exactly (vtkCellArray::ImportLegacyFormat reads past the end of a
/// list whose counts overrun it).
std::string CheckLegacyCells(std::istream& in, const Scan& scan, long long size)
{
  long long at = 0, value = 0;
  while (at < size)
  {
    long long points = 0;
    if (!ReadInteger(in, scan.Binary, points))
    {
      return "the cell list ends early or holds a word that is no integer";
    }
    if (points < 0 || points > size - at - 1)
    {
      return "a cell of " + std::to_string(points) + " points overruns the cell list";
    }
    for (long long k = 0; k < points; ++k)
    {
      if (!ReadInteger(in, scan.Binary, value))
      {
        return "the cell list ends early or holds a word that is no integer";
      }
    }
    at += 1 + points;
  }
  return "";
}

/// The count at words[at] (a non-negative integer), times factor values of type, must fit in
/// the file; values is set to count.
std::string Fits(const Scan& scan, const std::vector<std::string>& words, std::size_t at,
  long long factor, const std::string& type, long long& count)
{
  if (at >= words.size() || !ParseCount(words[at], count))
  {
    return Quote(words[0]) + " line with count " +
      Quote(at < words.size() ? words[at] : "missing");
  }
  const double bytes = static_cast<double>(count) * factor * ValueBytes(scan.Binary, type);
  if (bytes > static_cast<double>(scan.Size))
  {
    return Quote(words[0]) + " line declares " + std::to_string(count) + " x " +
      std::to_string(factor) + " values, more than the file's " + std::to_string(scan.Size) +
      " bytes hold";
  }
  return "";
}

/// Values per tuple of an attribute line (SCALARS, VECTORS, ...): 0 for other lines; the index
/// of its component count and type words when the line gives them.
long long AttributeWidth(const std::vector<std::string>& words, std::size_t& typeAt)
{
  const std::string keyword = Lower(words[0]);
  long long components = 1;
  typeAt = 2;
  if (keyword == "scalars")
  {
    return words.size() > 3 && ParseCount(words[3], components) ? components : 1;
  }
  if (keyword == "vectors" || keyword == "normals")
  {
    return 3;
  }
  if (keyword == "tensors")
  {
    return 9;
  }
  if (keyword == "tensors6")
  {
    return 6;
  }
  if (keyword == "global_ids" || keyword == "pedigree_ids" || keyword == "edge_flags")
  {
    return 1;
  }
  typeAt = 3;
  if (keyword == "texture_coordinates" || keyword == "color_scalars")
  {
    return words.size() > 2 && ParseCount(words[2], components) ? components : -1;
  }
  return 0;
}

/// A line inside an ASCII FIELD block (words empty for an empty line): an array's header
/// 'name components tuples type' with a type vtkDataReader knows (it crashes on others), its
/// values, 'NULL_ARRAY', or a METADATA block. Sets handled when the line belonged to the block.
std::string CheckFieldLine(Scan& scan, const std::vector<std::string>& words, bool& handled)
{
  handled = scan.InMetadata || scan.FieldValues > 0 || (scan.FieldArrays > 0 && !words.empty());
  if (scan.InMetadata)
  {
    scan.InMetadata = !words.empty();
    return "";
  }
  if (scan.FieldValues > 0)
  {
    // vtkPolyDataReader crashes on a dataset FIELD block it cannot read (found by fuzzing).
    for (std::size_t k = 0; k < words.size() && static_cast<long long>(k) < scan.FieldValues; ++k)
    {
      if (!IsNumber(words[k]))
      {
        return Quote(words[k]) + " where a value of a FIELD array is due";
      }
    }
    scan.FieldValues -= static_cast<long long>(words.size());
    return "";
  }
  if (!handled)
  {
    return "";
  }
  if (words[0] == "METADATA")
  {
    scan.InMetadata = true;
    return "";
  }
  --scan.FieldArrays;
  if (words[0] == "NULL_ARRAY")
  {
    return "";
  }
  long long components = 0, tuples = 0;
  if (words.size() != 4 || !ParseCount(words[1], components) ||
    !ParseCount(words[2], tuples) || !IsType(words[3]))
  {
    return "field array line " + Quote(words[0]) +
      " is not 'name components tuples type' with a known type";
  }
  const std::string type = Lower(words[3]);
  if (type == "string" || type == "utf8_string" || type == "variant")
  {
    // One value a line (empty ones too) or two words a value: the rest of the block is not
    // walked; vtkDataReader reads these types safely.
    scan.FieldArrays = 0;
    return "";
  }
  long long count = 0;
  const std::string problem = components > INT_MAX
    ? "field array " + Quote(words[0]) + " with " + words[1] + " components"
    : Fits(scan, words, 2, components, words[3], count);
  scan.FieldValues = problem.empty() ? components * tuples : 0;
  return problem;
}

/// One line of the file that declares a count: a section, an attribute or a field array.
std::string CheckCountLine(Scan& scan, const std::vector<std::string>& words)
{
  const std::string keyword = Lower(words[0]);
  if (keyword.rfind("field", 0) == 0 && keyword != "field")
  {
    // vtkPolyDataReader takes any word that starts so for FIELD, and crashes on what follows.
    return Quote(words[0]) + " reads as FIELD to vtkPolyDataReader, which cannot read it";
  }
  long long count = 0;
  std::size_t typeAt = 0;
  const long long width = AttributeWidth(words, typeAt);
  if (keyword == "points")
  {
    // vtkPolyDataReader crashes on points of a type it does not know (found by fuzzing).
    const std::string type = words.size() > 2 ? Lower(words[2]) : "";
    if (!IsType(type) || type == "bit" || type == "string" || type == "utf8_string" ||
      type == "variant")
    {
      return "POINTS of type " + Quote(words.size() > 2 ? words[2] : "") + ", not a number type";
    }
    return Fits(scan, words, 1, 3, type, count);
  }
  if (IsCellSection(keyword))
  {
    const std::string problem = Fits(scan, words, 1, 1, "char", count);
    return problem.empty() ? Fits(scan, words, 2, 1, "char", count) : problem;
  }
  if (keyword == "point_data" || keyword == "cell_data")
  {
    return Fits(scan, words, 1, 1, "bit", scan.Tuples);
  }
  if (keyword == "field")
  {
    const std::string problem = Fits(scan, words, 2, 1, "char", count);
    scan.FieldArrays = scan.Binary ? 0 : count;
    return problem;
  }
  if (keyword == "lookup_table" && words.size() == 3)
  {
    return Fits(scan, words, 2, 4, "char", count);
  }
  if (width != 0 && scan.Tuples >= 0)
  {
    if (width < 0 || width > INT_MAX)
    {
      return Quote(words[0]) + " line with " + Quote(words[2]) + " components";
    }
    const std::string type = words.size() > typeAt ? words[typeAt] : "char";
    return Fits(scan, { words[0], std::to_string(scan.Tuples) }, 1, width, type, count);
  }
  long long components = 0;
  if (words.size() == 4 && IsType(words[3]) && ParseCount(words[1], components))
  {
    // A field array: name, components, tuples, type.
    if (components > INT_MAX)
    {
      return "field array " + Quote(words[0]) + " with " + words[1] + " components";
    }
    return Fits(scan, words, 2, components, words[3], count);
  }
  return "";
}

/// The four header lines: the version line (up to 5.1, which VTK 9.2 writes; the version picks
/// the cell format), a title, ASCII or BINARY, DATASET POLYDATA.
std::string CheckHeader(std::istream& in, Scan& scan)
{
  const std::string prefix = "# vtk DataFile Version";
  std::string lines[4];
  int major = 0, minor = 0;
  for (std::string& line : lines)
  {
    std::getline(in, line);
  }
  if (lines[0].rfind(prefix, 0) != 0)
  {
    return "the first line is not '# vtk DataFile Version ...'";
  }
  if (std::sscanf(lines[0].c_str() + prefix.size(), "%d.%d", &major, &minor) != 2 || major < 0 ||
    minor < 0 || major > 5 || (major == 5 && minor > 1))
  {
    return "the version is not one from 0.0 to 5.1";
  }
  scan.Version = 10 * major + minor;
  const std::vector<std::string> encoding = SplitBlanks(lines[2]);
  const std::vector<std::string> dataset = SplitBlanks(lines[3]);
  if (encoding.size() != 1 || (Lower(encoding[0]) != "ascii" && Lower(encoding[0]) != "binary"))
  {
    return "the third line is not ASCII or BINARY";
  }
  if (dataset.size() != 2 || Lower(dataset[0]) != "dataset" || Lower(dataset[1]) != "polydata")
  {
    return "the fourth line is not 'DATASET POLYDATA'";
  }
  scan.Binary = Lower(encoding[0]) == "binary";
  return "";
}
} // namespace legacy
} // namespace

std::string CheckPLY(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  ply::Header header;
  std::string problem = ply::ReadHeader(in, header);
  if (problem.empty())
  {
    problem = ply::CheckLayout(header);
  }
  if (problem.empty() && header.Format == ply::Encoding::Ascii)
  {
    problem = ply::CheckAsciiBody(in, header);
  }
  else if (problem.empty())
  {
    const std::streamoff start = in.tellg(); // -1 when the header ends the file without a newline
    problem = ply::CheckBinaryBody(in, header, start < 0 ? 0 : FileSize(path) - static_cast<std::uintmax_t>(start));
  }
  return problem;
}

std::string CheckSTL(const std::string& path)
{
  // vtkSTLReader tells the two apart as vtksys does: by the share of text bytes at the start.
  if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return CheckAsciiSTL(path);
  }
  return CheckBinarySTL(path);
}

std::string CheckOBJ(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  obj::Kinds kinds;
  std::string problem = obj::FirstPass(in, kinds);
  if (problem.empty())
  {
    in.clear();
    in.seekg(0);
    problem = obj::SecondPass(in, kinds);
  }
  return problem;
}

std::string CheckVTP(const std::string& path)
{
  // The markup first, in a bounded pass: some files crash or stall any XML parser of VTK's.
  const std::string markup = ScanXmlMarkup(path);
  if (!markup.empty())
  {
    return markup;
  }
  // VTK's XML parser reads the structure, alone: vtkXMLPolyDataReader's own first pass already
  // trusts the arrays (a field array without a type crashes it).
  std::ifstream stream(path, std::ios::binary);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetStream(&stream);
  if (!parser->Parse())
  {
    return "its XML is not well formed";
  }
  vtkXMLDataElement* root = parser->GetRootElement();
  vtkXMLDataElement* polyData = root ? root->FindNestedElementWithName("PolyData") : nullptr;
  if (!polyData)
  {
    return "it has no PolyData element";
  }
  vtp::XmlFile file;
  file.In.open(path, std::ios::binary);
  file.Size = FileSize(path);
  std::string problem = vtp::ReadFileAttributes(file, root, parser);
  if (problem.empty())
  {
    problem = vtp::CheckArrays(file, polyData->FindNestedElementWithName("FieldData"), -1);
  }
  for (int i = 0; i < polyData->GetNumberOfNestedElements() && problem.empty(); ++i)
  {
    vtkXMLDataElement* piece = polyData->GetNestedElement(i);
    if (std::strcmp(piece->GetName(), "Piece") == 0)
    {
      problem = vtp::CheckPiece(file, piece);
    }
  }
  return problem;
}

std::string CheckLegacyVTK(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  legacy::Scan scan;
  scan.Size = FileSize(path);
  std::string problem = legacy::CheckHeader(in, scan);
  std::string line;
  for (long long number = 5; problem.empty() && std::getline(in, line); ++number)
  {
    const std::vector<std::string> words = SplitBlanks(line);
    long long size = 0;
    bool fieldLine = false;
    problem = legacy::CheckFieldLine(scan, words, fieldLine);
    if (problem.empty() && !fieldLine && !words.empty())
    {
      problem = legacy::CheckCountLine(scan, words);
    }
    if (problem.empty() && !fieldLine && !words.empty() && legacy::IsCellSection(words[0]) &&
      scan.Version < 50 && ParseCount(words.size() > 2 ? words[2] : "", size))
    {
      problem = legacy::CheckLegacyCells(in, scan, size);
    }
    if (!problem.empty())
    {
      problem = "line " + std::to_string(number) + ": " + problem;
    }
  }
  if (problem.empty() && (scan.FieldArrays > 0 || scan.FieldValues > 0))
  {
    problem = "the file ends inside a FIELD block (vtkPolyDataReader crashes on it)";
  }
  return problem;
}

} // namespace meshfiles
