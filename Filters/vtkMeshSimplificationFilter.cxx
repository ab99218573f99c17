// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeshSimplificationFilter.h"

#include "Simplification.h"
#include "vtkSimplificationAttributes.h"
#include "vtkSimplificationDeviation.h"
#include "vtkSimplificationDistributed.h"
#include "vtkSimplificationInput.h"
#include "vtkSimplificationPieces.h"
#include "vtkSimplificationRanges.h"
#include "vtkSimplificationThreads.h"

#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <sstream>


namespace
{
using Piece = vtkSimplification::Piece;

/// "N of the P points are locked (by ..., ...)", for a target not reached.
std::string LockNote(const Piece& piece, const meshsimp::Outcome& report, bool preserveBoundary)
{
  std::vector<std::string> causes;
  if (piece.UserLocks > 0)
  {
    causes.push_back("the Locked Points array " + piece.LockArray);
  }
  if (piece.SharedLocks > 0)
  {
    causes.push_back("shared with other pieces");
  }
  if (preserveBoundary)
  {
    causes.push_back("PreserveBoundary");
  }
  const bool every = report.LockedPoints == report.UsablePoints;
  std::string note = (every ? "every one of the " : std::to_string(report.LockedPoints) + " of the ") +
    std::to_string(report.UsablePoints) + (every ? " points is locked" : " points are locked");
  for (std::size_t i = 0; i < causes.size(); ++i)
  {
    note += (i == 0 ? " (" : ", ") + causes[i] + (i + 1 == causes.size() ? ")" : "");
  }
  return note;
}

/// A number as users typed it: no trailing zeros.
std::string Format(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}
}

vtkMeshSimplificationFilter::vtkMeshSimplificationFilter() = default;
vtkMeshSimplificationFilter::~vtkMeshSimplificationFilter() = default;

// The targets are clamped as vtkSetClampMacro would (NaN passes, for CheckTarget's error), the
// value asked for remembered for CheckTarget's warning.
void vtkMeshSimplificationFilter::SetTargetReduction(double reduction)
{
  const double clamped = reduction < 0.0 ? 0.0 : reduction > 1.0 ? 1.0 : reduction;
  if (reduction == this->RequestedReduction && clamped == this->TargetReduction)
  {
    return;
  }
  this->RequestedReduction = reduction;
  this->TargetReduction = clamped;
  this->Modified();
}

void vtkMeshSimplificationFilter::SetTargetTriangleCount(vtkIdType count)
{
  if (count == this->RequestedTriangleCount)
  {
    return;
  }
  this->RequestedTriangleCount = count;
  this->TargetTriangleCount = std::max<vtkIdType>(0, count);
  this->Modified();
}

void vtkMeshSimplificationFilter::SetMaximumError(double bound)
{
  if (bound == this->RequestedMaximumError)
  {
    return;
  }
  this->RequestedMaximumError = bound;
  this->MaximumError = bound < 0.0 ? 0.0 : bound;
  this->Modified();
}

vtkTypeBool vtkMeshSimplificationFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    vtkSimplification::MakeSurfacesOutput(vtkDataObject::GetData(inputVector[0], 0), outputVector->GetInformationObject(0));
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkMeshSimplificationFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkMeshSimplificationFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

bool vtkMeshSimplificationFilter::CheckTarget()
{
  // One line for a target that is not a number, and a warning for one that was clamped: the
  // target of the mode in force, with the value asked for and the value used.
  const struct
  {
    int Mode;
    const char* Name;
    double Requested, Used;
    const char* Range;
  } targets[] = {
    { TARGET_REDUCTION, "TargetReduction", this->RequestedReduction, this->TargetReduction,
      "outside [0, 1]" },
    { TARGET_TRIANGLE_COUNT, "TargetTriangleCount", static_cast<double>(this->RequestedTriangleCount),
      static_cast<double>(this->TargetTriangleCount), "below 0" },
    { TARGET_MAXIMUM_ERROR, "MaximumError", this->RequestedMaximumError, this->MaximumError,
      "below 0" },
  };
  for (const auto& target : targets)
  {
    if (target.Mode != this->TargetMode)
    {
      continue;
    }
    if (std::isnan(target.Used))
    {
      vtkErrorMacro(<< "Cannot simplify: " << target.Name << " is not a number.");
      return false;
    }
    if (target.Requested != target.Used)
    {
      vtkWarningMacro(<< target.Name << " " << Format(target.Requested) << " is " << target.Range
                      << ": " << Format(target.Used) << " is used.");
    }
  }
  return true;
}

