// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMeshSimplificationFilter
 * @brief   the front end every MeshSimplification filter shares: the target, the constraints,
 *          the input, the output mapping and the messages
 *
 * A subclass adds its algorithm's own settings and runs its core in RunCore; everything else is
 * here, so that a target and a constraint mean the same thing in every filter:
 *
 * - The target (TargetMode): a reduction (the fraction of the triangles to remove), a triangle
 *   count, or an error bound (MaximumError, relative to the bounding-box diagonal by default).
 *   A reduction or a count means the whole input: a composite input's blocks, and the pieces of
 *   a distributed one, share the count out by their triangles. A relative bound is relative to
 *   the whole input's diagonal. A count is met within the filter's tolerance, or a warning says
 *   why not; a target of no triangle gives an empty output, with a warning.
 * - Constraints: PreserveBoundary keeps every point of an open border; a point array chosen as
 *   input array 0 (Locked Points) locks the points where it is nonzero; with
 *   PreserveAttributeBorders, a point array chosen as input array 1 divides the points into
 *   regions of equal values, and no collapse or cluster joins two regions, so that a colour or
 *   label border stays sharp. Under MPI the points a piece shares with another piece are locked,
 *   so the simplified pieces still fit together; under a count, the border round then thins the
 *   borders on every piece at once and each piece goes to its share again with its thinned
 *   border locked (meshsimp::SimplifySharedBorders), so the whole meets its count.
 * - Input: vtkPolyData, any other dataset whose cells are surfaces (through vtkGeometryFilter,
 *   as Extract Surface does; one with 3-D cells is refused with a message that says to extract
 *   its surface first), or composite data of them: polygonal leaves are simplified, other leaves
 *   are passed through unchanged. Polygons are triangulated and strips decomposed; vertex and
 *   line cells are dropped with a warning. Before simplifying, the usable triangles are
 *   mended: repeated triangles dropped, turned-over ones turned back, and zero-width cracks
 *   closed (CloseCracks): two points at exactly the same position whose open borders run along
 *   each other in opposite directions, or alike where one side is turned over and the result
 *   can be oriented (split-off copies of a point, patches stored with their own copies of a
 *   shared border, soups) become one point where every point array has the same values at
 *   both (global and pedigree ids aside; a texture or colour seam stays open) and their locks
 *   and attribute regions agree; the field value JoinedPoints counts them. Points that only
 *   touch, and two copies of one sheet, stay apart. The input is never modified.
 * - Output: point data by one rule in every filter (vtkSimplificationAttributes.h: floating
 *   arrays interpolated, unsigned-char colours averaged and rounded, other arrays from one
 *   input point), cell data copied from the surviving triangles, the algorithm's own arrays
 *   and, with ComputeDeviation, the point array "Deviation" (each output point's distance to
 *   the input surface, input units) with "DeviationMaximum" and "DeviationRMS" in the field
 *   data. AchievedMaximumError and the field value "MaximumError" give the largest error the
 *   algorithm bounds, in MaximumError's units.
 * - Messages: one line each; when the output misses the target, the first says why.
 */
#ifndef vtkMeshSimplificationFilter_h
#define vtkMeshSimplificationFilter_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "ParameterTable.h" // for ForEachOwnSetting
#include "vtkPolyDataAlgorithm.h"

#include <memory>  // for std::unique_ptr
#include <string>  // for SetSettingByName
#include <utility> // for std::move
#include <vector>  // for the pieces of an execution

