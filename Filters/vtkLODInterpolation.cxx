// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLODInterpolation.h"

#include "LODInterpolation.h"
#include "vtkSimplificationAttributes.h"
#include "vtkSimplificationInput.h"
#include "vtkSimplificationPieces.h"
#include "vtkSimplificationRanges.h"
#include "vtkSimplificationThreads.h"

#include "vtkArrayDispatch.h"
#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProgressiveMesh.h"
#include "vtkStaticPointLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLODInterpolation);

namespace
{
/// A morphing point array's values at the partners, kept for the frames while the arrays and
/// the correspondence stay.
struct MorphedArray
{
  vtkDataArray* Detailed = nullptr;
  vtkDataArray* Coarse = nullptr;
  vtkMTimeType DetailedTime = 0, CoarseTime = 0;
  std::vector<double> Values;
  vtkSmartPointer<vtkDataArray> Output; // the last frame's, of the detailed array's type
};

/// The last frame's output arrays (see Reuse).
struct FrameArrays
{
  vtkSmartPointer<vtkDoubleArray> Places, Displacement;
  vtkSmartPointer<vtkFloatArray> SinglePlaces; // the points, where the output's are floats
  vtkSmartPointer<vtkCellArray::ArrayType64> Offsets, Connectivity; // the type SetData keeps as it is
};

/// An array for the tuples: the last frame's, kept, where nothing else holds it any more (its
/// memory is written again: a new array's pages would fault in again, which costs a frame of a
/// million points about as much as computing it), else a new one, kept in its place.
template <typename ArrayType>
ArrayType* Reuse(vtkSmartPointer<ArrayType>& kept, int components, vtkIdType tuples)
{
  if (!kept || kept->GetReferenceCount() > 1)
  {
    kept = vtkSmartPointer<ArrayType>::New();
  }
  kept->SetNumberOfComponents(components);
  kept->SetNumberOfTuples(tuples);
  kept->Modified();
  return kept;
}

/// Reuse for an array holding values (components per tuple), copied on the threads.
template <typename ArrayType>
ArrayType* Copied(vtkSmartPointer<ArrayType>& kept, const double* values, int components, vtkIdType tuples,
  const meshsimp::ExecutionContext& context)
{
  ArrayType* array = Reuse(kept, components, tuples);
  auto* to = array->GetPointer(0);
  context.For(components * tuples, [&](std::int64_t begin, std::int64_t end) {
    std::copy(values + begin, values + end, to + begin);
  }, components * tuples);
  return array;
}

/// Reuse for an array of like's type and components.
vtkDataArray* ReuseLike(vtkSmartPointer<vtkDataArray>& kept, vtkDataArray* like, vtkIdType tuples)
{
  if (!kept || kept->GetReferenceCount() > 1 || kept->GetDataType() != like->GetDataType())
  {
    kept.TakeReference(like->NewInstance());
  }
  kept->SetNumberOfComponents(like->GetNumberOfComponents());
  kept->SetNumberOfTuples(tuples);
  kept->Modified();
  return kept;
}

/// A blended value in an array's type: an integer rounded and held to the type's range.
template <typename Value>
Value Stored(double value)
{
  if (std::is_integral<Value>::value)
  {
    const double lowest = static_cast<double>(std::numeric_limits<Value>::lowest());
    const double highest = static_cast<double>(std::numeric_limits<Value>::max());
    return static_cast<Value>(std::min(highest, std::max(lowest, std::round(value))));
  }
  return static_cast<Value>(value);
}

/// Whether a point array morphs: floating-point values, or unsigned-char colours (3 or 4
/// components); integers besides (labels, ids) would mean nothing halfway.
bool Morphs(vtkDataArray* array)
{
  const int type = array->GetDataType(), components = array->GetNumberOfComponents();
  return type == VTK_FLOAT || type == VTK_DOUBLE || (type == VTK_UNSIGNED_CHAR && (components == 3 || components == 4));
}
}

