// SPDX-License-Identifier: BSD-3-Clause
// CheckSTL: a binary STL file's size against its triangle count, an ASCII one's solid, facet
// and vertex lines.
#include "MeshFileChecks.h"

#include "MeshFileCheckText.h"

#include <vtksys/SystemTools.hxx>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace meshfiles
{
using detail::FileSize;
using detail::Lower;
using detail::Quote;
using detail::SplitBlanks;

namespace
{
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
} // namespace

std::string CheckSTL(const std::string& path)
{
  // vtkSTLReader tells the two apart as vtksys does: by the share of text bytes at the start.
  if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return CheckAsciiSTL(path);
  }
  return CheckBinarySTL(path);
}

} // namespace meshfiles
