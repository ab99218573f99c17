// SPDX-License-Identifier: BSD-3-Clause
// vtkParallelDecimation on real meshes: counts within 2 %, closed stays closed, survivors are
// input points with their own point data, cell data copied, the Importance and VertexType
// arrays, both importance measures and edge choices, locks, a preserved rim, thread
// independence, input untouched.
#include "vtkParallelDecimation.h"

#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkTestErrorObserver.h"

#include "TestVTKHelpers.h"

#include <array>
#include <cmath>
#include <map>

namespace
{
/// Input point id by exact coordinates.
std::map<std::array<double, 3>, vtkIdType> PointIds(vtkPolyData* mesh)
{
  std::map<std::array<double, 3>, vtkIdType> ids;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    mesh->GetPoint(i, p.data());
    ids.emplace(p, i);
  }
  return ids;
}

void TestTargetsAndAttributes(vtkPolyData* cow)
{
  const double inputTriangles = cow->GetNumberOfPolys();
  const auto inputIds = PointIds(cow);
  for (const int measure : { vtkParallelDecimation::QUADRIC, vtkParallelDecimation::AVERAGE_PLANE })
  {
    for (const double reduction : { 0.5, 0.7, 0.9, 0.95 })
    {
      vtkNew<vtkParallelDecimation> filter;
      filter->SetInputData(cow);
      filter->SetTargetReduction(reduction);
      filter->SetImportanceMeasure(measure);
      filter->MoveSurvivorsOff();
      filter->Update();
      vtkPolyData* out = filter->GetOutput();
      const double target = std::round(inputTriangles * (1 - reduction));
      CHECK(std::abs(out->GetNumberOfPolys() - target) <= 0.02 * target);
      CHECK(meshsimp_test::OpenEdges(out) == 0);
      meshsimp_test::CheckCarriedData(cow, out);

      // Every output point is an input point with that point's own data.
      vtkPointData* pd = out->GetPointData();
      vtkDataArray* height = pd->GetArray("Height");
      vtkDataArray* texture = pd->GetTCoords();
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        std::array<double, 3> p;
        out->GetPoint(i, p.data());
        const auto found = inputIds.find(p);
        CHECK(found != inputIds.end());
        if (found != inputIds.end())
        {
          CHECK(height->GetTuple1(i) == cow->GetPointData()->GetArray("Height")->GetTuple1(found->second));
          CHECK(texture->GetTuple2(i)[0] == cow->GetPointData()->GetTCoords()->GetTuple2(found->second)[0]);
        }
      }
      vtkDataArray* importance = pd->GetArray("Importance");
      vtkDataArray* types = pd->GetArray("VertexType");
      CHECK(importance && types && importance->GetNumberOfTuples() == out->GetNumberOfPoints() &&
        types->GetNumberOfTuples() == out->GetNumberOfPoints());
      for (vtkIdType i = 0; importance && types && i < out->GetNumberOfPoints(); ++i)
      {
        const int type = static_cast<int>(types->GetTuple1(i));
        CHECK(type >= 0 && type <= 4);
        CHECK(type >= 3 ? importance->GetTuple1(i) == -1.0 : importance->GetTuple1(i) >= 0.0);
      }
      vtkDataArray* rounds = out->GetFieldData()->GetArray("Rounds");
      CHECK(rounds && rounds->GetTuple1(0) > 0);
      vtkDataArray* achieved = out->GetFieldData()->GetArray("AchievedReduction");
      CHECK(achieved &&
        std::abs(achieved->GetTuple1(0) - (1 - out->GetNumberOfPolys() / inputTriangles)) < 1e-12);

      // MoveSurvivors (QUADRIC) moves points, not data: the same triangles and point data, and
      // "MovedPoints" counts the points not at their input place.
      vtkNew<vtkParallelDecimation> moving;
      moving->SetInputData(cow);
      moving->SetTargetReduction(reduction);
      moving->SetImportanceMeasure(measure);
      moving->Update();
      vtkPolyData* moved = moving->GetOutput();
      CHECK(moved->GetNumberOfPoints() == out->GetNumberOfPoints());
      CHECK(moved->GetNumberOfPolys() == out->GetNumberOfPolys());
      vtkIdType away = 0;
      for (vtkIdType i = 0; i < std::min(moved->GetNumberOfPoints(), out->GetNumberOfPoints()); ++i)
      {
        std::array<double, 3> p, q;
        moved->GetPoint(i, p.data());
        out->GetPoint(i, q.data());
        away += p != q ? 1 : 0;
        CHECK(moved->GetPointData()->GetArray("Height")->GetTuple1(i) == height->GetTuple1(i));
      }
      vtkDataArray* count = moved->GetFieldData()->GetArray("MovedPoints");
      CHECK(count && count->GetTuple1(0) == away);
      CHECK(measure == vtkParallelDecimation::QUADRIC ? away > out->GetNumberOfPoints() / 2 : away == 0);
    }
  }
  // The paper's shortest-edge choice also meets the count and keeps the cow closed.
  vtkNew<vtkParallelDecimation> shortest;
  shortest->SetInputData(cow);
  shortest->SetImportanceMeasure(vtkParallelDecimation::AVERAGE_PLANE);
  shortest->SetHalfEdgeChoice(vtkParallelDecimation::SHORTEST_EDGE);
  shortest->Update();
  CHECK(std::abs(shortest->GetOutput()->GetNumberOfPolys() - 580) <= 12);
  CHECK(meshsimp_test::OpenEdges(shortest->GetOutput()) == 0);
}

