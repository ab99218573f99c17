// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationDeviation.h"

#include "vtkSimplificationAttributes.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticCellLocator.h"

#include <algorithm>
#include <cmath>

namespace vtkSimplification
{
namespace
{
/// The input's usable triangles (distinct ids in range, finite corners) over its points.
vtkSmartPointer<vtkPolyData> UsableSurface(vtkPoints* points, const TriangleInput& triangles)
{
  const meshsimp::TriangleMeshView& view = triangles.View;
  vtkNew<vtkCellArray> cells;
  for (std::int64_t t = 0; t < view.NumberOfTriangles; ++t)
  {
    const vtkIdType ids[3] = { view.Id(3 * t), view.Id(3 * t + 1), view.Id(3 * t + 2) };
    bool usable = ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2];
    for (int k = 0; k < 3 && usable; ++k)
    {
      usable = ids[k] >= 0 && ids[k] < view.NumberOfPoints && view.Point(ids[k]).allFinite();
    }
    if (usable)
    {
      cells->InsertNextCell(3, ids);
    }
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(cells);
  return surface;
}
}

void AddDeviation(vtkPoints* inputPoints, const TriangleInput& triangles, vtkPolyData* output,
  const meshsimp::ExecutionContext& context)
{
  const vtkIdType count = output->GetNumberOfPoints();
  vtkNew<vtkDoubleArray> deviation;
  deviation->SetName("Deviation");
  deviation->SetNumberOfValues(count);
  vtkSmartPointer<vtkPolyData> surface = UsableSurface(inputPoints, triangles);
  vtkNew<vtkStaticCellLocator> locator;
  if (count > 0 && surface->GetNumberOfCells() > 0)
  {
    locator->SetDataSet(surface);
    locator->BuildLocator();
    context.For(count, [&](std::int64_t begin, std::int64_t end) {
      vtkNew<vtkGenericCell> cell;
      for (vtkIdType p = begin; p < end; ++p)
      {
        double x[3], closest[3], distance2 = 0.0;
        vtkIdType cellId = -1;
        int subId = 0;
        output->GetPoint(p, x);
        locator->FindClosestPoint(x, closest, cell, cellId, subId, distance2);
        deviation->SetValue(p, cellId >= 0 ? std::sqrt(distance2) : 0.0);
      }
    }, 2000 * static_cast<std::int64_t>(count));
  }
  double maximum = 0.0, squares = 0.0;
  for (vtkIdType p = 0; p < count; ++p)
  {
    maximum = std::max(maximum, deviation->GetValue(p));
    squares += deviation->GetValue(p) * deviation->GetValue(p);
  }
  output->GetPointData()->AddArray(deviation);
  AddFieldValue(output, "DeviationMaximum", maximum);
  AddFieldValue(output, "DeviationRMS", count > 0 ? std::sqrt(squares / static_cast<double>(count)) : 0.0);
}

}