/// One piece's state from its core run to its output: what the piece call refers to, and the
/// core's result.
struct vtkMeshSimplificationFilter::PieceRun
{
  meshsimp::SimplificationOptions Options;
  std::vector<std::int32_t> Regions;
  meshsimp::ExecutionContext Execution;
  meshsimp::SimplifiedMesh Mesh;
  bool Ran = false;           // the core ran to its end
  bool SharesBorders = false; // see PieceCall
  std::int64_t Share = 0;     // with SharesBorders: the piece's share of the count,
  std::int64_t BorderRemovals = 0; // and the shared points its borders are to lose

  PieceCall Call(const Piece& piece, std::size_t i) const
  {
    return PieceCall{ i, piece.Input, piece.Triangles, piece.Triangles.View, this->Options, this->Execution,
      piece.Output, this->SharesBorders, false };
  }
};

namespace
{
/// Whether the execution has a border round to wait for: pieces that share points, under a count.
bool HasBorderRound(const vtkSimplification::InputPieces& run, int targetMode)
{
  return run.Shared && targetMode != vtkMeshSimplificationFilter::TARGET_MAXIMUM_ERROR &&
    std::any_of(run.Pieces.begin(), run.Pieces.end(), [](const vtkSimplification::Piece& piece) { return piece.SharedLocks > 0; });
}
}

int vtkMeshSimplificationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The pieces, read once; what they share (collective under MPI, so every process gets here
  // whatever it holds); each piece's core; the borders between pieces (collective too); then
  // each piece's output: at once where no border round is to come (so that a piece's result is
  // not kept beyond its output), else after it. The cores take the progress up to the
  // deviation's share, per piece or for all the pieces.
  this->AchievedMaximumError = 0.0;
  vtkSimplification::InputPieces run;
  std::string problem;
  if (!vtkSimplification::CollectPieces(vtkDataObject::GetData(inputVector[0], 0), vtkDataObject::GetData(outputVector, 0), run.Pieces, problem))
  {
    vtkErrorMacro(<< "Cannot simplify: " << problem << ".");
    return 1;
  }
  if (!this->CheckTarget())
  {
    return 1;
  }
  vtkSimplification::PreparePieces(this, run);
  const double count = static_cast<double>(run.Pieces.size());
  const double coreShare = this->ComputeDeviation ? 0.8 : 1.0;
  const bool waits = HasBorderRound(run, this->TargetMode);
  const double firstStages = waits ? 0.9 * coreShare : coreShare; // then the border round's last stage
  std::vector<PieceRun> states(run.Pieces.size());
  BorderTotals borders;
  for (std::size_t i = 0; i < run.Pieces.size() && !this->GetAbortExecute(); ++i)
  {
    const double slot = static_cast<double>(i) / count;
    this->SetProgressShiftScale(waits ? firstStages * slot : slot, firstStages / count);
    this->RunPiece(run, i, states[i]);
    if (!waits)
    {
      this->SetProgressShiftScale(slot + coreShare / count, (1.0 - coreShare) / count);
      this->FinishPiece(run, i, states[i], borders);
    }
  }
  borders = this->SimplifyBorders(run, states, firstStages, coreShare - firstStages);
  for (std::size_t i = 0; i < run.Pieces.size() && waits; ++i)
  {
    this->SetProgressShiftScale(coreShare + (1.0 - coreShare) * static_cast<double>(i) / count, (1.0 - coreShare) / count);
    this->FinishPiece(run, i, states[i], borders);
  }
  this->SetProgressShiftScale(0.0, 1.0);
  return 1;
}

