// SPDX-License-Identifier: BSD-3-Clause
// The front end every filter shares (vtkMeshSimplificationFilter), checked on each registered
// filter (MeshSimplificationFilterList.h): sharp attribute borders, a count shared out over
// composite blocks, blocks that are not polygonal passed through, surfaces of other datasets, 3-D
// cells refused, the Deviation array, the error reported in the bound's units, zero-width cracks
// closed unless point data differ, the original ids, and the output arrays' recorded ranges.
#include "MeshSimplificationFilters.h"

#include "vtkAppendFilter.h"
#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkTypeInt64Array.h"
#include "vtkCellLocator.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnstructuredGrid.h"

#include "TestBadInput.h"

#include <functional>
#include <vector>

namespace
{
using Factory = std::function<vtkSmartPointer<vtkMeshSimplificationFilter>()>;

/// A sphere whose RGB colour is red where x < 0 and blue elsewhere, with a label array of the
/// same halves (0 and 7).
vtkSmartPointer<vtkPolyData> TwoColouredSphere()
{
  vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> labels;
  labels->SetName("Labels");
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    const bool red = sphere->GetPoint(i)[0] < 0.0;
    colours->InsertNextTuple3(red ? 255 : 0, 0, red ? 0 : 255);
    labels->InsertNextValue(red ? 0 : 7);
  }
  sphere->GetPointData()->AddArray(colours);
  sphere->GetPointData()->AddArray(labels);
  return sphere;
}

/// How many output colours are neither pure red nor pure blue.
vtkIdType BlendedColours(vtkPolyData* output)
{
  vtkDataArray* colours = output->GetPointData()->GetArray("Colours");
  vtkIdType blended = 0;
  for (vtkIdType i = 0; colours && i < colours->GetNumberOfTuples(); ++i)
  {
    const double* c = colours->GetTuple3(i);
    blended += (c[0] == 255 && c[2] == 0) || (c[0] == 0 && c[2] == 255) ? 0 : 1;
  }
  return blended;
}

/// With PreserveAttributeBorders and the colour array chosen, no colour is blended across the
/// red-blue border and the count target is still met; choosing no array warns. Without it the
/// filters that interpolate (blends) make purple points, by the geometry alone: a filter that
/// weighs colours in its order (AttributeWeight) has that weight at 0 here.
void CheckAttributeBorders(const Factory& make, double tolerance, bool blends)
{
  vtkSmartPointer<vtkPolyData> sphere = TwoColouredSphere();
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
  filter->SetSettingByName("AttributeWeight", 0.0);
  filter->SetInputData(sphere);
  filter->SetTargetReduction(0.8);
  filter->Update();
  CHECK((BlendedColours(filter->GetOutput()) > 0) == blends);
  filter->PreserveAttributeBordersOn();
  filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Colours");
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  const double target = 0.2 * sphere->GetNumberOfPolys();
  CHECK(BlendedColours(output) == 0);
  CHECK(std::abs(output->GetNumberOfPolys() - target) <= tolerance * target + 1);
  vtkDataArray* labels = output->GetPointData()->GetArray("Labels");
  for (vtkIdType i = 0; labels && i < labels->GetNumberOfTuples(); ++i)
  {
    CHECK(labels->GetTuple1(i) == 0 || labels->GetTuple1(i) == 7);
  }
  vtkNew<meshsimp_test::MessageLog> log;
  filter->AddObserver(vtkCommand::WarningEvent, log);
  filter->SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  filter->Update();
  CHECK(log->Warnings.size() == 1 && meshsimp_test::Mentions(log->Warnings[0], "PreserveAttributeBorders"));
}

/// The sphere as a damaged export has it: a slit along the meridian y = 0, x > 0, its two sides
/// with their own copies of the points there (the same coordinates and point data), and an
/// array "Side" that is 1 on the copies only.
vtkSmartPointer<vtkPolyData> SlitSphere()
{
  vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
  vtkPoints* points = sphere->GetPoints();
  vtkPointData* pointData = sphere->GetPointData();
  const vtkIdType n = sphere->GetNumberOfPoints();
  std::vector<vtkIdType> copyOf(static_cast<std::size_t>(n), -1);
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkIdList> ids;
  for (vtkIdType t = 0; t < sphere->GetNumberOfPolys(); ++t)
  {
    sphere->GetCellPoints(t, ids);
    double y = 0.0;
    for (vtkIdType k = 0; k < 3; ++k)
    {
      y += points->GetPoint(ids->GetId(k))[1];
    }
    for (vtkIdType k = 0; k < 3 && y > 0.0; ++k)
    {
      const vtkIdType p = ids->GetId(k);
      if (points->GetPoint(p)[1] == 0.0 && points->GetPoint(p)[0] > 0.0)
      {
        if (copyOf[p] < 0)
        {
          copyOf[p] = points->InsertNextPoint(points->GetPoint(p));
          for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
          {
            vtkAbstractArray* array = pointData->GetAbstractArray(a);
            array->InsertTuple(copyOf[p], p, array);
          }
        }
        ids->SetId(k, copyOf[p]);
      }
    }
    triangles->InsertNextCell(ids);
  }
  sphere->SetPolys(triangles);
  vtkNew<vtkIntArray> side;
  side->SetName("Side");
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    side->InsertNextValue(i < n ? 0 : 1);
  }
  pointData->AddArray(side);
  return sphere;
}

