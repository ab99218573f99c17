// SPDX-License-Identifier: BSD-3-Clause
#include "OFFFile.h"

#include "WholeFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
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

/// The counts are not trusted with memory: a damaged header could claim more than any machine
/// holds. The lists grow with what is read; reserved up front only to a bounded size.
constexpr long long ReserveLimit = 1 << 22;

/// The header: the optional keyword (OFF, or COFF for colours) and the counts line; false with
/// the reason in error.
bool ReadHeader(std::istream& in, long long& points, long long& faces, bool& colours, std::string& error)
{
  std::string line;
  if (!NextDataLine(in, line))
  {
    error = "empty file";
    return false;
  }
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  colours = keyword == "COFF";
  if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0)
  {
    if (keyword != "OFF" && keyword != "COFF")
    {
      error = "only plain ASCII OFF and COFF are supported, not " + keyword;
      return false;
    }
    if (!(header >> std::ws).eof())
    {
      line = line.substr(line.find("OFF") + 3); // counts on the header line
    }
    else if (!NextDataLine(in, line))
    {
      error = "missing counts line";
      return false;
    }
  }
  std::istringstream counts(line);
  if (!(counts >> points >> faces) || points < 0 || faces < 0)
  {
    error = "bad counts line";
    return false;
  }
  return true;
}

/// count point lines: x y z, and with colours r g b a (0–255, or 0–1 when none is above 1).
bool ReadPoints(std::istream& in, long long count, bool colours, PolygonMesh& mesh, std::string& error)
{
  const int columns = colours ? 7 : 3;
  std::vector<double> rgba;
  mesh.Points.reserve(3 * static_cast<std::size_t>(std::min(count, ReserveLimit)));
  rgba.reserve(colours ? 4 * static_cast<std::size_t>(std::min(count, ReserveLimit)) : 0);
  std::string line;
  for (long long i = 0; i < count; ++i)
  {
    double values[7];
    bool ok = NextDataLine(in, line);
    const char* cursor = line.data();
    const char* end = cursor + line.size();
    for (int k = 0; k < columns && ok; ++k)
    {
      ok = NextNumber(cursor, end, values[k]);
    }
    if (!ok)
    {
      error = "bad or missing point " + std::to_string(i);
      return false;
    }
    mesh.Points.insert(mesh.Points.end(), values, values + 3);
    rgba.insert(rgba.end(), values + 3, values + columns);
  }
  const bool unit = std::all_of(rgba.begin(), rgba.end(), [](double c) { return c <= 1.0; });
  mesh.Colours.resize(rgba.size());
  std::transform(rgba.begin(), rgba.end(), mesh.Colours.begin(), [unit](double c) {
    return static_cast<std::uint8_t>(std::lround(std::min(255.0, std::max(0.0, unit ? 255.0 * c : c))));
  });
  return true;
}

/// count face lines: a corner count, then that many point indices.
bool ReadFaces(std::istream& in, long long count, long long points, PolygonMesh& mesh, std::string& error)
{
  mesh.FaceOffsets.reserve(static_cast<std::size_t>(std::min(count, ReserveLimit)) + 1);
  mesh.FaceIds.reserve(3 * static_cast<std::size_t>(std::min(count, ReserveLimit)));
  std::string line;
  for (long long f = 0; f < count; ++f)
  {
    long long size = 0;
    const bool found = NextDataLine(in, line);
    const char* cursor = line.data();
    const char* end = cursor + line.size();
    if (!found || !NextNumber(cursor, end, size) || size < 0)
    {
      error = "bad or missing face " + std::to_string(f);
      return false;
    }
    for (long long k = 0; k < size; ++k)
    {
      long long id = -1;
      if (!NextNumber(cursor, end, id) || id < 0 || id >= points)
      {
        error = "face " + std::to_string(f) + " has a bad point index";
        return false;
      }
      mesh.FaceIds.push_back(id);
    }
    mesh.FaceOffsets.push_back(static_cast<std::int64_t>(mesh.FaceIds.size()));
  }
  if (NextDataLine(in, line))
  {
    error = "data follow the last of the " + std::to_string(count) + " faces the counts line declares";
    return false;
  }
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
  long long points = -1, faces = -1;
  bool colours = false;
  if (!ReadHeader(in, points, faces, colours, error) || !ReadPoints(in, points, colours, mesh, error) ||
    !ReadFaces(in, faces, points, mesh, error))
  {
    error = path + ": " + error;
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
