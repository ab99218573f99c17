// SPDX-License-Identifier: BSD-3-Clause
#include "vtkProgressiveMesh.h"

#include "ProgressiveMesh.h"
#include "vtkSimplificationAttributes.h"
#include "vtkSimplificationDeviation.h"
#include "vtkSimplificationInput.h"

#include "vtkCellData.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numeric>
#include <sstream>

vtkStandardNewMacro(vtkProgressiveMesh);

/// The sequences of the last input, one per piece, and what they were built from.
struct vtkProgressiveMesh::Cache
{
  std::string Key; // the input's modification time and the properties the build depends on
  int Precision = -1;       // the OutputPointsPrecision Wholes were written with
  bool OriginalIds = false; // and GenerateOriginalIds
  std::vector<meshsimp::ProgressiveMesh> Pieces;
  std::vector<bool> Ready;
  /// Per piece, the whole sequence as a mesh (made once, at the first level written): levels are
  /// views of its first points and triangles, and output port 1 shows piece 0's.
  std::vector<vtkSmartPointer<vtkPolyData>> Wholes;
  /// Per piece of this update, the points of the level the target picked (written from the
  /// whole), or -1 when RunCore extracted it in full (see WritePiece); empty before RunCore.
  std::vector<std::int64_t> Levels;
  /// Per piece of this update, the output WritePiece wrote (to place its sequence on port 1).
  std::vector<vtkPolyData*> Outputs;
  /// Per piece, two buffers of the whole's corner count that levels' corners are views of: a
  /// level is written into one that no level shows any more (reference count 1: the views hold
  /// it), so a switch writes into memory already mapped instead of fresh pages.
  std::vector<std::array<vtkSmartPointer<vtkCellArray::ArrayType64>, 2>> CornerBuffers;
  /// Per piece, the input side of the deviation, made at the first level that measures it.
  std::vector<std::unique_ptr<meshsimp::DeviationInput>> DeviationInputs;
};

namespace
{
/// The arrays a sequence written by output port 1 carries.
const char* const ParentName = "Parent";
const char* const RemovedAtName = "RemovedAt";
const char* const ErrorName = "CollapseError";

/// The modification times of what a build and its output read in every leaf of the input: points,
/// cells, point and cell arrays, and which arrays are the active normals. Unlike the input's own time they survive shallow copies, such
/// as the one ParaView's vtkPVPostFilter makes of every filter's input at each update.
std::string InputStamp(vtkDataObject* input)
{
  std::ostringstream stamp;
  const auto add = [&stamp](vtkDataObject* leaf) {
    auto* points = vtkPointSet::SafeDownCast(leaf);
    if (!points)
    {
      stamp << (leaf ? leaf->GetMTime() : 0) << ';';
      return;
    }
    stamp << (points->GetPoints() ? points->GetPoints()->GetMTime() : 0) << ',';
    if (auto* surface = vtkPolyData::SafeDownCast(leaf))
    {
      for (vtkCellArray* cells : { surface->GetVerts(), surface->GetLines(), surface->GetPolys(), surface->GetStrips() })
      {
        stamp << cells->GetMTime() << ',';
      }
    }
    else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(leaf))
    {
      stamp << (grid->GetCells() ? grid->GetCells()->GetMTime() : 0) << ',' << (grid->GetCellTypesArray() ? grid->GetCellTypesArray()->GetMTime() : 0) << ',';
    }
    else
    {
      stamp << leaf->GetMTime() << ',';
    }
    for (vtkDataSetAttributes* arrays : { static_cast<vtkDataSetAttributes*>(points->GetPointData()),
           static_cast<vtkDataSetAttributes*>(points->GetCellData()) })
    {
      for (int i = 0; i < arrays->GetNumberOfArrays(); ++i)
      {
        vtkAbstractArray* array = arrays->GetAbstractArray(i);
        stamp << (array ? array->GetMTime() : 0) << ',';
      }
      vtkDataArray* normals = arrays->GetNormals(); // which are recomputed (SetPrefixOutput)
      stamp << (normals ? normals->GetName() ? normals->GetName() : "(unnamed)" : "(none)") << '|';
    }
    stamp << ';';
  };
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> leaf = vtk::TakeSmartPointer(composite->NewIterator());
    for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
    {
      add(leaf->GetCurrentDataObject());
    }
  }
  else
  {
    add(input);
  }
  return stamp.str();
}

bool IsSequence(vtkPolyData* input)
{
  return input->GetPointData()->GetArray(ParentName) && input->GetCellData()->GetArray(RemovedAtName);
}

