// SPDX-License-Identifier: BSD-3-Clause
// vtkProgressiveMesh on the cow: levels from one build (a target change re-extracts, a build
// property or a modified input rebuilds), each level equal to a fresh build's, points that are
// input points with their own data, the CollapseLevel array, the sequence port written as .vtp
// and read back without a build, thread independence, input untouched.
#include "vtkProgressiveMesh.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkFloatArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include "TestVTKHelpers.h"

#include <algorithm>
#include <array>
#include <map>

namespace
{
/// The points and triangles of two meshes are the same, in the same order.
bool SameMesh(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfPolys() != b->GetNumberOfPolys())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return false;
    }
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, x);
    b->GetCellPoints(c, y);
    for (vtkIdType k = 0; k < 3; ++k)
    {
      if (x->GetNumberOfIds() != 3 || y->GetNumberOfIds() != 3 || x->GetId(k) != y->GetId(k))
      {
        return false;
      }
    }
  }
  return true;
}

vtkSmartPointer<vtkPolyData> FreshLevel(vtkPolyData* input, double reduction)
{
  vtkNew<vtkProgressiveMesh> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(reduction);
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 1);
  auto level = vtkSmartPointer<vtkPolyData>::New();
  level->DeepCopy(filter->GetOutput());
  return level;
}

void TestLevelsFromOneBuild(vtkPolyData* cow)
{
  vtkNew<vtkProgressiveMesh> filter;
  filter->SetInputData(cow);
  const double triangles = cow->GetNumberOfPolys();
  for (const double reduction : { 0.9, 0.5, 0.98, 0.7, 0.0 })
  {
    filter->SetTargetReduction(reduction);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    CHECK(filter->GetNumberOfBuilds() == 1);
    CHECK(std::abs(out->GetNumberOfPolys() - std::round(triangles * (1 - reduction))) <= 1);
    CHECK(meshsimp_test::OpenEdges(out) == 0);
    CHECK(SameMesh(out, FreshLevel(cow, reduction)));
    meshsimp_test::CheckCarriedData(cow, out);
    vtkDataArray* level = out->GetPointData()->GetArray("CollapseLevel");
    CHECK(level && level->GetRange()[0] >= 0.0 && level->GetRange()[0] < 1.0 && level->GetRange()[1] == 1.0);
    vtkDataArray* count = out->GetFieldData()->GetArray("LevelTriangles");
    CHECK(count && count->GetTuple1(0) == out->GetNumberOfPolys());
  }
  // Another output precision writes the level again from the same build (issue 45: it built
  // the whole sequence again).
  filter->SetTargetReduction(0.9);
  filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 1 && filter->GetOutput()->GetPoints()->GetDataType() == VTK_DOUBLE);
  filter->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 1 && filter->GetOutput()->GetPoints()->GetDataType() == VTK_FLOAT);
  CHECK(std::abs(filter->GetOutput()->GetNumberOfPolys() - std::round(triangles * 0.1)) <= 1);
  // A build property, or a change of the input's points, builds again.
  filter->SetCurvatureWeight(1.0);
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 2);
  filter->SetTargetTriangleCount(300);
  filter->SetTargetModeToTriangleCount();
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 2 && filter->GetOutput()->GetNumberOfPolys() == 300);
  cow->GetPoints()->Modified();
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 3);
  // A cell array changed in place (and marked modified) reaches the next level too.
  vtkDataArray* cellValues = cow->GetCellData()->GetArray("SourceCell");
  CHECK(cellValues != nullptr);
  if (cellValues)
  {
    vtkSmartPointer<vtkDataArray> before = vtk::TakeSmartPointer(cellValues->NewInstance());
    before->DeepCopy(cellValues);
    for (vtkIdType c = 0; c < cellValues->GetNumberOfTuples(); ++c)
    {
      cellValues->SetComponent(c, 0, 12345.0);
    }
    cellValues->Modified();
    filter->Update();
    vtkDataArray* carried = filter->GetOutput()->GetCellData()->GetArray(cellValues->GetName());
    CHECK(carried && carried->GetRange(0)[0] == 12345.0 && carried->GetRange(0)[1] == 12345.0);
    cellValues->DeepCopy(before);
    cellValues->Modified();
  }
}