/// The correspondence and what it was built from (the inputs, their modification times, the
/// mode): rebuilt only when one of them changes.
struct vtkLODInterpolation::Cache
{
  vtkPolyData* Detailed = nullptr;
  vtkPolyData* Coarse = nullptr;
  vtkMTimeType DetailedTime = 0, CoarseTime = 0; // their geometry's (GeometryTime)
  int Mode = -1;
  std::pair<vtkAbstractArray*, vtkMTimeType> Record{ nullptr, 0 }; // what Exact read, and when it changed
  vtkSimplification::TriangleInput DetailedTriangles, CoarseTriangles;
  meshsimp::MorphPartners Partners;
  double Diagonal = 0.0;
  meshsimp::MergeSchedule Merges; // for MergeDistance Scheduled
  double Scheduled = -1.0;
  meshsimp::MorphFrame Frame; // the last frame's, its memory reused
  std::vector<MorphedArray> Arrays; // the morphing arrays' partner values
  FrameArrays Written;
};

namespace
{
/// Whether a surface has polygons or strips.
bool HasSurfaceCells(vtkPolyData* surface)
{
  return surface->GetNumberOfPolys() + surface->GetNumberOfStrips() > 0;
}

/// When a surface's points or cells last changed. (Not the data object's time: ParaView's
/// pipeline touches a source's point, cell and field data on every update downstream, which
/// would rebuild the correspondence at every frame.)
vtkMTimeType GeometryTime(vtkPolyData* mesh)
{
  vtkMTimeType time = 0;
  for (vtkObject* part : { static_cast<vtkObject*>(mesh->GetPoints()), static_cast<vtkObject*>(mesh->GetPolys()),
         static_cast<vtkObject*>(mesh->GetStrips()), static_cast<vtkObject*>(mesh->GetVerts()),
         static_cast<vtkObject*>(mesh->GetLines()) })
  {
    time = std::max(time, part ? part->GetMTime() : 0);
  }
  vtkPoints* points = mesh->GetPoints();
  return points && points->GetData() ? std::max(time, points->GetData()->GetMTime()) : time;
}

/// The array Exact reads the coarse surface's record from (its field data InputToOutputPointIds,
/// else its point data vtkOriginalPointIds; null: none), and when it last changed.
std::pair<vtkAbstractArray*, vtkMTimeType> Record(vtkPolyData* coarse)
{
  vtkAbstractArray* map = coarse->GetFieldData()->GetAbstractArray(vtkSimplification::InputToOutputPointIdsName);
  vtkAbstractArray* record = map ? map : coarse->GetPointData()->GetAbstractArray("vtkOriginalPointIds");
  return { record, record ? record->GetMTime() : 0 };
}

/// Per point of from, the id of the nearest point of to (VTK's static point locator).
std::vector<std::int32_t> NearestPoints(
  const meshsimp::TriangleMeshView& from, vtkPolyData* to, const meshsimp::ExecutionContext& context)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  std::vector<std::int32_t> nearest(static_cast<std::size_t>(from.NumberOfPoints), -1);
  context.For(from.NumberOfPoints, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t p = begin; p < end; ++p)
    {
      nearest[p] = static_cast<std::int32_t>(locator->FindClosestPoint(from.Point(p).data()));
    }
  }, 1000 * from.NumberOfPoints);
  return nearest;
}