void vtkMeshSimplificationFilter::RunPiece(vtkSimplification::InputPieces& run, std::size_t i, PieceRun& state)
{
  Piece& piece = run.Pieces[i];
  if (!piece.Readable)
  {
    return;
  }
  // The common options: the target (this piece's share of a count), the locks and regions.
  meshsimp::SimplificationOptions& options = state.Options;
  meshsimp::Target& goal = options.Goal;
  goal.Mode = static_cast<meshsimp::TargetMode>(this->TargetMode);
  goal.Reduction = this->TargetReduction;
  goal.TriangleCount = this->TargetTriangleCount;
  const double triangles = static_cast<double>(piece.Triangles.View.NumberOfTriangles);
  if (run.Shared && run.Totals.Triangles > 0.0)
  {
    goal.TriangleCount = std::llround(static_cast<double>(this->TargetTriangleCount) * triangles / run.Totals.Triangles);
  }
  goal.MaximumError = this->MaximumError;
  goal.RelativeError = this->RelativeError;
  goal.ReferenceLength = run.Shared ? run.Totals.Diagonal : 0.0;
  goal.Tolerance = this->TargetTolerance;
  options.PreserveBoundary = this->PreserveBoundary;
  if (vtkAbstractArray* array = vtkSimplification::SelectedPointArray(this, 0, piece.Input, "Locked Points"))
  {
    piece.UserLocks = vtkSimplification::ReadLockedPoints(array, piece.Locks, piece.UserLocked);
    piece.LockArray = std::string("'") + (array->GetName() ? array->GetName() : "") + "'";
  }
  options.LockedPoints = piece.Locks.empty() ? nullptr : piece.Locks.data();
  options.CloseCracks = this->CloseCracks;
  vtkPointData* pointData = piece.Input->GetPointData();
  options.SamePointData = [pointData](std::int64_t a, std::int64_t b) {
    return vtkSimplification::SamePointData(pointData, a, b);
  };
  if (this->PreserveAttributeBorders)
  {
    vtkAbstractArray* array = vtkSimplification::SelectedPointArray(this, 1, piece.Input, "attribute borders");
    if (array)
    {
      state.Regions = vtkSimplification::ReadRegions(array);
      options.Regions = state.Regions.data();
    }
    else
    {
      vtkWarningMacro(<< run.Name(i) << "PreserveAttributeBorders is on, but no point array is chosen for it.");
    }
  }
  this->ReserveForBorders(piece, state);

  state.Execution = vtkSimplification::MakeExecutionContext(this, this->NumberOfThreads);
  const bool none = (this->TargetMode == TARGET_REDUCTION && this->TargetReduction == 1.0) ||
    (this->TargetMode == TARGET_TRIANGLE_COUNT && this->TargetTriangleCount == 0);
  if (none)
  {
    vtkWarningMacro(<< run.Name(i) << "The output is empty: "
                    << (this->TargetMode == TARGET_REDUCTION ? "TargetReduction 1" : "TargetTriangleCount 0")
                    << " asks for no triangle.");
  }
  else if (!this->RunCore(state.Call(piece, i), state.Mesh))
  {
    vtkWarningMacro(<< run.Name(i) << "Aborted: the output is empty.");
    state.Mesh = meshsimp::SimplifiedMesh();
  }
  else
  {
    state.Ran = true;
  }
}

void vtkMeshSimplificationFilter::ReserveForBorders(const Piece& piece, PieceRun& state) const
{
  // A piece whose points are shared with other pieces keeps them through its core, so its
  // border keeps the input's resolution. Its core aims at its share plus two triangles a shared
  // point (the fans along a locked border; with less, the interior is drawn onto the border). The
  // border round then removes the shared points a border loses when a count keeps a fraction f
  // of the triangles: all but b √f of b (a border's points thin out as a length, the triangles
  // as an area); last, the piece is taken to its share with its thinned border locked.
  meshsimp::Target& goal = state.Options.Goal;
  if (goal.Bounded() || piece.SharedLocks == 0)
  {
    return;
  }
  const std::int64_t triangles = piece.Triangles.View.NumberOfTriangles;
  state.SharesBorders = true;
  state.Share = goal.TriangleCountFor(triangles);
  const double kept = static_cast<double>(state.Share) / static_cast<double>(std::max<std::int64_t>(1, triangles));
  state.BorderRemovals = std::llround(static_cast<double>(piece.SharedLocks) * (1.0 - std::sqrt(kept)));
  goal.SetTriangleCount(std::min(triangles, state.Share + 2 * piece.SharedLocks));
}

