// SPDX-License-Identifier: BSD-3-Clause
// Checks shared by the VTK-level tests.
#ifndef MeshSimplification_TestVTKHelpers_h
#define MeshSimplification_TestVTKHelpers_h

#include "vtkPolyData.h"

#include "TestHelpers.h"

#include <cmath>

namespace meshsimp_test
{
/// The filter never modifies its input: input still equals the copy taken before it ran (same
/// points, NaN where the copy has NaN, same number of cells).
inline void CheckInputUntouched(vtkPolyData* input, vtkPolyData* copy)
{
  CHECK(input->GetNumberOfPoints() == copy->GetNumberOfPoints());
  CHECK(input->GetNumberOfCells() == copy->GetNumberOfCells());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    input->GetPoint(i, a);
    copy->GetPoint(i, b);
    for (int k = 0; k < 3; ++k)
    {
      CHECK(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])));
    }
  }
}
}

#endif
