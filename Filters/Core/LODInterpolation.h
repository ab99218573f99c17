// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file LODInterpolation.h
 * @brief A morph between two levels of detail of one surface, whatever made them: Zhou, Zhang,
 * Shi and Pan, "A new simplification algorithm for colored or textured polygonal models", §5.
 *
 * Once per pair of surfaces, every point of the detailed mesh gets a partner on the coarse mesh
 * (MorphPartners: the paper's nearest vertices, the nearest point of the coarse surface, or the
 * coarse point the detailed one became in the simplification that made the coarse mesh), and
 * the adjacent points that ever come close enough to merge are listed with when they do
 * (MergeSchedule). A frame at parameter t then puts each detailed point at
 * (1 − t) P_detailed + t P_partner on the detailed triangles, joins adjacent points closer than
 * t times the merge distance and drops the triangles left without area (Morph): its cost is one
 * pass over the points and the triangles, with no search. t = 0 is the detailed mesh exactly; at
 * t = 1 every point lies on the coarse surface. The paper's nearest-vertex queries are the
 * caller's (the VTK filter asks VTK's static point locators).
 */
#ifndef MeshSimplification_LODInterpolation_h
#define MeshSimplification_LODInterpolation_h

#include "Execution.h"
#include "TriangleMesh.h"

#include <algorithm>
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
 * Beyond the paper: every detailed point listed (every one when the list is empty) goes to the
 * closest point of the coarse surface (an exact search on a grid of the coarse triangles), with
 * the corners of the coarse triangle it lies on and its barycentric weights there. A detailed
 * point goes to a point near it rather than to a far vertex, so thin parts fold far less. The
 * points not listed, and any without a usable coarse triangle, stay where they are; listed ids
 * must be distinct (ids out of range are skipped).
 */
MorphPartners PairSurfacePoints(const TriangleMeshView& detailed, const TriangleMeshView& coarse,
  const std::vector<std::int32_t>& listed = {}, const ExecutionContext& context = {});

/**
 * A geomorph (Hoppe, "Progressive meshes"): every detailed point d goes to the coarse point
 * ancestor[d] it became in the simplification that made the coarse mesh, so that at t = 1 the
 * detailed triangles lie on the coarse ones. Ids out of range (-1: not known) leave the point
 * where it is.
 */
MorphPartners PairAncestors(
  const TriangleMeshView& detailed, const TriangleMeshView& coarse, const std::vector<std::int32_t>& ancestor);

/// The adjacent detailed points (sharing a triangle edge) that come closer than t times the
/// merge distance for some t in (0, 1], with the parameters where they do.
struct MergeSchedule
{
  /// The parameter range [0, 1] in this many equal slots.
  static constexpr int Slots = 64;
  std::vector<std::int32_t> Ends; // 2 per edge, the lower id first
  /// Per edge: its ends are closer than t · mergeDistance exactly for From < t < To (To is
  /// infinite where they stay so).
  std::vector<double> From, To;
  /// The edges by slot of From (SlotOffsets: Slots + 1 entries), in each slot by their ends, so
  /// that a frame reads only the slots up to its t, along the points.
  std::vector<std::int64_t> SlotOffsets = std::vector<std::int64_t>(Slots + 1, 0);

  std::int64_t NumberOfEdges() const { return static_cast<std::int64_t>(this->From.size()); }
  /// Whether the arrays agree in size (a frame reads nothing of a schedule where they do not).
  bool Consistent() const
  {
    return this->SlotOffsets.size() == Slots + 1 && this->SlotOffsets.back() == this->NumberOfEdges() &&
      this->Ends.size() == 2 * this->From.size() && this->To.size() == this->From.size();
  }
  /// The slot of parameter t in [0, 1].
  static int Slot(double t) { return std::min(Slots - 1, static_cast<int>(t * Slots)); }
};

/**
 * The merges of every frame, from the partners and the merge distance (mesh units): the
 * distance of two adjacent points at t, |(1 − t) (P_a − P_b) + t (Q_a − Q_b)|, falls below
 * t · mergeDistance on one interval of t (a quadratic's sign), computed here once so that a
 * frame only reads it. samePartnerOnly (a geomorph's rule): only points bound for one coarse
 * point join, so that at t = 1 the triangles left are those of the coarse mesh, whatever the
 * distance between its points; and a triangle that vanishes (two corners bound for one point)
 * but would turn over on its way, where its third corner crosses the line of the other two,
 * loses its edge at the moment it stands square to its first normal: those two corners join
 * then, and stay joined; any two adjacent points bound for one point join at t = 1 at the
 * latest, where they meet, whatever the merge distance.
 */
MergeSchedule ScheduleMerges(const TriangleMeshView& detailed, const MorphPartners& partners, double mergeDistance,
  const ExecutionContext& context = {}, bool samePartnerOnly = false);

/// One frame of the morph: the detailed points, in their order, on the detailed triangles.
struct MorphFrame
{
  /// Per detailed point, the lowest id among the points it merged with (its own where none):
  /// the triangles use these ids, so a point that merged into another is left unused, at the
  /// same place.
  std::vector<std::int32_t> Root;
  /// The merged sets of two points or more (CSR: GroupOffsets has one entry more than there are
  /// sets), members in ascending order, the root first.
  std::vector<std::int32_t> GroupOffsets = { 0 };
  std::vector<std::int32_t> GroupMembers;
  std::vector<std::int32_t> Triangles;      // 3 per output triangle
  std::vector<std::int32_t> TriangleSource; // per output triangle, its detailed triangle
  /// Per detailed point, how far it stands from its place in the detailed mesh.
  std::vector<double> Displacement;

  std::int64_t NumberOfTriangles() const { return static_cast<std::int64_t>(this->TriangleSource.size()); }
  std::int64_t NumberOfGroups() const { return static_cast<std::int64_t>(this->GroupOffsets.size()) - 1; }
};

/**
 * The paper's steps 3 and 4 at parameter t (clamped to [0, 1]), writing the detailed mesh's
 * number of points times 3 coordinates to points: each detailed point at (1 − t) P + t Target;
 * the scheduled pairs of adjacent points closer than t · mergeDistance join, every set at the
 * place of its member nearest to their mean (on the coarse surface at t = 1, where a mean on a
 * curved surface would not be), and triangles with two corners joined go. t = 0 gives the
 * detailed mesh exactly, points and triangles. Triangles of the detailed mesh with an id out of
 * range are left out; partners or a schedule of another mesh leave the points in place.
 * The result does not depend on the context's threads.
 */
void Morph(const TriangleMeshView& detailed, const MorphPartners& partners, const MergeSchedule& merges, double t,
  double* points, MorphFrame& frame, const ExecutionContext& context = {});

} // namespace meshsimp

#endif
