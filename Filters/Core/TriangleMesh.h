// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TriangleMesh.h
 * @brief Triangle-mesh views and adjacency in flat arrays, shared by all filters.
 *
 * Indices are 32-bit: the core serves meshes up to 2^31 − 1 points and triangles. The
 * vertex→triangle adjacency is a CSR (offsets + ids) built by counting, so it costs two flat
 * arrays and no per-vertex allocation.
 */
#ifndef MeshSimplification_TriangleMesh_h
#define MeshSimplification_TriangleMesh_h

#include "Execution.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace meshsimp
{

/// A read-only view of an indexed triangle mesh: 3 doubles per point, 3 ids per triangle.
struct TriangleMeshView
{
  const double* Points = nullptr;
  std::int64_t NumberOfPoints = 0;
  const std::int32_t* Triangles = nullptr;
  std::int64_t NumberOfTriangles = 0;

  Eigen::Vector3d Point(std::int64_t i) const
  {
    return { this->Points[3 * i], this->Points[3 * i + 1], this->Points[3 * i + 2] };
  }
};

/**
 * True when triangle t has three distinct in-range indices and finite corner coordinates.
 * Invalid triangles are skipped by every algorithm (they count as dropped input).
 */
bool IsUsableTriangle(const TriangleMeshView& mesh, std::int64_t t);

/// Vertex → incident triangles, as CSR arrays.
struct VertexTriangleAdjacency
{
  std::vector<std::int32_t> Offsets;   // NumberOfPoints + 1
  std::vector<std::int32_t> Triangles; // incident triangle ids, ascending per vertex

  /// Only triangles with usable[t] != 0 are linked.
  void Build(const TriangleMeshView& mesh, const std::vector<std::uint8_t>& usable);

  const std::int32_t* Begin(std::int64_t v) const { return this->Triangles.data() + this->Offsets[v]; }
  const std::int32_t* End(std::int64_t v) const { return this->Triangles.data() + this->Offsets[v + 1]; }
};

/// An edge used by exactly one triangle, oriented as in that triangle.
struct BoundaryEdge
{
  std::int32_t V0, V1, Triangle;
};

/// Boundary edges in triangle order (an edge shared by three or more triangles is not one).
std::vector<BoundaryEdge> FindBoundaryEdges(const TriangleMeshView& mesh,
  const std::vector<std::uint8_t>& usable, const VertexTriangleAdjacency& adjacency,
  const ExecutionContext& context = {});

} // namespace meshsimp

#endif
