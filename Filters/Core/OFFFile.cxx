// SPDX-License-Identifier: BSD-3-Clause
#include "OFFFile.h"

#include "WholeFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace meshsimp
{
namespace
{
/// Next line holding data: comments stripped, blank lines skipped.
bool NextDataLine(std::istream& in, std::string& line)
{
  while (std::getline(in, line))
  {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

/// The next number on a line from cursor on, past blanks (a leading '+' allowed); moves cursor
/// past it. std::from_chars: no locale, no stream per line (the reader's cost was that).
template <typename T>
bool NextNumber(const char*& cursor, const char* end, T& value)
{
  while (cursor < end && std::isspace(static_cast<unsigned char>(*cursor)))
  {
    ++cursor;
  }
  if (cursor + 1 < end && cursor[0] == '+' && cursor[1] != '-')
  {
    ++cursor;
  }
  std::from_chars_result parsed = std::from_chars(cursor, end, value);
  if constexpr (std::is_floating_point_v<T>)
  {
    if (parsed.ec == std::errc::result_out_of_range)
    {
      // Beyond double's range (1e400, 1e-400): its infinity or zero, as strtod would give
      // (beyond long double's too, an error).
      long double wide = 0.0L;
      parsed = std::from_chars(cursor, end, wide);
      value = static_cast<T>(wide);
    }
  }
  if (parsed.ec != std::errc())
  {
    return false;
  }
  cursor = parsed.ptr;
  return true;
}
}

bool ReadOFF(const std::string& path, PolygonMesh& mesh, std::string& error)
{
  std::ifstream in(path);
  if (!in)
  {
    error = "cannot open " + path;
    return false;
  }
  mesh = PolygonMesh();
  std::string line;
  if (!NextDataLine(in, line))
  {
    error = path + ": empty file";
    return false;
  }
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0)
  {
    if (keyword != "OFF")
    {
      error = path + ": only plain ASCII OFF is supported, not " + keyword;
      return false;
    }
    if (!(header >> std::ws).eof())
    {
      line = line.substr(line.find("OFF") + 3); // counts on the header line
    }
    else if (!NextDataLine(in, line))
    {
      error = path + ": missing counts line";
      return false;
    }
  }
  long long numberOfPoints = -1, numberOfFaces = -1;
  std::istringstream counts(line);
  if (!(counts >> numberOfPoints >> numberOfFaces) || numberOfPoints < 0 || numberOfFaces < 0)
  {
    error = path + ": bad counts line";
    return false;
  }
  // The counts are not trusted with memory: a damaged header could claim more than any machine
  // holds. The lists grow with what is read; reserved up front only to a bounded size.
  constexpr long long ReserveLimit = 1 << 22;
  mesh.Points.reserve(3 * static_cast<std::size_t>(std::min(numberOfPoints, ReserveLimit)));
  for (long long i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    bool ok = NextDataLine(in, line);
    const char* cursor = line.data();
    const char* end = cursor + line.size();
    for (int k = 0; k < 3 && ok; ++k)
    {
      ok = NextNumber(cursor, end, p[k]);
    }
    if (!ok)
    {
      error = path + ": bad or missing point " + std::to_string(i);
      return false;
    }
    mesh.Points.insert(mesh.Points.end(), p, p + 3);
  }
  mesh.FaceOffsets.reserve(static_cast<std::size_t>(std::min(numberOfFaces, ReserveLimit)) + 1);
  mesh.FaceIds.reserve(3 * static_cast<std::size_t>(std::min(numberOfFaces, ReserveLimit)));
  for (long long f = 0; f < numberOfFaces; ++f)
  {
    long long size = 0;
    const bool found = NextDataLine(in, line);
    const char* cursor = line.data();
    const char* end = cursor + line.size();
    if (!found || !NextNumber(cursor, end, size) || size < 0)
    {
      error = path + ": bad or missing face " + std::to_string(f);
      return false;
    }
    for (long long k = 0; k < size; ++k)
    {
      long long id = -1;
      if (!NextNumber(cursor, end, id) || id < 0 || id >= numberOfPoints)
      {
        error = path + ": face " + std::to_string(f) + " has a bad point index";
        return false;
      }
      mesh.FaceIds.push_back(id);
    }
    mesh.FaceOffsets.push_back(static_cast<std::int64_t>(mesh.FaceIds.size()));
  }
  if (NextDataLine(in, line))
  {
    error = path + ": data follow the last of the " + std::to_string(numberOfFaces) +
      " faces the counts line declares";
    return false;
  }
  return true;
}

namespace
{
/// The mesh as OFF text; false when a write failed.
bool WriteOFFText(std::FILE* out, const PolygonMesh& mesh)
{
  const std::size_t faces = mesh.FaceOffsets.size() - 1;
  std::fprintf(out, "OFF\n%zu %zu 0\n", mesh.Points.size() / 3, faces);
  for (std::size_t i = 0; i < mesh.Points.size(); i += 3)
  {
    std::fprintf(out, "%.17g %.17g %.17g\n", mesh.Points[i], mesh.Points[i + 1], mesh.Points[i + 2]);
  }
  for (std::size_t f = 0; f < faces; ++f)
  {
    std::fprintf(out, "%lld", static_cast<long long>(mesh.FaceOffsets[f + 1] - mesh.FaceOffsets[f]));
    for (std::int64_t k = mesh.FaceOffsets[f]; k < mesh.FaceOffsets[f + 1]; ++k)
    {
      std::fprintf(out, " %lld", static_cast<long long>(mesh.FaceIds[k]));
    }
    std::fprintf(out, "\n");
  }
  return !std::ferror(out);
}
}

bool WriteOFF(const std::string& path, const PolygonMesh& mesh, std::string& error)
{
  std::string reason;
  if (WriteWholeFile(path, [&mesh](std::FILE* out) { return WriteOFFText(out, mesh); }, reason))
  {
    return true;
  }
  error = "cannot write " + path + ": " + reason;
  return false;
}

} // namespace meshsimp
