// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VolumeTriangleCollapse.h
 * @brief Triangle-collapse simplification ordered by the squared volume error of Zhou, Zhang
 * and Cheng, "Mesh simplification by volume variation with feature preserving".
 *
 * Each step collapses the triangle of least constriction error into one vertex, removing it and
 * its (up to three) edge neighbours, on the shared collapse engine (CollapseMesh) and its checks.
 *
 * - Per triangle i (eq. 3–4): Q_i = 1/9 · W_i · N_i · φ_i · S_i² · p pᵀ, with p its plane, S_i its
 *   area, the shape factor W_i = 2 (1 − cos min α) · S_i (§3.2), the normal constraint factor
 *   N_i = mean over its adjacent triangles j of (1 − |n_i · n_j|) / 2 (§3.2) plus 0.01 (N is 0 on
 *   a flat region, whose planes would then not hold a placed vertex on them), and the constraint
 *   weight φ_i of §3.1. The paper leaves φ loosely defined ("the original square volume
 *   variation"); here φ_i = 1 + E_i / S_i³, E_i being the mean squared-volume error already
 *   accumulated at the triangle's corners, so regions that have absorbed much volume change
 *   become dearer and the error spreads evenly. All three factors can be switched off.
 * - The constriction matrix of a triangle sums Q_i over it and its adjacent triangles (every
 *   triangle sharing a vertex, Definition 2); its cost is eq. (5), v̄ᵀ Q̄ v̄ at the new vertex.
 * - Placement (§3.4): the minimiser of eq. (5) when Q̄ is well conditioned (judged by pivot and
 *   eigenvalue ratios, not det ≠ 0), else the blend of eq. (8) with weights ∝ the vertices'
 *   adjacent areas, moved along the directions Q̄ does determine (onto a crease, onto a plane).
 *   A minimiser farther than two edge lengths from the triangle falls back to the blend; a
 *   placement that would fold the mesh to the cheapest corner that does not.
 * - Gauss curvature (eq. 6–7): K_t = Σ |angle deficit| / Σ adjacent areas over the triangle's
 *   corners. A triangle whose K_t, measured in units of the current mean triangle area (so the
 *   threshold does not depend on the mesh's scale or resolution), exceeds FeatureCurvature is a
 *   strong feature and collapses onto its corner of largest |K_v|. Off by default (0): the sliver
 *   fans of CAD and building models score as spikes, so the rule costs more distance than it
 *   keeps (vtkVolumeTriangleCollapse.h; VolumeTriangleCollapse.md gives the figures).
 * - Boundaries (§3.5): a triangle with one boundary corner collapses onto it; one with two onto
 *   the point ω v_i + (1 − ω) v_j of least error on that pair; one with three is kept. Boundary
 *   corners (a sharp turn of the boundary) never move. PreserveBoundary locks every boundary
 *   vertex; LockedPoints locks the caller's choice. The cut between the pieces of a distributed
 *   mesh (points locked as shared with another piece) is no border of the surface: a triangle
 *   with one corner on it collapses its other edge instead, as a free edge is placed.
 * - The count: collapses stop at the target; one that would remove too many triangles (more than
 *   1 %, or one triangle, below the target) is replaced by the collapse of one of the
 *   triangle's edges. When no triangle's plan is legal before the target (on small meshes of
 *   higher genus the link condition refuses every one), half-edge collapses of any edge go on,
 *   cheapest first by the quadric sums of their ends (with EdgeCollapses).
 * - Zero-cost triangles whose cost is set again queue behind the waiting zero-cost ones (§3.5,
 *   Fig. 7): the heap's tie rule (CollapseHeap).
 * - After a collapse the new vertex's triangles get their geometry, quadrics and costs at once,
 *   their corners their angle sums and quadric sums. Triangles further out, whose constriction
 *   matrices hold some of the changed quadrics, are re-evaluated when they reach the top of the
 *   heap and requeued if their cost has grown past the next one; their own normal factors are
 *   refreshed when a collapse next changes them.
 * - Beyond the paper (BatchSize, default 64; at most one collapse per 1000 input triangles):
 *   the cheapest queued triangles whose neighbourhoods (every vertex of the triangles around
 *   their corners) are disjoint are popped together and evaluated and checked on the context's
 *   threads; then collapsed in key order under the heap's rule (one whose cost grew past the
 *   next key is queued again); then the updates around the new vertices run on the threads, each
 *   writing its own neighbourhood's data only. Triangles passed over for their neighbourhoods
 *   wait for the next batch; near the target a batch is one collapse. The result depends on
 *   BatchSize, never on the thread count; 1 is the strict heap order. Batches let a second
 *   thread shorten the run on large meshes without moving the output farther from the input;
 *   on one thread they cost a little time (VolumeTriangleCollapse.md gives the figures).
 * - Constriction matrices are assembled from per-vertex sums of Q_i (a triangle across an edge
 *   is in two of the three sums, the triangle itself in all three).
 * - Beyond the paper (EdgeCollapses, default on): each triangle also prices its three edges,
 *   an edge's quadric summing the Q_i around its two ends (t and the triangle across it, which
 *   hold both, once) and its point minimising it as above. When the cheapest edge's error is
 *   under a quarter of the triangle's, the triangle's plan is that edge collapse instead. A
 *   triangle collapse always cuts into a curved surface, an edge along a cylinder's ruling line
 *   or a gently curved direction hardly does, so edge collapses lower the mean distance to the
 *   input (VolumeTriangleCollapse.md gives the figures). The heap key is the error per
 *   nominally removed triangle (four for a triangle, two for an edge). An edge-boundary
 *   triangle likewise prices its boundary edge alone, at its point of least error on the
 *   segment: without that a disk fanned around one vertex (a triangulated polygon) cannot be
 *   simplified at all, since every triangle is edge-boundary and §3.5's collapse leaves a rim
 *   vertex with two neighbours.
 * - Beyond the paper (SurfaceErrorWeight, default 3000; 0 gives the paper's order): the heap
 *   key adds the new point's squared distances to the planes of the input triangles merged
 *   into the collapsing vertices (Garland–Heckbert quadrics, area-weighted, summed through the
 *   collapses) and to the planes through their open-border edges perpendicular to the border
 *   triangles (edge² weights: moving a rim within the surface's plane sweeps no volume), times
 *   the weight and the squared mean input triangle area (so the term has the volume error's
 *   units, length⁸). Placement is unchanged. By volume alone a few collapses on
 *   gently curved surfaces, where the normal factor makes volume cheap, move the surface far
 *   from the input; the term keeps the Hausdorff distance down (VolumeTriangleCollapse.md).
 * - The engine's angle guard (MinimumAngle, default 10°) is a price, not a wall: a collapse it
 *   alone refuses waits in the heap at its priority times (MinimumAngle / a)², a its smallest
 *   new angle, and is made when every collapse that makes no sliver costs more. As a wall it
 *   made the order skip the right collapses on steep terrain, where thin triangles are the
 *   shape, and left the output far from the input there (VolumeTriangleCollapse.md). A flat
 *   collapse — its error under 10⁻⁷ · Σ weights · (longest edge)², the point within about
 *   3·10⁻⁴ edge lengths of its planes — that fails only the guard, and for which no corner
 *   placement passes, is still made: on a plane or a straight crease it loses nothing,
 *   and CAD meshes need thin triangles along their creases. When the guard refuses every
 *   collapse left before the target, it is lowered a step (halved; 0 below 2°) and every
 *   triangle requeued, so the filter stops early only when no collapse keeps the mesh valid.
 * - Beyond the paper (MaximumError): a collapse whose point would lie farther than the bound
 *   from a plane of the input triangles merged into it (PlaneDistanceBound) is not made; the
 *   order stays the one above.
 */
#ifndef MeshSimplification_VolumeTriangleCollapse_h
#define MeshSimplification_VolumeTriangleCollapse_h

#include "Simplification.h"
#include "VolumeCollapseParameters.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

/// The volume collapse's settings: its own (VolumeCollapseParameters) and the common ones
/// (the target, locks, open borders and regions: SimplificationOptions). A count is met within
/// the target's Tolerance (1 % by default, or one triangle).
struct VolumeCollapseOptions : SimplificationOptions, VolumeCollapseParameters
{
};

/**
 * The collapse's output (SimplifiedMesh): each output point's sources are the input points
 * merged into it, with the weights of the placements along the way (the surviving point
 * first); point arrays "SquareVolumeError" (the squared-volume error accumulated at the point,
 * input units) and, under an error bound, "PlaneDistance" (the point's distance to its planes,
 * input units; Report's MaximumError is the largest).
 */
struct VolumeCollapseResult : SimplifiedMesh
{
  double SquareVolumeError = 0.0; // Σ eq. (5) over the collapses (the paper's ΔV), input units
  /// The smallest angle the guard let through: a priced collapse's smallest new angle (see
  /// MinimumAngle), or the guard itself where it refused every collapse left before the target
  /// and was lowered (halved, 0 below 2°) to go on.
  double FinalMinimumAngle = 0.0;
};

/// Runs the simplification. Returns false when aborted through the context's progress.
bool VolumeTriangleCollapse(const TriangleMeshView& input, const VolumeCollapseOptions& options,
  VolumeCollapseResult& result, const ExecutionContext& context = {});

} // namespace meshsimp

#endif
