// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProgressiveMesh.h
 * @brief Real-time progressive meshes (Wu and Fei): one build of the whole sequence of half-edge
 * collapses, then any level of detail as a prefix of it, without replaying a collapse.
 *
 * The build (BuildProgressiveMesh):
 * - The cost of the half-edge collapse x -> y (x removed, its triangles moved onto y) is a
 *   weighted sum (ProgressiveMeshParameters) of the L1 length |x - y|_1 and the curvature
 *   1 - N_ABC . N_ABD of the edge's two triangles (§4), the L1 distance of extra coordinates such
 *   as colours (§7) and, beyond the paper, the quadric error of y for the planes merged into x
 *   (by default the quadric error alone, chosen by the numbers: see ProgressiveMeshParameters).
 *   Each vertex's cost is that of its cheapest edge (Step 2); one heap of vertices (Step 3);
 *   after a collapse y is re-costed at once and its ring when it reaches the top (Step 5,
 *   lazily: a key that rose goes back under its true cost).
 * - Legality is a vertex-kind table plus an ordered list of checks that says which failed
 *   (Refusal): interior, border and fixed vertices (locked, non-manifold, pinched); a border
 *   vertex moves only along its border and never into the interior (§7); regions are never
 *   merged; the link condition; no vertex loses its last triangle (nor a closed fan falls below
 *   three); no remaining triangle turns over or degenerates. The checks run when a vertex reaches
 *   the top of the heap, on its candidates in cost order; the first legal one is collapsed.
 * - It runs down to the coarsest mesh the checks allow. Flat arrays, no allocation per collapse.
 *
 * The sequence (ProgressiveMesh): points renumbered so that those removed last come first, so a
 * level of k points is the prefix [0, k); each removed point's Parent (a smaller index);
 * triangles ordered by the point whose collapse removes them (RemovedBy, those never removed
 * first), so a level's triangles are a prefix too. ExtractLevel maps each corner to its first
 * ancestor below k. A count, a reduction or an error bound picks the level (LevelFor).
 */
#ifndef MeshSimplification_ProgressiveMesh_h
#define MeshSimplification_ProgressiveMesh_h

#include "ProgressiveMeshParameters.h"
#include "Simplification.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

struct ProgressiveMeshOptions : SimplificationOptions, ProgressiveMeshParameters
{
  /// Optional extra coordinates per input point (colours, texture coordinates: §7), Dimension
  /// values each; the cost adds AttributeWeight times their L1 distance divided by ExtraScale
  /// (the caller's scale that brings them to [0, 1]).
  const double* ExtraCoordinates = nullptr;
  int ExtraDimension = 0;
  double ExtraScale = 1.0;
  /// The build stops once at most this many triangles remain (0: at the coarsest mesh the
  /// checks allow), for callers that want one level and not the whole sequence.
  std::int64_t StopTriangles = 0;
};

/// Why a collapse was refused: the first check that failed, in the order they run.
enum class Refusal : std::uint8_t
{
  None,
  Kind,          // the kind table: a fixed vertex, or a border vertex into the interior
  Region,        // the two ends are in different regions
  AcrossBorder,  // a border vertex along an edge that is not a border edge
  Link,          // the link condition: the ends share a neighbour off the edge's triangles, or the
                 // edge's two triangles share all three points
  SharedEdges,   // a new edge between two points shared with another piece (under MPI)
  LastTriangles, // a point would keep no triangle (a closed fan, locked or not, fewer than three)
  Flip           // a remaining triangle would turn over or degenerate
};

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

/// Builds the sequence of the usable input; returns false when aborted.
bool BuildProgressiveMesh(const TriangleMeshView& input, const ProgressiveMeshOptions& options,
  ProgressiveMesh& sequence, const ExecutionContext& context = {});

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
