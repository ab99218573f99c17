// SPDX-License-Identifier: BSD-3-Clause
// vtkOctreeVertexClustering on bad input: the module's common cases (TestBadInput.h) and its
// own: a clamped error bound, and counts it cannot reach.
#include "vtkOctreeVertexClustering.h"

#include "TestBadInput.h"

#include <array>
#include <vector>

int TestOctreeVertexClusteringBadInput(int, char*[])
{
  meshsimp_test::CheckBadInputCases(
    [](double reduction) {
      vtkNew<vtkOctreeVertexClustering> filter;
      filter->SetTargetReduction(reduction);
      return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
    },
    0.03);
  // A negative error bound is clamped to 0 (exact).
  {
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    vtkNew<vtkOctreeVertexClustering> filter;
    filter->SetInputData(sphere);
    filter->SetTargetModeToMaximumError();
    filter->SetMaximumError(-3);
    CHECK(filter->GetMaximumError() == 0.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 0.9 * sphere->GetNumberOfPolys());
    CHECK(filter->GetAchievedMaximumError() < 1e-9);
  }
  // A reduction of 0 gives the input back, as the collapse filters do (issue 45: the steep
  // terrain lost 143 of its 32 768 triangles and its points moved): the same triangles, the
  // same points bit for bit, no error.
  {
    vtkNew<vtkXMLPolyDataReader> terrain;
    terrain->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/jacksboro_dem_half.vtp");
    terrain->Update();
    vtkPolyData* input = terrain->GetOutput();
    const meshsimp_test::Run run = meshsimp_test::Simplify(
      [](double reduction) {
        vtkNew<vtkOctreeVertexClustering> filter;
        filter->SetTargetReduction(reduction);
        return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
      },
      input, 0.0);
    const auto sorted = [](vtkPolyData* mesh) {
      std::vector<std::array<double, 3>> points(mesh->GetNumberOfPoints());
      for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
      {
        mesh->GetPoint(i, points[i].data());
      }
      std::sort(points.begin(), points.end());
      return points;
    };
    CHECK(run.Output->GetNumberOfPolys() == input->GetNumberOfPolys() && run.Warnings.empty());
    CHECK(sorted(run.Output) == sorted(input));
    vtkDataArray* reached = run.Output->GetFieldData()->GetArray("MaximumError");
    CHECK(reached && reached->GetTuple1(0) == 0.0);
  }
  // A bound so large that every cluster would merge (issue 45: 0 triangles and MaximumError 0,
  // without a word): the coarsest mesh the clustering makes, its error, and a warning.
  {
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    const meshsimp_test::Run run = meshsimp_test::Simplify(
      [](double bound) {
        vtkNew<vtkOctreeVertexClustering> filter;
        filter->SetTargetModeToMaximumError();
        filter->SetMaximumError(bound);
        return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
      },
      sphere, 0.3);
    vtkDataArray* reached = run.Output->GetFieldData()->GetArray("MaximumError");
    CHECK(run.Output->GetNumberOfPolys() >= 4 && reached && reached->GetTuple1(0) > 0.0);
    CHECK(run.Warnings.size() == 1 && meshsimp_test::Mentions(run.Warnings[0], "MaximumError 0.3") &&
      meshsimp_test::Mentions(run.Warnings[0], "coarsest mesh"));
  }
  // ParaView's default Sphere (96 triangles) at the default reduction (10 triangles): not an
  // empty mesh. Clustering alone stops at 12; the collapses that finish it reach the count.
  {
    vtkNew<vtkSphereSource> source;
    source->Update();
    const meshsimp_test::Run run = meshsimp_test::Simplify(
      [](double reduction) {
        vtkNew<vtkOctreeVertexClustering> filter;
        filter->SetTargetReduction(reduction);
        return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
      },
      source->GetOutput(), 0.9);
    CHECK(source->GetOutput()->GetNumberOfPolys() == 96 && run.Output->GetNumberOfPolys() == 10);
    CHECK(run.Warnings.empty());
  }
  // A count the clustering cannot reach is met as nearly as it can, with a warning that says
  // why: MaximumCellSize keeping cells small (over the target), or no count near a tiny one.
  {
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    vtkNew<vtkOctreeVertexClustering> filter;
    vtkNew<meshsimp_test::MessageLog> observer;
    filter->AddObserver(vtkCommand::WarningEvent, observer);
    filter->SetInputData(sphere);
    filter->SetTargetReduction(0.9);
    filter->SetMaximumCellSize(0.02);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 0.2 * sphere->GetNumberOfPolys());
    CHECK(observer->Warnings.size() == 1 && meshsimp_test::Mentions(observer->Warnings[0], "MaximumCellSize"));
    observer->Warnings.clear();
    filter->SetMaximumCellSize(1.0);
    filter->SetTargetModeToTriangleCount();
    filter->SetTargetTriangleCount(2);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 2);
    CHECK(observer->Warnings.size() == 1 && meshsimp_test::Mentions(observer->Warnings[0], "nearest count"));
  }
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
