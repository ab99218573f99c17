// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OFFFile.h
 * @brief Reading and writing Object File Format (.off) meshes, which VTK has no reader for.
 *
 * Supports the plain ASCII variant: an optional "OFF" header keyword, the counts line, points
 * (extra columns are ignored), and polygons of any size; and COFF (MeshLab's and Geomview's),
 * whose points carry an RGBA colour each, 0–255, or 0–1 when no value in the file is above 1. Comments (#) and blank
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
  std::vector<std::uint8_t> Colours; // 4 per point (RGBA) from a COFF file, else empty
};

/// Returns false with a one-line message in error on failure, data after the declared faces
/// included (a short count would drop faces).
bool ReadOFF(const std::string& path, PolygonMesh& mesh, std::string& error);
/// Writes the whole file or none (WholeFile.h): false with a one-line message in error.
bool WriteOFF(const std::string& path, const PolygonMesh& mesh, std::string& error);

} // namespace meshsimp

#endif
