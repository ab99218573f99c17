// SPDX-License-Identifier: BSD-3-Clause
// vtkParallelDecimation on bad input: the module's common cases (TestBadInput.h) and its own
// angles clamped.
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
    filter->SetFeatureAngle(400);
    CHECK(filter->GetFeatureAngle() == 180.0);
  }
  meshsimp_test::CheckErrorBoundClamped<vtkParallelDecimation>();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
