// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkLODInterpolation
 * @brief Morphs between two levels of detail of one surface: Zhou, Zhang, Shi and Pan, "A new
 * simplification algorithm for colored or textured polygonal models", §5.
 *
 * Input 0 is the detailed surface, input 1 the coarse one; any two surfaces (outputs of this
 * module's filters, of ParaView's Decimate, two files). Or input 0 alone, a Progressive Mesh
 * sequence: the surfaces are two of its levels (DetailedReduction, CoarseReduction). Composite
 * data morphs block by block: the detailed input's polygonal blocks with the coarse input's in
 * the same order (both must have as many), each pair with its own correspondence, into an
 * output of the detailed input's structure. Every detailed point gets a partner on
 * the coarse surface once (Correspondence): NEAREST_VERTEX, the paper's, pairs every coarse
 * point with its nearest detailed point and every other detailed point with its nearest coarse
 * point; NEAREST_SURFACE_POINT (default) sends every detailed point to the closest point of the
 * coarse surface, so that thin parts do not fold onto a far vertex; EXACT, a geomorph (Hoppe,
 * "Progressive meshes"), sends every detailed point to the coarse point it became, where the
 * coarse surface was simplified from this detailed one and says so: the field data
 * InputToOutputPointIds that this module's filters write with GenerateOriginalIds (every
 * point's; where the detailed surface is itself a level of the same input with
 * vtkOriginalPointIds, two levels of one surface, through those), or else the point data
 * vtkOriginalPointIds of any filter (each coarse point's own input point; the points no record
 * places go to the nearest surface point).
 *
 * The output is the detailed surface's points, in their order, each at
 * (1 − Interpolation) P_detailed + Interpolation P_partner, on its triangles; adjacent points
 * closer than Interpolation · MergeDistance (a fraction of the detailed surface's diagonal) join
 * at the place of the member nearest to their mean, with the mean of their point data; the
 * triangles use the lowest id of each joined set (the others are left
 * unused, at the same place) and the triangles left without area go; with EXACT, two adjacent
 * points bound for one coarse point also join before a triangle between them would turn over,
 * and at Interpolation 1 at the latest, whatever the MergeDistance. Point ids thus stay the
 * detailed surface's in every frame. Interpolation 0 gives the detailed surface exactly.
 * Changing Interpolation alone reuses the correspondence and which points join when (computed
 * once per MergeDistance): a frame is one pass over the points and triangles, threaded. With
 * InterpolationFromTime the time asked for sets the frame (times 0 to 1 are reported).
 *
 * Point data: every floating-point point array of the detailed surface, and every unsigned-char
 * colour array (3 or 4 components), that the coarse surface has too (same name and number of
 * components) morphs towards it, in its own type (colours rounded); the others (labels, ids:
 * integers that mean nothing halfway) pass unchanged; the active normals stay unit. The points
 * are of the detailed surface's type (OutputPointsPrecision). Cell data follow the detailed
 * triangles. The point array "Displacement" holds how far each point
 * stands from its place on the detailed surface (input units); the field data
 * "CorrespondenceBuilds" how many times the correspondence has been built. The arrays a frame
 * writes (all but those it shares with the detailed surface) carry their ranges in VTK's range
 * cache, so that an application that asks for them after every frame (ParaView does) does not
 * compute them again.
 *
 * @sa vtkMeshSimplificationFilter vtkProgressiveMesh
 */
#ifndef vtkLODInterpolation_h
#define vtkLODInterpolation_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for the levels' filters

#include <vector>

class vtkProgressiveMesh;

namespace meshsimp
{
struct ExecutionContext;
}

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkLODInterpolation : public vtkPolyDataAlgorithm
{
public:
  static vtkLODInterpolation* New();
  vtkTypeMacro(vtkLODInterpolation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CorrespondenceModes
  {
    NEAREST_VERTEX = 0,
    NEAREST_SURFACE_POINT = 1,
    EXACT = 2
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
   * How each detailed point finds its partner: NEAREST_VERTEX (the paper),
   * NEAREST_SURFACE_POINT (default), or EXACT where the coarse surface was simplified from the
   * detailed one and carries the record (see the class comment).
   */
  vtkSetClampMacro(Correspondence, int, NEAREST_VERTEX, EXACT);
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

  ///@{
  /**
   * Off (default): the filter makes each frame. On, for playback on the GPU: the output is the
   * detailed surface as it is, with the point array "CoarsePoints" (floats, each point's place
   * at Interpolation 1) as its active tangents, for a vertex shader to blend
   * mix(P, CoarsePoints, t) from one uniform, so that a frame costs a render and no pipeline
   * update (LODInterpolation.md gives the representation's settings); Interpolation and
   * MergeDistance then do nothing (points do not join).
   */
  vtkSetMacro(MorphInShader, bool);
  vtkGetMacro(MorphInShader, bool);
  vtkBooleanMacro(MorphInShader, bool);
  ///@}

  ///@{
  /**
   * With one input, a Progressive Mesh sequence (vtkProgressiveMesh's second output, or its
   * file): the detailed and the coarse surfaces are its levels at these reductions (defaults 0,
   * every point, and 0.9), each recording what its points became, so that Exact is a geomorph
   * between them (a warning where DetailedReduction is not below CoarseReduction). Ignored
   * with two inputs.
   */
  vtkSetClampMacro(DetailedReduction, double, 0.0, 1.0);
  vtkGetMacro(DetailedReduction, double);
  vtkSetClampMacro(CoarseReduction, double, 0.0, 1.0);
  vtkGetMacro(CoarseReduction, double);
  ///@}

  ///@{
  /**
   * The type of the frame's points: vtkAlgorithm::DEFAULT_PRECISION (default), the detailed
   * surface's (floats stay floats: half the memory, and a renderer takes them without a
   * conversion); SINGLE_PRECISION, floats; DOUBLE_PRECISION, doubles. The morph itself is
   * computed in doubles.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
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
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLODInterpolation(const vtkLODInterpolation&) = delete;
  void operator=(const vtkLODInterpolation&) = delete;
  struct Cache;
  /// The correspondence for these surfaces in built, built again only where their geometry or
  /// the Correspondence changed; false, with an error, where it cannot be.
  bool Pair(vtkPolyData* detailed, vtkPolyData* coarse, const meshsimp::ExecutionContext& context, Cache& built);
  /// The partners of the Correspondence for the triangles Pair extracted.
  bool MakePartners(vtkPolyData* detailed, vtkPolyData* coarse, const meshsimp::ExecutionContext& context, Cache& built);
  /// The frame at t of one surface (or block) into output; false, with an error, where it cannot
  /// be made.
  bool Morph(vtkPolyData* detailed, vtkPolyData* coarse, double t, const meshsimp::ExecutionContext& context, Cache& built,
    vtkPolyData* output);
  /// With a sequence alone (or composite data of sequences): its two levels (made by filters
  /// kept here, which extract them from the sequence without building it again).
  bool Levels(vtkDataObject* sequence, vtkDataObject*& detailed, vtkDataObject*& coarse);

  double Interpolation = 0.0;
  double MergeDistance = 0.001;
  int Correspondence = NEAREST_SURFACE_POINT;
  bool InterpolationFromTime = false;
  bool MorphInShader = false;
  double DetailedReduction = 0.0;
  double CoarseReduction = 0.9;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  int CorrespondenceBuilds = 0;
  std::vector<Cache> Built; // per surface (block): the correspondence and what it was built from
  vtkSmartPointer<vtkProgressiveMesh> DetailedLevel, CoarseLevel; // with a sequence alone
};

#endif