/// Every point and cell array of two meshes holds the same values.
bool SameArrays(vtkPolyData* a, vtkPolyData* b)
{
  bool same = true;
  for (const auto& [x, y] : { std::make_pair<vtkFieldData*, vtkFieldData*>(a->GetPointData(), b->GetPointData()),
         std::make_pair<vtkFieldData*, vtkFieldData*>(a->GetCellData(), b->GetCellData()) })
  {
    same = same && x->GetNumberOfArrays() == y->GetNumberOfArrays();
    for (int i = 0; same && i < x->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* u = x->GetArray(i);
      vtkDataArray* v = y->GetArray(u ? u->GetName() : "");
      same = u && v && u->GetNumberOfTuples() == v->GetNumberOfTuples() && u->GetNumberOfComponents() == v->GetNumberOfComponents();
      for (vtkIdType t = 0; same && t < u->GetNumberOfTuples(); ++t)
      {
        for (int c = 0; c < u->GetNumberOfComponents(); ++c)
        {
          same = same && u->GetComponent(t, c) == v->GetComponent(t, c);
        }
      }
    }
  }
  return same;
}

void TestLevelsAsViews(vtkPolyData* decorated)
{
  // Without normals to recompute, every level is written as views of the whole
  // sequence's first points, arrays and offsets (SetPrefixOutput): it equals a fresh build's,
  // and it stays valid after the sequence it shows is gone (a rebuild, the filter deleted).
  auto cow = vtkSmartPointer<vtkPolyData>::New();
  cow->DeepCopy(decorated);
  cow->GetPointData()->SetNormals(nullptr);
  cow->GetCellData()->SetNormals(nullptr);
  vtkNew<vtkFloatArray> normals; // a plain array until made the active normals below
  normals->DeepCopy(decorated->GetPointData()->GetNormals());
  normals->SetName("MadeActive");
  cow->GetPointData()->AddArray(normals);
  auto kept = vtkSmartPointer<vtkPolyData>::New(), expected = vtkSmartPointer<vtkPolyData>::New();
  {
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetInputData(cow);
    for (const double reduction : { 0.3, 0.9, 0.5, 0.0, 0.99 })
    {
      filter->SetTargetReduction(reduction);
      filter->Update();
      const vtkSmartPointer<vtkPolyData> fresh = FreshLevel(cow, reduction);
      CHECK(SameMesh(filter->GetOutput(), fresh) && SameArrays(filter->GetOutput(), fresh));
    }
    CHECK(filter->GetNumberOfBuilds() == 1);
    // Views: the level's points and offsets are the sequence's first ones, in the same memory.
    vtkPolyData* level = filter->GetOutput();
    vtkPolyData* sequence = filter->GetSequenceOutput();
    CHECK(level->GetPoints()->GetVoidPointer(0) == sequence->GetPoints()->GetVoidPointer(0));
    CHECK(level->GetPolys()->IsStorage64Bit() && sequence->GetPolys()->IsStorage64Bit() &&
      level->GetPolys()->GetOffsetsArray64()->GetPointer(0) == sequence->GetPolys()->GetOffsetsArray64()->GetPointer(0));
    kept->ShallowCopy(level);
    expected->DeepCopy(level);
    // A deep copy owns its values: it does not keep the sequence alive.
    CHECK(expected->GetPoints()->GetData()->GetInformation()->GetNumberOfKeys() == 0);
    // Corners are written into a buffer that no level shows any more (the pipeline releases the
    // output's last level before the next): the same memory for each new level, never the one a
    // level someone still holds (kept) shows.
    const auto cornerMemory = [&filter] { return filter->GetOutput()->GetPolys()->GetConnectivityArray()->GetVoidPointer(0); };
    const void* held = cornerMemory();
    std::vector<const void*> used;
    for (const double reduction : { 0.2, 0.6, 0.4 })
    {
      filter->SetTargetReduction(reduction);
      filter->Update();
      used.push_back(cornerMemory());
      CHECK(SameMesh(filter->GetOutput(), FreshLevel(cow, reduction)));
    }
    CHECK(used[0] != held && used[1] == used[0] && used[2] == used[0]);
    CHECK(SameMesh(kept, expected) && SameArrays(kept, expected));
    filter->SetTargetReduction(1.0); // no triangle asked for: empty, not the last level
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() == 0);
    filter->SetTargetReduction(0.99);
    filter->SetCurvatureWeight(0.5); // a new build: the cached sequence goes
    filter->Update();
    CHECK(filter->GetNumberOfBuilds() == 2);
    // An array made the active normals (nothing else changed) builds again, and the level's
    // normals are recomputed (unit).
    cow->GetPointData()->SetActiveNormals("MadeActive");
    filter->Update();
    vtkDataArray* recomputed = filter->GetOutput()->GetPointData()->GetNormals();
    CHECK(filter->GetNumberOfBuilds() == 3 && recomputed &&
      recomputed->GetNumberOfTuples() == filter->GetOutput()->GetNumberOfPoints() &&
      std::abs(vtkMath::Norm(recomputed->GetTuple3(0)) - 1.0) < 1e-5);
  }
  CHECK(SameMesh(kept, expected) && SameArrays(kept, expected));
}

