// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationAttributes.h"

#include "vtkAlgorithm.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace vtkSimplification
{
namespace
{
/// How a point array reaches the output (see the file's rule).
enum class Rule : std::uint8_t
{
  Interpolate,    // floating point: weighted
  RoundedAverage, // unsigned-char colours: weighted, rounded to the nearest
  Representative  // labels, ids, flags, strings: the representative's value
};

Rule RuleOf(vtkAbstractArray* array)
{
  const bool numeric = vtkDataArray::SafeDownCast(array) != nullptr;
  const int components = array->GetNumberOfComponents();
  switch (numeric ? array->GetDataType() : VTK_VOID)
  {
    case VTK_FLOAT:
    case VTK_DOUBLE:
      return Rule::Interpolate;
    case VTK_UNSIGNED_CHAR:
      return components == 3 || components == 4 ? Rule::RoundedAverage : Rule::Representative;
    default:
      return Rule::Representative;
  }
}

/// Interpolated or averaged tuples: per component, the weighted mean of the sources of nonzero
/// weight, clamped to their range (so equal values give exactly that value), optionally rounded.
struct Blend
{
  template <typename ArrayT>
  void operator()(ArrayT* in, vtkDataArray* outArray, const meshsimp::SimplifiedMesh& mesh, bool round) const
  {
    using T = vtk::GetAPIType<ArrayT>;
    auto* out = vtkArrayDownCast<ArrayT>(outArray);
    const auto source = vtk::DataArrayTupleRange(in);
    auto target = vtk::DataArrayTupleRange(out);
    const int components = in->GetNumberOfComponents();
    for (std::int64_t p = 0; p < mesh.NumberOfPoints(); ++p)
    {
      const std::int32_t begin = mesh.SourceOffsets[p], end = mesh.SourceOffsets[p + 1];
      for (int c = 0; c < components; ++c)
      {
        double sum = 0.0, low = std::numeric_limits<double>::infinity(), high = -low;
        for (std::int32_t i = begin; i < end; ++i)
        {
          const double weight = mesh.SourceWeights[i];
          const double value = static_cast<double>(source[mesh.SourcePoints[i]][c]);
          sum += weight * value;
          low = weight != 0.0 ? std::min(low, value) : low;
          high = weight != 0.0 ? std::max(high, value) : high;
        }
        double value = low > high ? static_cast<double>(source[mesh.SourcePoints[begin]][c])
                                  : std::min(high, std::max(low, sum));
        value = round ? std::round(value) : value;
        target[p][c] = static_cast<T>(value);
      }
    }
  }
};

vtkSmartPointer<vtkAbstractArray> MapArray(vtkAbstractArray* in, const meshsimp::SimplifiedMesh& mesh)
{
  const vtkIdType count = static_cast<vtkIdType>(mesh.NumberOfPoints());
  auto out = vtk::TakeSmartPointer(in->NewInstance());
  out->SetName(in->GetName());
  out->SetNumberOfComponents(in->GetNumberOfComponents());
  for (int c = 0; c < in->GetNumberOfComponents(); ++c)
  {
    if (const char* name = in->GetComponentName(c))
    {
      out->SetComponentName(c, name);
    }
  }
  out->SetNumberOfTuples(count);
  const Rule rule = RuleOf(in);
  if (rule == Rule::Representative)
  {
    vtkNew<vtkIdList> from, to;
    from->SetNumberOfIds(count);
    to->SetNumberOfIds(count);
    for (vtkIdType p = 0; p < count; ++p)
    {
      from->SetId(p, mesh.Representative(p));
      to->SetId(p, p);
    }
    out->InsertTuples(to, from, in);
  }
  else if (!vtkArrayDispatch::Dispatch::Execute(
             vtkDataArray::SafeDownCast(in), Blend{}, vtkDataArray::SafeDownCast(out), mesh, rule == Rule::RoundedAverage))
  {
    Blend{}(vtkDataArray::SafeDownCast(in), vtkDataArray::SafeDownCast(out), mesh, rule == Rule::RoundedAverage);
  }
  return out;
}

vtkSmartPointer<vtkPoints> MakePoints(const std::vector<double>& coordinates, int precision, vtkPoints* inputPoints)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  const bool doubles = precision == vtkAlgorithm::DOUBLE_PRECISION ||
    (precision == vtkAlgorithm::DEFAULT_PRECISION && inputPoints && inputPoints->GetDataType() == VTK_DOUBLE);
  points->SetDataType(doubles ? VTK_DOUBLE : VTK_FLOAT);
  const vtkIdType count = static_cast<vtkIdType>(coordinates.size() / 3);
  points->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(i, coordinates.data() + 3 * i);
  }
  return points;
}