namespace meshsimp
{
struct ExecutionContext;
struct SimplificationOptions;
struct SimplifiedMesh;
struct TriangleMeshView;
}
namespace vtkSimplification
{
struct InputPieces;
struct Piece;
struct TriangleInput;
}

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkMeshSimplificationFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMeshSimplificationFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Creates the output's data object: vtkPolyData, or the composite input's type.
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  enum TargetModes
  {
    TARGET_REDUCTION = 0,
    TARGET_TRIANGLE_COUNT = 1,
    TARGET_MAXIMUM_ERROR = 2
  };

  ///@{
  /**
   * What decides how far to simplify: TargetReduction (default), TargetTriangleCount or
   * MaximumError.
   */
  vtkSetClampMacro(TargetMode, int, TARGET_REDUCTION, TARGET_MAXIMUM_ERROR);
  vtkGetMacro(TargetMode, int);
  void SetTargetModeToReduction() { this->SetTargetMode(TARGET_REDUCTION); }
  void SetTargetModeToTriangleCount() { this->SetTargetMode(TARGET_TRIANGLE_COUNT); }
  void SetTargetModeToMaximumError() { this->SetTargetMode(TARGET_MAXIMUM_ERROR); }
  ///@}

  ///@{
  /**
   * The fraction of the input triangles to remove, in [0, 1] (default 0.9): 1 removes them all.
   * A value outside is clamped, and the execution warns that it was.
   */
  void SetTargetReduction(double reduction);
  vtkGetMacro(TargetReduction, double);
  ///@}

  ///@{
  /**
   * The number of triangles to keep in TargetTriangleCount mode (default 1000), over the whole
   * input: the blocks of a composite input and the pieces of a distributed one share it out by
   * their triangles. A negative count is clamped to 0, and the execution warns that it was.
   */
  void SetTargetTriangleCount(vtkIdType count);
  vtkGetMacro(TargetTriangleCount, vtkIdType);
  ///@}

  ///@{
  /**
   * The error bound of MaximumError mode (default 0.01): what it bounds is the algorithm's
   * (see the subclass). A distance, relative to the whole input's bounding-box diagonal when
   * RelativeError is on (default), else in input units. A negative bound is clamped to 0, and
   * the execution warns that it was.
   */
  void SetMaximumError(double bound);
  vtkGetMacro(MaximumError, double);
  vtkSetMacro(RelativeError, bool);
  vtkGetMacro(RelativeError, bool);
  vtkBooleanMacro(RelativeError, bool);
  ///@}

  ///@{
  /**
   * Keep every point of an open border where it is (default off).
   */
  vtkSetMacro(PreserveBoundary, bool);
  vtkGetMacro(PreserveBoundary, bool);
  vtkBooleanMacro(PreserveBoundary, bool);
  ///@}

  ///@{
  /**
   * Keep the borders between the values of the point array chosen as input array 1 sharp
   * (default off): no collapse or cluster joins points of different values, so colours or
   * labels never blend across a border. Select the array with
   * SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name).
   */
  vtkSetMacro(PreserveAttributeBorders, bool);
  vtkGetMacro(PreserveAttributeBorders, bool);
  vtkBooleanMacro(PreserveAttributeBorders, bool);
  ///@}

  ///@{
  /**
   * Close zero-width cracks before simplifying (default on): two points at exactly the same
   * position on the two sides of a crack become one point where every point array agrees and
   * their locks agree (see Input above). Turn it off when points are split on purpose and
   * the split must stay (it then stays open, as a border).
   */
  vtkSetMacro(CloseCracks, bool);
  vtkGetMacro(CloseCracks, bool);
  vtkBooleanMacro(CloseCracks, bool);
  ///@}

  ///@{
  /**
   * Add the point array "Deviation", in input units: at each output point the larger of its
   * distance to the input surface and the largest distance to the output surface of the input
   * points it stands for, so that the two meshes' differences show both ways; with its maximum
   * (the two-sided, Hausdorff, distance) and RMS in the field data as "DeviationMaximum" and
   * "DeviationRMS" (default off; on in ParaView). It takes the last fifth of the progress.
   */
  vtkSetMacro(ComputeDeviation, bool);
  vtkGetMacro(ComputeDeviation, bool);
  vtkBooleanMacro(ComputeDeviation, bool);
  ///@}

  ///@{
  /**
   * Threads; 0 (default) uses all cores. The output does not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * vtkAlgorithm::DEFAULT_PRECISION (default: as the input), SINGLE_PRECISION or
   * DOUBLE_PRECISION for the output points.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Add the point array "vtkOriginalPointIds" (each output point's representative: the input
   * point whose labels and ids it carries, see the point-data rule above) and the cell array
   * "vtkOriginalCellIds" (the input cell each output triangle comes from), the names and
   * meaning of vtkGeometryFilter's: the correspondence a later filter reads to map values
   * between the input and the output. Ids are those of the filter's input (of each block of a
   * composite input, of each piece under MPI; for an unstructured grid, the grid's own, not
   * those of the surface made from it); arrays of those names in the input are replaced. For
   * a vtkPolyData input, also the field data "InputToOutputPointIds": per input point, the
   * output point that stands for it (-1: none), what vtkLODInterpolation's EXACT
   * correspondence reads to morph the input into the output. Default off.
   */
  vtkSetMacro(GenerateOriginalIds, bool);
  vtkGetMacro(GenerateOriginalIds, bool);
  vtkBooleanMacro(GenerateOriginalIds, bool);
  ///@}

  /**
   * Sets a setting by the name its setter and the plugin give it: the common ones
   * (PreserveBoundary, CloseCracks, ComputeDeviation, GenerateOriginalIds,
   * OutputPointsPrecision, NumberOfThreads) or the filter's own (its parameters' table, e.g.
   * "FeatureAngle"), as a number (a flag: nonzero is on; an enumeration: its value), clamped to
   * the range its setter clamps to. Returns false, changing nothing, for a name the filter does
   * not have or a value that is not a finite number. The command-line tool's --set goes
   * through it.
   */
  bool SetSettingByName(const std::string& name, double value);

  /// Calls visit with each setting SetSettingByName takes, the common ones first: its name,
  /// value, range, one line of help (which the plugin's documentation of the property begins
  /// with) and a setter. The command-line tool's --settings lists them.
  void ForEachSetting(const meshsimp::SettingVisit& visit);

  /**
   * The largest error the algorithm bounds, after the last execution, in MaximumError's units
   * (a fraction of the diagonal when RelativeError is on); 0 when the algorithm does not
   * measure it in the mode used.
   */
  vtkGetMacro(AchievedMaximumError, double);


