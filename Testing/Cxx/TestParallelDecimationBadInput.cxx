// SPDX-License-Identifier: BSD-3-Clause
// vtkParallelDecimation on bad input: the module's common cases (TestBadInput.h), and targets
// out of range (clamped; removing everything stops early with a warning, the mesh still valid).
#include "vtkParallelDecimation.h"

#include "TestBadInput.h"

int TestParallelDecimationBadInput(int, char*[])
{
  const meshsimp_test::FilterFactory make = [](double reduction) {
    vtkNew<vtkParallelDecimation> filter;
    filter->SetTargetReduction(reduction);
    return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
  };
  meshsimp_test::CheckBadInputCases(make, 0.02);
  {
    vtkNew<vtkParallelDecimation> filter;
    filter->SetTargetReduction(1.5);
    CHECK(filter->GetTargetReduction() == 1.0);
    filter->SetTargetReduction(-1);
    CHECK(filter->GetTargetReduction() == 0.0);
    filter->SetFeatureAngle(400);
    CHECK(filter->GetFeatureAngle() == 180.0);
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    const meshsimp_test::Run all = meshsimp_test::Simplify(make, sphere, 1.5);
    CHECK(all.Warned && !all.Failed);
    CHECK(all.Output->GetNumberOfPolys() >= 4 && all.Output->GetNumberOfPolys() < 100);
    const meshsimp_test::Run none = meshsimp_test::Simplify(make, sphere, -1);
    CHECK(none.Output->GetNumberOfPolys() == sphere->GetNumberOfPolys());
  }
  meshsimp_test::CheckErrorBoundClamped<vtkParallelDecimation>();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
