// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkProgressiveMesh
 * @brief   real-time progressive meshes (Wu and Fei): build the collapse sequence once, then
 *          any level of detail at once
 *
 * After S. Wu and G. Fei, "Real-time generation of progressive meshes". The first execution
 * builds the whole sequence of half-edge collapses (the removed point moves onto a neighbour),
 * cheapest first, down to the coarsest mesh the checks allow:
 * - the cost of a collapse is QuadricWeight times its quadric error (Garland-Heckbert; the
 *   default, beyond the paper), plus LengthWeight times its L1 length (in mean edge lengths) and
 *   CurvatureWeight times 1 - N_ABC . N_ABD of the edge's two triangles (the paper's cost, §4;
 *   both 0 by default), plus AttributeWeight times the L1 distance of the values of the
 *   Attribute Coordinates array (§7). The quadric alone keeps the levels closest to the
 *   input; the paper's cost takes the shortest edge first whatever the collapse does to a
 *   crease, and its levels lie far from the input (ProgressiveMesh.md gives the figures);
 * - a collapse keeps the mesh valid: border points move only along their border and never
 *   into the interior (§7), locked and non-manifold points stay, regions of the Attribute
 *   Borders array never merge, no triangle turns over.
 *
 * The target (reduction, count or error bound) then picks a level: the first points of the
 * sequence and the triangles still alive, their corners mapped to their surviving ancestors. No
 * collapse is replayed, and changing only the target does not rebuild: the sequence is cached,
 * keyed on the modification times of the input's points, cells and point arrays (which survive
 * the shallow copies ParaView makes at each update) and on the properties the build depends
 * on, so dragging
 * TargetReduction in ParaView updates the view at once (NumberOfBuilds counts the builds).
 * Output points are input points, with their point data unchanged; cell data follows the
 * surviving triangles. Point array "CollapseLevel": the fraction of the sequence at which each
 * point disappears (0 the first removed, 1 never); field data "LevelTriangles" and "LevelPoints". With
 * ComputeDeviation, "Deviation" is two-sided as in the other filters: an output point is an
 * input point, but the removed points it stands for lie off the level's surface; it is measured
 * at each target change (off, a level switch costs only its extraction). Under an error
 * bound, the bound is on the quadric distance of the collapses (the RMS distance of a removed
 * point to the planes merged into it), the same measure as "MaximumError" in the field data.
 *
 * Output port 1 is the whole sequence as one vtkPolyData: every point in collapse order (the
 * last removed first) with its point data, point arrays "Parent" (the point it collapses into,
 * -1 for the base points) and "CollapseError", and the triangles ordered by their cell array
 * "RemovedAt" (the point whose collapse removes them, -1: none). For a composite input it is a
 * composite dataset of the input's structure with each surface block's sequence (other blocks
 * empty). Saved as .vtp (.vtm) it can be read back: given such data as input, the filter
 * extracts levels from it without rebuilding (arrays that do not form a sequence are rebuilt
 * from, with a warning). It is empty when the target asks for no triangle (TargetReduction 1,
 * TargetTriangleCount 0), which builds nothing.
 */
#ifndef vtkProgressiveMesh_h
#define vtkProgressiveMesh_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkMeshSimplificationFilter.h"

#include "ProgressiveMeshParameters.h" // the filter's own settings and defaults

#include <memory> // for std::unique_ptr

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkProgressiveMesh : public vtkMeshSimplificationFilter
  , protected meshsimp::ProgressiveMeshParameters
{
public:
  static vtkProgressiveMesh* New();
  vtkTypeMacro(vtkProgressiveMesh, vtkMeshSimplificationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The weights of the cost (see above): the L1 length and the curvature 1 - N_ABC . N_ABD of
   * the paper (default 0 each; 1, 1 and QuadricWeight 0 give the paper's cost), and the quadric
   * error (default 1).
   */
  vtkSetClampMacro(LengthWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LengthWeight, double);
  vtkSetClampMacro(CurvatureWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CurvatureWeight, double);
  vtkSetClampMacro(QuadricWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(QuadricWeight, double);
  ///@}

  ///@{
  /**
   * The weight of the L1 distance of the values of the point array chosen as input array 2
   * (colours, texture coordinates: §7), default 1: unsigned-char colours count 255 as 1, other
   * arrays their range as 1, so a change from black to white costs AttributeWeight, as much as
   * the quadric error of a mean triangle one mean edge length away. Select the array with
   * SetInputArrayToProcess(2, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name).
   */
  vtkSetClampMacro(AttributeWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AttributeWeight, double);
  ///@}

  /// How many times the sequence was built (not extracted from the cache) since construction.
  vtkGetMacro(NumberOfBuilds, int);

  /// The whole sequence (output port 1) of a single-surface input; for a composite input use
  /// GetOutputDataObject(1).
  vtkPolyData* GetSequenceOutput();

  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  vtkProgressiveMesh();
  ~vtkProgressiveMesh() override;
  void ForEachOwnSetting(const meshsimp::SettingVisit& visit) override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) override;
  /// Port 1: each piece's whole sequence where port 0 has its level (see the class comment).
  void WriteSequences(vtkDataObject* levels, vtkDataObject* sequences);
  void WritePiece(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh) override;
  /// The level's deviation from the sequence: its points and the removed points each stands for
  /// (meshsimp::ListLevelSources), also where WritePiece wrote the level without extracting it.
  bool AddDeviation(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh) override;

  int NumberOfBuilds = 0;

private:
  vtkProgressiveMesh(const vtkProgressiveMesh&) = delete;
  void operator=(const vtkProgressiveMesh&) = delete;

  struct Cache;
  std::unique_ptr<Cache> Sequences;
};

#endif