vtkMeshSimplificationFilter::BorderTotals vtkMeshSimplificationFilter::SimplifyBorders(
  vtkSimplification::InputPieces& run, std::vector<PieceRun>& states, double progress, double progressShare)
{
  // Collective: every process takes part whatever its pieces, under a count target. The border
  // round, then each piece to its share; where pieces stay above (a piece's part cut off by the
  // borders can only lose border points), again with the excess as the border round's count.
  BorderTotals totals;
  if (!run.Shared || this->TargetMode == TARGET_MAXIMUM_ERROR)
  {
    return totals;
  }
  double removals = 0.0;
  for (const PieceRun& state : states)
  {
    removals += state.Ran && state.SharesBorders ? static_cast<double>(state.BorderRemovals) : 0.0;
  }
  std::int64_t count = std::llround(vtkSimplification::SumOverProcesses(removals));
  for (int round = 0; round < MaximumBorderRounds && (round == 0 || count > 0); ++round)
  {
    const std::int64_t removed = this->ThinBorders(run, states, count);
    double local[2] = { 0.0, 0.0 };
    for (std::size_t i = 0; i < states.size() && !this->GetAbortExecute(); ++i)
    {
      PieceRun& state = states[i];
      if (state.Ran && state.SharesBorders)
      {
        // The first time, each piece in its slot of the progress; later (rarely, and smaller) at its end.
        const double slot = progressShare / static_cast<double>(states.size());
        this->SetProgressShiftScale(progress + (round == 0 ? slot * static_cast<double>(i) : progressShare),
          round == 0 ? slot : 0.0);
        state.Ran = this->Resimplify(run.Pieces[i], i, state);
        local[0] += static_cast<double>(state.Mesh.NumberOfTriangles());
        local[1] += static_cast<double>(state.Share);
      }
    }
    totals.Triangles = vtkSimplification::SumOverProcesses(local[0]);
    totals.Target = vtkSimplification::SumOverProcesses(local[1]);
    const double slack = this->TargetTolerance * totals.Target;
    count = removed > 0 && totals.Triangles > totals.Target + slack ? std::llround(totals.Triangles - totals.Target) : 0;
  }
  return totals;
}

std::int64_t vtkMeshSimplificationFilter::ThinBorders(
  vtkSimplification::InputPieces& run, std::vector<PieceRun>& states, std::int64_t count)
{
  std::vector<meshsimp::PieceBorders> sides;
  std::deque<std::vector<std::uint8_t>> locks; // (a deque: the sides keep pointers to them)
  sides.reserve(states.size());
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    PieceRun& state = states[i];
    if (state.Ran && state.SharesBorders)
    {
      // The shared points the round may remove: not those the user locked too.
      const Piece& piece = run.Pieces[i];
      std::vector<std::uint8_t>& movable = locks.emplace_back(piece.Locks);
      for (std::size_t p = 0; p < piece.UserLocked.size(); ++p)
      {
        movable[p] = piece.UserLocked[p] ? 1 : movable[p];
      }
      sides.emplace_back(state.Mesh, piece.Triangles.View, movable.data(), state.Options.Regions,
        static_cast<double>(piece.Key));
    }
  }
  std::vector<meshsimp::PieceBorders*> pieces;
  for (meshsimp::PieceBorders& side : sides)
  {
    pieces.push_back(&side);
  }
  return meshsimp::SimplifySharedBorders(pieces, count, vtkSimplification::MakeBorderExchange());
}

bool vtkMeshSimplificationFilter::Resimplify(const Piece& piece, std::size_t i, PieceRun& state)
{
  // The core again, on the piece's result, to the piece's share: each of its points takes the
  // locks and region of the input point it stands for.
  meshsimp::SimplifiedMesh& first = state.Mesh;
  state.Mesh.Report.TargetTriangles = state.Share;
  if (first.NumberOfTriangles() <= state.Share)
  {
    return true;
  }
  const std::int64_t points = first.NumberOfPoints();
  std::vector<std::uint8_t> locks(static_cast<std::size_t>(points), 0);
  std::vector<std::int32_t> regions(state.Regions.empty() ? 0 : static_cast<std::size_t>(points));
  for (std::int64_t p = 0; p < points; ++p)
  {
    const std::int32_t source = first.Representative(p);
    locks[p] = piece.Locks.empty() ? 0 : piece.Locks[source];
    if (!regions.empty())
    {
      regions[p] = state.Regions[source];
    }
  }
  meshsimp::SimplificationOptions options = state.Options;
  options.Goal.SetTriangleCount(state.Share);
  options.LockedPoints = locks.data();
  options.Regions = regions.empty() ? nullptr : regions.data();
  options.CloseCracks = false;
  options.SamePointData = nullptr;
  const meshsimp::TriangleMeshView mesh{ first.Points.data(), points, first.Triangles.data(), first.NumberOfTriangles() };
  const PieceCall call{ i, piece.Input, piece.Triangles, mesh, options, state.Execution, piece.Output, true, true };
  meshsimp::SimplifiedMesh second;
  if (!this->RunCore(call, second))
  {
    vtkWarningMacro(<< "Aborted: the output is empty.");
    first = meshsimp::SimplifiedMesh();
    return false;
  }
  meshsimp::ComposeSources(first, std::move(second));
  return true;
}

