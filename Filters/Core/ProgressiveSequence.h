// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProgressiveSequence.h
 * @brief A progressive mesh's sequence of collapses and the queries every reader of it uses: the
 * level a target picks, each point's ancestor in a level, a level's corners, points and sources.
 *
 * The sequence (ProgressiveMesh, made by BuildProgressiveMesh in ProgressiveMesh.h): points
 * renumbered so that those removed last come first, so a level of k points is the prefix
 * [0, k); each removed point's Parent (a smaller index); triangles ordered by the point whose
 * collapse removes them (RemovedBy, those never removed first), so a level's triangles are a
 * prefix too. ExtractLevel maps each corner to its first ancestor below k. A count, a reduction
 * or an error bound picks the level (LevelFor).
 *
 * Progressive Mesh extracts its levels with them, the octree finishes a count with them, and a
 * filter that reads levels (their points, their correspondence with the input) needs no more.
 */
#ifndef MeshSimplification_ProgressiveSequence_h
#define MeshSimplification_ProgressiveSequence_h

#include "Simplification.h"

#include <cstdint>
#include <string>
#include <vector>

namespace meshsimp
{

/// The whole collapse sequence of a mesh: every level of detail at once.
struct ProgressiveMesh
{
  /// Per point, in collapse order (the last removed first): its input point, and the point it
  /// collapses into (a smaller index), -1 for the BasePoints points never removed.
  std::vector<std::int32_t> InputPoint;
  std::vector<std::int32_t> Parent;
  /// Per point, the largest collapse error (input units) up to and including its own collapse
  /// (0 for base points): it falls with the index, so a bound picks a level by bisection.
  std::vector<double> Error;
  /// 3 per triangle, point indices; those never removed first, then by RemovedBy ascending.
  std::vector<std::int32_t> Triangles;
  std::vector<std::int32_t> InputTriangle;
  /// Per triangle, the point whose collapse removes it, -1 when none does.
  std::vector<std::int32_t> RemovedBy;
  std::int64_t BasePoints = 0;
  /// The prepared input's counts (usable triangles and points, diagonal, locks).
  Outcome Report;
  /// What stops the sequence at its coarsest level, as a continuation of LevelFor's reason
  /// (": of the N points left, ..."); empty for a build stopped early or a sequence read back.
  std::string CoarsestReason;

  std::int64_t NumberOfPoints() const { return static_cast<std::int64_t>(this->Parent.size()); }
  std::int64_t NumberOfCollapses() const { return this->NumberOfPoints() - this->BasePoints; }
  /// The triangles of the level with the first points points.
  std::int64_t TrianglesAt(std::int64_t points) const;
  /// For the first points points, the fraction of the sequence done before each disappears
  /// (the first removed 0, the last (collapses - 1) / collapses, one never removed 1).
  std::vector<double> CollapseLevel(std::int64_t points) const;
  /// Empty when the arrays form a sequence as described above, else what is wrong.
  std::string Validate(std::int64_t inputPoints) const;
};

/// The level (its number of points) a target picks: the count nearest the target's count, or
/// the most collapses whose error stays within its bound (bound in input units). outcome gets
/// the stop reason when the target lies beyond the coarsest level.
std::int64_t LevelFor(const ProgressiveMesh& sequence, const Target& goal, Outcome& outcome);

/// For the level with the first points points: each removed point's first ancestor below
/// points (entry p - points for point p).
std::vector<std::int32_t> LevelAncestors(const ProgressiveMesh& sequence, std::int64_t points);

/// The corners of the level's TrianglesAt(points) triangles, each point mapped to its first
/// ancestor below points, 3 per triangle into corners (Index: the caller's index type, such as a
/// cell array's, so a level needs no second copy).
template <class Index>
void LevelCorners(const ProgressiveMesh& sequence, std::int64_t points, Index* corners)
{
  const std::vector<std::int32_t> ancestor = LevelAncestors(sequence, points);
  const std::int64_t k = sequence.NumberOfPoints() - static_cast<std::int64_t>(ancestor.size());
  const std::int64_t count = 3 * sequence.TrianglesAt(k);
  for (std::int64_t i = 0; i < count; ++i)
  {
    const std::int32_t p = sequence.Triangles[i];
    corners[i] = static_cast<Index>(p < k ? p : ancestor[p - k]);
  }
}

/// The level with the first points points, in input coordinates, each point its own source;
/// point array "CollapseLevel" and field values "LevelTriangles" and "LevelPoints".
void ExtractLevel(const ProgressiveMesh& sequence, std::int64_t points, const TriangleMeshView& input,
  SimplifiedMesh& level);

/// The level's sources in full: each of its points (weight 1), then the removed points whose
/// ancestor it is (weight 0), for what reads the correspondence (TwoSidedDeviation).
void ListLevelSources(const ProgressiveMesh& sequence, std::int64_t points, SimplifiedMesh& level);

/// Runs the target on the sequence: LevelFor, then ExtractLevel, with the sequence's Report.
void ExtractTarget(const ProgressiveMesh& sequence, const Target& goal, const TriangleMeshView& input,
  SimplifiedMesh& level);

} // namespace meshsimp

#endif
