// SPDX-License-Identifier: BSD-3-Clause
// vtkProgressiveMesh on bad input: the module's common cases (TestBadInput.h), its weights
// clamped, and a sequence whose arrays are damaged (rebuilt, with a warning).
#include "vtkProgressiveMesh.h"

#include "vtkCellData.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"

#include "TestBadInput.h"

#include <cstdlib>

int TestProgressiveMeshBadInput(int, char*[])
{
  const meshsimp_test::FilterFactory make = [](double reduction) {
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetTargetReduction(reduction);
    return vtkSmartPointer<vtkPolyDataAlgorithm>(filter);
  };
  meshsimp_test::CheckBadInputCases(make, 0.01);
  {
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetLengthWeight(-1);
    filter->SetQuadricWeight(-5);
    CHECK(filter->GetLengthWeight() == 0.0 && filter->GetQuadricWeight() == 0.0);
  }
  meshsimp_test::CheckErrorBoundClamped<vtkProgressiveMesh>();
  {
    // A sequence whose Parent array points forward is refused and the sequence built anew.
    vtkNew<vtkProgressiveMesh> filter;
    filter->SetInputData(meshsimp_test::Sphere());
    filter->Update();
    vtkNew<vtkPolyData> damaged;
    damaged->DeepCopy(filter->GetSequenceOutput());
    vtkDataArray* parent = damaged->GetPointData()->GetArray("Parent");
    parent->SetTuple1(parent->GetNumberOfTuples() - 1, parent->GetNumberOfTuples() - 1);
    const meshsimp_test::Run run = meshsimp_test::Simplify(make, damaged, 0.5);
    CHECK(run.Warnings.size() == 1 && meshsimp_test::Mentions(run.Warnings[0], "building it anew"));
    CHECK(std::abs(run.Output->GetNumberOfPolys() - damaged->GetNumberOfPolys() / 2) <= 1);
  }
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