void TestPointsAreInputPoints(vtkPolyData* cow)
{
  // The points are input points, but Deviation is two-sided: the removed points they stand for
  // are off the level's surface (it was 0 everywhere, issue 45, §2), and a level switch with
  // the sequence cached measures it again.
  {
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetInputData(cow);
    filter->ComputeDeviationOn();
    double previous = 0.0;
    for (const double reduction : { 0.9, 0.5 })
    {
      filter->SetTargetReduction(reduction);
      filter->Update();
      vtkDataArray* deviation = filter->GetOutput()->GetPointData()->GetArray("Deviation");
      vtkDataArray* maximum = filter->GetOutput()->GetFieldData()->GetArray("DeviationMaximum");
      CHECK(deviation && deviation->GetNumberOfTuples() == filter->GetOutput()->GetNumberOfPoints() &&
        deviation->GetRange()[0] >= 0.0 && deviation->GetRange()[1] > 0.0);
      CHECK(maximum && maximum->GetTuple1(0) > 0.0 && maximum->GetTuple1(0) != previous);
      previous = maximum ? maximum->GetTuple1(0) : 0.0;
    }
    CHECK(filter->GetNumberOfBuilds() == 1);
  }
  std::map<std::array<double, 3>, vtkIdType> ids;
  for (vtkIdType i = 0; i < cow->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    cow->GetPoint(i, p.data());
    ids.emplace(p, i);
  }
  vtkSmartPointer<vtkPolyData> out = FreshLevel(cow, 0.9);
  vtkDataArray* height = out->GetPointData()->GetArray("Height");
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    out->GetPoint(i, p.data());
    const auto found = ids.find(p);
    CHECK(found != ids.end() && height->GetTuple1(i) == cow->GetPointData()->GetArray("Height")->GetTuple1(found->second));
  }
}

/// Progress values seen, and whether to abort once one passes 0.3.
struct ProgressLog
{
  vtkProgressiveMesh* Filter = nullptr;
  std::vector<double> Values;
  bool AbortMidway = false;
  static void Receive(vtkObject*, unsigned long, void* self, void* value)
  {
    auto* log = static_cast<ProgressLog*>(self);
    log->Values.push_back(*static_cast<double*>(value));
    if (log->AbortMidway && log->Values.back() > 0.3)
    {
      log->Filter->SetAbortExecute(1);
    }
  }
};

void TestProgressAndAbort(vtkPolyData* cow)
{
  // Progress rises from 0 to 1 through the build; Abort during the build leaves the output
  // empty, with a warning, and no sequence: the next update builds it.
  vtkNew<vtkProgressiveMesh> filter;
  filter->SetInputData(cow);
  ProgressLog log;
  log.Filter = filter;
  log.AbortMidway = true;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&log);
  onProgress->SetCallback(ProgressLog::Receive);
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  vtkNew<vtkTest::ErrorObserver> messages;
  filter->AddObserver(vtkCommand::WarningEvent, messages);
  filter->Update();
  CHECK(filter->GetOutput()->GetNumberOfPolys() == 0 && filter->GetNumberOfBuilds() == 0);
  CHECK(messages->GetWarning() && messages->GetWarningMessage().find("Aborted") != std::string::npos);
  log.Values.clear();
  log.AbortMidway = false;
  filter->SetAbortExecute(0);
  filter->Modified();
  filter->Update();
  CHECK(filter->GetNumberOfBuilds() == 1 && filter->GetOutput()->GetNumberOfPolys() == 580);
  CHECK(log.Values.size() >= 5 && std::is_sorted(log.Values.begin(), log.Values.end()) && log.Values.back() == 1.0);
}

