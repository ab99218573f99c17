// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OctreeVertexClustering.h
 * @brief Adaptive octree vertex clustering with quadric-optimal representatives (Zhou et al., §2–3).
 *
 * Zhou, Zhang, Shi and Pan, "A new simplification algorithm for colored or textured polygonal
 * models". The bounding cube is refined as an octree (vertices are inserted in the spatial order
 * of the compact mesh, see MakeCompactMesh), and every leaf's vertices are clustered to one
 * representative. Unlike a uniform grid
 * (Rossignac–Borrel, vtkQuadricClustering):
 *  - a leaf is split where it is too large (MaximumCellSize), too full (MaximumVerticesPerCell),
 *    where clustering it would flip a triangle of its related set (§2.4), and where its error
 *    exceeds the bound ε (§2.5 step 3); with a triangle-count target, leaves are split in
 *    decreasing order of error until the count is met, a flipping leaf as if its error were
 *    10 % larger, and then a leaf at each triangle still turned over (past the count; see
 *    below);
 *  - vertices of a leaf that are not connected by edges inside it form separate clusters, so
 *    distinct parts of the surface are never merged (the distortion of Figure 1); beyond the
 *    paper, an edge between vertices that face away from each other (unit mean normals more
 *    than 140 degrees apart: the two sides of a thin wall, joined across its rim) joins
 *    nothing either, so a wall thinner than a cell keeps both its faces where the tear rules
 *    below do not reach (where walls meet in non-manifold edges), unless a vertex whose normal
 *    lies between them (a rounded rim's) joins both; so does a vertex whose normals nearly
 *    cancel (a folded fan): it faces no way, and none of its edges is cut;
 *  - the representative minimises the quadric of its related triangles' planes (eq. 2–3, 5–7)
 *    plus boundary planes perpendicular to boundary edges; when that system is near singular,
 *    or its solution lies outside the cluster's cell (within the input's bounding box), it
 *    falls back to the best of the cluster's vertices, its weighted centre and the solution
 *    clamped into the cell, so that no point leaves its cell or the input's box;
 *  - the second error term e2 (squared distances of the cluster's vertices to the new triangles
 *    around the representative, eq. 8–11) is added by the paper's fixed-point iteration.
 *
 * Beyond the paper, four rules keep thin parts: a cluster none of whose triangles survives
 * (a leg folded onto its neighbours) is charged the distance of its vertices to the nearest
 * neighbouring representative, so its leaf is split first; a folded cluster (its normals
 * spread, |area-weighted mean unit normal| < 1/2) that sticks out of the surface collapses to
 * its tip, not to a point inside it; a split log lets late, cheap splits be undone to make
 * room for a leaf of far larger error when a count target is tight; and, with a count target,
 * a cluster that still loses every triangle while it touches a single surviving cluster (the
 * cap of a trunk or a finger) joins that cluster, whose point then represents both: the
 * point of the joined set (its tip when it protrudes) or the cluster's own, whichever has the
 * smaller cluster error over the set.
 *
 * Where the input is a surface, clustering makes no open or non-manifold edge that it did not
 * have: a cluster left with one triangle (a flap) joins a neighbour, and a cluster at an edge
 * that tears is split into pieces (parts of its cell) that merge under the link condition, as
 * a last resort into single points. Mending and the splits at turned triangles only add
 * triangles; where they take the count over a count target (steep terrain, thin parts: a
 * coarser tree would tear more), the clustered
 * mesh is finished by quadric half-edge collapses under the link condition (ProgressiveMesh's
 * core; the multiphase scheme of Garland and Shaffer): a collapsed point's clusters join the
 * point it collapses into, so the output is still a clustering of the input, without tears and
 * within the count's tolerance. Not with cell limits (a joined point would cross them), and a
 * locked point is joined by nothing.
 *
 * What ε bounds: the cluster error of a representative v0 is the largest distance from v0 to
 * the supporting plane of any triangle of its cluster's related set (every input triangle with
 * a vertex in the cluster) and to the boundary planes of its boundary edges; for a folded
 * cluster it is also the largest distance of its vertices to v0 (to the segment from where it
 * meets its neighbours to v0 when it collapsed to its tip). With an error bound, leaves are
 * refined until every cluster error, and the error of every cluster that would vanish, is at
 * most ε, unless a leaf holds a single vertex (error 0) or coincident points.
 */
#ifndef MeshSimplification_OctreeVertexClustering_h
#define MeshSimplification_OctreeVertexClustering_h

#include "OctreeClusteringParameters.h"
#include "Simplification.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

/// The clustering's settings: its own (OctreeClusteringParameters) and the common ones (the
/// target, locks, open borders and regions: SimplificationOptions). A count is met within the
/// target's Tolerance (3 % by default here) unless clustering has no count nearer it (the
/// Outcome says so).
struct OctreeClusteringOptions : SimplificationOptions, OctreeClusteringParameters
{
  OctreeClusteringOptions() { this->Goal.Tolerance = 0.03; }
};

/**
 * The clustering's output (SimplifiedMesh): each output point's sources are its cluster's
 * input points with area weights, the heaviest first; point arrays "ClusterSize" (points
 * merged) and "ClusterError" (the bounded cluster error above, input units); Report's
 * MaximumError is the largest cluster error. Locked points are clusters of their own at their
 * input coordinates, bit for bit, and no cluster joins them.
 */
struct OctreeClusteringResult : SimplifiedMesh
{
  /// Input vertex → output point, −1 for vertices whose cluster has no surviving triangle and
  /// joined none (see above).
  std::vector<std::int32_t> VertexToPoint;
  /// Per output point, the box it lies in (6 values: lower corner, upper corner, input units):
  /// its cluster's octree cell within the input's bounding box (with joined caps, the box
  /// around their cells too).
  std::vector<double> PointCells;
  std::int64_t NumberOfLeaves = 0;
  int Depth = 0;
};

/// Runs the clustering. Invalid triangles (bad index, repeated index, non-finite corner) are
/// skipped. Under an error bound that would leave no triangle (every cluster merged), the
/// coarsest mesh the clustering makes (its nearest count to one triangle) is given instead, with
/// a note. Returns false only when
/// aborted.
bool OctreeVertexClustering(const TriangleMeshView& mesh, const OctreeClusteringOptions& options,
  OctreeClusteringResult& result, const ExecutionContext& context = {});

} // namespace meshsimp

#endif
