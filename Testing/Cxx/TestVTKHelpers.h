// SPDX-License-Identifier: BSD-3-Clause
// Checks shared by the VTK-level tests.
#ifndef MeshSimplification_TestVTKHelpers_h
#define MeshSimplification_TestVTKHelpers_h

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPartitionedDataSet.h"
#include "vtkMath.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkOFFMeshReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include "TestHelpers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace meshsimp_test
{
/// The filter never modifies its input: input still equals the copy taken before it ran (same
/// points, NaN where the copy has NaN, same number of cells).
inline void CheckInputUntouched(vtkPolyData* input, vtkPolyData* copy)
{
  CHECK(input->GetNumberOfPoints() == copy->GetNumberOfPoints());
  CHECK(input->GetNumberOfCells() == copy->GetNumberOfCells());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    copy->GetPoint(i, b);
    for (int k = 0; k < 3; ++k)
    {
      CHECK(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])));
    }
  }
}

/// The cow with point arrays of every kind (scalars, vectors, normals, colours, texture
/// coordinates, constants of several types, labels) and a cell-id array.
inline vtkSmartPointer<vtkPolyData> DecoratedCow()
{
  vtkNew<vtkOFFMeshReader> reader;
  reader->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/cow.off");
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->SplittingOff();
  normals->ComputeCellNormalsOn();
  normals->Update();
  auto cow = vtkSmartPointer<vtkPolyData>::New();
  cow->DeepCopy(normals->GetOutput());

  const vtkIdType n = cow->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("Velocity");
  velocity->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkDoubleArray> constant;
  constant->SetName("Constant");
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  vtkNew<vtkUnsignedCharArray> paint;
  paint->SetName("Paint");
  paint->SetNumberOfComponents(4);
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    cow->GetPoint(i, p);
    height->InsertNextValue(p[1]);
    velocity->InsertNextTuple3(p[0], 2 * p[1], -p[2]);
    colors->InsertNextTuple3(i % 256, 128, 255 - i % 256);
    tcoords->InsertNextTuple2(p[0], p[2]);
    constant->InsertNextValue(0.1);
    material->InsertNextValue(7);
    paint->InsertNextTuple4(255, 255, 0, 255);
    label->InsertNextValue(i % 3 == 0 ? 1 : i % 3 == 1 ? 1000 : 1000000);
  }
  cow->GetPointData()->AddArray(material);
  cow->GetPointData()->AddArray(paint);
  cow->GetPointData()->AddArray(label);
  cow->GetPointData()->SetScalars(height);
  cow->GetPointData()->SetVectors(velocity);
  cow->GetPointData()->AddArray(colors);
  cow->GetPointData()->SetTCoords(tcoords);
  cow->GetPointData()->AddArray(constant);
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("SourceCell");
  for (vtkIdType c = 0; c < cow->GetNumberOfCells(); ++c)
  {
    cellIds->InsertNextValue(c);
  }
  cow->GetCellData()->AddArray(cellIds);
  return cow;
}

/// What every filter must carry from the decorated cow to its output: each point array with
/// its type and components (scalars, texture coordinates and normals active), floating values
/// that are convex combinations (Height stays in range), constants of every type exactly
/// (a double 0.1, an int 7, an RGBA colour with 255s), labels that some input point has, unit
/// normals, and cell data copied from distinct input cells.
inline void CheckCarriedData(vtkPolyData* cow, vtkPolyData* out)
{
  vtkPointData* pd = out->GetPointData();
  for (int a = 0; a < cow->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* in = cow->GetPointData()->GetArray(a);
    vtkDataArray* carried = pd->GetArray(in->GetName());
    CHECK(carried && carried->GetDataType() == in->GetDataType() &&
      carried->GetNumberOfComponents() == in->GetNumberOfComponents() &&
      carried->GetNumberOfTuples() == out->GetNumberOfPoints());
  }
  CHECK(pd->GetScalars() && std::string(pd->GetScalars()->GetName()) == "Height");
  CHECK(pd->GetTCoords() && pd->GetNormals());
  double range[2];
  cow->GetPointData()->GetArray("Height")->GetRange(range);
  for (vtkIdType i = 0; pd->GetNormals() && i < out->GetNumberOfPoints(); ++i)
  {
    CHECK(pd->GetArray("Constant")->GetTuple1(i) == 0.1);
    CHECK(pd->GetArray("Material")->GetTuple1(i) == 7.0);
    const double* paint = pd->GetArray("Paint")->GetTuple4(i);
    CHECK(paint[0] == 255 && paint[1] == 255 && paint[2] == 0 && paint[3] == 255);
    const double label = pd->GetArray("Label")->GetTuple1(i);
    CHECK(label == 1 || label == 1000 || label == 1000000);
    const double h = pd->GetArray("Height")->GetTuple1(i);
    CHECK(h >= range[0] - 1e-12 && h <= range[1] + 1e-12);
    CHECK(std::abs(vtkMath::Norm(pd->GetNormals()->GetTuple3(i)) - 1.0) < 1e-5);
  }
  vtkDataArray* sourceCells = out->GetCellData()->GetArray("SourceCell");
  CHECK(sourceCells && sourceCells->GetNumberOfTuples() == out->GetNumberOfCells());
  std::set<vtkIdType> distinct;
  for (vtkIdType c = 0; sourceCells && c < sourceCells->GetNumberOfTuples(); ++c)
  {
    distinct.insert(static_cast<vtkIdType>(sourceCells->GetTuple1(c)));
  }
  CHECK(static_cast<vtkIdType>(distinct.size()) == out->GetNumberOfCells());
  CHECK(out->GetCellData()->GetNormals() != nullptr);
}

