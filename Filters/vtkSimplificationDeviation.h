// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationDeviation.h
 * @brief The error users colour by (private to the module): each output point's distance to
 * the input surface.
 */
#ifndef vtkSimplificationDeviation_h
#define vtkSimplificationDeviation_h

#include "Execution.h"
#include "vtkSimplificationInput.h"

class vtkPoints;
class vtkPolyData;

namespace vtkSimplification
{

/**
 * Adds the point array "Deviation" to output: the distance of each of its points to the
 * nearest of the input's usable triangles (a cell locator over them), in input units, and its
 * maximum and root mean square over the points as the field values "DeviationMaximum" and
 * "DeviationRMS". The points are measured on the context's threads.
 */
void AddDeviation(vtkPoints* inputPoints, const TriangleInput& triangles, vtkPolyData* output,
  const meshsimp::ExecutionContext& context);

}

#endif