vtkSmartPointer<vtkCellArray> MakeTriangles(const std::vector<std::int32_t>& triangles)
{
  const vtkIdType count = static_cast<vtkIdType>(triangles.size() / 3);
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(3 * count);
  vtkIdType* offset = offsets->GetPointer(0);
  for (vtkIdType i = 0; i <= count; ++i)
  {
    offset[i] = 3 * i;
  }
  std::copy(triangles.begin(), triangles.end(), connectivity->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

Eigen::Vector3d AreaNormal(const std::vector<double>& points, const std::vector<std::int32_t>& triangles, std::size_t t)
{
  auto corner = [&](int k) { return Eigen::Vector3d(points.data() + 3 * static_cast<std::size_t>(triangles[3 * t + k])); };
  return (corner(1) - corner(0)).cross(corner(2) - corner(0));
}

Eigen::Vector3d UnitOrUp(const Eigen::Vector3d& n)
{
  const double length = n.norm();
  return length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d(0, 0, 1);
}

/// Area-weighted point normals and per-triangle normals of the output, into the active normal
/// arrays the mapping made; where the mesh carries its normals, the mapped point normals
/// renormalised instead (the area-weighted one where a blend cancels out), and where the input
/// had none (nor a point array named Normals), new area-weighted ones named Normals.
void RecomputeNormals(const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output)
{
  if (mesh.CarriesNormals && !output->GetPointData()->GetNormals() && !output->GetPointData()->GetArray("Normals"))
  {
    vtkNew<vtkFloatArray> added;
    added->SetName("Normals");
    added->SetNumberOfComponents(3);
    added->SetNumberOfTuples(output->GetNumberOfPoints());
    added->Fill(0.0);
    output->GetPointData()->SetNormals(added);
  }
  vtkDataArray* pointNormals = output->GetPointData()->GetNormals();
  vtkDataArray* cellNormals = output->GetCellData()->GetNormals();
  if (!pointNormals && !cellNormals)
  {
    return;
  }
  std::vector<Eigen::Vector3d> sums(pointNormals ? mesh.NumberOfPoints() : 0, Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < mesh.Triangles.size() / 3; ++t)
  {
    const Eigen::Vector3d n = AreaNormal(mesh.Points, mesh.Triangles, t);
    for (int k = 0; k < 3 && pointNormals; ++k)
    {
      sums[mesh.Triangles[3 * t + k]] += n;
    }
    if (cellNormals)
    {
      cellNormals->SetTuple(static_cast<vtkIdType>(t), UnitOrUp(n).data());
    }
  }
  for (std::size_t i = 0; i < sums.size(); ++i)
  {
    Eigen::Vector3d carried;
    pointNormals->GetTuple(static_cast<vtkIdType>(i), carried.data());
    const bool keep = mesh.CarriesNormals && carried.allFinite() && carried.norm() > 1e-6;
    pointNormals->SetTuple(static_cast<vtkIdType>(i), UnitOrUp(keep ? carried : sums[i]).data());
  }
}

/// An array of the type's values, converted as static_cast does.
template <typename ArrayType>
vtkSmartPointer<vtkDataArray> MakeTypedArray(const meshsimp::NamedArray& named)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(named.Name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(named.Values.size()));
  std::transform(named.Values.begin(), named.Values.end(), array->GetPointer(0),
    [](double value) { return static_cast<typename ArrayType::ValueType>(value); });
  return array;
}

vtkSmartPointer<vtkDataArray> MakeNamedArray(const meshsimp::NamedArray& named)
{
  switch (named.Type)
  {
    case meshsimp::NamedArray::Kind::Integer:
      return MakeTypedArray<vtkIntArray>(named);
    case meshsimp::NamedArray::Kind::Byte:
      return MakeTypedArray<vtkUnsignedCharArray>(named);
    default:
      return MakeTypedArray<vtkDoubleArray>(named);
  }
}
}

