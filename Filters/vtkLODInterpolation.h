// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkLODInterpolation
 * @brief Morphs between two levels of detail of one surface: Zhou, Zhang, Shi and Pan, "A new
 * simplification algorithm for colored or textured polygonal models", §5.
 *
 * Input 0 is the detailed surface, input 1 the coarse one; any two surfaces (outputs of this
 * module's filters, of ParaView's Decimate, two files). Every detailed point gets a partner on
 * the coarse surface once (Correspondence): NEAREST_VERTEX, the paper's, pairs every coarse
 * point with its nearest detailed point and every other detailed point with its nearest coarse
 * point; NEAREST_SURFACE_POINT (default) sends every detailed point to the closest point of the
 * coarse surface, so that thin parts do not fold onto a far vertex. The output is the detailed
 * triangles with each point at (1 − Interpolation) P_detailed + Interpolation P_partner;
 * adjacent points closer than Interpolation · MergeDistance (a fraction of the detailed
 * surface's diagonal) join and the triangles left without area go. Interpolation 0 gives the
 * detailed surface exactly. Changing Interpolation alone reuses the correspondence; with
 * InterpolationFromTime the time asked for sets the frame (times 0 to 1 are reported).
 *
 * Point data: every numeric point array of the detailed surface, morphed towards the coarse
 * surface's array of the same name and number of components where it has one (colours and
 * scalars morph), kept otherwise; the active normals renormalised. Cell data follow the
 * detailed triangles. The point array "Displacement" holds how far each point stands from its
 * place on the detailed surface (input units); the field data "CorrespondenceBuilds" how many
 * times the correspondence has been built.
 *
 * @sa vtkMeshSimplificationFilter vtkProgressiveMesh
 */
#ifndef vtkLODInterpolation_h
#define vtkLODInterpolation_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkLODInterpolation : public vtkPolyDataAlgorithm
{
public:
  static vtkLODInterpolation* New();
  vtkTypeMacro(vtkLODInterpolation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CorrespondenceModes
  {
    NEAREST_VERTEX = 0,
    NEAREST_SURFACE_POINT = 1
  };

  ///@{
  /**
   * 0 (default): the detailed surface; 1: every point on the coarse surface.
   */
  vtkSetClampMacro(Interpolation, double, 0.0, 1.0);
  vtkGetMacro(Interpolation, double);
  ///@}

  ///@{
  /**
   * Adjacent points closer than Interpolation times this (a fraction of the detailed surface's
   * bounding-box diagonal; default 0.001) join into one. 0: none join.
   */
  vtkSetClampMacro(MergeDistance, double, 0.0, 1.0);
  vtkGetMacro(MergeDistance, double);
  ///@}

  ///@{
  /**
   * How each detailed point finds its partner: NEAREST_VERTEX (the paper) or
   * NEAREST_SURFACE_POINT (default).
   */
  vtkSetClampMacro(Correspondence, int, NEAREST_VERTEX, NEAREST_SURFACE_POINT);
  vtkGetMacro(Correspondence, int);
  ///@}

  ///@{
  /**
   * Off (default): Interpolation sets the frame. On: the time the pipeline asks for does (in
   * [0, 1]), and the filter reports the times 0, 0.05, ..., 1, so that ParaView's Play button
   * and Animation View morph the surface.
   */
  vtkSetMacro(InterpolationFromTime, bool);
  vtkGetMacro(InterpolationFromTime, bool);
  vtkBooleanMacro(InterpolationFromTime, bool);
  ///@}

  /// The coarse surface (input 1).
  void SetCoarseConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetCoarseData(vtkDataObject* data) { this->SetInputData(1, data); }

  /// How many times the correspondence has been built (once per change of an input or of
  /// Correspondence, not per frame).
  vtkGetMacro(CorrespondenceBuilds, int);

protected:
  vtkLODInterpolation();
  ~vtkLODInterpolation() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLODInterpolation(const vtkLODInterpolation&) = delete;
  void operator=(const vtkLODInterpolation&) = delete;
  /// The correspondence for these inputs, built again only where their geometry or the
  /// Correspondence changed; false, with an error, where it cannot be.
  bool Pair(vtkPolyData* detailed, vtkPolyData* coarse);

  double Interpolation = 0.0;
  double MergeDistance = 0.001;
  int Correspondence = NEAREST_SURFACE_POINT;
  bool InterpolationFromTime = false;
  int CorrespondenceBuilds = 0;
  struct Cache;
  std::unique_ptr<Cache> Built; // the correspondence and what it was built from
};

#endif
