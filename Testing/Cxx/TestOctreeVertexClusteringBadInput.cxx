// SPDX-License-Identifier: BSD-3-Clause
// vtkOctreeVertexClustering on bad input: the module's common cases (TestBadInput.h) and its
// own target clamping.
#include "vtkOctreeVertexClustering.h"

#include "TestBadInput.h"

int TestOctreeVertexClusteringBadInput(int, char*[])
{
  meshsimp_test::CheckBadInputCases(
    [](double reduction) {
      vtkNew<vtkOctreeVertexClustering> filter;
      filter->SetTargetReduction(reduction);
      return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
    },
    0.03);
  // Out-of-range targets are clamped: reduction 1.5 → 1 (no triangle left), −1 → 0 (no
  // triangle removed but duplicates), and a negative error bound → 0 (exact).
  {
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    vtkNew<vtkOctreeVertexClustering> filter;
    filter->SetInputData(sphere);
    filter->SetTargetReduction(1.5);
    CHECK(filter->GetTargetReduction() == 1.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() == 0);
    filter->SetTargetReduction(-1);
    CHECK(filter->GetTargetReduction() == 0.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() == sphere->GetNumberOfPolys());
    filter->SetTargetModeToMaximumError();
    filter->SetMaximumError(-3);
    CHECK(filter->GetMaximumError() == 0.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 0.9 * sphere->GetNumberOfPolys());
    CHECK(filter->GetAchievedMaximumError() < 1e-9);
  }
  // A count the clustering cannot reach is met as nearly as it can, with a warning that says
  // why: MaximumCellSize keeping cells small (over the target), or no count near a tiny one.
  {
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    vtkNew<vtkOctreeVertexClustering> filter;
    vtkNew<vtkTest::ErrorObserver> observer;
    filter->AddObserver(vtkCommand::WarningEvent, observer);
    filter->SetInputData(sphere);
    filter->SetTargetReduction(0.9);
    filter->SetMaximumCellSize(0.02);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 0.2 * sphere->GetNumberOfPolys());
    CHECK(observer->GetWarning() && observer->GetWarningMessage().find("MaximumCellSize") != std::string::npos);
    observer->Clear();
    filter->SetMaximumCellSize(1.0);
    filter->SetTargetModeToTriangleCount();
    filter->SetTargetTriangleCount(2);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() < 2);
    CHECK(observer->GetWarning() && observer->GetWarningMessage().find("nearest count") != std::string::npos);
  }
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