/// The slit of SlitSphere closes where no point array tells its sides apart (the output is a
/// closed sphere, the points joined counted in the field data), and stays open where one does
/// (here "Side" until it is removed) or CloseCracks is off. The input is not changed.
void CheckCracks(const Factory& make)
{
  vtkSmartPointer<vtkPolyData> slit = SlitSphere();
  CHECK(meshsimp_test::OpenEdges(slit) > 20);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(slit);
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
  filter->SetInputData(slit);
  filter->SetTargetReduction(0.5);
  filter->Update();
  CHECK(meshsimp_test::OpenEdges(filter->GetOutput()) > 0);
  meshsimp_test::CheckInputUntouched(slit, copy);
  auto sameData = vtkSmartPointer<vtkPolyData>::New();
  sameData->ShallowCopy(slit);
  sameData->GetPointData()->RemoveArray("Side");
  // 64-bit integers are told apart exactly (2^60 and 2^60 + 1 are one double).
  const vtkIdType n = slit->GetNumberOfPoints(), whole = meshsimp_test::Sphere()->GetNumberOfPoints();
  vtkNew<vtkTypeInt64Array> big;
  big->SetName("Big");
  for (vtkIdType i = 0; i < n; ++i)
  {
    big->InsertNextValue((vtkTypeInt64(1) << 60) + (i < whole ? 0 : 1));
  }
  sameData->GetPointData()->AddArray(big);
  filter->SetInputData(sameData);
  filter->Update();
  CHECK(meshsimp_test::OpenEdges(filter->GetOutput()) > 0);
  sameData->GetPointData()->RemoveArray("Big");
  // Global ids name every point apart and do not count; a string array with one value does.
  vtkNew<vtkIdTypeArray> globalIds;
  vtkNew<vtkStringArray> label;
  label->SetName("Label");
  for (vtkIdType i = 0; i < n; ++i)
  {
    globalIds->InsertNextValue(i);
    label->InsertNextValue("skin");
  }
  sameData->GetPointData()->SetGlobalIds(globalIds);
  sameData->GetPointData()->AddArray(label);
  filter->SetInputData(sameData);
  filter->Update();
  vtkPolyData* closed = filter->GetOutput();
  CHECK(meshsimp_test::OpenEdges(closed) == 0 && closed->GetNumberOfPolys() > 0);
  vtkDataArray* joined = closed->GetFieldData()->GetArray("JoinedPoints");
  CHECK(joined && joined->GetTuple1(0) == static_cast<double>(n - whole));
  // With CloseCracks off the slit stays open, as a border.
  filter->CloseCracksOff();
  filter->Update();
  vtkPolyData* open = filter->GetOutput();
  CHECK(meshsimp_test::OpenEdges(open) > 0 && !open->GetFieldData()->GetArray("JoinedPoints"));
}

/// A multiblock of the sphere, the sphere made twice as fine, and an image: a triangle count
/// means the whole input, shared out by the blocks' triangles; the image passes through.
void CheckCompositeCount(const Factory& make, double tolerance)
{
  vtkSmartPointer<vtkPolyData> coarse = meshsimp_test::Sphere();
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(64);
  source->SetPhiResolution(32);
  source->Update();
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 5, 6);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, coarse);
  blocks->SetBlock(1, source->GetOutput());
  blocks->SetBlock(2, image);
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
  filter->SetInputData(blocks);
  filter->SetTargetModeToTriangleCount();
  filter->SetTargetTriangleCount(600);
  filter->Update();
  auto* output = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  CHECK(output && output->GetNumberOfBlocks() == 3);
  auto* first = vtkPolyData::SafeDownCast(output ? output->GetBlock(0) : nullptr);
  auto* second = vtkPolyData::SafeDownCast(output ? output->GetBlock(1) : nullptr);
  auto* passed = vtkImageData::SafeDownCast(output ? output->GetBlock(2) : nullptr);
  CHECK(first && second && passed);
  if (!first || !second || !passed)
  {
    return;
  }
  const double total = coarse->GetNumberOfPolys() + source->GetOutput()->GetNumberOfPolys();
  const double got = first->GetNumberOfPolys() + second->GetNumberOfPolys();
  CHECK(std::abs(got - 600) <= 2 * tolerance * 600 + 2);
  CHECK(std::abs(second->GetNumberOfPolys() - 600 * source->GetOutput()->GetNumberOfPolys() / total) <=
    tolerance * 600 + 2);
  CHECK(passed->GetNumberOfPoints() == image->GetNumberOfPoints() && passed->GetDimensions()[2] == 6);
}

