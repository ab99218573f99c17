// SPDX-License-Identifier: BSD-3-Clause
// vtkVolumeTriangleCollapse on bad input: the module's common cases (TestBadInput.h), and a
// target it cannot reach (it stops early with a warning, the mesh still valid).
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
  {
    vtkNew<vtkVolumeTriangleCollapse> filter;
    filter->SetTargetReduction(1.5);
    CHECK(filter->GetTargetReduction() == 1.0);
    filter->SetTargetReduction(-1);
    CHECK(filter->GetTargetReduction() == 0.0);
    vtkSmartPointer<vtkPolyData> sphere = meshsimp_test::Sphere();
    const meshsimp_test::Run all = meshsimp_test::Simplify(make, sphere, 1.5);
    CHECK(all.Warned && !all.Failed);
    CHECK(all.Output->GetNumberOfPolys() >= 4 && all.Output->GetNumberOfPolys() < 100);
    const meshsimp_test::Run none = meshsimp_test::Simplify(make, sphere, -1);
    CHECK(none.Output->GetNumberOfPolys() == sphere->GetNumberOfPolys());
  }
  meshsimp_test::CheckErrorBoundClamped<vtkVolumeTriangleCollapse>();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