/// Per detailed point, the coarse point it became (-1: not known), from what the simplification
/// that made the coarse surface recorded: its field data InputToOutputPointIds (this module's
/// filters with GenerateOriginalIds: every input point's; where the detailed surface is itself
/// such a level of the same input, its points through its own vtkOriginalPointIds), else its
/// point data vtkOriginalPointIds (any filter that keeps them: each coarse point's own input
/// point). False, with the problem, where the coarse surface has neither or they cannot be of
/// this detailed one.
bool Ancestors(vtkPolyData* detailed, vtkPolyData* coarse, std::vector<std::int32_t>& ancestor, std::string& problem)
{
  const vtkIdType detailedPoints = detailed->GetNumberOfPoints(), coarsePoints = coarse->GetNumberOfPoints();
  ancestor.assign(static_cast<std::size_t>(detailedPoints), -1);
  const auto id = [](vtkDataArray* ids, vtkIdType i, vtkIdType count) {
    const double value = ids->GetComponent(i, 0);
    return value >= 0 && value < count ? static_cast<vtkIdType>(value) : vtkIdType{ -1 };
  };
  vtkAbstractArray* record = Record(coarse).first;
  auto* values = vtkArrayDownCast<vtkDataArray>(record);
  const bool map = record && record == coarse->GetFieldData()->GetAbstractArray(vtkSimplification::InputToOutputPointIdsName);
  if (!values || values->GetNumberOfComponents() != 1 || (!map && values->GetNumberOfTuples() != coarsePoints))
  {
    problem = "Exact needs the coarse surface to carry vtkOriginalPointIds (turn on Generate Original Ids in the filter "
              "that made it from the detailed surface)";
    return false;
  }
  if (!map)
  {
    for (vtkIdType c = 0; c < coarsePoints; ++c)
    {
      const vtkIdType d = id(values, c, detailedPoints);
      if (d >= 0)
      {
        ancestor[d] = static_cast<std::int32_t>(c);
      }
    }
    return true;
  }
  // A level of the same input (its own map as long): through its points' input points.
  vtkAbstractArray* own = detailed->GetFieldData()->GetAbstractArray(vtkSimplification::InputToOutputPointIdsName);
  vtkDataArray* level = detailed->GetPointData()->GetArray("vtkOriginalPointIds");
  const bool throughLevel = own && own->GetNumberOfTuples() == values->GetNumberOfTuples() && level &&
    level->GetNumberOfComponents() == 1 && level->GetNumberOfTuples() == detailedPoints;
  if (!throughLevel && values->GetNumberOfTuples() != detailedPoints)
  {
    problem = std::string("the coarse surface's ") + vtkSimplification::InputToOutputPointIdsName + " lists " +
      std::to_string(values->GetNumberOfTuples()) + " points, the detailed surface has " + std::to_string(detailedPoints) +
      " (the coarse surface was made from another)";
    return false;
  }
  for (vtkIdType d = 0; d < detailedPoints; ++d)
  {
    const vtkIdType input = throughLevel ? id(level, d, values->GetNumberOfTuples()) : d;
    ancestor[d] = input >= 0 ? static_cast<std::int32_t>(id(values, input, coarsePoints)) : -1;
  }
  return true;
}

/// Per detailed point, a coarse array's value at its partner: the blend of the partner's corners'
/// values with their weights (its own value, from the detailed array, where it has no partner).
struct BlendAtPartners
{
  template <typename CoarseArray>
  void operator()(CoarseArray* coarse, vtkDataArray* detailed, const meshsimp::MorphPartners& partners,
    const meshsimp::ExecutionContext& context, std::vector<double>& values) const
  {
    const auto other = vtk::DataArrayTupleRange(coarse);
    const int components = coarse->GetNumberOfComponents();
    values.assign(static_cast<std::size_t>(partners.NumberOfPoints() * components), 0.0);
    context.For(partners.NumberOfPoints(), [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t d = begin; d < end; ++d)
      {
        const std::int32_t* corner = partners.Coarse.data() + 3 * d;
        for (int k = 0; k < components; ++k)
        {
          double& value = values[d * components + k];
          value = corner[0] < 0 ? detailed->GetComponent(d, k) : 0.0;
          for (int j = 0; j < 3 && corner[j] >= 0; ++j)
          {
            value += partners.Weights[3 * d + j] * static_cast<double>(other[corner[j]][k]);
          }
        }
      }
    }, 20 * components * partners.NumberOfPoints());
  }
};