/// The array carries its ranges in VTK's range cache (a filter recorded them), and they equal
/// the ranges VTK computes for a copy: every component's and the norm's, with and without
/// infinities.
inline void CheckRecordedRanges(vtkDataArray* array)
{
  CHECK(array->GetInformation()->Has(vtkAbstractArray::PER_COMPONENT()));
  vtkSmartPointer<vtkDataArray> computed = vtk::TakeSmartPointer(array->NewInstance());
  computed->DeepCopy(array);
  computed->Modified(); // drops whatever ranges the copy took along
  for (int c = -1; c < array->GetNumberOfComponents(); ++c)
  {
    double recorded[2], ranged[2], recordedFinite[2], rangedFinite[2];
    array->GetRange(recorded, c);
    computed->GetRange(ranged, c);
    array->GetFiniteRange(recordedFinite, c);
    computed->GetFiniteRange(rangedFinite, c);
    CHECK(recorded[0] == ranged[0] && recorded[1] == ranged[1]);
    CHECK(recordedFinite[0] == rangedFinite[0] && recordedFinite[1] == rangedFinite[1]);
  }
}
/// Boundary plus non-manifold edges: zero for a closed 2-manifold.
inline vtkIdType OpenEdges(vtkPolyData* mesh)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(mesh);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

/// A shallow copy of mesh with a point array "Locked" that is 1 on every step-th point.
inline vtkSmartPointer<vtkPolyData> WithLockArray(vtkPolyData* mesh, vtkIdType step)
{
  auto marked = vtkSmartPointer<vtkPolyData>::New();
  marked->ShallowCopy(mesh);
  vtkNew<vtkUnsignedCharArray> locks;
  locks->SetName("Locked");
  locks->SetNumberOfValues(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    locks->SetValue(i, i % step == 0 ? 1 : 0);
  }
  marked->GetPointData()->AddArray(locks);
  return marked;
}

/// The coordinates of a mesh's points, to look points up exactly.
inline std::set<std::array<double, 3>> PointSet(vtkPolyData* mesh)
{
  std::set<std::array<double, 3>> points;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    mesh->GetPoint(i, p.data());
    points.insert(p);
  }
  return points;
}

