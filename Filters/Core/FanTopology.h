// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file FanTopology.h
 * @brief What kind of vertex a vertex is, from the triangles around it: one closed fan, one open
 * fan, inside a hinge, or anything else; and where a half-edge collapse may take it, by the
 * classes of its two ends (HalfEdgeRules). The collapse engine and Progressive Mesh classify
 * their vertices with it, and the octree tests its clusters' surfaces.
 */
#ifndef MeshSimplification_FanTopology_h
#define MeshSimplification_FanTopology_h

#include "TriangleMesh.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace meshsimp
{

enum class VertexClass : std::uint8_t
{
  Interior,   // a closed fan of triangles
  Boundary,   // an open fan: two boundary edges
  Corner,     // a boundary vertex where the boundary turns sharply (see CollapseMesh::Build)
  Hinge,      // inside a hinge: a chain of edges of k >= 3 triangles each (see IsHinge)
  NonManifold // anything else: several fans, a hinge's end or turn, inconsistent orientation
};

/// What a half-edge collapse may do by the classes of its two vertices: never; only along an
/// edge of the removed vertex's own kind (Boundary: an open border edge, of one triangle; Hinge:
/// a hinge edge, of three or more), so that a border or hinge only loses vertices, like a
/// polyline; or freely, the collapse engine's other checks deciding.
enum class CollapseRule : std::uint8_t
{
  Never,
  AlongEdge,
  Free
};

/**
 * The rule of a half-edge collapse that removes a vertex of the row's class into a neighbour of
 * the column's (after meshoptimizer's kCanCollapse): an interior vertex goes anywhere; a border
 * vertex along the border (never into the interior, which would pull the border in); a hinge
 * vertex along the hinge; a corner or a non-manifold vertex nowhere. A locked vertex is removed
 * by no rule, whatever its class. A filter's own rules come on top (features, regions).
 */
constexpr CollapseRule HalfEdgeRules[5][5] = {
  // kept: Interior         Boundary               Corner                 Hinge                  NonManifold
  { CollapseRule::Free, CollapseRule::Free, CollapseRule::Free, CollapseRule::Free, CollapseRule::Free },       // Interior
  { CollapseRule::Never, CollapseRule::AlongEdge, CollapseRule::AlongEdge, CollapseRule::AlongEdge,
    CollapseRule::AlongEdge },                                                                                    // Boundary
  { CollapseRule::Never, CollapseRule::Never, CollapseRule::Never, CollapseRule::Never, CollapseRule::Never },   // Corner
  { CollapseRule::Never, CollapseRule::Never, CollapseRule::Never, CollapseRule::AlongEdge,
    CollapseRule::AlongEdge },                                                                                    // Hinge
  { CollapseRule::Never, CollapseRule::Never, CollapseRule::Never, CollapseRule::Never, CollapseRule::Never },   // NonManifold
};

/// HalfEdgeRules for a collapse of removed into kept.
constexpr CollapseRule HalfEdgeRule(VertexClass removed, VertexClass kept)
{
  return HalfEdgeRules[static_cast<int>(removed)][static_cast<int>(kept)];
}

/// Whether an edge of that many triangles is one a vertex of the class may collapse along
/// (CollapseRule::AlongEdge): one for a Boundary vertex, three or more for a Hinge vertex.
constexpr bool IsOwnEdge(VertexClass removed, int triangles)
{
  return removed == VertexClass::Boundary ? triangles == 1 : removed == VertexClass::Hinge && triangles >= 3;
}

/// ClassifyFan's working memory: reuse one per thread, it keeps its allocations.
struct FanWorkspace
{
  FanLookup ByPrevious;
  std::vector<std::int32_t> Successor;
  std::vector<std::uint8_t> Reached;
  std::vector<std::pair<std::int32_t, std::int32_t>> Ends; // IsHinge: (far vertex, corner)
};

/**
 * The class of a vertex from its corners {triangle, next, previous}: one closed fan (Interior),
 * one open fan (Boundary, with fanFirst and fanLast its first and last corner) or anything else
 * (NonManifold); never Corner, which CollapseMesh::Build decides from the boundary's turn. A
 * corner's successor is the corner whose previous vertex is its next one.
 */
VertexClass ClassifyFan(
  const Corner* first, const Corner* last, std::int32_t& fanFirst, std::int32_t& fanLast, FanWorkspace& work);

/**
 * Whether a vertex whose fan is not one (ClassifyFan: NonManifold) lies inside a hinge, where k
 * >= 3 sheets meet along a chain of edges like the pages of a book at its spine (the walls and
 * slabs of a building model): it has exactly two edges of more than two triangles, to ends[0]
 * and ends[1], with k triangles each, and its triangles are k fans, each from one of those edges
 * to the other (its link is k paths from ends[0] to ends[1]). No edge of one triangle is allowed.
 */
bool IsHinge(const Corner* first, const Corner* last, std::int32_t ends[2], FanWorkspace& work);

} // namespace meshsimp

#endif