void MapPointData(vtkPointData* inPD, const meshsimp::SimplifiedMesh& mesh, vtkPointData* outPD)
{
  outPD->Initialize();
  for (int i = 0; i < inPD->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* in = inPD->GetAbstractArray(i);
    const int index = outPD->AddArray(MapArray(in, mesh));
    const int attribute = inPD->IsArrayAnAttribute(i);
    if (attribute >= 0)
    {
      outPD->SetActiveAttribute(index, attribute);
    }
  }
}

bool SamePointData(vtkPointData* pd, vtkIdType a, vtkIdType b)
{
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(i);
    const char* name = array->GetName();
    if (array == pd->GetGlobalIds() || array == pd->GetPedigreeIds() ||
      (name && std::strcmp(name, SurfacePointIdsName) == 0))
    {
      continue; // one per point by definition: they name the copies, not what they carry
    }
    const int components = array->GetNumberOfComponents();
    // Doubles hold every value of the other numeric types exactly but 64-bit integers': those,
    // and strings, compare as variants.
    vtkDataArray* numbers = vtkDataArray::SafeDownCast(array);
    numbers = numbers && (numbers->GetDataTypeSize() < 8 || numbers->GetDataType() == VTK_DOUBLE) ? numbers : nullptr;
    for (int c = 0; c < components; ++c)
    {
      if (numbers)
      {
        const double x = numbers->GetComponent(a, c), y = numbers->GetComponent(b, c);
        if (x != y && !(std::isnan(x) && std::isnan(y)))
        {
          return false;
        }
      }
      else if (array->GetVariantValue(a * components + c) != array->GetVariantValue(b * components + c))
      {
        return false;
      }
    }
  }
  return true;
}

namespace
{
/// What every output gets after its points, triangles and input arrays: normals recomputed, the
/// core's point arrays (unless the arrays already hold them) and field values, the input's
/// field data, AchievedReduction.
void FinishOutput(vtkPolyData* input, const TriangleInput& triangles, const meshsimp::SimplifiedMesh& mesh,
  bool addPointArrays, vtkPolyData* output)
{
  RecomputeNormals(mesh, output);
  for (std::size_t i = 0; addPointArrays && i < mesh.PointArrays.size(); ++i)
  {
    output->GetPointData()->AddArray(MakeNamedArray(mesh.PointArrays[i]));
  }
  output->GetFieldData()->PassData(input->GetFieldData());
  output->GetFieldData()->RemoveArray(InputToOutputPointIdsName); // the input's own, of another mesh
  for (const auto& [name, value] : mesh.FieldValues)
  {
    AddFieldValue(output, name.c_str(), value);
  }
  const double inputTriangles = static_cast<double>(triangles.View.NumberOfTriangles);
  const double numberOfTriangles = static_cast<double>(mesh.NumberOfTriangles());
  AddFieldValue(output, "AchievedReduction", inputTriangles > 0.0 ? 1.0 - numberOfTriangles / inputTriangles : 0.0);
}

/// The points of the input's triangles that no output point lists (the front end joined them to
/// a point at the same place, closing a crack) take the output point of a listed point there.
void MapJoinedPoints(const meshsimp::TriangleMeshView& input, vtkIdTypeArray* map)
{
  std::vector<vtkIdType> unlisted;
  for (std::int64_t i = 0; i < 3 * input.NumberOfTriangles; ++i)
  {
    const std::int64_t p = input.Id(i);
    if (p >= 0 && p < input.NumberOfPoints && map->GetValue(p) < 0)
    {
      unlisted.push_back(p);
    }
  }
  if (unlisted.empty())
  {
    return;
  }
  std::map<std::array<double, 3>, vtkIdType> listed;
  for (vtkIdType p = 0; p < input.NumberOfPoints; ++p)
  {
    const Eigen::Vector3d x = input.Point(p);
    if (map->GetValue(p) >= 0 && x.allFinite()) // NaN would break the map's order
    {
      listed.emplace(std::array<double, 3>{ x[0], x[1], x[2] }, map->GetValue(p));
    }
  }
  for (const vtkIdType p : unlisted)
  {
    const Eigen::Vector3d x = input.Point(p);
    const auto found = x.allFinite() ? listed.find({ x[0], x[1], x[2] }) : listed.end();
    map->SetValue(p, found == listed.end() ? -1 : found->second);
  }
}

/// vtkOriginalPointIds and vtkOriginalCellIds, vtkGeometryFilter's names: each output point's
/// representative input point, each output triangle's input cell.
void AddOriginalIds(const TriangleInput& triangles, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkIdTypeArray> points;
  points->SetName("vtkOriginalPointIds");
  points->SetNumberOfValues(static_cast<vtkIdType>(mesh.NumberOfPoints()));
  for (std::int64_t p = 0; p < mesh.NumberOfPoints(); ++p)
  {
    points->SetValue(static_cast<vtkIdType>(p), mesh.Representative(p));
  }
  output->GetPointData()->AddArray(points);
  vtkNew<vtkIdTypeArray> cells;
  cells->SetName("vtkOriginalCellIds");
  cells->SetNumberOfValues(static_cast<vtkIdType>(mesh.NumberOfTriangles()));
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    cells->SetValue(static_cast<vtkIdType>(t), triangles.SourceCell(mesh.TriangleSource[t]));
  }
  output->GetCellData()->AddArray(cells);
}