void vtkMeshSimplificationFilter::FinishPiece(
  vtkSimplification::InputPieces& run, std::size_t i, PieceRun& state, BorderTotals& borders)
{
  const Piece& piece = run.Pieces[i];
  if (!piece.Readable)
  {
    return;
  }
  const meshsimp::SimplifiedMesh& mesh = state.Mesh;
  const PieceCall call = state.Call(piece, i);
  if (state.Ran)
  {
    this->WarnAboutOutcome(run, i, state, borders);
  }
  this->WritePiece(call, mesh);
  if (mesh.Report.MaximumError >= 0.0)
  {
    const double error = state.Options.Goal.InBoundUnits(mesh.Report.MaximumError, mesh.Report.Diagonal);
    this->AchievedMaximumError = std::max(this->AchievedMaximumError, error);
    vtkSimplification::AddFieldValue(piece.Output, "MaximumError", error);
  }
  if (mesh.Report.JoinedPoints > 0)
  {
    vtkSimplification::AddFieldValue(piece.Output, "JoinedPoints", static_cast<double>(mesh.Report.JoinedPoints));
  }
  if (this->ComputeDeviation && !this->GetAbortExecute() && !this->AddDeviation(call, mesh))
  {
    vtkWarningMacro(<< run.Name(i) << "Aborted: the output has no Deviation.");
  }
  if (!this->GetAbortExecute())
  {
    vtkSimplification::RecordOutputRanges(piece.Input, piece.Output, call.Execution);
  }
}

void vtkMeshSimplificationFilter::ForEachSetting(const meshsimp::SettingVisit& visit)
{
  // The common settings, each with its setter's range (a flag: 0 or 1; the setters call
  // Modified on a change), then the filter's own.
  const auto flag = [this, &visit](const char* name, bool value, void (vtkMeshSimplificationFilter::*set)(bool),
                      bool (vtkMeshSimplificationFilter::*get)(), const char* help) {
    visit(meshsimp::SettingEntry{ name, value ? 1.0 : 0.0, 0.0, 1.0, help, [this, set, get](double v) {
                                   (this->*set)(v != 0.0);
                                   return (this->*get)() ? 1.0 : 0.0;
                                 } });
  };
  const auto number = [this, &visit](const char* name, int value, int minimum, int maximum,
                        void (vtkMeshSimplificationFilter::*set)(int), int (vtkMeshSimplificationFilter::*get)(),
                        const char* help) {
    visit(meshsimp::SettingEntry{ name, double(value), double(minimum), double(maximum), help,
      [this, set, get, minimum, maximum](double v) {
        (this->*set)(static_cast<int>(std::min(std::max(v, double(minimum)), double(maximum))));
        return double((this->*get)());
      } });
  };
  flag("PreserveBoundary", this->PreserveBoundary, &vtkMeshSimplificationFilter::SetPreserveBoundary,
    &vtkMeshSimplificationFilter::GetPreserveBoundary,
    "Keep every point of an open border where it is, so the outline of a terrain or an open scan keeps its shape.");
  flag("CloseCracks", this->CloseCracks, &vtkMeshSimplificationFilter::SetCloseCracks,
    &vtkMeshSimplificationFilter::GetCloseCracks,
    "Close zero-width cracks before simplifying: two points at the same position on the two sides of a crack "
    "become one point.");
  flag("ComputeDeviation", this->ComputeDeviation, &vtkMeshSimplificationFilter::SetComputeDeviation,
    &vtkMeshSimplificationFilter::GetComputeDeviation,
    "Add the point array Deviation (input units): how far the output stands off the input around each output "
    "point, both ways.");
  flag("GenerateOriginalIds", this->GenerateOriginalIds, &vtkMeshSimplificationFilter::SetGenerateOriginalIds,
    &vtkMeshSimplificationFilter::GetGenerateOriginalIds,
    "Add the point array vtkOriginalPointIds (each output point's representative input point) and the cell "
    "array vtkOriginalCellIds (each output triangle's input cell), as Extract Surface names them, and the field "
    "data InputToOutputPointIds (each input point's output point), which LoD Interpolation's Exact reads.");
  number("OutputPointsPrecision", this->OutputPointsPrecision, vtkAlgorithm::SINGLE_PRECISION,
    vtkAlgorithm::DEFAULT_PRECISION, &vtkMeshSimplificationFilter::SetOutputPointsPrecision,
    &vtkMeshSimplificationFilter::GetOutputPointsPrecision, "Precision of the output points.");
  number("NumberOfThreads", this->NumberOfThreads, this->GetNumberOfThreadsMinValue(),
    this->GetNumberOfThreadsMaxValue(), &vtkMeshSimplificationFilter::SetNumberOfThreads,
    &vtkMeshSimplificationFilter::GetNumberOfThreads, "Threads (0: all cores).");
  this->ForEachOwnSetting(visit);
}

