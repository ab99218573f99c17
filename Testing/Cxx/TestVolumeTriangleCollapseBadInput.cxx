// SPDX-License-Identifier: BSD-3-Clause
// vtkVolumeTriangleCollapse on bad input: the module's common cases (TestBadInput.h).
#include "vtkVolumeTriangleCollapse.h"

#include "TestBadInput.h"

int TestVolumeTriangleCollapseBadInput(int, char*[])
{
  const meshsimp_test::FilterFactory make = [](double reduction) {
    vtkNew<vtkVolumeTriangleCollapse> filter;
    filter->SetTargetReduction(reduction);
    return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
  };
  meshsimp_test::CheckBadInputCases(make, 0.01);
  // Out-of-range targets are clamped; removing every triangle of a closed surface is not
  // possible without breaking it, so the filter stops with a warning at the smallest mesh.
  meshsimp_test::CheckErrorBoundClamped<vtkVolumeTriangleCollapse>();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
