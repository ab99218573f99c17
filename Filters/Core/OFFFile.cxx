// SPDX-License-Identifier: BSD-3-Clause
#include "OFFFile.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

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
    if (!NextDataLine(in, line) || std::sscanf(line.c_str(), "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3)
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
    std::istringstream face;
    if (NextDataLine(in, line))
    {
      face.str(line);
    }
    if (!(face >> size) || size < 0)
    {
      error = path + ": bad or missing face " + std::to_string(f);
      return false;
    }
    for (long long k = 0; k < size; ++k)
    {
      long long id = -1;
      if (!(face >> id) || id < 0 || id >= numberOfPoints)
      {
        error = path + ": face " + std::to_string(f) + " has a bad point index";
        return false;
      }
      mesh.FaceIds.push_back(id);
    }
    mesh.FaceOffsets.push_back(static_cast<std::int64_t>(mesh.FaceIds.size()));
  }
  return true;
}

bool WriteOFF(const std::string& path, const PolygonMesh& mesh, std::string& error)
{
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out)
  {
    error = "cannot write " + path;
    return false;
  }
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
  const bool ok = std::fclose(out) == 0;
  if (!ok)
  {
    error = "error writing " + path;
  }
  return ok;
}

} // namespace meshsimp
