// SPDX-License-Identifier: BSD-3-Clause
// CheckLegacyVTK: a legacy VTK polydata file's header lines, every count against the file's
// size, the FIELD blocks and the cell lists of files before version 5.
#include "MeshFileChecks.h"

#include "MeshFileCheckText.h"

#include <climits>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace meshfiles
{
using detail::FileSize;
using detail::IsNumber;
using detail::Lower;
using detail::ParseCount;
using detail::ParseInteger;
using detail::Quote;
using detail::SplitBlanks;

namespace
{
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
