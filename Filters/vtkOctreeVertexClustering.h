// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOctreeVertexClustering
 * @brief   simplify a triangle mesh by adaptive octree vertex clustering
 *
 * vtkOctreeVertexClustering implements the geometric simplification of Zhou, Zhang, Shi and
 * Pan, "A new simplification algorithm for colored or textured polygonal models" (§2–3). The
 * target, the constraints, the input and output handling are the common ones of
 * vtkMeshSimplificationFilter; a count is met within 3 %, or a warning says why not.
 * Like vtkQuadricClustering it replaces all vertices of a spatial cell by one representative,
 * but the cells are the leaves of an adaptive octree instead of a uniform grid:
 *
 * - a leaf is split where it is larger than MaximumCellSize, holds more than
 *   MaximumVerticesPerCell vertices, where its representative would flip a neighbouring
 *   triangle (PreventFlips), and where its cluster error exceeds the bound (MaximumError) —
 *   or, with a triangle target, in decreasing order of error until the target is met;
 * - vertices of a leaf that are not connected by edges inside it are not merged, so nearby but
 *   separate parts of a model (two fingers, two sheets) stay apart; nor are vertices joined
 *   only by edges across which the surface turns away (normals more than 140 degrees apart: the
 *   two faces of a wall thinner than a cell, joined at a sharp rim), so both faces keep their
 *   place where no vertex between them (on a rounded rim, or one whose normals cancel) joins
 *   both;
 * - the representative minimises the quadric of the planes of its related triangles and of
 *   planes through boundary edges (BoundaryPlanes), refined by ErrorIterations rounds of the
 *   paper's e2 iteration; when the quadric is near singular, or its minimum lies outside the
 *   cluster's cell, the best of the cluster's vertices, its weighted centre and the minimum
 *   clamped into the cell is used, so that no point leaves its cell or the input's bounds.
 *
 * Beyond the paper: a cluster that would lose all its triangles (a leg folded onto its
 * neighbours) is split first; a folded cluster that sticks out collapses to its tip, so thin
 * parts become cones instead of vanishing; and with a count target late cheap splits can be
 * undone to afford a split of far larger error. Where the input is a surface, clustering makes
 * no open or non-manifold edge it did not have (clusters that would tear it are split into
 * pieces), and a leaf at a triangle still turned over is split; where that takes the count
 * over a count target (steep terrain, thin parts), quadric
 * half-edge collapses of the clustered mesh under the link condition finish it (multiphase
 * simplification, Garland and Shaffer): each collapsed point's clusters join a neighbour's.
 *
 * The cluster error (a distance) is the largest distance from the representative to the plane
 * of any input triangle touching the cluster and to its boundary planes; for a folded cluster
 * (normals spread over more than a half-space: a tip or a thin part) also the largest distance
 * of its points to the representative, or to the segment to it when it collapsed to its tip.
 * With TargetMode = MaximumError every output point's cluster error is at most the bound.
 *
 * Degenerate and duplicate output triangles are removed and unused points dropped. Locked
 * points (Locked Points, PreserveBoundary, and under MPI the points this piece shares with other
 * pieces) are clusters of their own at their input coordinates, so the simplified pieces still
 * meet along their common border; with PreserveAttributeBorders no cluster joins points of
 * different values of the chosen array.
 *
 * Each output point's sources are its cluster's input points with area weights, the heaviest
 * first: floating-point arrays are averaged with them, labels and ids come from the heaviest.
 * Two point arrays are added: "ClusterSize" (the number of input points merged) and
 * "ClusterError" (the cluster error above, input units); the field data holds
 * "MaximumClusterError" (input units) and AchievedMaximumError is the largest in MaximumError's
 * units.
 *
 * @warning Vertex clustering does not preserve topology: holes may close, thin parts may
 * become non-manifold. The output is deterministic for a given input whatever NumberOfThreads.
 *
 * @sa vtkQuadricClustering vtkQuadricDecimation vtkBinnedDecimation
 */
#ifndef vtkOctreeVertexClustering_h
#define vtkOctreeVertexClustering_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkMeshSimplificationFilter.h"

#include "OctreeClusteringParameters.h" // the filter's own settings and defaults

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkOctreeVertexClustering : public vtkMeshSimplificationFilter
  , protected meshsimp::OctreeClusteringParameters
{
public:
  static vtkOctreeVertexClustering* New();
  vtkTypeMacro(vtkOctreeVertexClustering, vtkMeshSimplificationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Leaves with a larger edge are always split (§2.4 rule a). Relative to the bounding-box
   * diagonal; 1 (default) sets no limit.
   */
  vtkSetClampMacro(MaximumCellSize, double, 1e-6, 1.0);
  vtkGetMacro(MaximumCellSize, double);
  ///@}

  ///@{
  /**
   * Leaves with more vertices are always split (§2.4 rule b); 0 (default) sets no limit.
   */
  vtkSetClampMacro(MaximumVerticesPerCell, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumVerticesPerCell, int);
  ///@}

  ///@{
  /**
   * Iterations of the e2 term (paper §3, default 3); 0 uses the face quadric alone.
   */
  vtkSetClampMacro(ErrorIterations, int, 0, 20);
  vtkGetMacro(ErrorIterations, int);
  ///@}

  ///@{
  /**
   * Add planes perpendicular to boundary edges so that open borders keep their shape
   * (default on), with this weight relative to the face planes (default 10, from 0 to 1000).
   */
  vtkSetMacro(BoundaryPlanes, bool);
  vtkGetMacro(BoundaryPlanes, bool);
  vtkBooleanMacro(BoundaryPlanes, bool);
  vtkSetClampMacro(BoundaryWeight, double, 0.0, 1000.0);
  vtkGetMacro(BoundaryWeight, double);
  ///@}

  ///@{
  /**
   * Split leaves whose representative would turn a neighbouring triangle against its
   * original normal (§2.4, default on), and keep the representatives' iteration from turning
   * one. After refinement the leaves at turned triangles are split again, while they can be
   * split (mending may still turn a few); with a count target even past the target, and
   * quadric collapses take the mesh back to it (not with MaximumCellSize or
   * MaximumVerticesPerCell, which no collapse may cross, nor where the input is no surface).
   */
  vtkSetMacro(PreventFlips, bool);
  vtkGetMacro(PreventFlips, bool);
  vtkBooleanMacro(PreventFlips, bool);
  ///@}

protected:
  vtkOctreeVertexClustering();
  ~vtkOctreeVertexClustering() override = default;
  void ForEachOwnSetting(const meshsimp::SettingVisit& visit) override;

  bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) override;

private:
  vtkOctreeVertexClustering(const vtkOctreeVertexClustering&) = delete;
  void operator=(const vtkOctreeVertexClustering&) = delete;
};

#endif
