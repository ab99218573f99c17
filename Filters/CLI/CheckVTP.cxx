// SPDX-License-Identifier: BSD-3-Clause
// CheckVTP: a VTK XML polydata file's markup and structure, then every array of every piece
// against the data its format and block headers describe.
#include "MeshFileChecks.h"

#include "MeshFileCheckText.h"
#include "XmlMarkupScan.h"

#include "vtkBase64Utilities.h"
#include "vtkNew.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace meshfiles
{
using detail::FileSize;
using detail::ParseCount;
using detail::ParseInteger;
using detail::Quote;

namespace
{
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
} // namespace

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

} // namespace meshfiles
