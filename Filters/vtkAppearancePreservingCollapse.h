// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAppearancePreservingCollapse
 * @brief   simplify a triangle mesh for how it looks: shading, colours and features kept
 *
 * vtkAppearancePreservingCollapse implements the "Similarity of Appearance" simplification of
 * Franc's dissertation "Methods for Polygonal Mesh Simplification" (ch. 7) on the collapse
 * engine (meshsimp::AppearancePreservingCollapse gives the rules in full):
 *
 * - Each vertex's importance is the inverse length of the mean of its triangles' unit normals,
 *   weighted by their angles at it: 1 on a flat fan, larger where the surface bends. A vertex
 *   goes by contracting one of its edges to a new point on a curve through the edge's ends that
 *   their normals shape (and a second across the edge's two triangles), nearer the more
 *   important end; no triangle may turn by more than MaximumNormalDeviation.
 * - Order NORMAL_SPREAD is the chapter's: the least important vertex first, along the edge that
 *   changes the area least. Order QUADRIC (default), beyond the chapter: the contraction of
 *   least error first, the error being the distance to the planes of the input triangles it
 *   stands for and the deviation of the point data the mesh is seen by from its linear fields
 *   over them (Hoppe's quadric, weighted by AttributeWeight): point normals, unsigned-char
 *   colours (3 or 4 components), texture coordinates, the active scalars and the array chosen
 *   as input array 2, each scaled to [0, 1]. Its point is the one of least error among the
 *   chapter's, the first curve's, the edge's ends and the planes' nearest point, and its point
 *   data the blend of the ends' of least error there; so colour and shading edges keep their
 *   points and lines.
 *   At the end each free interior point (not on a border or seam, not locked) moves along its
 *   normal to the least distance from the planes merged into it, so that the coarse triangles
 *   straddle a curved surface (not in MaximumError mode).
 * - In the Normal Spread order, extreme vertices (their normals spread as a crease of
 *   ExtremeAngle does) stay where they are; an edge between two of them is contracted only
 *   where it is sharp (FlatEdgeAngle), so creases lose points along their line. (In the Quadric
 *   order the planes merged into a feature's point keep it.)
 * - VertexMemory (default off): a vertex next to a collapse waits for the next pass, which keeps
 *   the triangles even over the surface.
 * - Seams (points at one position with different point data, which crack closing keeps apart)
 *   and open borders: border points go only along their border; a seam point and its twin go
 *   together, along the seam onto a neighbour and its twin, so no crack opens; where more than
 *   two points meet, they stay.
 *
 * The target, the constraints, the input and the output mapping are the common ones of
 * vtkMeshSimplificationFilter: every point array is carried (floating arrays blended as each
 * collapse's point data; the active normals blended and renormalised, not recomputed, so the
 * shading stays the input's, or, where the input has none, area-weighted ones added as the
 * active "Normals"), and the point array "Importance" holds each output point's
 * importance; the field data holds "Passes". Under MPI, the stage after the border round
 * weighs geometry alone. A
 * triangle count is met within 1 %. In MaximumError mode it removes, in the same order, as far
 * as every output point stays within the bound of the planes of the input triangles it stands
 * for (the point array "PlaneDistance", input units).
 *
 * @sa vtkQuadricDecimation vtkParallelDecimation vtkVolumeTriangleCollapse
 */
#ifndef vtkAppearancePreservingCollapse_h
#define vtkAppearancePreservingCollapse_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkMeshSimplificationFilter.h"

#include "AppearanceCollapseParameters.h" // the filter's own settings and defaults

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkAppearancePreservingCollapse
  : public vtkMeshSimplificationFilter
  , protected meshsimp::AppearanceCollapseParameters
{
public:
  static vtkAppearancePreservingCollapse* New();
  vtkTypeMacro(vtkAppearancePreservingCollapse, vtkMeshSimplificationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Orders
  {
    NORMAL_SPREAD = 0,
    QUADRIC = 1
  };

  ///@{
  /**
   * NORMAL_SPREAD: the chapter's order (least important vertex first) and edge choice (least area
   * change), by the geometry alone. QUADRIC (default): the contraction of least quadric error
   * first, point data included, placed at the least-error point among the chapter's curve points,
   * the edge's ends and the planes' point of least distance.
   */
  virtual void SetOrder(int order);
  virtual int GetOrder() const;
  ///@}

  ///@{
  /**
   * Normal Spread order, degrees (default 60): a vertex whose triangles' normals spread as those
   * of a crease of this angle is extreme, a feature kept where it is.
   */
  vtkSetClampMacro(ExtremeAngle, double, 0.0, 180.0);
  vtkGetMacro(ExtremeAngle, double);
  ///@}

  ///@{
  /**
   * Degrees (default 45): no triangle's normal turns by more than this in a collapse. Before a
   * count target, when no collapse is left, it is raised by 15 degrees at a time, with a warning.
   */
  vtkSetClampMacro(MaximumNormalDeviation, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * Normal Spread order, degrees (default 150): an edge between two extreme vertices whose
   * triangles meet at more than this is flat and never contracted; below it, a sharp edge, along
   * which extreme vertices go.
   */
  vtkSetClampMacro(FlatEdgeAngle, double, 0.0, 180.0);
  vtkGetMacro(FlatEdgeAngle, double);
  ///@}

  ///@{
  /**
   * A vertex whose neighbourhood a collapse changed waits for the next pass (default off).
   */
  vtkSetMacro(VertexMemory, bool);
  vtkGetMacro(VertexMemory, bool);
  vtkBooleanMacro(VertexMemory, bool);
  ///@}

  ///@{
  /**
   * Degrees (default 60): where an open border turns by more than this, its point is kept.
   */
  vtkSetClampMacro(BoundaryCornerAngle, double, 0.0, 180.0);
  vtkGetMacro(BoundaryCornerAngle, double);
  ///@}

  ///@{
  /**
   * QUADRIC order: the weight of the point data against the geometry, in bounding-box diagonals
   * per unit of deviation (each component scaled to [0, 1]); default 0.1, 0: geometry alone.
   */
  vtkSetClampMacro(AttributeWeight, double, 0.0, 1e6);
  vtkGetMacro(AttributeWeight, double);
  ///@}

  ///@{
  /**
   * QUADRIC order: each kind of point data's factor on AttributeWeight (default 1; 0 leaves the
   * kind out): the active point normals, the unsigned-char colours (3 or 4 components), the
   * active texture coordinates, and the active scalars with the Attribute Coordinates array.
   */
  vtkSetClampMacro(NormalWeight, double, 0.0, 1e3);
  vtkGetMacro(NormalWeight, double);
  vtkSetClampMacro(ColorWeight, double, 0.0, 1e3);
  vtkGetMacro(ColorWeight, double);
  vtkSetClampMacro(TextureCoordinateWeight, double, 0.0, 1e3);
  vtkGetMacro(TextureCoordinateWeight, double);
  vtkSetClampMacro(ScalarWeight, double, 0.0, 1e3);
  vtkGetMacro(ScalarWeight, double);
  ///@}

protected:
  vtkAppearancePreservingCollapse();
  ~vtkAppearancePreservingCollapse() override = default;
  void ForEachOwnSetting(const meshsimp::SettingVisit& visit) override;

  bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) override;

private:
  vtkAppearancePreservingCollapse(const vtkAppearancePreservingCollapse&) = delete;
  void operator=(const vtkAppearancePreservingCollapse&) = delete;
};

#endif