/// A dataset whose cells are surfaces (the sphere as an unstructured grid, as after Merge
/// Blocks) is simplified like the polygonal sphere; one with 3-D cells is refused in one line
/// that says to extract its surface first.
void CheckOtherDatasets(const Factory& make)
{
  vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
  vtkNew<vtkAppendFilter> grid;
  grid->SetInputData(sphere);
  grid->Update();
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
  filter->SetInputData(grid->GetOutput());
  filter->SetTargetReduction(0.5);
  filter->Update();
  const double target = 0.5 * sphere->GetNumberOfPolys();
  CHECK(std::abs(filter->GetOutput()->GetNumberOfPolys() - target) <= 0.05 * target);

  vtkNew<vtkUnstructuredGrid> tetrahedra;
  vtkNew<vtkPoints> points;
  for (const double* p : { std::array<double, 3>{ 0, 0, 0 }.data(), std::array<double, 3>{ 1, 0, 0 }.data(),
         std::array<double, 3>{ 0, 1, 0 }.data(), std::array<double, 3>{ 0, 0, 1 }.data() })
  {
    points->InsertNextPoint(p);
  }
  tetrahedra->SetPoints(points);
  const vtkIdType tetra[4] = { 0, 1, 2, 3 };
  tetrahedra->InsertNextCell(VTK_TETRA, 4, tetra);
  vtkNew<meshsimp_test::MessageLog> log, executive;
  vtkSmartPointer<vtkMeshSimplificationFilter> refusing = make();
  refusing->AddObserver(vtkCommand::ErrorEvent, log);
  refusing->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  refusing->SetInputData(tetrahedra);
  refusing->Update();
  CHECK(log->Errors.size() == 1 && executive->Errors.empty());
  CHECK(!log->Errors.empty() && meshsimp_test::Mentions(log->Errors[0], "apply Extract Surface first"));
}

