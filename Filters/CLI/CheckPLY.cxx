// SPDX-License-Identifier: BSD-3-Clause
// CheckPLY: an ASCII or binary PLY file's header, then every vertex and face record, as
// vtkPLYReader would read them.
#include "MeshFileChecks.h"

#include "MeshFileCheckText.h"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace meshfiles
{
using detail::FileSize;
using detail::IsNumber;
using detail::ParseCount;
using detail::ParseInteger;
using detail::Quote;
using detail::SplitBlanks;

namespace
{
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

} // namespace meshfiles
