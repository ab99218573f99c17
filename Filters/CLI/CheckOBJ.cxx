// SPDX-License-Identifier: BSD-3-Clause
// CheckOBJ: an OBJ file's lines, material names, vertex coordinates and every face corner, read
// in vtkOBJReader's two passes.
#include "MeshFileChecks.h"

#include "MeshFileCheckText.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace meshfiles
{
using detail::IsNumber;
using detail::Quote;
using detail::SplitBlanks;

namespace
{
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
} // namespace

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

} // namespace meshfiles