/// The largest distance from a point of from to the surface of to (a cell locator over to); with
/// insideTriangles also from the centre and edge middles of each of from's triangles.
double LargestDistance(vtkPolyData* from, vtkPolyData* to, bool insideTriangles = false)
{
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double largest = 0.0;
  const auto measure = [&](const double* x) {
    double closest[3], distance2;
    vtkIdType cellId;
    int subId;
    locator->FindClosestPoint(x, closest, cell, cellId, subId, distance2);
    largest = std::max(largest, std::sqrt(distance2));
  };
  for (vtkIdType i = 0; i < from->GetNumberOfPoints(); ++i)
  {
    measure(from->GetPoint(i));
  }
  for (vtkIdType c = 0; insideTriangles && c < from->GetNumberOfCells(); ++c)
  {
    double p[3][3];
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    from->GetCellPoints(c, count, ids);
    for (int k = 0; k < 3 && count == 3; ++k)
    {
      from->GetPoint(ids[k], p[k]);
    }
    for (int k = 0; k < 3 && count == 3; ++k)
    {
      const double middle[3] = { 0.5 * (p[k][0] + p[(k + 1) % 3][0]), 0.5 * (p[k][1] + p[(k + 1) % 3][1]),
        0.5 * (p[k][2] + p[(k + 1) % 3][2]) };
      measure(middle);
    }
    if (count == 3)
    {
      const double centre[3] = { (p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3,
        (p[0][2] + p[1][2] + p[2][2]) / 3 };
      measure(centre);
    }
  }
  return largest;
}

/// Deviation is two-sided (issue 45, §2): each output point's value is at least its own
/// distance to the input, and the maximum, in the field data with the RMS, is the two-sided
/// distance between the meshes' points and surfaces (each way measured independently with a
/// cell locator: the output's points, triangle centres and edge middles, which the deviation
/// measures, to the input; the input's points to the output), within 5 %: the local search may
/// only overestimate, and by little.
void CheckDeviation(const Factory& make)
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  for (const int mode : { vtkMeshSimplificationFilter::TARGET_REDUCTION, vtkMeshSimplificationFilter::TARGET_MAXIMUM_ERROR })
  {
    vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
    filter->SetInputData(cow);
    filter->SetTargetMode(mode);
    filter->ComputeDeviationOn();
    filter->Update();
    vtkPolyData* output = filter->GetOutput();
    vtkDataArray* deviation = output->GetPointData()->GetArray("Deviation");
    CHECK(deviation && deviation->GetNumberOfTuples() == output->GetNumberOfPoints());
    vtkNew<vtkCellLocator> locator;
    locator->SetDataSet(cow);
    locator->BuildLocator();
    vtkNew<vtkGenericCell> cell;
    double largest = 0.0, squares = 0.0;
    for (vtkIdType i = 0; deviation && i < output->GetNumberOfPoints(); ++i)
    {
      double closest[3], distance2;
      vtkIdType cellId;
      int subId;
      locator->FindClosestPoint(output->GetPoint(i), closest, cell, cellId, subId, distance2);
      CHECK(deviation->GetTuple1(i) >= std::sqrt(distance2) - 1e-9);
      largest = std::max(largest, deviation->GetTuple1(i));
      squares += deviation->GetTuple1(i) * deviation->GetTuple1(i);
    }
    const double twoSided = std::max(LargestDistance(output, cow, true), LargestDistance(cow, output));
    vtkDataArray* maximum = output->GetFieldData()->GetArray("DeviationMaximum");
    vtkDataArray* rms = output->GetFieldData()->GetArray("DeviationRMS");
    CHECK(maximum && maximum->GetTuple1(0) == largest && largest > 0.0);
    CHECK(largest >= twoSided - 1e-9 && largest <= 1.05 * twoSided);
    CHECK(rms && std::abs(rms->GetTuple1(0) - std::sqrt(squares / output->GetNumberOfPoints())) < 1e-12);
  }
}

/// Under an error bound the reported maximum error is in the bound's units: a fraction of the
/// diagonal when relative, input units when not; the cow scaled by 100 makes the two differ.
void CheckErrorUnits(const Factory& make)
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  vtkNew<vtkTransform> scale;
  scale->Scale(100, 100, 100);
  vtkNew<vtkTransformPolyDataFilter> scaled;
  scaled->SetTransform(scale);
  scaled->SetInputData(cow);
  scaled->Update();
  const double diagonal = scaled->GetOutput()->GetLength();
  for (const bool relative : { true, false })
  {
    const double bound = relative ? 0.01 : 0.01 * diagonal;
    vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
    filter->SetInputData(scaled->GetOutput());
    filter->SetTargetModeToMaximumError();
    filter->SetMaximumError(bound);
    filter->SetRelativeError(relative);
    filter->Update();
    const double reached = filter->GetAchievedMaximumError();
    CHECK(reached > 0.3 * bound && reached <= bound * (1 + 1e-9));
    vtkDataArray* field = filter->GetOutput()->GetFieldData()->GetArray("MaximumError");
    CHECK(field && field->GetTuple1(0) == reached);
  }
}

/// The sphere with an id array of its points and one of its cells; as an unstructured grid, with
/// an unused point first and a line cell before each triangle, so that the ids of the surface
/// the filters make from it are not the grid's.
vtkSmartPointer<vtkDataSet> SphereWithIds(bool grid)
{
  vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
  vtkSmartPointer<vtkDataSet> data = sphere;
  if (grid)
  {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(9.0, 9.0, 9.0);
    for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
    {
      points->InsertNextPoint(sphere->GetPoint(i));
    }
    auto unstructured = vtkSmartPointer<vtkUnstructuredGrid>::New();
    unstructured->SetPoints(points);
    vtkNew<vtkIdList> cell;
    for (vtkIdType t = 0; t < sphere->GetNumberOfCells(); ++t)
    {
      sphere->GetCellPoints(t, cell);
      const vtkIdType line[2] = { cell->GetId(0) + 1, cell->GetId(1) + 1 };
      unstructured->InsertNextCell(VTK_LINE, 2, line);
      const vtkIdType triangle[3] = { cell->GetId(0) + 1, cell->GetId(1) + 1, cell->GetId(2) + 1 };
      unstructured->InsertNextCell(VTK_TRIANGLE, 3, triangle);
    }
    data = unstructured;
  }
  vtkNew<vtkIdTypeArray> pointIds, cellIds;
  pointIds->SetName("PointIds");
  cellIds->SetName("CellIds");
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    pointIds->InsertNextValue(i);
  }
  for (vtkIdType i = 0; i < data->GetNumberOfCells(); ++i)
  {
    cellIds->InsertNextValue(i);
  }
  data->GetPointData()->AddArray(pointIds);
  data->GetCellData()->AddArray(cellIds);
  return data;
}