/// A morphing point array of the detailed surface for the frame at t, into output (an array of
/// its type): each point's value blended as its place, (1 − t) its own + t its partner's; the
/// members of a merged set take their mean; unit vectors (normals) stay unit.
struct MorphValues
{
  template <typename DetailedArray>
  void operator()(DetailedArray* detailed, const std::vector<double>& towards, vtkDataArray* output,
    const meshsimp::MorphFrame& frame, double t, bool unit, const meshsimp::ExecutionContext& context) const
  {
    using Value = vtk::GetAPIType<DetailedArray>;
    const auto own = vtk::DataArrayTupleRange(detailed);
    auto out = vtk::DataArrayTupleRange(static_cast<DetailedArray*>(output));
    const int components = detailed->GetNumberOfComponents();
    // Writes one tuple from values (components doubles), made unit where asked.
    const auto write = [&](std::int64_t d, double* values) {
      const double length2 = unit ? std::inner_product(values, values + components, values, 0.0) : 0.0;
      const double scale = length2 > 0.0 ? 1.0 / std::sqrt(length2) : 1.0;
      for (int k = 0; k < components; ++k)
      {
        out[d][k] = Stored<Value>(values[k] * scale);
      }
    };
    context.For(own.size(), [&](std::int64_t begin, std::int64_t end) {
      std::vector<double> values(components);
      for (std::int64_t d = begin; d < end; ++d)
      {
        for (int k = 0; k < components; ++k)
        {
          values[k] = (1.0 - t) * static_cast<double>(own[d][k]) + t * towards[d * components + k];
        }
        write(d, values.data());
      }
    }, 4 * components * own.size());
    context.For(frame.NumberOfGroups(), [&](std::int64_t begin, std::int64_t end) {
      std::vector<double> mean(components);
      for (std::int64_t g = begin; g < end; ++g)
      {
        const std::int32_t first = frame.GroupOffsets[g], last = frame.GroupOffsets[g + 1];
        std::fill(mean.begin(), mean.end(), 0.0);
        for (std::int32_t i = first; i < last; ++i)
        {
          for (int k = 0; k < components; ++k)
          {
            mean[k] += static_cast<double>(out[frame.GroupMembers[i]][k]) / (last - first);
          }
        }
        for (std::int32_t i = first; i < last; ++i)
        {
          write(frame.GroupMembers[i], mean.data());
        }
      }
    }, 10 * components * static_cast<std::int64_t>(frame.GroupOffsets.back()));
  }
};

/// A morphing array's entry: its partners' values (BlendAtPartners), kept from frame to frame
/// until the correspondence or either array changes, and its last output.
MorphedArray& PartnerValues(vtkDataArray* detailed, vtkDataArray* coarse,
  const meshsimp::MorphPartners& partners, const meshsimp::ExecutionContext& context,
  std::vector<MorphedArray>& kept)
{
  auto entry = std::find_if(kept.begin(), kept.end(), [&](const MorphedArray& k) { return k.Detailed == detailed; });
  if (entry == kept.end())
  {
    entry = kept.insert(kept.end(), MorphedArray());
  }
  if (entry->Detailed != detailed || entry->Coarse != coarse || entry->DetailedTime != detailed->GetMTime() ||
    entry->CoarseTime != coarse->GetMTime())
  {
    *entry = { detailed, coarse, detailed->GetMTime(), coarse->GetMTime(), {}, entry->Output };
    BlendAtPartners worker;
    if (!vtkArrayDispatch::Dispatch::Execute(coarse, worker, detailed, partners, context, entry->Values))
    {
      worker(coarse, detailed, partners, context, entry->Values);
    }
  }
  return *entry;
}

/// Every point array of the detailed surface for the frame: the arrays that morph (Morphs) and
/// that the coarse surface also has (same name and components) morphed in their own type, the
/// others as they are (a merged set's triangles use its lowest id, whose value that is); the
/// active attributes kept active, the normals unit.
void MorphPointData(vtkPointData* detailed, vtkPointData* coarse, const meshsimp::MorphPartners& partners,
  const meshsimp::MorphFrame& frame, double t, const meshsimp::ExecutionContext& context,
  std::vector<MorphedArray>& kept, vtkPointData* output)
{
  const vtkIdType detailedPoints = partners.NumberOfPoints();
  for (int i = 0; i < detailed->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = detailed->GetArray(i);
    if (!array || array->GetNumberOfTuples() != detailedPoints || !array->GetName())
    {
      continue;
    }
    vtkDataArray* match = coarse->GetArray(array->GetName());
    const bool morphs = t > 0.0 && match && match->GetNumberOfComponents() == array->GetNumberOfComponents() && Morphs(array);
    vtkSmartPointer<vtkDataArray> morphed = array;
    const int attribute = detailed->IsArrayAnAttribute(i);
    if (morphs)
    {
      MorphedArray& entry = PartnerValues(array, match, partners, context, kept);
      morphed = ReuseLike(entry.Output, array, detailedPoints);
      morphed->SetName(array->GetName());
      const std::vector<double>& towards = entry.Values;
      const bool unit = attribute == vtkDataSetAttributes::NORMALS;
      MorphValues worker;
      if (!vtkArrayDispatch::DispatchByValueType<vtkTypeList::Create<float, double, unsigned char>>::Execute(
            array, worker, towards, morphed.Get(), frame, t, unit, context))
      {
        worker(array, towards, morphed.Get(), frame, t, unit, context);
      }
    }
    output->AddArray(morphed);
    if (attribute >= 0)
    {
      output->SetActiveAttribute(morphed->GetName(), attribute);
    }
  }
}