protected:
  /// Calls visit with each of the filter's own settings (see ForEachSetting): with a parameters
  /// table, meshsimp::VisitParameters<Table>(*this, visit).
  virtual void ForEachOwnSetting(const meshsimp::SettingVisit& visit);

  vtkMeshSimplificationFilter();
  ~vtkMeshSimplificationFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * One piece of an execution as the subclass's hooks see it, passed to each call: its place
   * among the execution's pieces (a composite input's blocks, a process's piece), its input
   * surface (with the arrays it can use), its triangles and their view for the core (Mesh), the
   * common options (its share of the target, locks, regions), the execution context (threads,
   * progress, abort) and its output.
   */
  struct PieceCall
  {
    std::size_t Index;
    vtkPolyData* Input;
    const vtkSimplification::TriangleInput& Triangles;
    /// What the core simplifies: the piece's triangles (Triangles.View), or, at the border
    /// round's last stage, the piece's first result (see SharesBorders).
    const meshsimp::TriangleMeshView& Mesh;
    const meshsimp::SimplificationOptions& Common;
    const meshsimp::ExecutionContext& Execution;
    vtkPolyData* Output;
    /// The piece shares borders with other pieces. Its core aims above its share, the border
    /// round thins the borders on every piece at once (meshsimp::SimplifySharedBorders), and
    /// the core runs again on the result (Mesh) to the share with the thinned border locked:
    /// RunCore gives whole meshes, and WritePiece and AddDeviation get the last.
    bool SharesBorders;
    /// Mesh is the piece's first result (that last stage), not its triangles.
    bool OnFirstResult;
  };

  /**
   * The subclass's algorithm on one piece: its own settings from its properties added to the
   * common options, and its core run on the piece's triangles into result. Returns false when
   * aborted.
   */
  virtual bool RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result) = 0;

  /**
   * What RunCore does in every filter: the core's options made of the common ones and the
   * filter's own parameters (its Options derives from both), its core run, and its result kept as
   * the common SimplifiedMesh. The core's header must be included where this is used.
   */
  template <class Options, class Result, class Parameters>
  static bool RunWith(bool (*core)(const meshsimp::TriangleMeshView&, const Options&, Result&,
                        const meshsimp::ExecutionContext&),
    const Parameters& own, const PieceCall& piece, meshsimp::SimplifiedMesh& result)
  {
    Options options;
    static_cast<meshsimp::SimplificationOptions&>(options) = piece.Common;
    static_cast<Parameters&>(options) = own;
    Result full;
    const bool finished = core(piece.Mesh, options, full, piece.Execution);
    result = std::move(static_cast<meshsimp::SimplifiedMesh&>(full));
    return finished;
  }

  /// Writes the piece's output from its core's result: vtkSimplification::SetOutput.
  virtual void WritePiece(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh);

  /// Adds the Deviation array with ComputeDeviation from mesh, the core's result written to the
  /// piece's output (vtkSimplification::AddDeviation); returns false when aborted.
  virtual bool AddDeviation(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh);

  /// How far from a count target the subclass's algorithm may end (a fraction of the count).
  double TargetTolerance = 0.01;

  int TargetMode = TARGET_REDUCTION;
  double TargetReduction = 0.9;
  double RequestedReduction = 0.9; // as set, before clamping
  vtkIdType TargetTriangleCount = 1000;
  vtkIdType RequestedTriangleCount = 1000; // as set, before clamping
  double MaximumError = 0.01;
  double RequestedMaximumError = 0.01; // as set, before clamping
  bool RelativeError = true;
  bool PreserveBoundary = false;
  bool PreserveAttributeBorders = false;
  bool CloseCracks = true;
  bool ComputeDeviation = false;
  int NumberOfThreads = 0;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  bool GenerateOriginalIds = false;
  double AchievedMaximumError = 0.0;

