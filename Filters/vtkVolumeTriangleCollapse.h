// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVolumeTriangleCollapse
 * @brief   simplify a triangle mesh by collapsing triangles in order of squared volume error
 *
 * vtkVolumeTriangleCollapse implements Zhou, Zhang and Cheng, "Mesh simplification by volume
 * variation with feature preserving". Each step collapses the triangle of least constriction
 * error into one new vertex, removing it and its (up to three) edge neighbours:
 *
 * - the error of a collapse is the weighted sum of the squared volumes of the tetrahedra between
 *   the new vertex and the triangle's neighbourhood (every triangle sharing one of its
 *   vertices), eq. (2)–(5); each triangle's term is weighted by a normal factor (how much it
 *   bends against its neighbours), optionally a shape factor (bad triangles go first) and a
 *   constraint weight that grows with the error already absorbed around it (UseNormalFactor,
 *   UseShapeFactor, UseVolumeWeights);
 * - the new vertex minimises that error where it is well determined, else it is the
 *   area-weighted blend of the three corners (eq. 8) — along a crease, the blend moved onto the
 *   crease;
 * - with FeatureCurvature (off by default, see there), a triangle of high Gauss curvature (a
 *   corner, a tip: eq. 6–7) collapses onto its corner of largest curvature instead;
 * - on open meshes a triangle with one boundary vertex collapses onto it, one with two onto the
 *   best point of the segment between them; sharp boundary corners never move, and
 *   PreserveBoundary keeps the whole boundary in place;
 * - beyond the paper, a triangle collapses its cheapest edge instead when that costs much less
 *   (EdgeCollapses, default on), which lowers the mean distance to the input on curved
 *   surfaces; a triangle with two boundary corners may collapse its boundary edge alone,
 *   which lets a triangulated polygon (a fan) be simplified at all;
 * - beyond the paper, the order also weighs how far a collapse moves the surface from the input
 *   triangles merged into it (SurfaceErrorWeight), which keeps the Hausdorff distance down;
 * - every collapse keeps the mesh manifold (link condition), never folds a triangle over and
 *   never makes one degenerate; a closed 2-manifold input gives a closed 2-manifold output;
 *   an angle guard (MinimumAngle, default 10°) keeps new slivers out where they are not needed.
 *
 * The target, the constraints (PreserveBoundary, Locked Points, attribute borders, the points a
 * piece shares with other pieces under MPI), the input and the output mapping are the common
 * ones of vtkMeshSimplificationFilter. The triangle count is met within 1 % or one triangle;
 * the filter stops early, with a warning, only when no legal collapse is left. In MaximumError
 * mode it collapses, in the same order, as far as it can while every output point stays within
 * the bound of the planes of the input triangles it stands for (their supporting planes and,
 * along open borders, the planes through the border edges perpendicular to them: Ronfard and
 * Rossignac's measure, the one the octree filter bounds); the point array "PlaneDistance" holds
 * each output point's distance in input units, AchievedMaximumError the largest in the bound's
 * units. Non-manifold vertices are kept in place.
 *
 * Each output point's sources are the input points merged into it, with the weights of the
 * placements along the way (barycentric, along the boundary edge, or all on the corner it
 * collapsed onto): floating-point arrays are interpolated with them, labels and ids come from
 * the surviving point. The point array "SquareVolumeError" holds the error accumulated at each
 * output point; the field data holds "SquareVolumeError" (the sum over all collapses, the
 * paper's volume error, in length to the 8th power).
 *
 * @sa vtkQuadricDecimation vtkDecimatePro vtkOctreeVertexClustering
 */
#ifndef vtkVolumeTriangleCollapse_h
#define vtkVolumeTriangleCollapse_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkMeshSimplificationFilter.h"

#include "VolumeCollapseParameters.h" // the filter's own settings and defaults

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkVolumeTriangleCollapse : public vtkMeshSimplificationFilter
  , protected meshsimp::VolumeCollapseParameters
{
public:
  static vtkVolumeTriangleCollapse* New();
  vtkTypeMacro(vtkVolumeTriangleCollapse, vtkMeshSimplificationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Gauss-curvature threshold of strong features (eq. 6–7), dimensionless: a triangle's
   * curvature times the current mean triangle area. A cube's corner scores about 0.1 (its face
   * planes keep it anyway); 0.3 keeps only sharper spikes than a cube's corner. Default 0: the
   * rule is off, because it costs more than it keeps: the sliver fans of CAD and building
   * models score as spikes (their corners' areas are tiny) and snap collapses across thin slabs,
   * which raises the mean distance to the input; it does keep sharp tips, such as a subdivided
   * cow's horns, closer to the input. VolumeTriangleCollapse.md gives the figures.
   */
  vtkSetClampMacro(FeatureCurvature, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FeatureCurvature, double);
  ///@}

  ///@{
  /**
   * Boundary corners sharper than BoundaryCornerAngle (degrees, default 60) never move.
   */
  vtkSetClampMacro(BoundaryCornerAngle, double, 0.0, 180.0);
  vtkGetMacro(BoundaryCornerAngle, double);
  ///@}

  ///@{
  /**
   * The factors of each triangle's error term (§3.1–3.2): the normal constraint factor
   * (default on), the shape factor 2 (1 − cos min α) · S (default off: it makes slivers cheap
   * to collapse, which on CAD meshes removes creases), and the constraint weight of the error
   * already accumulated (default on).
   */
  vtkSetMacro(UseNormalFactor, bool);
  vtkGetMacro(UseNormalFactor, bool);
  vtkBooleanMacro(UseNormalFactor, bool);
  vtkSetMacro(UseShapeFactor, bool);
  vtkGetMacro(UseShapeFactor, bool);
  vtkBooleanMacro(UseShapeFactor, bool);
  vtkSetMacro(UseVolumeWeights, bool);
  vtkGetMacro(UseVolumeWeights, bool);
  vtkBooleanMacro(UseVolumeWeights, bool);
  ///@}

  ///@{
  /**
   * Let a triangle collapse its cheapest edge instead when that edge's error (the same volume
   * terms over the triangles around its two ends) is under a quarter of the triangle's
   * (default on; beyond the paper). A triangle collapse always changes a curved surface, while
   * an edge along a cylinder's ruling line or a gently curved direction merges at almost no
   * error: this lowers the mean distance to the input, and most collapses become edge
   * collapses. Off gives the paper's triangle collapses only, which is faster but farther from
   * the input; on terrain the angle guard then often has to be lowered to reach the target (see
   * MinimumAngle). VolumeTriangleCollapse.md gives the figures.
   */
  vtkSetMacro(EdgeCollapses, bool);
  vtkGetMacro(EdgeCollapses, bool);
  vtkBooleanMacro(EdgeCollapses, bool);
  ///@}

  ///@{
  /**
   * Weight of the surface term added to each collapse's heap key (default 3000; beyond the
   * paper, 0 gives the paper's order): the new point's squared distances to the planes of the
   * input triangles merged into the collapsing vertices (Garland–Heckbert quadrics, weighted by
   * area) and, along open borders, to the planes through the border edges perpendicular to
   * their triangles (weighted by the squared edge length), times the squared mean input
   * triangle area, which gives the term the volume error's units. The placement stays the
   * paper's. The border planes see what volume does not: a chord cut across a hole's rim in the
   * surface's own plane sweeps no volume, so without them holes get triangles across them.
   * Ordered by volume alone, a few collapses on gently curved surfaces, where the normal factor
   * makes volume cheap, move the surface far from the input; the term keeps the Hausdorff
   * distance down at a similar volume change. VolumeTriangleCollapse.md gives the figures.
   */
  vtkSetClampMacro(SurfaceErrorWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SurfaceErrorWeight, double);
  ///@}

  ///@{
  /**
   * The angle guard, in degrees (default 10; 0 turns it off): a collapse that creates an angle
   * a below it (where the collapsed neighbourhood had none as small) waits until every collapse
   * that creates none costs (MinimumAngle / a)² times more, so thin triangles are made only
   * where the shape needs them (steep terrain, creases). A collapse that
   * leaves the surface where it was (a plane, a straight crease) may still make thin triangles
   * when no placement on a corner avoids them: CAD meshes need them along their creases.
   * When the guard refuses every collapse left before the target, it is lowered in steps
   * (halved; 0 below 2°) with a warning, rather than the filter stopping early.
   */
  vtkSetClampMacro(MinimumAngle, double, 0.0, 30.0);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /**
   * Collapses made per batch (default 64; 1 keeps the strict order of the paper's heap). The
   * cheapest queued triangles whose neighbourhoods (every vertex of the triangles around their
   * corners) are disjoint are evaluated and checked together, collapsed in cost order, and the
   * costs around them updated together, on NumberOfThreads threads. The output depends on the
   * batch size, never on the thread count.
   */
  vtkSetClampMacro(BatchSize, int, 1, 4096);
  vtkGetMacro(BatchSize, int);
  ///@}

protected:
  vtkVolumeTriangleCollapse();
  ~vtkVolumeTriangleCollapse() override = default;
  void ForEachOwnSetting(const meshsimp::SettingVisit& visit) override;

  bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) override;

private:
  vtkVolumeTriangleCollapse(const vtkVolumeTriangleCollapse&) = delete;
  void operator=(const vtkVolumeTriangleCollapse&) = delete;
};

#endif
