// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationInput.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGeometryFilter.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVariant.h"

#include <algorithm>
#include <limits>
#include <map>

namespace vtkSimplification
{

namespace
{
std::string TooManyTriangles(std::int64_t count)
{
  return "the input has " + std::to_string(count) + " triangles, more than the " +
    std::to_string(meshsimp::MaximumTriangles) + " the filters take";
}

} // namespace

vtkSmartPointer<vtkPolyData> WithUsableAttributes(vtkAlgorithm* filter, vtkPolyData* input)
{
  vtkSmartPointer<vtkPolyData> usable = input;
  const struct
  {
    int Association;
    vtkIdType Count;
    const char* What;
  } sets[2] = { { vtkDataObject::POINT, input->GetNumberOfPoints(), "point" },
    { vtkDataObject::CELL, input->GetNumberOfCells(), "cell" } };
  for (const auto& set : sets)
  {
    vtkDataSetAttributes* data = input->GetAttributes(set.Association);
    for (int i = data->GetNumberOfArrays() - 1; i >= 0; --i) // from the end: indices stay valid
    {
      vtkAbstractArray* array = data->GetAbstractArray(i);
      if (array->GetNumberOfTuples() >= set.Count)
      {
        continue;
      }
      vtkWarningWithObjectMacro(filter, << "Not passing " << set.What << " data array '"
                                        << (array->GetName() ? array->GetName() : "") << "': it has "
                                        << array->GetNumberOfTuples() << " tuples for "
                                        << set.Count << " " << set.What << "s.");
      if (usable == input)
      {
        usable = vtkSmartPointer<vtkPolyData>::New();
        usable->ShallowCopy(input); // shares every array; the input keeps its own lists
      }
      usable->GetAttributes(set.Association)->RemoveArray(i);
    }
  }
  return usable;
}

namespace
{

/// The input's points as the view's float or double coordinates, or a copy in doubles.
bool ViewPoints(vtkPolyData* input, TriangleInput& out, std::string& error)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints >= std::numeric_limits<std::int32_t>::max())
  {
    error = "the input has more than 2^31 - 1 points";
    return false;
  }
  out.View.NumberOfPoints = numberOfPoints;
  if (numberOfPoints == 0)
  {
    return true;
  }
  vtkDataArray* coordinates = input->GetPoints()->GetData();
  auto* doubles = vtkDoubleArray::SafeDownCast(coordinates);
  auto* floats = vtkFloatArray::SafeDownCast(coordinates);
  if (doubles && doubles->GetNumberOfComponents() == 3)
  {
    out.View.Points = doubles->GetPointer(0);
  }
  else if (floats && floats->GetNumberOfComponents() == 3)
  {
    out.View.FloatPoints = floats->GetPointer(0);
  }
  else
  {
    out.PointCopy.resize(3 * numberOfPoints);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      coordinates->GetTuple(i, out.PointCopy.data() + 3 * i);
    }
    out.View.Points = out.PointCopy.data();
  }
  return true;
}

/// The cell ghost flags that mark cells not to simplify (another piece's copies under MPI, or
/// hidden ones), or null when no polygon or strip has one.
vtkUnsignedCharArray* SkippedCellFlags(vtkPolyData* input, vtkIdType firstPolygon)
{
  vtkUnsignedCharArray* ghosts = input->GetCellGhostArray();
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  if (!ghosts || ghosts->GetNumberOfValues() < numberOfCells)
  {
    return nullptr; // PrepareTriangles leaves out arrays that are too short
  }
  const unsigned char skipped = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  for (vtkIdType id = firstPolygon; id < numberOfCells; ++id)
  {
    if (ghosts->GetValue(id) & skipped)
    {
      return ghosts;
    }
  }
  return nullptr;
}