/// The cow as a vtkPartitionedDataSet of its two halves (x < 0 and x >= 0): the partitions are
/// simplified each, and the points they share are locked, so that the output's partitions still
/// close up into one closed surface (merged by coordinates); the border round then thins the cut
/// on both sides, so that the halves together meet the count (within 3 %). With every point in
/// the Locked Points array, the border round removes none of the cut's either. A multiblock of
/// the same halves treats them as separate datasets, which open at the cut.
template <typename Filter>
void CheckPartitionedInput(vtkPolyData* cow)
{
  vtkNew<vtkPartitionedDataSet> halves, lockedHalves;
  vtkNew<vtkMultiBlockDataSet> blocks;
  vtkNew<vtkIntArray> everyPoint;
  everyPoint->SetName("Locked");
  everyPoint->SetNumberOfValues(cow->GetNumberOfPoints());
  everyPoint->Fill(1);
  for (unsigned int half = 0; half < 2; ++half)
  {
    vtkNew<vtkIdList> keep;
    for (vtkIdType c = 0; c < cow->GetNumberOfCells(); ++c)
    {
      double centre[3] = { 0.0, 0.0, 0.0 };
      vtkIdType size;
      const vtkIdType* ids;
      cow->GetCellPoints(c, size, ids);
      for (vtkIdType k = 0; k < size; ++k)
      {
        centre[0] += cow->GetPoint(ids[k])[0] / static_cast<double>(size);
      }
      if ((centre[0] < 0.0) == (half == 0))
      {
        keep->InsertNextId(c);
      }
    }
    vtkNew<vtkPolyData> part;
    part->SetPoints(cow->GetPoints());
    part->AllocateExact(keep->GetNumberOfIds(), 3 * keep->GetNumberOfIds());
    for (vtkIdType i = 0; i < keep->GetNumberOfIds(); ++i)
    {
      vtkIdType size;
      const vtkIdType* ids;
      cow->GetCellPoints(keep->GetId(i), size, ids);
      part->InsertNextCell(VTK_TRIANGLE, size, ids);
    }
    halves->SetPartition(half, part);
    blocks->SetBlock(half, part);
    vtkNew<vtkPolyData> locked;
    locked->ShallowCopy(part);
    locked->GetPointData()->AddArray(everyPoint);
    lockedHalves->SetPartition(half, locked);
  }
  const auto openEdgesOfMerged = [](vtkDataObject* output, vtkIdType& triangles) {
    vtkNew<vtkAppendPolyData> append;
    vtkSmartPointer<vtkCompositeDataIterator> leaf =
      vtk::TakeSmartPointer(vtkCompositeDataSet::SafeDownCast(output)->NewIterator());
    for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
    {
      append->AddInputData(vtkPolyData::SafeDownCast(leaf->GetCurrentDataObject()));
    }
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(append->GetOutputPort());
    clean->Update();
    triangles = clean->GetOutput()->GetNumberOfPolys();
    return OpenEdges(clean->GetOutput());
  };
  vtkNew<Filter> filter;
  filter->SetTargetReduction(0.8);
  filter->SetComputeDeviation(true);
  filter->SetInputData(halves);
  // Progress only rises, through the cores, the border round and the deviations.
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* values, void* value) {
    static_cast<std::vector<double>*>(values)->push_back(*static_cast<double*>(value));
  });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->Update();
  CHECK(progress.size() > 4 && std::is_sorted(progress.begin(), progress.end()) && progress.back() == 1.0);
  auto* partitions = vtkPartitionedDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  CHECK(partitions && partitions->GetNumberOfPartitions() == 2);
  vtkIdType triangles = 0;
  CHECK(partitions && openEdgesOfMerged(partitions, triangles) == 0);
  const double target = 0.2 * static_cast<double>(cow->GetNumberOfCells());
  CHECK(std::abs(static_cast<double>(triangles) - target) <= 0.03 * target + 2);
  filter->SetInputData(lockedHalves);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Locked");
  filter->Update();
  CHECK(openEdgesOfMerged(filter->GetOutputDataObject(0), triangles) == 0 && triangles == cow->GetNumberOfCells());
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  filter->SetInputData(blocks);
  filter->Update();
  auto* separate = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  CHECK(separate && separate->GetNumberOfBlocks() == 2);
  CHECK(separate && openEdgesOfMerged(separate, triangles) > 0);
}