/// With GenerateOriginalIds, vtkOriginalPointIds and vtkOriginalCellIds name each output point's
/// representative and each triangle's input cell: the same ids the point-data rule and the
/// cell-data copy use (an integer point array of ids and a cell array of ids come out equal to
/// them), each point's distinct and in range; at a second target too (Progressive Mesh then
/// writes its level from the cached sequence), and for an unstructured grid, whose ids are the
/// grid's, not those of the surface made from it; without it, neither array is there, nor any
/// array of the front end's own.
void CheckOriginalIds(const Factory& make)
{
  for (const bool grid : { false, true })
  {
    vtkSmartPointer<vtkDataSet> input = SphereWithIds(grid);
    vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
    filter->SetInputData(input);
    filter->SetTargetReduction(0.8);
    filter->Update();
    vtkPolyData* plain = filter->GetOutput();
    CHECK(!plain->GetPointData()->GetArray("vtkOriginalPointIds") && !plain->GetCellData()->GetArray("vtkOriginalCellIds"));
    CHECK(!plain->GetPointData()->GetArray("vtkSimplificationSurfacePointIds") &&
      !plain->GetCellData()->GetArray("vtkSimplificationSurfaceCellIds"));
    filter->GenerateOriginalIdsOn();
    for (const double reduction : { 0.8, 0.5 })
    {
      filter->SetTargetReduction(reduction);
      filter->Update();
      vtkPolyData* output = filter->GetOutput();
      vtkDataArray* original = output->GetPointData()->GetArray("vtkOriginalPointIds");
      vtkDataArray* originalCells = output->GetCellData()->GetArray("vtkOriginalCellIds");
      CHECK(original && originalCells && output->GetNumberOfCells() > 0);
      CHECK(!output->GetPointData()->GetArray("vtkSimplificationSurfacePointIds"));
      if (!original || !originalCells)
      {
        return;
      }
      vtkDataArray* carried = output->GetPointData()->GetArray("PointIds");
      std::vector<bool> seen(static_cast<std::size_t>(input->GetNumberOfPoints()), false);
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        const vtkIdType id = static_cast<vtkIdType>(original->GetTuple1(i));
        const bool inRange = id >= 0 && id < input->GetNumberOfPoints();
        CHECK(inRange && !seen[id] && carried->GetTuple1(i) == id);
        seen[id] = inRange;
      }
      vtkDataArray* copied = output->GetCellData()->GetArray("CellIds");
      for (vtkIdType t = 0; t < output->GetNumberOfCells(); ++t)
      {
        CHECK(originalCells->GetTuple1(t) == copied->GetTuple1(t));
      }
    }
  }
}

/// The arrays a filter writes carry their ranges (VTK's range cache), equal to the ranges VTK
/// computes; the arrays it shares with its input are left as they are.
void CheckRecordedRanges(const Factory& make)
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = make();
  filter->SetInputData(cow);
  filter->ComputeDeviationOn();
  filter->GenerateOriginalIdsOn();
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  std::vector<vtkDataArray*> written = { output->GetPoints()->GetData() };
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(output->GetPointData()), static_cast<vtkFieldData*>(output->GetCellData()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      written.push_back(data->GetArray(a));
    }
  }
  CHECK(written.size() >= 5); // points, the cow's arrays, Deviation, the original ids
  for (vtkDataArray* array : written)
  {
    meshsimp_test::CheckRecordedRanges(array);
  }
}

void CheckFilter(const Factory& make, double tolerance, bool blends)
{
  CheckOriginalIds(make);
  CheckAttributeBorders(make, tolerance, blends);
  CheckCracks(make);
  CheckCompositeCount(make, tolerance);
  CheckOtherDatasets(make);
  CheckDeviation(make);
  CheckErrorUnits(make);
  CheckRecordedRanges(make);
}
}

int TestFrontEnd(int, char*[])
{
#define MESHSIMPLIFICATION_CHECK(name, method, parameters, tolerance, blends, alias)                \
  CheckFilter([] { return vtkSmartPointer<vtk##name>::New(); }, tolerance, blends);
  MESHSIMPLIFICATION_FILTERS(MESHSIMPLIFICATION_CHECK)
#undef MESHSIMPLIFICATION_CHECK
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