void TestThreads(vtkPolyData* cow)
{
  for (const int measure : { vtkParallelDecimation::QUADRIC, vtkParallelDecimation::AVERAGE_PLANE })
  {
    meshsimp_test::CheckThreadIndependence(cow, [cow, measure](int threads) {
      vtkNew<vtkParallelDecimation> filter;
      filter->SetInputData(cow);
      filter->SetTargetReduction(0.9);
      filter->SetImportanceMeasure(measure);
      filter->SetNumberOfThreads(threads);
      filter->Update();
      return vtkSmartPointer<vtkPolyData>(filter->GetOutput());
    });
  }
}

void TestLocks(vtkPolyData* cow)
{
  // Locked points stay.
  vtkSmartPointer<vtkPolyData> marked = meshsimp_test::WithLockArray(cow, 40);
  vtkNew<vtkParallelDecimation> filter;
  filter->SetInputData(marked);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Locked");
  filter->Update();
  const auto outputIds = PointIds(filter->GetOutput());
  for (vtkIdType i = 0; i < cow->GetNumberOfPoints(); i += 40)
  {
    std::array<double, 3> p;
    cow->GetPoint(i, p.data());
    CHECK(outputIds.count(p) == 1);
  }
  CHECK(std::abs(filter->GetOutput()->GetNumberOfPolys() - 580) <= 12);

  // ParaView's "None" selects no array, silently; a name that is no point array warns.
  for (const char* name : { "None", "Nope" })
  {
    vtkNew<vtkTest::ErrorObserver> observer;
    vtkNew<vtkParallelDecimation> selected;
    selected->SetInputData(marked);
    selected->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
    selected->AddObserver(vtkCommand::WarningEvent, observer);
    selected->Update();
    CHECK(observer->GetWarning() == (std::string(name) == "Nope"));
    CHECK(std::abs(selected->GetOutput()->GetNumberOfPolys() - 580) <= 12);
  }
}
}

int TestParallelDecimation(int, char*[])
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  TestTargetsAndAttributes(cow);
  TestThreads(cow);
  TestLocks(cow);
  // An open mesh at a triangle count, its rim kept.
  meshsimp_test::CheckPreservedRim<vtkParallelDecimation>(0.02);
  meshsimp_test::CheckPartitionedInput<vtkParallelDecimation>(cow);
  meshsimp_test::CheckPointLabels<vtkParallelDecimation>(cow);
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