/// Appends the triangles of the polygons (ear-cut, a fan when that fails) and strips, from
/// cell id `cellId` on, skipping the cells flagged in ghosts.
void TriangulateCells(vtkPolyData* input, vtkUnsignedCharArray* ghosts, vtkIdType cellId, TriangleInput& out)
{
  const unsigned char skipped = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType source) {
    out.Triangles.insert(out.Triangles.end(),
      { static_cast<std::int32_t>(a), static_cast<std::int32_t>(b), static_cast<std::int32_t>(c) });
    out.SourceCells.push_back(source);
  };
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triangleIds;
  for (vtkCellArray* cells : { input->GetPolys(), input->GetStrips() })
  {
    const bool strips = cells == input->GetStrips();
    auto cell = vtk::TakeSmartPointer(cells->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell(), ++cellId)
    {
      vtkIdType size;
      const vtkIdType* ids;
      if (ghosts && (ghosts->GetValue(cellId) & skipped))
      {
        continue;
      }
      cell->GetCurrentCell(size, ids);
      out.NumberOfShortCells += size < 3;
      if (strips)
      {
        for (vtkIdType k = 0; k + 2 < size; ++k)
        {
          add(ids[k + (k % 2)], ids[k + 1 - (k % 2)], ids[k + 2], cellId);
        }
      }
      else if (size == 3)
      {
        add(ids[0], ids[1], ids[2], cellId);
      }
      else if (size > 3)
      {
        polygon->Initialize(static_cast<int>(size), ids, input->GetPoints());
        if (polygon->Triangulate(triangleIds) && triangleIds->GetNumberOfIds() == 3 * (size - 2))
        {
          for (vtkIdType k = 0; k < triangleIds->GetNumberOfIds(); k += 3)
          {
            const vtkIdType* ear = triangleIds->GetPointer(k);
            add(ids[ear[0]], ids[ear[1]], ids[ear[2]], cellId);
          }
        }
        else
        {
          for (vtkIdType k = 1; k + 1 < size; ++k)
          {
            add(ids[0], ids[k], ids[k + 1], cellId);
          }
        }
      }
    }
  }
}
}

bool ExtractTriangles(vtkPolyData* input, TriangleInput& out, std::string& error)
{
  out = TriangleInput();
  if (!ViewPoints(input, out, error))
  {
    return false;
  }
  out.NumberOfVerts = input->GetNumberOfVerts();
  out.NumberOfLines = input->GetNumberOfLines();
  // Cell ids of vtkPolyData run over verts, lines, polys, then strips.
  const vtkIdType firstPolygon = out.NumberOfVerts + out.NumberOfLines;
  vtkUnsignedCharArray* ghosts = SkippedCellFlags(input, firstPolygon);
  vtkCellArray* polys = input->GetPolys();
  if (polys->IsHomogeneous() == 3 && input->GetNumberOfStrips() == 0 && !ghosts)
  {
    // Triangles only, the common case: the connectivity is viewed in place.
    const vtkIdType count = polys->GetNumberOfCells();
    if (count > meshsimp::MaximumTriangles)
    {
      error = TooManyTriangles(count);
      return false;
    }
    if (polys->IsStorage64Bit())
    {
      out.View.Triangles64 = polys->GetConnectivityArray64()->GetPointer(0);
    }
    else
    {
      out.View.Triangles = polys->GetConnectivityArray32()->GetPointer(0);
    }
    out.FirstCell = firstPolygon;
    out.View.NumberOfTriangles = count;
    return true;
  }
  TriangulateCells(input, ghosts, firstPolygon, out);
  if (static_cast<std::int64_t>(out.SourceCells.size()) > meshsimp::MaximumTriangles)
  {
    error = TooManyTriangles(static_cast<std::int64_t>(out.SourceCells.size()));
    return false;
  }
  out.View.Triangles = out.Triangles.data();
  out.View.NumberOfTriangles = static_cast<std::int64_t>(out.SourceCells.size());
  return true;
}

vtkSmartPointer<vtkPolyData> AsSurface(vtkDataObject* data, std::string& problem)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  auto* dataSet = vtkDataSet::SafeDownCast(data);
  if (!dataSet)
  {
    problem = std::string("a ") + (data ? data->GetClassName() : "missing input") +
      " is neither a dataset nor composite data of datasets";
    return nullptr;
  }
  for (vtkIdType c = 0; c < dataSet->GetNumberOfCells(); ++c)
  {
    if (vtkCellTypes::GetDimension(static_cast<unsigned char>(dataSet->GetCellType(c))) == 3)
    {
      problem = std::string("the ") + dataSet->GetClassName() +
        " has 3-D cells; apply Extract Surface first to use its boundary surface";
      return nullptr;
    }
  }
  vtkNew<vtkGeometryFilter> surface;
  surface->SetInputData(dataSet);
  surface->PassThroughPointIdsOn();
  surface->PassThroughCellIdsOn();
  surface->SetOriginalPointIdsName(SurfacePointIdsName);
  surface->SetOriginalCellIdsName(SurfaceCellIdsName);
  surface->Update();
  return vtkSmartPointer<vtkPolyData>(surface->GetOutput());
}