/// Point labels and flags: pedigree ids (1000 + 7 i), global ids (i) and ghost flags
/// (HIDDENPOINT on every other point) on the cow, simplified by 90 %. Every filter gives each
/// output point all three of one input point (its representative: a collapse's survivor, a
/// cluster's heaviest point), never a value no input point has, and no two output points the
/// same one, so the global ids stay unique.
template <typename Filter>
void CheckPointLabels(vtkPolyData* cow)
{
  auto labelled = vtkSmartPointer<vtkPolyData>::New();
  labelled->ShallowCopy(cow);
  const vtkIdType n = cow->GetNumberOfPoints();
  vtkNew<vtkIdTypeArray> pedigree;
  pedigree->SetName("PointLabel");
  vtkNew<vtkIdTypeArray> global;
  global->SetName("PointGlobalId");
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  for (vtkIdType i = 0; i < n; ++i)
  {
    pedigree->InsertNextValue(1000 + 7 * i);
    global->InsertNextValue(i);
    ghosts->InsertNextValue(i % 2 ? vtkDataSetAttributes::HIDDENPOINT : 0);
  }
  // A shallow copy shares the cow's point data: a new one carries the labels.
  vtkNew<vtkPointData> pointData;
  pointData->ShallowCopy(cow->GetPointData());
  pointData->SetPedigreeIds(pedigree);
  pointData->SetGlobalIds(global);
  pointData->AddArray(ghosts);
  labelled->GetPointData()->ShallowCopy(pointData);

  vtkNew<Filter> filter;
  filter->SetInputData(labelled);
  filter->SetTargetReduction(0.9);
  filter->Update();
  vtkPointData* pd = filter->GetOutput()->GetPointData();
  auto* outGhosts = vtkUnsignedCharArray::SafeDownCast(pd->GetArray(vtkDataSetAttributes::GhostArrayName()));
  CHECK(outGhosts && outGhosts->GetNumberOfTuples() == filter->GetOutput()->GetNumberOfPoints());
  CHECK(cow->GetPointData()->GetPedigreeIds() == nullptr); // the input is untouched
  vtkDataArray* outPedigree = vtkArrayDownCast<vtkDataArray>(pd->GetPedigreeIds());
  vtkDataArray* outGlobal = pd->GetGlobalIds();
  CHECK(outPedigree && outGlobal);
  std::set<vtkIdType> sources;
  for (vtkIdType p = 0; outPedigree && outGlobal && outGhosts && p < outPedigree->GetNumberOfTuples(); ++p)
  {
    const vtkIdType label = static_cast<vtkIdType>(outPedigree->GetTuple1(p));
    const vtkIdType i = (label - 1000) / 7;
    CHECK((label - 1000) % 7 == 0 && i >= 0 && i < n);
    CHECK(static_cast<vtkIdType>(outGlobal->GetTuple1(p)) == i);
    CHECK(outGhosts->GetValue(p) == ghosts->GetValue(std::min(std::max<vtkIdType>(i, 0), n - 1)));
    sources.insert(i);
  }
  CHECK(outPedigree && static_cast<vtkIdType>(sources.size()) == outPedigree->GetNumberOfTuples());
}

/// An open mesh (a 64 × 64 hemisphere) simplified to 500 triangles with PreserveBoundary: the
/// count within countTolerance, and every rim point (z = 0) still there.
template <typename Filter>
void CheckPreservedRim(double countTolerance)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(64);
  source->SetPhiResolution(64);
  source->SetEndPhi(90);
  source->Update();
  vtkPolyData* cap = source->GetOutput();
  vtkNew<Filter> filter;
  filter->SetInputData(cap);
  filter->SetTargetModeToTriangleCount();
  filter->SetTargetTriangleCount(500);
  filter->PreserveBoundaryOn();
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  CHECK(std::abs(out->GetNumberOfPolys() - 500) <= countTolerance * 500);
  const std::set<std::array<double, 3>> outputPoints = PointSet(out);
  int rim = 0;
  for (vtkIdType i = 0; i < cap->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    cap->GetPoint(i, p.data());
    if (std::abs(p[2]) < 1e-9)
    {
      ++rim;
      CHECK(outputPoints.count(p) == 1);
    }
  }
  CHECK(rim >= 64);
}

/// The same output whatever the thread count (1, 2, 4), and the input untouched. run(threads)
/// runs the filter under test on cow and returns its output.
template <typename Run>
void CheckThreadIndependence(vtkPolyData* cow, Run run)
{
  vtkNew<vtkPolyData> before;
  before->DeepCopy(cow);
  const vtkMTimeType mtime = cow->GetMTime();
  vtkSmartPointer<vtkPolyData> outputs[3];
  const int threads[3] = { 1, 2, 4 };
  for (int k = 0; k < 3; ++k)
  {
    outputs[k] = run(threads[k]);
  }
  for (int k = 1; k < 3; ++k)
  {
    CHECK(outputs[k]->GetNumberOfPoints() == outputs[0]->GetNumberOfPoints());
    CHECK(outputs[k]->GetNumberOfPolys() == outputs[0]->GetNumberOfPolys());
    for (vtkIdType i = 0; i < outputs[0]->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      outputs[0]->GetPoint(i, a);
      outputs[k]->GetPoint(i, b);
      CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
    }
  }
  CHECK(cow->GetMTime() == mtime);
  CheckInputUntouched(cow, before);
  CHECK(cow->GetPointData()->GetNumberOfArrays() == before->GetPointData()->GetNumberOfArrays());
}
}

#endif