/// A surface AsSurface made carries its dataset's ids, mapped as labels (each output point the
/// value of its representative, each triangle its cell's): with originalIds they replace the
/// ids AddOriginalIds gave, which number the surface's points and cells; else they go.
void ResolveSurfaceIds(bool originalIds, vtkPolyData* output)
{
  const std::pair<vtkDataSetAttributes*, const char*> sides[] = {
    { output->GetPointData(), "vtkOriginalPointIds" }, { output->GetCellData(), "vtkOriginalCellIds" }
  };
  const char* surfaceNames[] = { SurfacePointIdsName, SurfaceCellIdsName };
  for (int side = 0; side < 2; ++side)
  {
    vtkDataSetAttributes* data = sides[side].first;
    vtkAbstractArray* ids = data->GetAbstractArray(surfaceNames[side]);
    if (!ids)
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> kept = ids;
    data->RemoveArray(surfaceNames[side]);
    if (originalIds)
    {
      data->RemoveArray(sides[side].second);
      kept->SetName(sides[side].second);
      data->AddArray(kept);
    }
  }
}

/// Held in a view's information: the array whose memory it shows, kept alive with the view. A
/// deep copy owns its values, so the key does not follow it (the whole would stay alive).
class vtkPrefixOwnerKey : public vtkInformationObjectBaseKey
{
public:
  vtkPrefixOwnerKey()
    : vtkInformationObjectBaseKey("PrefixOwner", "vtkSimplification")
  {
  }
  void DeepCopy(vtkInformation*, vtkInformation*) override {}
};
vtkInformationObjectBaseKey* const PrefixOwner = new vtkPrefixOwnerKey;

/// The first tuples of an array: a view of its memory where that is contiguous (the view keeps
/// it alive), else a copy; copied too when copy is set.
vtkSmartPointer<vtkAbstractArray> Prefix(vtkAbstractArray* whole, vtkIdType tuples, bool copy)
{
  auto part = vtk::TakeSmartPointer(whole->NewInstance());
  part->SetName(whole->GetName());
  part->SetNumberOfComponents(whole->GetNumberOfComponents());
  auto* data = vtkDataArray::SafeDownCast(whole);
  if (data && data->HasStandardMemoryLayout() && !copy)
  {
    part->SetVoidArray(data->GetVoidPointer(0), tuples * data->GetNumberOfComponents(), 1);
    part->GetInformation()->Set(PrefixOwner, whole);
  }
  else
  {
    part->InsertTuples(0, tuples, 0, whole);
  }
  return part;
}

/// The first tuples of every array of whole in part, with the same active attributes; normals
/// are copies (they are recomputed), the others views.
void PrefixArrays(vtkDataSetAttributes* whole, vtkIdType tuples, vtkDataSetAttributes* part)
{
  for (int i = 0; i < whole->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = whole->GetAbstractArray(i);
    part->AddArray(Prefix(array, tuples, array == whole->GetNormals()));
    for (int attribute = 0; attribute < vtkDataSetAttributes::NUM_ATTRIBUTES; ++attribute)
    {
      if (whole->GetAbstractAttribute(attribute) == array)
      {
        part->SetActiveAttribute(array->GetName(), attribute);
      }
    }
  }
}
}