bool PrepareTriangles(vtkAlgorithm* filter, vtkSmartPointer<vtkPolyData>& input, TriangleInput& triangles)
{
  input = WithUsableAttributes(filter, input);
  std::string problem;
  if (!ExtractTriangles(input, triangles, problem))
  {
    vtkErrorWithObjectMacro(filter, << "Cannot simplify: " << problem << ".");
    return false;
  }
  if (triangles.NumberOfShortCells > 0)
  {
    const vtkIdType count = triangles.NumberOfShortCells;
    vtkWarningWithObjectMacro(filter, << "Ignoring " << count
                                      << (count == 1 ? " polygon or strip" : " polygons and strips")
                                      << " of fewer than 3 points.");
  }
  const vtkIdType verts = triangles.NumberOfVerts, lines = triangles.NumberOfLines;
  if (verts + lines > 0)
  {
    const std::string vertexCells = verts > 0 ? std::to_string(verts) + (verts == 1 ? " vertex cell" : " vertex cells") : "";
    const std::string lineCells = lines > 0 ? std::to_string(lines) + (lines == 1 ? " line cell" : " line cells") : "";
    vtkWarningWithObjectMacro(filter, << "Dropping " << vertexCells << (verts > 0 && lines > 0 ? " and " : "")
                                      << lineCells << ": only triangles, polygons and strips are simplified.");
  }
  return true;
}

vtkAbstractArray* SelectedPointArray(vtkAlgorithm* filter, int index, vtkPolyData* input, const char* purpose)
{
  // Input array `index`, as SetInputArrayToProcess or the XML's selection chose it.
  vtkInformation* selection = filter->GetInputArrayInformation(index);
  vtkAbstractArray* array = nullptr;
  std::string name;
  if (selection->Has(vtkDataObject::FIELD_NAME()))
  {
    name = selection->Get(vtkDataObject::FIELD_NAME());
    if (name.empty() || name == "None")
    {
      return nullptr; // ParaView's "no array" choice
    }
    array = input->GetPointData()->GetAbstractArray(name.c_str());
    name = "'" + name + "'";
  }
  else if (selection->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    array = input->GetPointData()->GetAttribute(selection->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
    name = "of the selected attribute";
  }
  else
  {
    return nullptr; // nothing selected
  }
  if (!array || array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkWarningWithObjectMacro(filter, << "Ignoring the " << purpose << " array " << name
                                      << ": it is not a point-data array of the input.");
    return nullptr;
  }
  return array;
}

std::int64_t ReadLockedPoints(vtkAbstractArray* array, std::vector<std::uint8_t>& locks, std::vector<std::uint8_t>& userLocked)
{
  const vtkIdType n = array->GetNumberOfTuples();
  locks.resize(static_cast<std::size_t>(n), 0); // keeps the locks already set
  userLocked.assign(static_cast<std::size_t>(n), 0);
  auto* values = vtkDataArray::SafeDownCast(array);
  std::int64_t locked = 0;
  for (vtkIdType i = 0; i < n && values; ++i)
  {
    if (values->GetComponent(i, 0) != 0.0)
    {
      locks[i] = locks[i] == 0 ? 1 : locks[i];
      userLocked[i] = 1;
      ++locked;
    }
  }
  return locked;
}

std::vector<std::int32_t> ReadRegions(vtkAbstractArray* array)
{
  // Tuples compared as their variant values, component by component: numbers by value, strings
  // by text.
  const vtkIdType n = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  std::map<std::vector<vtkVariant>, std::int32_t> ids;
  std::vector<std::int32_t> regions(static_cast<std::size_t>(n));
  std::vector<vtkVariant> tuple(static_cast<std::size_t>(components));
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      tuple[c] = array->GetVariantValue(i * components + c);
    }
    regions[i] = ids.emplace(tuple, static_cast<std::int32_t>(ids.size())).first->second;
  }
  return regions;
}

}
