// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationDeviation.h
 * @brief The error users colour by (private to the module): how far each output point's part
 * of the surface is from the input, both ways.
 */
#ifndef vtkSimplificationDeviation_h
#define vtkSimplificationDeviation_h

#include "Deviation.h"
#include "Execution.h"
#include "Simplification.h"
#include "TriangleMesh.h"

class vtkPolyData;

namespace vtkSimplification
{

/**
 * Adds the point array "Deviation" to output, made of mesh from input: each point's two-sided
 * deviation (meshsimp::TwoSidedDeviation: the larger of its distance to the input and the
 * largest distance to the output of the input points it stands for), in input units, and its
 * maximum (the two-sided distance of the meshes) and root mean square over the points as the
 * field values "DeviationMaximum" and "DeviationRMS". Measured on the context's threads, with
 * its progress; returns false, adding nothing, when aborted.
 */
bool AddDeviation(const meshsimp::TriangleMeshView& input, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output,
  const meshsimp::ExecutionContext& context);
/// The same with the input side made before (kept for several outputs of one input).
bool AddDeviation(const meshsimp::DeviationInput& input, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output,
  const meshsimp::ExecutionContext& context);

}

#endif
