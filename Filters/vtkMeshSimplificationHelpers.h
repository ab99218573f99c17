// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMeshSimplificationHelpers.h
 * @brief What every MeshSimplification filter does around its core call (private to the module):
 * turn vtkPolyData into a flat triangle list, run the core with threads, progress and abort,
 * and build the output cells, points and normals.
 */
#ifndef vtkMeshSimplificationHelpers_h
#define vtkMeshSimplificationHelpers_h

#include "Execution.h"
#include "TriangleMesh.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkCellArray;
class vtkDataArray;
class vtkPoints;
class vtkPolyData;

namespace vtkMeshSimplificationHelpers
{

/// The triangles of a vtkPolyData: polygons are triangulated, strips decomposed. A triangle-only
/// input with float or double points is viewed in place, without copies.
struct TriangleInput
{
  std::vector<double> PointCopy; // filled only when the points are neither floats nor doubles
  std::vector<std::int32_t> Triangles; // filled only when cells had to be triangulated
  std::vector<vtkIdType> SourceCells;  // input cell of each triangle, with Triangles
  vtkIdType FirstCell = 0;             // input cell of triangle 0 when viewed in place
  vtkIdType NumberOfVerts = 0, NumberOfLines = 0;
  meshsimp::TriangleMeshView View;
  vtkIdType SourceCell(std::int64_t triangle) const
  {
    return this->SourceCells.empty() ? this->FirstCell + triangle : this->SourceCells[triangle];
  }
};

/// False with a message in error when the input cannot be processed at all (too large).
bool ExtractTriangles(vtkPolyData* input, TriangleInput& triangles, std::string& error);

/// Threads (0 = all cores) through vtkSMPTools' STDThread backend in a local scope, so the
/// application's global SMP setting is untouched; progress and abort through the algorithm.
meshsimp::ExecutionContext MakeExecutionContext(vtkAlgorithm* algorithm, int numberOfThreads);

/// The number of threads MakeExecutionContext uses.
int ResolveThreadCount(int numberOfThreads);

vtkSmartPointer<vtkPoints> MakePoints(
  const std::vector<double>& coordinates, int outputPointsPrecision, vtkPoints* inputPoints);
vtkSmartPointer<vtkCellArray> MakeTriangles(const std::vector<std::int32_t>& triangles);

/// Area-weighted point normals (or per-triangle normals) of a triangle list, written into an
/// existing 3-component array of the right size.
void ComputePointNormals(const std::vector<double>& points,
  const std::vector<std::int32_t>& triangles, vtkDataArray* normals);
void ComputeCellNormals(const std::vector<double>& points,
  const std::vector<std::int32_t>& triangles, vtkDataArray* normals);

}

#endif
