// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationInput.h
 * @brief How the filters read their input (private to the module): a surface from any dataset,
 * its triangles as a flat list for the core, and the point arrays that lock points or mark
 * attribute regions.
 */
#ifndef vtkSimplificationInput_h
#define vtkSimplificationInput_h

#include "TriangleMesh.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkAbstractArray;
class vtkAlgorithm;
class vtkDataObject;
class vtkPolyData;

namespace vtkSimplification
{

/// The triangles of a vtkPolyData: polygons are triangulated, strips decomposed. A triangle-only
/// input with float or double points is viewed in place, without copies.
struct TriangleInput
{
  std::vector<double> PointCopy;       // filled only when the points are neither floats nor doubles
  std::vector<std::int32_t> Triangles; // filled only when cells had to be triangulated
  std::vector<vtkIdType> SourceCells;  // input cell of each triangle, with Triangles
  vtkIdType FirstCell = 0;             // input cell of triangle 0 when viewed in place
  vtkIdType NumberOfVerts = 0, NumberOfLines = 0;
  vtkIdType NumberOfShortCells = 0; // polygons and strips of fewer than 3 points: no triangle
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
 * A dataset as the polygonal surface the filters simplify: vtkPolyData as it is; any other
 * dataset whose cells are surfaces (and vertices or lines) through vtkGeometryFilter, as
 * ParaView's Extract Surface does. Null with a message in problem for a dataset with 3-D cells
 * (it says to extract the surface first) or data that is not a dataset.
 */
vtkSmartPointer<vtkPolyData> AsSurface(vtkDataObject* data, std::string& problem);

/// The arrays a surface made by AsSurface carries: each of its points' and cells' ids in the
/// dataset it was made from (vtkGeometryFilter's pass-through ids, under names of ours so that
/// they are not mistaken for arrays the user gave). The output mapping turns them into
/// vtkOriginalPointIds and vtkOriginalCellIds, or drops them (SetOutput).
constexpr const char* SurfacePointIdsName = "vtkSimplificationSurfacePointIds";
constexpr const char* SurfaceCellIdsName = "vtkSimplificationSurfaceCellIds";

/**
 * ExtractTriangles as every filter starts: false with a one-line error for an input it cannot
 * process. Point and cell data arrays shorter than the input's points or cells (copying them
 * would read past their ends) are left out, each named in a warning: input becomes a shallow
 * copy without them (the input itself is never changed). Dropped vertex and line cells, and
 * polygons and strips of fewer than 3 points, are counted in a warning.
 */
bool PrepareTriangles(vtkAlgorithm* filter, vtkSmartPointer<vtkPolyData>& input, TriangleInput& triangles);

/// The input, or a shallow copy of it without the point and cell data arrays that are shorter
/// than its points or cells (copying their values would read past their ends), each named in a
/// warning. The input itself is never changed.
vtkSmartPointer<vtkPolyData> WithUsableAttributes(vtkAlgorithm* filter, vtkPolyData* input);

/**
 * The point array an algorithm selected as its input array `index` (SetInputArrayToProcess, or
 * the XML's array selection), or null: when none is selected (no name, or ParaView's "None"),
 * and, with a warning naming it and what it is for, when it is not a point array of the input.
 */
vtkAbstractArray* SelectedPointArray(vtkAlgorithm* filter, int index, vtkPolyData* input, const char* purpose);

/// User-chosen locks: flags set where the array's first component is nonzero (flags already
/// set stay set; locks grows to the array's tuples), and userLocked set to 1 there (0 elsewhere).
/// Returns the number of nonzero values.
std::int64_t ReadLockedPoints(vtkAbstractArray* array, std::vector<std::uint8_t>& locks, std::vector<std::uint8_t>& userLocked);

/// Attribute regions: one id per point, equal where the array's tuples are equal.
std::vector<std::int32_t> ReadRegions(vtkAbstractArray* array);

}

#endif