/// A sequence from the arrays of output port 1 read back: points and triangles as they are.
/// Empty when the arrays form one, else what is wrong.
std::string ReadSequence(vtkPolyData* input, const meshsimp::TriangleMeshView& mesh, meshsimp::ProgressiveMesh& sequence)
{
  vtkDataArray* parent = input->GetPointData()->GetArray(ParentName);
  vtkDataArray* removedAt = input->GetCellData()->GetArray(RemovedAtName);
  vtkDataArray* error = input->GetPointData()->GetArray(ErrorName);
  const vtkIdType n = mesh.NumberOfPoints, m = mesh.NumberOfTriangles;
  if (m != input->GetNumberOfCells() || removedAt->GetNumberOfTuples() != m)
  {
    return "its cells are not the sequence's triangles";
  }
  if (!error || error->GetNumberOfTuples() != n || parent->GetNumberOfTuples() != n)
  {
    return "its point arrays Parent and CollapseError do not cover its points";
  }
  // An index as the file has it, or -2 (which no check accepts) for what is none.
  const auto index = [](double value) {
    return value >= -1.0 && value < static_cast<double>(VTK_INT_MAX) && value == std::floor(value)
      ? static_cast<std::int32_t>(value) : -2;
  };
  sequence = meshsimp::ProgressiveMesh();
  sequence.InputPoint.resize(n);
  std::iota(sequence.InputPoint.begin(), sequence.InputPoint.end(), 0);
  sequence.Parent.resize(n);
  sequence.Error.resize(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    sequence.Parent[p] = index(parent->GetComponent(p, 0));
    sequence.Error[p] = error->GetComponent(p, 0);
  }
  while (sequence.BasePoints < n && sequence.Parent[sequence.BasePoints] == -1)
  {
    ++sequence.BasePoints;
  }
  sequence.Triangles.resize(3 * m);
  for (vtkIdType i = 0; i < 3 * m; ++i)
  {
    sequence.Triangles[i] = static_cast<std::int32_t>(mesh.Id(i));
  }
  sequence.InputTriangle.resize(m);
  std::iota(sequence.InputTriangle.begin(), sequence.InputTriangle.end(), 0);
  sequence.RemovedBy.resize(m);
  for (vtkIdType t = 0; t < m; ++t)
  {
    sequence.RemovedBy[t] = index(removedAt->GetComponent(t, 0));
  }
  sequence.Report.UsableTriangles = m;
  sequence.Report.UsablePoints = n;
  sequence.Report.Diagonal = input->GetLength();
  return sequence.Validate(n);
}

bool HasNormals(vtkPolyData* mesh)
{
  return mesh->GetPointData()->GetNormals() || mesh->GetCellData()->GetNormals();
}

/// A buffer of the pool that no view holds (made, of size values, at its first use), else a new
/// one outside the pool (both are still shown, by levels consumers hold).
vtkSmartPointer<vtkCellArray::ArrayType64> FreeBuffer(
  std::array<vtkSmartPointer<vtkCellArray::ArrayType64>, 2>& pool, vtkIdType size)
{
  for (vtkSmartPointer<vtkCellArray::ArrayType64>& buffer : pool)
  {
    if (!buffer)
    {
      buffer = vtkSmartPointer<vtkCellArray::ArrayType64>::New();
      buffer->SetNumberOfValues(size); // its pages are mapped as levels write them
    }
    if (buffer->GetReferenceCount() == 1)
    {
      return buffer;
    }
  }
  auto spare = vtkSmartPointer<vtkCellArray::ArrayType64>::New();
  spare->SetNumberOfValues(size);
  return spare;
}

/// What the front end needs of a level that WritePiece writes from the whole sequence's mesh:
/// the outcome, the level's triangles' sources (their count) and field values. Returns the
/// level's points.
std::int64_t LevelToWrite(const meshsimp::ProgressiveMesh& sequence, const meshsimp::Target& goal,
  meshsimp::SimplifiedMesh& result)
{
  result = meshsimp::SimplifiedMesh();
  result.Report = sequence.Report;
  const std::int64_t points = meshsimp::LevelFor(sequence, goal, result.Report);
  const std::int64_t triangles = sequence.TrianglesAt(points);
  result.TriangleSource.assign(sequence.InputTriangle.begin(), sequence.InputTriangle.begin() + triangles);
  result.FieldValues = { { "LevelTriangles", static_cast<double>(triangles) },
    { "LevelPoints", static_cast<double>(points) } };
  return points;
}