private:
  vtkMeshSimplificationFilter(const vtkMeshSimplificationFilter&) = delete;
  void operator=(const vtkMeshSimplificationFilter&) = delete;

  /// One piece's state from its core run to its output.
  struct PieceRun;
  /// The triangles of the pieces that share borders, and their targets, over every process.
  struct BorderTotals
  {
    double Triangles = 0.0, Target = 0.0;
    bool Warned = false; // a miss of the total is said once
  };

  bool CheckTarget();
  void RunPiece(vtkSimplification::InputPieces& run, std::size_t piece, PieceRun& state);
  void ReserveForBorders(const vtkSimplification::Piece& piece, PieceRun& state) const;
  /// The border round and the pieces' last stage, which report progress from progress on, over
  /// progressShare of it (collective).
  BorderTotals SimplifyBorders(
    vtkSimplification::InputPieces& run, std::vector<PieceRun>& states, double progress, double progressShare);
  /// The border round over the pieces that share borders: count triangles to remove.
  std::int64_t ThinBorders(vtkSimplification::InputPieces& run, std::vector<PieceRun>& states, std::int64_t count);
  bool Resimplify(const vtkSimplification::Piece& piece, std::size_t i, PieceRun& state);
  /// How many times the border round and the pieces' last stage alternate at most.
  static constexpr int MaximumBorderRounds = 3;
  void FinishPiece(vtkSimplification::InputPieces& run, std::size_t piece, PieceRun& state, BorderTotals& borders);
  void WarnAboutOutcome(const vtkSimplification::InputPieces& run, std::size_t piece, const PieceRun& state,
    BorderTotals& borders);
};

#endif
