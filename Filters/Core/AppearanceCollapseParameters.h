// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file AppearanceCollapseParameters.h
 * @brief The appearance-preserving collapse's own settings, with their defaults, in one place.
 *
 * Plain data with no dependency, so that the VTK filter can hold them (it derives from this
 * struct, as TTK's filters derive from their base classes) and nothing repeats the defaults.
 */
#ifndef meshsimp_AppearanceCollapseParameters_h
#define meshsimp_AppearanceCollapseParameters_h

#include "ParameterTable.h"

#include <cstdint>

namespace meshsimp
{

/// The order of the collapses and the choice of each one's edge.
enum class AppearanceOrder : std::uint8_t
{
  NormalSpread, // the chapter: least important vertex first (eq. 7.6), the edge of least area change
  Quadric       // beyond it: the contraction of least quadric error, point data included (Hoppe)
};

/// The three parameters of Franc's "Similarity of Appearance" (ch. 7 of "Methods for Polygonal
/// Mesh Simplification"), its vertex memory, and the order with the weight of the point data.
struct AppearanceCollapseParameters
{
  /// NormalSpread: the chapter's order (its importance) and edge choice (least area change), by
  /// the geometry alone. Quadric (default): the contraction of least error first, the error
  /// being the squared distances of its point to the planes of the input triangles merged into
  /// its ends and its point data's deviation from their linear fields over those triangles
  /// (Hoppe, "New quadric metric for simplifying meshes with appearance attributes"); the
  /// chapter's placement, extreme vertices and memory in both.
  AppearanceOrder Order = AppearanceOrder::Quadric;
  /// NormalSpread order: a vertex is extreme (a feature kept where it is) when the normals of its
  /// triangles spread as those of a crease of this dihedral turn do: its importance, the inverse
  /// length of their apical-angle-weighted mean (eq. 7.6), is then at least
  /// 1 / cos(ExtremeAngle / 2). Degrees. The Quadric order has no extreme vertices: the planes
  /// merged into a feature's point keep it, and pinned where they are, the points of a rough
  /// surface (most of a fractal terrain's) would leave no placement to the quadric.
  double ExtremeAngle = 60.0;
  /// No triangle's normal may turn by more than this in a collapse (degrees): the chapter's
  /// second parameter, against folds and for a smooth result.
  double MaximumNormalDeviation = 45.0;
  /// NormalSpread order: an edge between two extreme vertices is a flat edge, never contracted,
  /// when its two triangles meet at more than this angle (degrees; 180 is flat); below it, a
  /// sharp edge, the only one an extreme vertex with an extreme neighbour may go along.
  double FlatEdgeAngle = 150.0;
  /// The chapter's vertex memory: a vertex whose neighbourhood a collapse changed waits for the
  /// next pass over the queue, which spreads the reduction over the surface (its Fig. 7-12).
  /// Off by default: in the Quadric order it breaks the order of least error, and the images
  /// are further from the input's (AppearancePreservingCollapse.md gives the figures).
  bool VertexMemory = false;
  /// Boundary corners (the border turns by more than this, degrees) are never removed.
  double BoundaryCornerAngle = 60.0;
  /// Quadric order: the weight of the point data (colours, texture coordinates, normals, each
  /// component scaled to [0, 1]) against the geometry, in bounding-box diagonals: a component's
  /// deviation of 1 from its field counts as a distance of this many diagonals from the planes.
  double AttributeWeight = 0.1;
  /// Quadric order: each kind of point data's factor on AttributeWeight (0 leaves it out): the
  /// active point normals, the unsigned-char colours (3 or 4 components), the active texture
  /// coordinates, and the active scalars with the Attribute Coordinates array (active scalars
  /// that are unsigned-char colours count as colours). meshoptimizer's advice, for instance, is
  /// half the colours' weight for normals.
  double NormalWeight = 1.0;
  double ColorWeight = 1.0;
  double TextureCoordinateWeight = 1.0;
  double ScalarWeight = 1.0;

  /// The settings above by name (see ParameterTable.h): visit(name, member, minimum, maximum, help).
  template <class Self, class Visit>
  static void ForEach(Self& self, Visit&& visit)
  {
    visit("Order", self.Order, 0.0, 1.0,
      "0: the chapter's order and edge choice (least important vertex, least area change), geometry alone; "
      "1 (default): the contraction of least quadric error, point data included.");
    visit("ExtremeAngle", self.ExtremeAngle, 0.0, 180.0,
      "Normal Spread order, degrees: a vertex whose triangles' normals spread as a crease of this angle is extreme, a feature "
      "kept where it is.");
    visit("MaximumNormalDeviation", self.MaximumNormalDeviation, 0.0, 180.0,
      "Degrees: no triangle's normal turns by more than this in a collapse.");
    visit("FlatEdgeAngle", self.FlatEdgeAngle, 0.0, 180.0,
      "Normal Spread order, degrees: an edge between two extreme vertices whose triangles meet at more than this is flat and "
      "never contracted; below it, a sharp edge, along which extreme vertices go.");
    visit("VertexMemory", self.VertexMemory, 0.0, 1.0,
      "A vertex whose neighbourhood a collapse changed waits for the next pass, so that the reduction "
      "spreads over the surface (off by default).");
    visit("BoundaryCornerAngle", self.BoundaryCornerAngle, 0.0, 180.0,
      "Degrees: where an open border turns by more than this, its point is kept.");
    visit("AttributeWeight", self.AttributeWeight, 0.0, 1e6,
      "Quadric order: the weight of the point data (colours, texture coordinates, normals, scaled to [0, 1]) "
      "against the geometry, in bounding-box diagonals per unit of deviation.");
    visit("NormalWeight", self.NormalWeight, 0.0, 1e3,
      "Quadric order: the point normals' factor on AttributeWeight (0: left out).");
    visit("ColorWeight", self.ColorWeight, 0.0, 1e3,
      "Quadric order: the unsigned-char colours' factor on AttributeWeight (0: left out).");
    visit("TextureCoordinateWeight", self.TextureCoordinateWeight, 0.0, 1e3,
      "Quadric order: the texture coordinates' factor on AttributeWeight (0: left out).");
    visit("ScalarWeight", self.ScalarWeight, 0.0, 1e3,
      "Quadric order: the factor on AttributeWeight of the active scalars and the Attribute Coordinates array "
      "(0: left out).");
  }
};

} // namespace meshsimp

#endif
