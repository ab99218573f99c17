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
class vtkPointData;
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

/// The input's triangles (polygons and strips triangulated), without ghost and hidden cells
/// (vtkGhostType DUPLICATECELL or HIDDENCELL: another piece's copies under MPI, or blanked).
/// False with a message in error when the input cannot be processed at all (too large).
bool ExtractTriangles(vtkPolyData* input, TriangleInput& triangles, std::string& error);

/**
 * ExtractTriangles as every filter starts: an error for an input it cannot process, a warning
 * for the vertex and line cells it drops. Point and cell data arrays shorter than the input's
 * points or cells (copying them would read past their ends) are left out, each named in a
 * warning: input becomes a shallow copy without them (the input itself is never changed). False
 * when there is nothing to simplify; then requestResult is what RequestData returns (0 after an
 * error, 1 for an empty input).
 */
bool PrepareTriangles(
  vtkAlgorithm* filter, vtkSmartPointer<vtkPolyData>& input, TriangleInput& triangles, int& requestResult);

/**
 * Under MPI (a global controller of several processes), the points each piece shares with the
 * piece of the same key on another process: its border points whose coordinates are on such a
 * piece's border too. locks[i] flags them meshsimp::SharedPointLock in pieces[i] (sized to its
 * points when any is found, else empty). Locked, they keep the pieces' common border as it is,
 * so the simplified pieces still fit together without cracks; the collapse filters also join no
 * two of them by a new edge, which the other piece could make too (an edge of four triangles
 * once the pieces are merged). Collective: every process calls it once per execution, with
 * whatever pieces it holds (keys are the leaves' flat indices of a composite input).
 */
void LockSharedPoints(const std::vector<vtkPolyData*>& pieces, const std::vector<vtkIdType>& keys,
  std::vector<std::vector<std::uint8_t>>& locks);

/// False, with an error, when the target in force is not a number (vtkSetClampMacro lets NaN
/// through): the reduction for TargetMode 0, the error bound for 2 (the filters share the modes).
bool CheckTarget(vtkAlgorithm* filter, int targetMode, double reduction, double maximumError);

/// For a warning about a target not reached: "" without locks, else how many points are locked
/// (shared with other pieces under MPI, or, where the filter has one, chosen by the user's array).
std::string LockedPointsNote(const std::vector<std::uint8_t>& locked, bool userArray);

/// Warns about ignored non-finite points and about an abort; returns finished.
bool ReportRun(vtkAlgorithm* filter, bool finished, std::int64_t nonFinitePoints);

/// The output cells of a filter: triangles (with their points), the input cell data of each
/// triangle's source cell, recomputed cell normals if the input had them, and the input's
/// field data plus AchievedReduction.
void SetOutputTriangles(vtkPolyData* input, vtkPolyData* output, const TriangleInput& triangles,
  const std::vector<double>& points, const std::vector<std::int32_t>& outputTriangles,
  const std::vector<std::int32_t>& sourceTriangles, int outputPointsPrecision);

/// User-chosen locks: one flag per input point, set where input array 0 (if one is selected)
/// is nonzero (flags already set stay set). False when none is selected (no name, or
/// ParaView's "None"), and with a warning when the selected array is not a point array of the
/// input.
bool ReadLockedPoints(vtkAlgorithm* filter, vtkPolyData* input, std::vector<std::uint8_t>& locked);

/// Adds a one-value array to the output's field data.
void AddFieldValue(vtkPolyData* output, const char* name, double value);

/// The point data of output points that are input points (pointSource: the input point of each
/// output point, no two alike): every array copied from its point, global ids included, which
/// stay unique (VTK's default leaves them out, for outputs where they might not).
void CopySurvivorPointData(
  vtkPointData* inPD, vtkPointData* outPD, const std::vector<std::int32_t>& pointSource);

/// Whether point array index of inPD is interpolated where a filter merges points, by VTK's
/// rules (outPD's interpolate flags): not pedigree or global ids, which are labels, nor the ghost
/// flags, which are bits.
bool IsInterpolated(vtkPointData* inPD, vtkPointData* outPD, int index);

/// Adds a point-data array of one value per output point.
void AddPointValues(vtkPolyData* output, const char* name, const std::vector<double>& values);

/// Threads (0 = all cores) of a worker pool that lives as long as the context, so that filters
/// working in rounds do not start threads for every loop (VTK's SMP setting is untouched);
/// progress and abort through the algorithm.
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