/// The frame's triangles with the detailed surface's cell data. Where every detailed triangle
/// is kept (no point joined) and the detailed surface is triangles alone, viewed in place, those
/// are the detailed surface's: shared, not copied.
void WriteTriangles(vtkPolyData* detailed, const vtkSimplification::TriangleInput& triangles,
  const meshsimp::MorphFrame& frame, const meshsimp::ExecutionContext& context, FrameArrays& written,
  vtkPolyData* output)
{
  const meshsimp::TriangleMeshView& view = triangles.View;
  const vtkIdType count = frame.NumberOfTriangles();
  if (count == view.NumberOfTriangles && triangles.Triangles.empty() && triangles.FirstCell == 0 &&
    detailed->GetNumberOfCells() == view.NumberOfTriangles)
  {
    output->SetPolys(detailed->GetPolys());
    output->GetCellData()->ShallowCopy(detailed->GetCellData());
    return;
  }
  vtkTypeInt64* offsets = Reuse(written.Offsets, 1, count + 1)->GetPointer(0);
  vtkTypeInt64* connectivity = Reuse(written.Connectivity, 1, 3 * count)->GetPointer(0);
  context.For(count + 1, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t t = begin; t < end; ++t)
    {
      offsets[t] = 3 * t;
    }
    std::copy(frame.Triangles.begin() + 3 * begin, frame.Triangles.begin() + 3 * std::min<std::int64_t>(end, count),
      connectivity + 3 * begin);
  }, 4 * count);
  vtkNew<vtkCellArray> cells;
  cells->SetData(written.Offsets, written.Connectivity);
  output->SetPolys(cells);
  vtkCellData* cellData = detailed->GetCellData();
  output->GetCellData()->CopyAllocate(cellData, count);
  if (cellData->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> sources;
    sources->SetNumberOfIds(count);
    for (vtkIdType t = 0; t < count; ++t)
    {
      sources->SetId(t, triangles.SourceCell(frame.TriangleSource[t]));
    }
    output->GetCellData()->CopyData(cellData, sources.GetPointer(), vtkIdType{ 0 });
  }
}
/// For the GPU: the detailed surface with each point's place at t = 1, "CoarsePoints", as its
/// active tangents (the attribute VTK 9.2's polygon mapper passes to a vertex shader).
void WriteShaderInput(vtkPolyData* detailed, const meshsimp::MorphPartners& partners, vtkPolyData* output)
{
  output->ShallowCopy(detailed);
  vtkNew<vtkFloatArray> targets;
  targets->SetName("CoarsePoints");
  targets->SetNumberOfComponents(3);
  targets->SetNumberOfTuples(partners.NumberOfPoints());
  std::copy(partners.Targets.begin(), partners.Targets.end(), targets->GetPointer(0));
  output->GetPointData()->SetTangents(targets);
}

