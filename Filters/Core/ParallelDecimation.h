// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParallelDecimation.h
 * @brief Schroeder-style vertex decimation by half-edge collapse in rounds of super-independent
 * vertex sets (Franc, "Methods for Polygonal Mesh Simplification", ch. 5–6), on the shared
 * collapse engine.
 *
 * - Classification (§5.2): a vertex is simple (a closed fan, no sharp edge), boundary (an open
 *   fan), interior-edge (exactly two sharp edges), corner (one or three and more sharp edges, or a
 *   sharp turn of the boundary) or complex (non-manifold). An edge is sharp when the normals of its
 *   two triangles differ by more than FeatureAngle. Corners, complex and locked vertices stay.
 * - Importance (§5.2): for a simple vertex the distance to the average plane of its triangles
 *   (eq. 5.1–5.3: area-weighted normal and centre); for boundary and interior-edge vertices the
 *   distance to the line through the two neighbours along the boundary or the sharp edges
 *   (eq. 5.4).
 * - Ordering (§5.6): vertices go into buckets by y = C x / (x + k) of their importance relative to
 *   the largest one (eq. 5.6), with k and C from the parameters a and α (eq. 5.13: a fraction a of
 *   the importance range fills a share α of the buckets), in O(N) by counting; within a bucket,
 *   by vertex id.
 * - Rounds (§5.5): in bucket order, a vertex joins the round's set when no vertex within one edge
 *   of it is within one edge of a vertex already taken, so the triangles around two taken vertices
 *   never share an edge (Fig. 5-6) and no two removals touch the same data. Hubs (vertices of 32
 *   triangles or more, the centres of fans) are the exception: the stars of a round's vertices
 *   may share them (still no edge), and a hub never survives a collapse, so that a round takes
 *   many vertices around one instead of a single one; the engine updates the hubs' triangle
 *   lists after the concurrent removals. Every taken vertex is
 *   then removed concurrently, without locks, by collapsing one of its half-edges into a
 *   neighbour: the legal one of least area change among those that turn no triangle by more than
 *   MaximumNormalDeviation (§5.3), or the shortest legal one (§5.5 step 6). Boundary and
 *   interior-edge vertices collapse only along their boundary or sharp edges. The engine's checks
 *   apply (link condition, plane-side fold-over test, no degenerate triangle). The touched
 *   vertices are re-evaluated, and rounds repeat until the target. Under the Quadric measure a
 *   simple vertex whose least-error neighbour is still there and absorbed nothing in the round
 *   is only updated: its old least error still bounds its old neighbours' (their errors can only
 *   grow), so the survivor, its one new neighbour, is the only option to price. Survivors so
 *   updated are evaluated in full at the end, for the output's importance and type.
 * - Each round considers only the least important RoundFraction of the candidates, so that the
 *   order stays close to a global one; the result does not depend on the number of threads.
 * - When no vertex is removable before the target (every one is a corner, or none of its
 *   half-edges keeps the normals within the deviation), FeatureAngle and MaximumNormalDeviation
 *   are raised by 15° and the vertices re-evaluated. Where even 180° misses the target (beyond
 *   its tolerance), raising them removed features and reached nothing, so the decimation is
 *   made again without raising them (RoundObserver sees both runs); its result comes with a
 *   note that says so, and Relaxations 0.
 * - Survivors keep their point data. Under the Quadric measure they then move, by default
 *   (MoveSurvivors), to the point of least error of their accumulated quadric (the planes of
 *   every input triangle merged into them), at most half their shortest edge away, and only
 *   where no triangle around them turns by more than 60°: a final placement pass in the spirit
 *   of Garland–Heckbert's optimal placement, beyond the paper, which keeps points where they are.
 *   Without it every output point is an input point, bit for bit.
 * - Beyond the paper (MaximumError): a half-edge (or a survivor's move) that would leave the
 *   survivor farther than the bound from a plane of the input triangles it stands for
 *   (PlaneDistanceBound) is not taken; the vertex tries its next one.
 */
#ifndef MeshSimplification_ParallelDecimation_h
#define MeshSimplification_ParallelDecimation_h

#include "ParallelDecimationParameters.h"
#include "Simplification.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace meshsimp
{

class CollapseMesh;

enum class DecimationVertexType : std::uint8_t
{
  Simple,
  Boundary,
  InteriorEdge,
  Corner,
  Complex
};

/// The decimation's settings: its own (ParallelDecimationParameters) and the common ones (the
/// target, locks, open borders and regions: SimplificationOptions). A count is met within the
/// target's Tolerance (2 % by default).
struct ParallelDecimationOptions : SimplificationOptions, ParallelDecimationParameters
{
  ParallelDecimationOptions() { this->Goal.Tolerance = 0.02; }
  /// Called with the mesh and the vertices taken for each round before they are removed (for
  /// tests and diagnostics; the rounds of both runs where the decimation is made again without
  /// raising the angles); may be empty.
  std::function<void(const CollapseMesh&, const std::vector<std::int32_t>&)> RoundObserver;
};

/**
 * The decimation's output (SimplifiedMesh): each output point's source is its own input point
 * (survivors keep their data); point arrays "Importance" (the final importance, -1 where the
 * point can never be removed), "VertexType" (DecimationVertexType) and, under an error bound,
 * "PlaneDistance" (the point's distance to its planes, input units; Report's MaximumError is the
 * largest); field values "Rounds" and "MovedPoints".
 */
struct ParallelDecimationResult : SimplifiedMesh
{
  std::int64_t Rounds = 0;
  /// Times FeatureAngle and MaximumNormalDeviation were raised by 15° because no vertex was
  /// removable under them before the target (0 where raising them missed it and the decimation
  /// was made again without).
  std::int64_t Relaxations = 0;
  std::int64_t MovedPoints = 0; // survivors MoveSurvivors moved
};

/// Runs the decimation; the context's ParallelFor carries the threads. Returns false when
/// aborted through the context's progress.
bool ParallelDecimation(const TriangleMeshView& input, const ParallelDecimationOptions& options,
  ParallelDecimationResult& result, const ExecutionContext& context = {});

/// The bucketing function of eq. (5.6) with k and C from eq. (5.13): maps x in [0, 1] (importance
/// over the largest importance) onto [0, 1], a onto α. Increasing, so buckets keep the order.
double BucketPosition(double x, double a, double alpha);

/// §5.6's O(N) ordering: the vertices sorted by the bucket of BucketPosition(importance /
/// largest), one bucket per vertex on average, in their given order within a bucket; only the
/// buckets holding the first `limit` vertices are written out. work is working memory; the
/// context's threads find the buckets.
void BucketOrder(const double* importance, const std::vector<std::int32_t>& vertices, double largest,
  double a, double alpha, std::vector<std::int32_t>& order, std::vector<std::int32_t>& work,
  std::size_t limit = static_cast<std::size_t>(-1), const ExecutionContext& context = {});

} // namespace meshsimp

#endif