bool vtkMeshSimplificationFilter::SetSettingByName(const std::string& name, double value)
{
  bool found = false;
  this->ForEachSetting([&](const meshsimp::SettingEntry& entry) {
    if (!found && name == entry.Name && std::isfinite(value))
    {
      found = true;
      if (entry.Set(value) != entry.Value)
      {
        this->Modified(); // (a common setting's setter has already)
      }
    }
  });
  return found;
}

void vtkMeshSimplificationFilter::ForEachOwnSetting(const meshsimp::SettingVisit&) {}

void vtkMeshSimplificationFilter::WritePiece(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh)
{
  vtkSimplification::SetOutput(
    piece.Input, piece.Triangles, mesh, this->OutputPointsPrecision, this->GenerateOriginalIds, piece.Output);
}

bool vtkMeshSimplificationFilter::AddDeviation(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh)
{
  return vtkSimplification::AddDeviation(piece.Mesh, mesh, piece.Output, piece.Execution);
}

void vtkMeshSimplificationFilter::WarnAboutOutcome(const vtkSimplification::InputPieces& run, std::size_t i,
  const PieceRun& state, BorderTotals& borders)
{
  // The count's miss first, with its reason, then what the algorithm changed to get there, then
  // what it left out of the input. Pieces that share borders are judged together.
  const meshsimp::SimplifiedMesh& mesh = state.Mesh;
  const meshsimp::Outcome& report = mesh.Report;
  const std::int64_t count = state.SharesBorders ? std::llround(borders.Triangles) : mesh.NumberOfTriangles();
  const std::int64_t target = state.SharesBorders ? std::llround(borders.Target) : report.TargetTriangles;
  const std::int64_t slack = std::max<std::int64_t>(1, static_cast<std::int64_t>(this->TargetTolerance * static_cast<double>(target)));
  const bool missed = this->TargetMode != TARGET_MAXIMUM_ERROR && std::abs(count - target) > slack;
  const bool said = state.SharesBorders && borders.Warned; // the pieces' total is said once
  borders.Warned = borders.Warned || (state.SharesBorders && (missed || report.Stop == meshsimp::StopReason::AllLocked));
  if (!said && (missed || report.Stop == meshsimp::StopReason::AllLocked))
  {
    std::string reason = report.Stop == meshsimp::StopReason::AllLocked ? LockNote(run.Pieces[i], report, this->PreserveBoundary)
      : !report.Reason.empty() ? report.Reason
      : state.SharesBorders    ? "the borders between the pieces could not be simplified further"
                               : "no change that keeps the mesh valid is left";
    if (report.LockedPoints > 0 && report.Stop != meshsimp::StopReason::AllLocked)
    {
      reason += "; " + LockNote(run.Pieces[i], report, this->PreserveBoundary);
    }
    vtkWarningMacro(<< run.Name(i) << (state.SharesBorders ? "The pieces together reached " : "Reached ") << count
                    << " triangles where " << target << " were asked for: " << reason << ".");
  }
  const std::string lead = this->TargetMode == TARGET_MAXIMUM_ERROR
    ? "Under MaximumError " + Format(this->MaximumError) + ", "
    : "To reach " + std::to_string(target) + " triangles, ";
  for (const std::string& note : report.Notes)
  {
    vtkWarningMacro(<< run.Name(i) << lead << note << ".");
  }
  if (report.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< run.Name(i) << "Ignoring the triangles of " << report.NonFinitePoints
                    << " points with NaN or infinite coordinates.");
  }
}

void vtkMeshSimplificationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetMode: " << this->TargetMode << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetTriangleCount: " << this->TargetTriangleCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RelativeError: " << this->RelativeError << "\n";
  os << indent << "PreserveBoundary: " << this->PreserveBoundary << "\n";
  os << indent << "PreserveAttributeBorders: " << this->PreserveAttributeBorders << "\n";
  os << indent << "CloseCracks: " << this->CloseCracks << "\n";
  os << indent << "ComputeDeviation: " << this->ComputeDeviation << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "GenerateOriginalIds: " << this->GenerateOriginalIds << "\n";
  os << indent << "AchievedMaximumError: " << this->AchievedMaximumError << "\n";
}