/// The frame at t: its points (of type precision, VTK_FLOAT or VTK_DOUBLE), triangles with cell
/// data, point data and Displacement, the arrays it wrote with their ranges recorded.
void WriteFrame(vtkPolyData* detailed, vtkPolyData* coarse, const vtkSimplification::TriangleInput& triangles,
  const meshsimp::MorphPartners& partners, const meshsimp::MergeSchedule& merges, double t, int precision,
  const meshsimp::ExecutionContext& context, meshsimp::MorphFrame& frame, std::vector<MorphedArray>& kept,
  FrameArrays& written, vtkPolyData* output)
{
  const meshsimp::TriangleMeshView& view = triangles.View;
  vtkDoubleArray* places = Reuse(written.Places, 3, view.NumberOfPoints);
  meshsimp::Morph(view, partners, merges, t, places->GetPointer(0), frame, context);
  const bool single = precision == VTK_FLOAT;
  vtkNew<vtkPoints> points;
  points->SetData(single ? Copied(written.SinglePlaces, places->GetPointer(0), 3, view.NumberOfPoints, context)
                         : static_cast<vtkDataArray*>(places));
  output->SetPoints(points);
  WriteTriangles(detailed, triangles, frame, context, written, output);
  MorphPointData(detailed->GetPointData(), coarse->GetPointData(), partners, frame, t, context, kept, output->GetPointData());
  vtkDoubleArray* displacement = Copied(written.Displacement, frame.Displacement.data(), 1, view.NumberOfPoints, context);
  displacement->SetName("Displacement");
  output->GetPointData()->AddArray(displacement);
  vtkSimplification::RecordOutputRanges(detailed, output, context);
}
} // namespace

vtkLODInterpolation::vtkLODInterpolation()
{
  this->SetNumberOfInputPorts(2);
}

vtkLODInterpolation::~vtkLODInterpolation() = default;

vtkTypeBool vtkLODInterpolation::ProcessRequest(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    vtkSimplification::MakeSurfacesOutput(vtkDataObject::GetData(inputs[0], 0), outputs->GetInformationObject(0));
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputs, outputs);
}

int vtkLODInterpolation::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1); // a Progressive Mesh sequence alone
  }
  return 1;
}

int vtkLODInterpolation::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

bool vtkLODInterpolation::Levels(vtkDataObject* sequence, vtkDataObject*& detailed, vtkDataObject*& coarse)
{
  std::vector<vtkSimplification::Piece> pieces;
  std::string problem;
  if (!vtkSimplification::CollectPieces(sequence, nullptr, pieces, problem) || pieces.empty() ||
    !pieces[0].Input->GetPointData()->GetArray("Parent") || !pieces[0].Input->GetCellData()->GetArray("RemovedAt"))
  {
    return false;
  }
  if (this->DetailedReduction >= this->CoarseReduction)
  {
    vtkWarningMacro("Detailed Reduction " << this->DetailedReduction << " is not below Coarse Reduction "
                                          << this->CoarseReduction << ": the detailed level is not the finer one.");
  }
  vtkSmartPointer<vtkProgressiveMesh>* levels[2] = { &this->DetailedLevel, &this->CoarseLevel };
  const double reductions[2] = { this->DetailedReduction, this->CoarseReduction };
  for (int i = 0; i < 2; ++i)
  {
    vtkSmartPointer<vtkProgressiveMesh>& level = *levels[i];
    level = level ? level : vtkSmartPointer<vtkProgressiveMesh>::New();
    if (level->GetInput() != sequence)
    {
      level->SetInputData(sequence);
    }
    level->SetTargetReduction(reductions[i]);
    level->GenerateOriginalIdsOn();
    level->ComputeDeviationOff();
    level->Update();
  }
  detailed = this->DetailedLevel->GetOutputDataObject(0);
  coarse = this->CoarseLevel->GetOutputDataObject(0);
  return true;
}

