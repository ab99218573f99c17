// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OFFFile.h
 * @brief Reading and writing Object File Format (.off) meshes, which VTK has no reader for.
 *
 * Supports the plain ASCII variant: an optional "OFF" header keyword, the counts line, points
 * (extra columns such as colours are ignored), and polygons of any size. Comments (#) and blank
 * lines are skipped. Numbers are read with std::from_chars: the same values as strtod gives, in
 * any locale (no hexadecimal floats); one beyond double's range becomes its infinity or zero.
 */
#ifndef MeshSimplification_OFFFile_h
#define MeshSimplification_OFFFile_h

#include <cstdint>
#include <string>
#include <vector>

namespace meshsimp
{

struct PolygonMesh
{
  std::vector<double> Points;              // 3 per point
  std::vector<std::int64_t> FaceOffsets{ 0 }; // CSR over FaceIds
  std::vector<std::int64_t> FaceIds;
};

/// Returns false with a one-line message in error on failure, data after the declared faces
/// included (a short count would drop faces).
bool ReadOFF(const std::string& path, PolygonMesh& mesh, std::string& error);
/// Writes the whole file or none (WholeFile.h): false with a one-line message in error.
bool WriteOFF(const std::string& path, const PolygonMesh& mesh, std::string& error);

} // namespace meshsimp

#endif