/// The whole sequence as a mesh for output port 1: every point, in collapse order, every
/// triangle, and the arrays that let it be read back.
meshsimp::SimplifiedMesh WholeSequence(const meshsimp::ProgressiveMesh& sequence, const meshsimp::TriangleMeshView& mesh)
{
  meshsimp::SimplifiedMesh whole;
  meshsimp::ExtractLevel(sequence, sequence.NumberOfPoints(), mesh, whole); // every point and triangle
  whole.FieldValues.clear();
  whole.AddPointArray(ParentName, std::vector<double>(sequence.Parent.begin(), sequence.Parent.end()),
    meshsimp::NamedArray::Kind::Integer);
  whole.AddPointArray(ErrorName, sequence.Error);
  return whole;
}
}

vtkProgressiveMesh::vtkProgressiveMesh()
  : Sequences(new Cache)
{
  this->SetNumberOfOutputPorts(2);
}

vtkProgressiveMesh::~vtkProgressiveMesh() = default;

vtkPolyData* vtkProgressiveMesh::GetSequenceOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkProgressiveMesh::FillOutputPortInformation(int port, vtkInformation* info)
{
  return this->Superclass::FillOutputPortInformation(port, info); // both ports: the input's kind
}

vtkTypeBool vtkProgressiveMesh::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  const vtkTypeBool result = this->Superclass::ProcessRequest(request, inputVector, outputVector);
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    // Port 1 is of port 0's kind: a polydata, or a composite dataset of the input's structure.
    vtkDataObject* levels = outputVector->GetInformationObject(0)->Get(vtkDataObject::DATA_OBJECT());
    vtkInformation* info = outputVector->GetInformationObject(1);
    vtkDataObject* sequences = info->Get(vtkDataObject::DATA_OBJECT());
    if (levels && (!sequences || sequences->GetDataObjectType() != levels->GetDataObjectType()))
    {
      info->Set(vtkDataObject::DATA_OBJECT(), vtk::TakeSmartPointer(levels->NewInstance()));
    }
  }
  return result;
}

int vtkProgressiveMesh::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The cached sequences serve while the input and every property the build depends on are
  // unchanged; another OutputPointsPrecision or GenerateOriginalIds only writes the whole
  // sequences' meshes again.
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  std::ostringstream key;
  key.precision(17);
  key << InputStamp(input) << ' ' << this->PreserveBoundary << ' ' << this->PreserveAttributeBorders << ' '
      << this->CloseCracks;
  meshsimp::ProgressiveMeshParameters::ForEach(static_cast<const meshsimp::ProgressiveMeshParameters&>(*this),
    [&key](const char*, const auto& value, double, double, const char*) { key << ' ' << meshsimp::AsNumber(value); });
  for (int index = 0; index < 3; ++index)
  {
    vtkInformation* selection = this->GetInputArrayInformation(index);
    key << " '" << (selection->Has(vtkDataObject::FIELD_NAME()) ? selection->Get(vtkDataObject::FIELD_NAME()) : "")
        << "' " << (selection->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()) ? selection->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()) : -1);
  }
  if (key.str() != this->Sequences->Key)
  {
    *this->Sequences = Cache();
    this->Sequences->Key = key.str();
  }
  if (this->Sequences->Precision != this->OutputPointsPrecision ||
    this->Sequences->OriginalIds != this->GenerateOriginalIds)
  {
    this->Sequences->Wholes.clear();
    this->Sequences->Precision = this->OutputPointsPrecision;
    this->Sequences->OriginalIds = this->GenerateOriginalIds;
  }
  this->Sequences->Levels.clear();
  this->Sequences->Outputs.clear();
  vtkDataObject* sequences = vtkDataObject::GetData(outputVector, 1);
  sequences->Initialize();
  const int result = this->Superclass::RequestData(request, inputVector, outputVector);
  this->WriteSequences(vtkDataObject::GetData(outputVector, 0), sequences);
  return result;
}

void vtkProgressiveMesh::WriteSequences(vtkDataObject* levels, vtkDataObject* sequences)
{
  // Each piece's whole sequence where port 0 has its level: the polydata itself, or the same
  // place in a composite dataset of port 0's structure.
  const Cache& cache = *this->Sequences;
  const auto sequenceOf = [&cache](vtkDataObject* level) -> vtkPolyData* {
    const auto found = std::find(cache.Outputs.begin(), cache.Outputs.end(), level);
    const std::size_t i = static_cast<std::size_t>(found - cache.Outputs.begin());
    return found != cache.Outputs.end() && i < cache.Wholes.size() ? cache.Wholes[i].Get() : nullptr;
  };
  auto* compositeLevels = vtkCompositeDataSet::SafeDownCast(levels);
  auto* compositeSequences = vtkCompositeDataSet::SafeDownCast(sequences);
  if (!compositeLevels || !compositeSequences)
  {
    vtkPolyData* whole = sequenceOf(levels);
    if (whole && vtkPolyData::SafeDownCast(sequences))
    {
      sequences->ShallowCopy(whole);
    }
    return;
  }
  compositeSequences->CopyStructure(compositeLevels);
  vtkSmartPointer<vtkCompositeDataIterator> leaf = vtk::TakeSmartPointer(compositeLevels->NewIterator());
  for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
  {
    if (vtkPolyData* whole = sequenceOf(leaf->GetCurrentDataObject()))
    {
      vtkNew<vtkPolyData> copy;
      copy->ShallowCopy(whole);
      compositeSequences->SetDataSet(leaf, copy);
    }
  }
}

