// SPDX-License-Identifier: BSD-3-Clause
// vtkAppearancePreservingCollapse on bad input: the module's common cases (TestBadInput.h) and
// its own angles and weight clamped.
#include "vtkAppearancePreservingCollapse.h"

#include "TestBadInput.h"

int TestAppearancePreservingCollapseBadInput(int, char*[])
{
  const meshsimp_test::FilterFactory make = [](double reduction) {
    vtkNew<vtkAppearancePreservingCollapse> filter;
    filter->SetTargetReduction(reduction);
    return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
  };
  meshsimp_test::CheckBadInputCases(make, 0.01);
  {
    vtkNew<vtkAppearancePreservingCollapse> filter;
    filter->SetExtremeAngle(400);
    filter->SetMaximumNormalDeviation(-5);
    filter->SetAttributeWeight(-1);
    CHECK(filter->GetExtremeAngle() == 180.0 && filter->GetMaximumNormalDeviation() == 0.0 &&
      filter->GetAttributeWeight() == 0.0);
  }
  meshsimp_test::CheckErrorBoundClamped<vtkAppearancePreservingCollapse>();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