bool vtkLODInterpolation::MakePartners(
  vtkPolyData* detailed, vtkPolyData* coarse, const meshsimp::ExecutionContext& context, Cache& built)
{
  const meshsimp::TriangleMeshView& d = built.DetailedTriangles.View;
  const meshsimp::TriangleMeshView& c = built.CoarseTriangles.View;
  switch (this->Correspondence)
  {
    case NEAREST_VERTEX:
      built.Partners =
        meshsimp::PairNearestVertices(d, c, NearestPoints(c, detailed, context), NearestPoints(d, coarse, context));
      return true;
    case NEAREST_SURFACE_POINT:
      built.Partners = meshsimp::PairSurfacePoints(d, c, {}, context);
      return true;
    default:
      break;
  }
  std::vector<std::int32_t> ancestor, unknown;
  std::string problem;
  if (!Ancestors(detailed, coarse, ancestor, problem))
  {
    vtkErrorMacro(<< "Cannot morph: " << problem << ".");
    return false;
  }
  built.Partners = meshsimp::PairAncestors(d, c, ancestor);
  for (std::int32_t p = 0; p < static_cast<std::int32_t>(ancestor.size()); ++p)
  {
    if (ancestor[p] < 0)
    {
      unknown.push_back(p);
    }
  }
  if (!unknown.empty()) // the points no record places go to the nearest point of the coarse surface
  {
    const meshsimp::MorphPartners nearest = meshsimp::PairSurfacePoints(d, c, unknown, context);
    for (const std::int32_t p : unknown)
    {
      std::copy_n(nearest.Targets.begin() + 3 * p, 3, built.Partners.Targets.begin() + 3 * p);
      std::copy_n(nearest.Coarse.begin() + 3 * p, 3, built.Partners.Coarse.begin() + 3 * p);
      std::copy_n(nearest.Weights.begin() + 3 * p, 3, built.Partners.Weights.begin() + 3 * p);
    }
  }
  return true;
}

bool vtkLODInterpolation::Pair(vtkPolyData* detailed, vtkPolyData* coarse, const meshsimp::ExecutionContext& context, Cache& built)
{
  if (built.Detailed == detailed && built.Coarse == coarse && built.DetailedTime == GeometryTime(detailed) &&
    built.CoarseTime == GeometryTime(coarse) && built.Mode == this->Correspondence &&
    (this->Correspondence != EXACT || built.Record == Record(coarse)))
  {
    return true;
  }
  built = Cache();
  std::string problem;
  if (!vtkSimplification::ExtractTriangles(detailed, built.DetailedTriangles, problem) ||
    !vtkSimplification::ExtractTriangles(coarse, built.CoarseTriangles, problem))
  {
    vtkErrorMacro(<< "Cannot morph: " << problem << ".");
    built = Cache();
    return false;
  }
  const meshsimp::TriangleMeshView& d = built.DetailedTriangles.View;
  const meshsimp::TriangleMeshView& c = built.CoarseTriangles.View;
  if (d.NumberOfTriangles == 0 || c.NumberOfTriangles == 0)
  {
    vtkErrorMacro(<< "Cannot morph: the " << (d.NumberOfTriangles == 0 ? "detailed" : "coarse")
                  << " surface has no triangles.");
    built = Cache();
    return false;
  }
  if (!this->MakePartners(detailed, coarse, context, built))
  {
    built = Cache();
    return false;
  }
  built.Diagonal = detailed->GetLength();
  built.Detailed = detailed;
  built.Coarse = coarse;
  built.DetailedTime = GeometryTime(detailed);
  built.CoarseTime = GeometryTime(coarse);
  built.Mode = this->Correspondence;
  built.Record = Record(coarse);
  ++this->CorrespondenceBuilds;
  return true;
}

