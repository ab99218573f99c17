// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file LODInterpolation.h
 * @brief A morph between two levels of detail of one surface, whatever made them: Zhou, Zhang,
 * Shi and Pan, "A new simplification algorithm for colored or textured polygonal models", §5.
 *
 * Every point of the detailed mesh gets a partner on the coarse mesh, once (MorphPartners:
 * the paper's nearest vertices, or the nearest point of the coarse surface); a frame at
 * parameter t then puts each detailed point at (1 − t) P_detailed + t P_partner on the detailed
 * triangles, joins adjacent points closer than t times the merge distance and drops the
 * triangles left without area (Morph). t = 0 is the detailed mesh exactly; at t = 1 every point
 * lies on the coarse surface. The nearest-point queries are the caller's (the VTK filter asks
 * VTK's static locators), so this file holds the pairing and the frames alone.
 */
#ifndef MeshSimplification_LODInterpolation_h
#define MeshSimplification_LODInterpolation_h

#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

/// Where each detailed point goes at t = 1, and whose point data it takes there.
struct MorphPartners
{
  /// Per detailed point, 3 coordinates: its place on the coarse mesh.
  std::vector<double> Targets;
  /// Per detailed point, 3 coarse point ids (-1 where fewer) and their weights (summing to 1):
  /// one vertex, or the corners of the coarse triangle its target lies on.
  std::vector<std::int32_t> Coarse;
  std::vector<double> Weights;

  std::int64_t NumberOfPoints() const { return static_cast<std::int64_t>(this->Targets.size() / 3); }
};

/**
 * The paper's steps 1 and 2, from nearest-point queries the caller answers: every coarse point
 * c pairs with its nearest detailed point nearestDetailed[c] (where several coarse points choose
 * one detailed point, the nearest of them, then the lowest id); every detailed point d that no
 * coarse point chose pairs with its nearest coarse point nearestCoarse[d]. Ids out of range
 * (-1: no answer) leave a detailed point where it is, its own partner.
 */
MorphPartners PairNearestVertices(const TriangleMeshView& detailed, const TriangleMeshView& coarse,
  const std::vector<std::int32_t>& nearestDetailed, const std::vector<std::int32_t>& nearestCoarse);

/**
 * Beyond the paper: every detailed point d goes to the closest point of the coarse surface,
 * given as the coarse triangle triangle[d] and the barycentric weights barycentric[3 d .. 3 d + 2]
 * of its corners (the caller's cell locator finds them). A detailed point goes to a point near
 * it rather than to a far vertex, so thin parts fold far less. Triangles out of range leave the
 * point where it is.
 */
MorphPartners PairSurfacePoints(const TriangleMeshView& detailed, const TriangleMeshView& coarse,
  const std::vector<std::int32_t>& triangle, const std::vector<double>& barycentric);

/// One frame of the morph, on the detailed triangles.
struct MorphFrame
{
  std::vector<double> Points;               // 3 per output point
  std::vector<std::int32_t> Triangles;      // 3 per output triangle
  std::vector<std::int32_t> TriangleSource; // per output triangle, its detailed triangle
  /// Per output point, the detailed points it stands for (CSR: PointOffsets has one entry more
  /// than there are points); one each unless points merged.
  std::vector<std::int32_t> PointOffsets;
  std::vector<std::int32_t> PointSources;
  /// Per output point, how far it stands from where its first source is in the detailed mesh.
  std::vector<double> Displacement;

  std::int64_t NumberOfPoints() const { return static_cast<std::int64_t>(this->Points.size() / 3); }
  std::int64_t NumberOfTriangles() const { return static_cast<std::int64_t>(this->TriangleSource.size()); }
};

/**
 * The paper's steps 3 and 4 at parameter t (clamped to [0, 1]): each detailed point at
 * (1 − t) P + t Target; adjacent points (sharing a triangle edge) closer than t · mergeDistance
 * (mesh units) join at the mean of their places, and triangles with two corners joined go. The
 * threshold grows with t so that t = 0 gives the detailed mesh exactly, points and triangles;
 * where no points join the output's points are the detailed mesh's, in its order. Triangles of
 * the detailed mesh with an id out of range are left out.
 */
void Morph(const TriangleMeshView& detailed, const MorphPartners& partners, double t, double mergeDistance,
  MorphFrame& frame);

} // namespace meshsimp

#endif
