// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file AppearancePreservingCollapse.h
 * @brief Simplification for how a mesh looks: Franc, "Methods for Polygonal Mesh
 * Simplification", ch. 7 "Similarity of Appearance", as a policy on the collapse engine's
 * vertex queue (VertexQueue.h).
 *
 * - Importance (eq. 7.6): the inverse length of the mean of a vertex's triangles' unit normals,
 *   each weighted by its apical angle at the vertex: 1 on a flat fan, larger the more the
 *   normals spread.
 * - A vertex goes by contracting one of its edges to a new point on the quadric curve of
 *   eq. 7.7–7.14 (CurvePoint) between the edge's ends, built from their unit normals, at the
 *   parameter given by their importance (t = I_2 / (I_1 + I_2): the new point leans towards the
 *   more important end); where the quad of the edge's two triangles is not arrow-shaped, a
 *   second curve across its far corners, at a parameter from their importance weighted by the
 *   inverse of their distance to the first point, and the new point midway between the two
 *   curve points (Fig. 7-9). No triangle may turn by more than MaximumNormalDeviation, and the
 *   engine's checks hold (link condition, folds, locks, regions). Before a count target, when no
 *   collapse is left, MaximumNormalDeviation is raised by 15 degrees at a time (up to 180), with
 *   a note, as Parallel Decimation raises its angles.
 * - Order NormalSpread is the chapter's: the least important vertex first, along the edge whose
 *   contraction changes the area least.
 * - Order Quadric (default), beyond the chapter, because the chapter alone stays far from the
 *   input: the contraction of least error first, each vertex keyed by its cheapest one. The
 *   error is that of Hoppe, "New quadric metric for simplifying meshes with appearance
 *   attributes": the area-weighted squared distances of the point to the planes of the input
 *   triangles merged into the edge's ends (and to planes along open borders), plus, for each
 *   component of the point data (AttributeCoordinates, scaled to [0, 1]), the squared deviation
 *   of the new value from the component's linear field over each of those triangles, times
 *   AttributeWeight² (a deviation of 1 then counts as that many diagonals). The point is the one
 *   of least error among the chapter's, the first curve's alone (the second, across the far
 *   corners, pulls a point on a colour border off it), the ends and the planes' nearest point
 *   within the edge's reach; the point data the blend of the ends' of least error there (as
 *   meshoptimizer's simplifyWithUpdate re-fits values, within the blends the output follows).
 *   At the end each free interior point (not on a border or seam, not locked) moves along its
 *   normal to the least distance from its merged planes, where no triangle turns by more than
 *   MaximumNormalDeviation (as set, not as relaxed) from where it was before any point settled
 *   and the point stays within the ball of its farthest neighbour: the triangles of a coarse curved
 *   surface cut under it while their points stay on it, and moved out the points share the
 *   distance on both sides (simplifyWithUpdate moves its points to their quadrics' minimum at
 *   the end; along the normal alone, a point on a colour border stays on it). Not under an
 *   error bound, which the collapses' points meet.
 * - In the NormalSpread order, extreme vertices (importance at least 1 / cos(ExtremeAngle / 2))
 *   stay where they are: an edge with one extreme end collapses onto it, one with two onto the
 *   more important; an extreme vertex with an extreme neighbour may go only along an edge to an
 *   extreme neighbour, and only a sharp one (its triangles meet at less than FlatEdgeAngle).
 *   The Quadric order has none: the planes merged into a feature's point keep it.
 * - VertexMemory: a vertex whose star a collapse changed waits for the next pass.
 * - Beyond the chapter: open borders. A border vertex goes only along its border, onto the
 *   neighbour (a half-edge collapse), and an interior vertex next to a border onto the border
 *   point; border corners (BoundaryCornerAngle) and locked points stay; a hinge vertex only
 *   along its hinge (the engine's rules). A seam, where two border points share a position but
 *   not their point data, is two borders that go together: a seam point goes only along the
 *   seam onto its neighbour, and its twin onto its neighbour's twin in the same step, or
 *   neither (VertexQueue's twin plans), so no crack opens; where more than two points meet,
 *   they stay.
 * - Beyond the chapter (MaximumError): a collapse whose point would lie farther than the bound
 *   from a plane of the input triangles merged into it (PlaneDistanceBound) is not made.
 * - The output's point normals are the sources' blended (CarriesNormals): the curve and quadric
 *   points stay on the surface the normals describe. Where the input has none, the front end
 *   gives the output area-weighted ones.
 */
#ifndef MeshSimplification_AppearancePreservingCollapse_h
#define MeshSimplification_AppearancePreservingCollapse_h

#include "AppearanceCollapseParameters.h"
#include "Simplification.h"

#include <Eigen/Core>

#include <cstdint>

namespace meshsimp
{

/// The collapse's settings: its own (AppearanceCollapseParameters), the common ones (the target,
/// locks, open borders and regions: SimplificationOptions) and the point data it weighs. A count
/// is met within the target's Tolerance (1 % by default, or one triangle).
struct AppearanceCollapseOptions : SimplificationOptions, AppearanceCollapseParameters
{
  /// Optional, AttributeDimension values per input point, each scaled by the caller to [0, 1]
  /// (a colour's channel over 255, a texture coordinate over its range, a normal's component
  /// halved and shifted): what AttributeWeight weighs.
  const double* AttributeCoordinates = nullptr;
  int AttributeDimension = 0;
};

/**
 * The output (SimplifiedMesh): each output point's sources are the input points contracted into
 * it with the weights of its point data's blends (the end nearer its point first); point array "Importance"
 * (each output point's importance, eq. 7.6, on the output mesh) and, under an error bound,
 * "PlaneDistance" (input units; Report's MaximumError is the largest); field value "Passes".
 */
struct AppearanceCollapseResult : SimplifiedMesh
{
  std::int64_t Passes = 0; // passes over the queue (VertexMemory), 1 without
};

/// Runs the simplification. Returns false when aborted through the context's progress.
bool AppearancePreservingCollapse(const TriangleMeshView& input, const AppearanceCollapseOptions& options,
  AppearanceCollapseResult& result, const ExecutionContext& context = {});

/**
 * Eq. 7.7–7.14 as printed: the point at parameter t of the quadric curve from p1 (t = 0) to p2
 * (t = 1) built from the Gram–Schmidt tangents of the unit normals n1 and n2 (the curve is not
 * tangent to them, and rises less than a circular arc over its chord: see
 * AppearancePreservingCollapse.md); the straight segment's point where the normals are (nearly)
 * parallel, or opposite.
 */
Eigen::Vector3d CurvePoint(const Eigen::Vector3d& p1, const Eigen::Vector3d& n1, const Eigen::Vector3d& p2,
  const Eigen::Vector3d& n2, double t);

} // namespace meshsimp

#endif