int vtkLODInterpolation::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  vtkInformation* info = outputs->GetInformationObject(0);
  if (!this->InterpolationFromTime)
  {
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    return 1;
  }
  constexpr int steps = 21;
  double times[steps];
  for (int i = 0; i < steps; ++i)
  {
    times[i] = static_cast<double>(i) / (steps - 1);
  }
  const double range[2] = { 0.0, 1.0 };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times, steps);
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkLODInterpolation::RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  vtkDataObject* detailed = vtkDataObject::GetData(inputs[0]);
  vtkDataObject* coarse = vtkDataObject::GetData(inputs[1]);
  vtkDataObject* output = vtkDataObject::GetData(outputs);
  if (auto* surface = vtkPolyData::SafeDownCast(output))
  {
    surface->Initialize(); // empty unless a frame is made
  }
  if (!detailed || (!coarse && !this->Levels(detailed, detailed, coarse)))
  {
    vtkErrorMacro("Cannot morph: LoD Interpolation needs two surfaces, the detailed one (input 0) and the coarse one "
                  "(input 1), or a Progressive Mesh sequence alone (input 0).");
    return 1;
  }
  // Composite data morphs block by block: the detailed input's surfaces with the coarse one's
  // in the same order, each pair with its own correspondence.
  std::vector<vtkSimplification::Piece> details, coarses;
  std::string problem;
  if (!vtkSimplification::CollectPieces(detailed, output, details, problem) ||
    !vtkSimplification::CollectPieces(coarse, nullptr, coarses, problem))
  {
    vtkErrorMacro("Cannot morph: " << problem << ".");
    return 1;
  }
  if (details.size() != coarses.size())
  {
    vtkErrorMacro("Cannot morph: the detailed input has " << details.size() << " surfaces and the coarse input "
                                                          << coarses.size() << "; give both the same blocks.");
    return 1;
  }
  vtkInformation* request = outputs->GetInformationObject(0);
  const double t = this->InterpolationFromTime && request->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? std::min(1.0, std::max(0.0, request->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())))
    : this->Interpolation;
  const meshsimp::ExecutionContext context = vtkSimplification::MakeExecutionContext(this, 0);
  this->Built.resize(details.size());
  const bool blocks = vtkCompositeDataSet::SafeDownCast(detailed) != nullptr;
  for (std::size_t k = 0; k < details.size(); ++k)
  {
    const bool flat[2] = { !HasSurfaceCells(details[k].Input), !HasSurfaceCells(coarses[k].Input) };
    if (blocks && (flat[0] || flat[1])) // an empty block (after a clip, say) leaves the others to morph
    {
      vtkWarningMacro("Block " << k << ": the " << (flat[0] ? "detailed" : "coarse") << " block has no triangles; its frame is left empty.");
      continue;
    }
    if (!this->Morph(details[k].Input, coarses[k].Input, t, context, this->Built[k], details[k].Output))
    {
      return 1;
    }
  }
  return 1;
}

bool vtkLODInterpolation::Morph(vtkPolyData* detailed, vtkPolyData* coarse, double t, const meshsimp::ExecutionContext& context,
  Cache& built, vtkPolyData* output)
{
  if (!this->Pair(detailed, coarse, context, built))
  {
    return false;
  }
  const double mergeDistance = this->MergeDistance * built.Diagonal;
  if (!this->MorphInShader && built.Scheduled != mergeDistance)
  {
    built.Merges = meshsimp::ScheduleMerges(
      built.DetailedTriangles.View, built.Partners, mergeDistance, context, this->Correspondence == EXACT);
    built.Scheduled = mergeDistance;
  }
  this->UpdateProgress(0.5);
  // The data the frame maps: without arrays shorter than their points or cells (a warning each).
  const vtkSmartPointer<vtkPolyData> detailedData = vtkSimplification::WithUsableAttributes(this, detailed);
  const vtkSmartPointer<vtkPolyData> coarseData = vtkSimplification::WithUsableAttributes(this, coarse);
  if (this->MorphInShader)
  {
    WriteShaderInput(detailedData, built.Partners, output);
  }
  else
  {
    const bool single = this->OutputPointsPrecision == SINGLE_PRECISION ||
      (this->OutputPointsPrecision == DEFAULT_PRECISION && detailed->GetPoints()->GetDataType() == VTK_FLOAT);
    WriteFrame(detailedData, coarseData, built.DetailedTriangles, built.Partners, built.Merges, t,
      single ? VTK_FLOAT : VTK_DOUBLE, context, built.Frame, built.Arrays, built.Written, output);
  }
  output->GetFieldData()->PassData(detailed->GetFieldData());
  vtkNew<vtkIntArray> builds;
  builds->SetName("CorrespondenceBuilds");
  builds->InsertNextValue(this->CorrespondenceBuilds);
  output->GetFieldData()->AddArray(builds);
  return true;
}

void vtkLODInterpolation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Interpolation: " << this->Interpolation << "\n";
  os << indent << "MergeDistance: " << this->MergeDistance << "\n";
  os << indent << "Correspondence: " << this->Correspondence << "\n";
  os << indent << "InterpolationFromTime: " << this->InterpolationFromTime << "\n";
  os << indent << "MorphInShader: " << this->MorphInShader << "\n";
  os << indent << "DetailedReduction: " << this->DetailedReduction << "\n";
  os << indent << "CoarseReduction: " << this->CoarseReduction << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "CorrespondenceBuilds: " << this->CorrespondenceBuilds << "\n";
}
