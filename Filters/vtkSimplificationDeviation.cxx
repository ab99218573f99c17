// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationDeviation.h"

#include "Deviation.h"
#include "vtkSimplificationAttributes.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace vtkSimplification
{

bool AddDeviation(const meshsimp::TriangleMeshView& input, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output,
  const meshsimp::ExecutionContext& context)
{
  return AddDeviation(meshsimp::DeviationInput(input), mesh, output, context);
}

bool AddDeviation(const meshsimp::DeviationInput& input, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output,
  const meshsimp::ExecutionContext& context)
{
  const std::vector<double> values = meshsimp::TwoSidedDeviation(input, mesh, context);
  const vtkIdType count = output->GetNumberOfPoints();
  if (static_cast<vtkIdType>(values.size()) != count)
  {
    return false;
  }
  vtkNew<vtkDoubleArray> deviation;
  deviation->SetName("Deviation");
  deviation->SetNumberOfValues(count);
  double maximum = 0.0, squares = 0.0;
  for (vtkIdType p = 0; p < count; ++p)
  {
    deviation->SetValue(p, values[p]);
    maximum = std::max(maximum, values[p]);
    squares += values[p] * values[p];
  }
  output->GetPointData()->AddArray(deviation);
  AddFieldValue(output, "DeviationMaximum", maximum);
  AddFieldValue(output, "DeviationRMS", count > 0 ? std::sqrt(squares / static_cast<double>(count)) : 0.0);
  return true;
}

}