void SetOutput(vtkPolyData* input, const TriangleInput& triangles, const meshsimp::SimplifiedMesh& mesh,
  int outputPointsPrecision, bool originalIds, vtkPolyData* output)
{
  output->SetPoints(MakePoints(mesh.Points, outputPointsPrecision, input->GetPoints()));
  output->SetPolys(MakeTriangles(mesh.Triangles));
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(mesh.NumberOfTriangles());
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, numberOfTriangles);
  // Each array's tuples in one call: a call per triangle costs VTK's dispatch over the arrays
  // for every triangle, even where the input has no cell array.
  if (inCD->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> sources;
    sources->SetNumberOfIds(numberOfTriangles);
    for (vtkIdType i = 0; i < numberOfTriangles; ++i)
    {
      sources->SetId(i, triangles.SourceCell(mesh.TriangleSource[i]));
    }
    outCD->CopyData(inCD, sources.GetPointer(), vtkIdType{ 0 });
  }
  MapPointData(input->GetPointData(), mesh, output->GetPointData());
  if (originalIds)
  {
    AddOriginalIds(triangles, mesh, output);
  }
  const bool surface = output->GetPointData()->GetAbstractArray(SurfacePointIdsName) != nullptr;
  ResolveSurfaceIds(originalIds, output);
  FinishOutput(input, triangles, mesh, true, output);
  if (originalIds && !surface) // a made surface's points are not the input's
  {
    AddInputToOutputIds(mesh, triangles.View, output);
  }
}

vtkSmartPointer<vtkDataArray> PrefixView(vtkDataArray* array, vtkIdType tuples)
{
  return vtkDataArray::SafeDownCast(Prefix(array, tuples, false));
}

void SetPrefixOutput(vtkPolyData* input, const TriangleInput& triangles, vtkPolyData* whole, vtkIdType points,
  vtkCellArray::ArrayType64* corners, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output)
{
  vtkNew<vtkPoints> prefix;
  prefix->SetData(vtkDataArray::SafeDownCast(Prefix(whole->GetPoints()->GetData(), points, false)));
  output->SetPoints(prefix);
  // The offsets (0, 3, 6, ...) a view of the whole's, in the cell array's own 64-bit storage
  // type, which SetData keeps as it is (other types it converts, and a view would lose its owner).
  const vtkIdType count = corners->GetNumberOfValues() / 3;
  vtkSmartPointer<vtkCellArray::ArrayType64> offsets;
  if (whole->GetPolys()->IsStorage64Bit())
  {
    offsets = vtkCellArray::ArrayType64::SafeDownCast(Prefix(whole->GetPolys()->GetOffsetsArray64(), count + 1, false));
  }
  else
  {
    offsets = vtkSmartPointer<vtkCellArray::ArrayType64>::New();
    offsets->SetNumberOfValues(count + 1);
    for (vtkIdType i = 0; i <= count; ++i)
    {
      offsets->SetValue(i, 3 * i);
    }
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, corners);
  output->SetPolys(cells);
  PrefixArrays(whole->GetCellData(), count, output->GetCellData());
  PrefixArrays(whole->GetPointData(), points, output->GetPointData());
  // The whole's point arrays include the core's (its first points' values are the level's).
  FinishOutput(input, triangles, mesh, false, output);
}

void AddInputToOutputIds(const meshsimp::SimplifiedMesh& mesh, const meshsimp::TriangleMeshView& input, vtkPolyData* output)
{
  const vtkIdType inputPoints = input.NumberOfPoints;
  vtkNew<vtkIdTypeArray> map;
  map->SetName(InputToOutputPointIdsName);
  map->SetNumberOfValues(inputPoints);
  map->FillValue(-1);
  for (std::size_t p = 0; p + 1 < mesh.SourceOffsets.size(); ++p) // the sources' points, listed alone or not
  {
    for (std::int32_t i = mesh.SourceOffsets[p]; i < mesh.SourceOffsets[p + 1]; ++i)
    {
      if (mesh.SourcePoints[i] >= 0 && mesh.SourcePoints[i] < inputPoints)
      {
        map->SetValue(mesh.SourcePoints[i], static_cast<vtkIdType>(p));
      }
    }
  }
  MapJoinedPoints(input, map);
  output->GetFieldData()->AddArray(map);
}

void AddFieldValue(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}

}