bool vtkProgressiveMesh::RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result)
{
  // The piece's sequence: read from a sequence given as input, cached, or built; then the level
  // the target picks. The border round's last stage, on the piece's first result, builds a
  // sequence of its own that is not kept (weighing geometry alone).
  if (piece.OnFirstResult)
  {
    meshsimp::ProgressiveMeshOptions options;
    static_cast<meshsimp::SimplificationOptions&>(options) = piece.Common;
    static_cast<meshsimp::ProgressiveMeshParameters&>(options) = *this;
    meshsimp::ProgressiveMesh sequence;
    if (!meshsimp::BuildProgressiveMesh(piece.Mesh, options, sequence, piece.Execution))
    {
      return false;
    }
    meshsimp::ExtractTarget(sequence, piece.Common.Goal, piece.Mesh, result);
    return true;
  }
  Cache& cache = *this->Sequences;
  const std::size_t i = piece.Index;
  const meshsimp::TriangleMeshView& mesh = piece.Triangles.View;
  cache.Pieces.resize(std::max(cache.Pieces.size(), i + 1));
  cache.Ready.resize(cache.Pieces.size(), false);
  meshsimp::ProgressiveMesh& sequence = cache.Pieces[i];
  if (!cache.Ready[i] && IsSequence(piece.Input))
  {
    const std::string problem = ReadSequence(piece.Input, mesh, sequence);
    cache.Ready[i] = problem.empty();
    if (!problem.empty())
    {
      vtkWarningMacro(<< "The input has the arrays of a sequence, but " << problem << ": building it anew.");
    }
  }
  if (!cache.Ready[i])
  {
    meshsimp::ProgressiveMeshOptions options;
    static_cast<meshsimp::SimplificationOptions&>(options) = piece.Common;
    static_cast<meshsimp::ProgressiveMeshParameters&>(options) = *this;
    std::vector<double> extra;
    if (auto* array = vtkDataArray::SafeDownCast(
          vtkSimplification::SelectedPointArray(this, 2, piece.Input, "attribute coordinates")))
    {
      const int k = array->GetNumberOfComponents();
      extra.resize(static_cast<std::size_t>(array->GetNumberOfTuples()) * k);
      for (vtkIdType p = 0; p < array->GetNumberOfTuples(); ++p)
      {
        array->GetTuple(p, extra.data() + p * k);
      }
      const auto range = std::minmax_element(extra.begin(), extra.end());
      const double span = extra.empty() ? 0.0 : *range.second - *range.first;
      options.ExtraCoordinates = extra.data();
      options.ExtraDimension = k;
      options.ExtraScale = vtkUnsignedCharArray::SafeDownCast(array) ? 255.0 : (span > 0.0 ? span : 1.0);
    }
    if (!meshsimp::BuildProgressiveMesh(mesh, options, sequence, piece.Execution))
    {
      return false;
    }
    cache.Ready[i] = true;
    ++this->NumberOfBuilds;
  }
  cache.Levels.resize(cache.Pieces.size(), -1);
  cache.Levels[i] = -1;
  // Normals are recomputed from the level's own mesh, and the border round edits the mesh: then
  // it is extracted in full.
  const bool normals = i < cache.Wholes.size() && cache.Wholes[i] ? HasNormals(cache.Wholes[i]) : HasNormals(piece.Input);
  if (!normals && !piece.SharesBorders)
  {
    cache.Levels[i] = LevelToWrite(sequence, piece.Common.Goal, result);
    return true;
  }
  meshsimp::ExtractTarget(sequence, piece.Common.Goal, mesh, result);
  return true;
}

