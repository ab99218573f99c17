// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParallelDecimation
 * @brief   fast vertex decimation by half-edge collapse, in rounds that run on all cores
 *
 * vtkParallelDecimation implements the parallel decimation of Franc's dissertation "Methods for
 * Polygonal Mesh Simplification" (ch. 5–6). Vertices are removed: each removal collapses one of
 * the vertex's edges into a neighbour, which keeps its point data. With the QUADRIC measure the
 * survivors then move to the point of least error of the planes they stand for (MoveSurvivors,
 * default on: it lowers the distance to the input; see ParallelDecimation.md for the figures);
 * without it the output points are a subset of the input points, coordinates included.
 *
 * - Vertex types: simple, boundary, interior-edge (two sharp edges), corner and complex
 *   (non-manifold). An edge is sharp where its triangles' normals differ by more than
 *   FeatureAngle; corners (one or three and more sharp edges, or a boundary turning by more than
 *   BoundaryCornerAngle) and complex vertices are kept. Boundary and interior-edge vertices are
 *   removed only along their boundary or sharp edges, so creases and borders keep their line.
 * - Importance, the order of removal: with ImportanceMeasure AVERAGE_PLANE (the paper) the
 *   distance to the average plane of the vertex's triangles, or to the line through its two
 *   boundary or feature neighbours (eq. 5.1–5.4), plus, with AccumulateError, the importance of
 *   the vertices already collapsed into it; with QUADRIC (default) the least accumulated
 *   plane-distance error (Garland–Heckbert quadrics) of the vertex's allowed collapses, which
 *   remembers every removed vertex's planes and so keeps the output closer to the input.
 * - Ordering without sorting (§5.6): vertices go into buckets by a function of their importance
 *   that spreads the least important ones (BucketImportance a, BucketShare α; the paper's 2 %
 *   and 80 %).
 * - Rounds (§5.5): the least important vertices (RoundFraction of them per round) are taken
 *   greedily while any two taken vertices stay at least three edges apart (a
 *   super-independent set: their triangles share no edge; only the centre of a fan of 32 or
 *   more triangles may be near several, and it is never a collapse's survivor), and then removed
 *   concurrently without locks. Each removal collapses
 *   the legal edge of least area change among those that turn no triangle by more than
 *   MaximumNormalDeviation (HalfEdgeChoice LEAST_AREA_CHANGE, §5.3) or the shortest legal edge
 *   (SHORTEST_EDGE, §5.5); with QUADRIC, the edge of least error. Every collapse keeps the mesh
 *   manifold (link condition) and never folds or degenerates a triangle.
 * - The output is the same for any NumberOfThreads.
 *
 * The triangle count is met within 2 % (TargetReduction or TargetTriangleCount). When no vertex
 * is removable before that (all corners, or no edge within the deviation), FeatureAngle and
 * MaximumNormalDeviation are raised by 15° at a time, with a warning. Where even 180° misses
 * the target, raising them removed features and reached nothing, so the decimation is made
 * again with the angles as set: the filter then stops where nothing is removable under them,
 * with a warning that says so. In MaximumError mode it removes, in
 * the same order and without raising the angles, as far as it can while every survivor (moved
 * or not) stays within the bound of the planes of the input triangles it stands for (their
 * supporting planes and, along open borders, the planes through the border edges perpendicular
 * to them: Ronfard and Rossignac's measure, the one the octree filter bounds); a vertex whose
 * best half-edge would break the bound takes its next. The point array "PlaneDistance" holds
 * each output point's distance in input units, AchievedMaximumError the largest in the bound's
 * units.
 *
 * The target, the constraints (PreserveBoundary, Locked Points, attribute borders, the points a
 * piece shares with other pieces under MPI), the input and the output mapping are the common
 * ones of vtkMeshSimplificationFilter. Each output point's source is its own input point, so
 * its point data is that point's (normals are recomputed). The point array "Importance" holds
 * each output point's final importance (-1 for points that are never removed) and
 * "VertexType" its type (0 simple, 1 boundary, 2 interior-edge, 3 corner, 4 complex); the
 * field data holds "Rounds" and "MovedPoints".
 *
 * @sa vtkDecimatePro vtkQuadricDecimation vtkVolumeTriangleCollapse
 */
#ifndef vtkParallelDecimation_h
#define vtkParallelDecimation_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkMeshSimplificationFilter.h"

#include "ParallelDecimationParameters.h" // the filter's own settings and defaults

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkParallelDecimation : public vtkMeshSimplificationFilter
  , protected meshsimp::ParallelDecimationParameters
{
public:
  static vtkParallelDecimation* New();
  vtkTypeMacro(vtkParallelDecimation, vtkMeshSimplificationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ImportanceMeasures
  {
    AVERAGE_PLANE = 0,
    QUADRIC = 1
  };
  enum HalfEdgeChoices
  {
    LEAST_AREA_CHANGE = 0,
    SHORTEST_EDGE = 1
  };

  ///@{
  /**
   * Degrees between the normals of an edge's two triangles above which the edge is sharp
   * (default 75). Lower values keep more creases and corners.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Boundary corners sharper than BoundaryCornerAngle (degrees, default 60) are never removed.
   */
  vtkSetClampMacro(BoundaryCornerAngle, double, 0.0, 180.0);
  vtkGetMacro(BoundaryCornerAngle, double);
  ///@}

  ///@{
  /**
   * The order of removal: QUADRIC (default) or AVERAGE_PLANE (the paper's eq. 5.1–5.4), and for
   * AVERAGE_PLANE whether a survivor adds the importance of the vertices collapsed into it
   * (AccumulateError, default on).
   */
  virtual void SetImportanceMeasure(int measure);
  virtual int GetImportanceMeasure() const;
  vtkSetMacro(AccumulateError, bool);
  vtkGetMacro(AccumulateError, bool);
  vtkBooleanMacro(AccumulateError, bool);
  ///@}

  ///@{
  /**
   * QUADRIC only: after the last round, move each surviving point to the minimiser of its
   * accumulated quadric (the planes of every input triangle collapsed into it), at most half its
   * shortest edge away, unless a triangle around it would turn by more than 60°; locked points,
   * boundary corners and non-manifold points stay. Point data is not changed. Default on; off
   * keeps every output point at its input coordinates, bit for bit (AVERAGE_PLANE always does).
   */
  vtkSetMacro(MoveSurvivors, bool);
  vtkGetMacro(MoveSurvivors, bool);
  vtkBooleanMacro(MoveSurvivors, bool);
  ///@}

  ///@{
  /**
   * The edge an AVERAGE_PLANE vertex collapses along: LEAST_AREA_CHANGE (default, §5.3) among
   * those that turn no remaining triangle by more than MaximumNormalDeviation degrees (default
   * 90; also a limit for QUADRIC), or SHORTEST_EDGE (§5.5).
   */
  virtual void SetHalfEdgeChoice(int choice);
  virtual int GetHalfEdgeChoice() const;
  vtkSetClampMacro(MaximumNormalDeviation, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * The bucketing function of §5.6: the least important BucketImportance of the importance range
   * (default 0.02) fills BucketShare of the buckets (default 0.8).
   */
  vtkSetClampMacro(BucketImportance, double, 1e-6, 1.0);
  vtkGetMacro(BucketImportance, double);
  vtkSetClampMacro(BucketShare, double, 1e-6, 1.0);
  vtkGetMacro(BucketShare, double);
  ///@}

  ///@{
  /**
   * The share of the removable vertices, least important first, that one round considers
   * (default 0.1). Smaller keeps the order closer to a global one and takes more rounds.
   */
  vtkSetClampMacro(RoundFraction, double, 0.001, 1.0);
  vtkGetMacro(RoundFraction, double);
  ///@}

protected:
  vtkParallelDecimation();
  ~vtkParallelDecimation() override = default;
  void ForEachOwnSetting(const meshsimp::SettingVisit& visit) override;

  bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) override;

private:
  vtkParallelDecimation(const vtkParallelDecimation&) = delete;
  void operator=(const vtkParallelDecimation&) = delete;
};

#endif