/// data written to path by a Writer, and a Reader of that file (not yet updated).
template <class Writer, class Reader>
vtkSmartPointer<Reader> WrittenAndRead(vtkDataObject* data, const std::string& path)
{
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  CHECK(writer->Write() == 1);
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

void TestSequenceFile(vtkPolyData* cow)
{
  // Output port 1 saved as .vtp and read back gives every level without a build.
  vtkNew<vtkProgressiveMesh> filter;
  filter->SetInputData(cow);
  filter->Update();
  vtkPolyData* sequence = filter->GetSequenceOutput();
  CHECK(sequence->GetNumberOfPoints() == cow->GetNumberOfPoints());
  CHECK(sequence->GetNumberOfPolys() == cow->GetNumberOfPolys());
  CHECK(sequence->GetPointData()->GetArray("Parent") && sequence->GetCellData()->GetArray("RemovedAt"));
  auto reader = WrittenAndRead<vtkXMLPolyDataWriter, vtkXMLPolyDataReader>(
    sequence, MESHSIMPLIFICATION_TEST_OUTPUT "/progressive_cow.vtp");
  vtkNew<vtkProgressiveMesh> fromFile;
  fromFile->SetInputConnection(reader->GetOutputPort());
  for (const double reduction : { 0.6, 0.95 })
  {
    fromFile->SetTargetReduction(reduction);
    fromFile->Update();
    filter->SetTargetReduction(reduction);
    filter->Update();
    vtkPolyData* level = fromFile->GetOutput();
    CHECK(fromFile->GetNumberOfBuilds() == 0);
    CHECK(level->GetNumberOfPolys() == filter->GetOutput()->GetNumberOfPolys());
    CHECK(meshsimp_test::PointSet(level) == meshsimp_test::PointSet(filter->GetOutput()));
    CHECK(!level->GetPointData()->GetArray("Parent") && !level->GetCellData()->GetArray("RemovedAt"));
    CHECK(level->GetPointData()->GetArray("Height"));
  }
}
}

void TestCompositeSequences(vtkPolyData* cow)
{
  // A multiblock input: port 1 is a multiblock of the same structure with each surface block's
  // sequence (a missing block stays missing); saved as .vtm and read back, it gives every
  // block's level without a build.
  vtkNew<vtkPolyData> shifted;
  shifted->DeepCopy(cow);
  for (vtkIdType i = 0; i < shifted->GetNumberOfPoints(); ++i)
  {
    double p[3];
    shifted->GetPoint(i, p);
    p[0] += 2.0;
    shifted->GetPoints()->SetPoint(i, p);
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  blocks->SetBlock(0, cow);
  blocks->SetBlock(1, nullptr);
  blocks->SetBlock(2, shifted);
  vtkNew<vtkProgressiveMesh> filter;
  filter->SetInputData(blocks);
  filter->SetTargetReduction(0.8);
  filter->Update();
  CHECK(filter->GetSequenceOutput() == nullptr); // a composite: GetOutputDataObject(1)
  auto* sequences = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(1));
  CHECK(sequences && sequences->GetNumberOfBlocks() == 3);
  if (!sequences)
  {
    return;
  }
  for (const unsigned int b : { 0u, 2u })
  {
    auto* sequence = vtkPolyData::SafeDownCast(sequences->GetBlock(b));
    CHECK(sequence && sequence->GetNumberOfPoints() == cow->GetNumberOfPoints() &&
      sequence->GetNumberOfPolys() == cow->GetNumberOfPolys() && sequence->GetPointData()->GetArray("Parent") &&
      sequence->GetCellData()->GetArray("RemovedAt"));
  }
  auto reader = WrittenAndRead<vtkXMLMultiBlockDataWriter, vtkXMLMultiBlockDataReader>(
    sequences, MESHSIMPLIFICATION_TEST_OUTPUT "/progressive_blocks.vtm");
  vtkNew<vtkProgressiveMesh> fromFile;
  fromFile->SetInputConnection(reader->GetOutputPort());
  fromFile->SetTargetReduction(0.8);
  fromFile->Update();
  CHECK(fromFile->GetNumberOfBuilds() == 0 && filter->GetNumberOfBuilds() == 2);
  auto* built = vtkMultiBlockDataSet::SafeDownCast(filter->GetOutputDataObject(0));
  auto* read = vtkMultiBlockDataSet::SafeDownCast(fromFile->GetOutputDataObject(0));
  for (const unsigned int b : { 0u, 2u })
  {
    auto* a = vtkPolyData::SafeDownCast(built ? built->GetBlock(b) : nullptr);
    auto* c = vtkPolyData::SafeDownCast(read ? read->GetBlock(b) : nullptr);
    CHECK(a && c && a->GetNumberOfPolys() == c->GetNumberOfPolys() &&
      meshsimp_test::PointSet(a) == meshsimp_test::PointSet(c));
  }
}

int TestProgressiveMesh(int, char*[])
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  TestLevelsFromOneBuild(cow);
  TestLevelsAsViews(cow);
  TestPointsAreInputPoints(cow);
  TestSequenceFile(cow);
  TestCompositeSequences(cow);
  TestProgressAndAbort(cow);
  meshsimp_test::CheckPointLabels<vtkProgressiveMesh>(cow);
  meshsimp_test::CheckThreadIndependence(cow, [&](int threads) {
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetInputData(cow);
    filter->SetNumberOfThreads(threads);
    filter->Update();
    return vtkSmartPointer<vtkPolyData>(filter->GetOutput());
  });
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