void vtkProgressiveMesh::WritePiece(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh)
{
  // The level from the first points and triangles of the whole sequence's mesh, made now if it
  // is not yet; a piece without a sequence (aborted, nothing asked for) the usual way, and one
  // the border round edited the usual way beside its sequence.
  Cache& cache = *this->Sequences;
  const std::size_t i = piece.Index;
  vtkPolyData* output = piece.Output;
  cache.Outputs.resize(std::max(cache.Outputs.size(), i + 1), nullptr);
  cache.Outputs[i] = output;
  const bool lean = i < cache.Levels.size() && cache.Levels[i] >= 0;
  if (i >= cache.Ready.size() || !cache.Ready[i] || (!lean && mesh.NumberOfPoints() == 0))
  {
    this->Superclass::WritePiece(piece, mesh);
    return;
  }
  const meshsimp::ProgressiveMesh& sequence = cache.Pieces[i];
  cache.Wholes.resize(cache.Ready.size());
  vtkSmartPointer<vtkPolyData>& whole = cache.Wholes[i];
  if (!whole)
  {
    whole = vtkSmartPointer<vtkPolyData>::New();
    vtkSimplification::SetOutput(piece.Input, piece.Triangles, WholeSequence(sequence, piece.Triangles.View),
      this->OutputPointsPrecision, this->GenerateOriginalIds, whole);
    vtkNew<vtkIntArray> removedAt;
    removedAt->SetName(RemovedAtName);
    removedAt->SetNumberOfValues(static_cast<vtkIdType>(sequence.RemovedBy.size()));
    std::copy(sequence.RemovedBy.begin(), sequence.RemovedBy.end(), removedAt->GetPointer(0));
    whole->GetCellData()->AddArray(removedAt);
    whole->GetFieldData()->Initialize();
  }
  if (piece.SharesBorders)
  {
    this->Superclass::WritePiece(piece, mesh);
    return;
  }
  const std::int64_t points = lean ? cache.Levels[i] : mesh.NumberOfPoints();
  cache.CornerBuffers.resize(cache.Ready.size());
  const vtkSmartPointer<vtkDataArray> view = vtkSimplification::PrefixView(
    FreeBuffer(cache.CornerBuffers[i], static_cast<vtkIdType>(sequence.Triangles.size())), 3 * sequence.TrianglesAt(points));
  auto* corners = vtkCellArray::ArrayType64::SafeDownCast(view);
  meshsimp::LevelCorners(sequence, points, corners->GetPointer(0));
  vtkSimplification::SetPrefixOutput(piece.Input, piece.Triangles, whole, points, corners, mesh, output);
  if (this->GenerateOriginalIds && !piece.Input->GetPointData()->GetAbstractArray(vtkSimplification::SurfacePointIdsName))
  {
    meshsimp::SimplifiedMesh level; // the removed points each level point stands for
    meshsimp::ListLevelSources(sequence, points, level);
    vtkSimplification::AddInputToOutputIds(level, piece.Triangles.View, output);
  }
  for (const char* name : { ParentName, ErrorName })
  {
    output->GetPointData()->RemoveArray(name);
  }
  output->GetCellData()->RemoveArray(RemovedAtName);
}

bool vtkProgressiveMesh::AddDeviation(const PieceCall& piece, const meshsimp::SimplifiedMesh& mesh)
{
  Cache& cache = *this->Sequences;
  const std::size_t i = piece.Index;
  if (i >= cache.Ready.size() || !cache.Ready[i] || piece.SharesBorders)
  {
    return this->Superclass::AddDeviation(piece, mesh);
  }
  const meshsimp::ProgressiveMesh& sequence = cache.Pieces[i];
  const bool lean = i < cache.Levels.size() && cache.Levels[i] >= 0;
  const std::int64_t points = lean ? cache.Levels[i] : mesh.NumberOfPoints();
  meshsimp::SimplifiedMesh level;
  meshsimp::ExtractLevel(sequence, points, piece.Triangles.View, level);
  meshsimp::ListLevelSources(sequence, points, level);
  cache.DeviationInputs.resize(std::max(cache.DeviationInputs.size(), i + 1));
  std::unique_ptr<meshsimp::DeviationInput>& side = cache.DeviationInputs[i];
  if (!side)
  {
    side = std::make_unique<meshsimp::DeviationInput>(piece.Triangles.View);
  }
  return vtkSimplification::AddDeviation(*side, level, piece.Output, piece.Execution);
}

void vtkProgressiveMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  meshsimp::PrintParameters<meshsimp::ProgressiveMeshParameters>(*this, os, indent);
  os << indent << "NumberOfBuilds: " << this->NumberOfBuilds << "\n";
}

void vtkProgressiveMesh::ForEachOwnSetting(const meshsimp::SettingVisit& visit)
{
  meshsimp::VisitParameters<meshsimp::ProgressiveMeshParameters>(*this, visit);
}
