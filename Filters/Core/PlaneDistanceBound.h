// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file PlaneDistanceBound.h
 * @brief The error bound of the collapse filters: the largest distance from a vertex to the
 * planes of the input triangles it stands for (Ronfard and Rossignac's measure, the bound the
 * octree filter puts on its representatives).
 *
 * Every vertex starts with the supporting planes of its triangles and, along each of their
 * boundary edges, the plane through the edge perpendicular to the triangle (so a border cannot
 * be pulled in by more than the bound either). A collapse merges the planes of the merged
 * vertices into the kept one's; a policy checks the new position against all of them first.
 *
 * The sets are circular lists threaded through the triangles' corners (one index per corner),
 * so a merge splices two lists in O(1) and the storage stays flat: a plane per triangle, one
 * per boundary edge, a link per corner.
 */
#ifndef MeshSimplification_PlaneDistanceBound_h
#define MeshSimplification_PlaneDistanceBound_h

#include "CollapseMesh.h"
#include "Simplification.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace meshsimp
{

class PlaneDistanceBound
{
public:
  /// Takes every vertex's planes from the mesh as it is (before any collapse).
  void Build(const CollapseMesh& mesh);

  /// The largest distance from x to v's planes (0 when it has none).
  double Distance(std::int32_t v, const Eigen::Vector3d& x) const;

  /// The largest distance from the plan's position to the planes of all its vertices.
  double Distance(const CollapsePlan& plan) const;

  /// Moves the planes of the plan's merged vertices to the kept one, whose distance (the value
  /// Distance(plan) gave) becomes error.
  void Merge(const CollapsePlan& plan, double error);

  /// The distance recorded for v: its largest at its last merge or move, 0 before.
  double Error(std::int32_t v) const { return this->Errors[v]; }
  void SetError(std::int32_t v, double error) { this->Errors[v] = error; }

private:
  std::vector<Eigen::Vector4d> Planes;     // per triangle: unit normal n and d, n · x + d = 0
  std::vector<Eigen::Vector4d> EdgePlanes; // per boundary edge
  std::vector<std::int32_t> EdgePlaneOf;   // per corner: the edge from it to the next, or -1
  std::vector<std::int32_t> Next;          // per corner: the next corner of its vertex's set
  std::vector<std::int32_t> Head;          // per vertex: a corner of its set, -1 when empty
  std::vector<double> Errors;              // per vertex
};

/// The point array "PlaneDistance": each output point's distance to its planes (survivors: the
/// engine vertex of each output point), times toInput (input units per mesh unit); the largest
/// as the report's MaximumError.
void AddPlaneDistances(const PlaneDistanceBound& bound, const std::vector<std::int32_t>& survivors, double toInput,
  SimplifiedMesh& result);

} // namespace meshsimp

#endif
