// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationAttributes.h
 * @brief The one output mapping of every filter (private to the module): a core's
 * SimplifiedMesh becomes the output's points, triangles, point and cell data and error arrays.
 *
 * Point data follows one rule, whatever the filter, from each output point's sources (the input
 * points it stands for, SimplifiedMesh::SourcePoints):
 * - floating-point arrays are interpolated with the sources' weights (clamped to the sources'
 *   range, so a constant stays exactly constant);
 * - unsigned-char colours (3 or 4 components) are averaged the same way and rounded to the
 *   nearest value;
 * - every other array (integer labels, material and region ids, flags and ghost flags, global
 *   and pedigree ids, strings) takes the value of one input point, the representative (the
 *   surviving point of a collapse, the heaviest point of a cluster): never a value no input
 *   point has. No two output points have the same representative, so global ids stay unique.
 * Active normals are recomputed from the output triangles. Cell data is copied from the input
 * cell of each output triangle.
 */
#ifndef vtkSimplificationAttributes_h
#define vtkSimplificationAttributes_h

#include "Simplification.h"
#include "vtkSimplificationInput.h"
#include "vtkSmartPointer.h" // for PrefixView
#include "vtkCellArray.h" // for vtkCellArray::ArrayType64

class vtkDataArray;
class vtkPointData;
class vtkPolyData;

namespace vtkSimplification
{

/// The output of a piece: points (OutputPointsPrecision: vtkAlgorithm's precisions, DEFAULT as
/// the input's points), triangles, cell data, point data by the rule above, the core's point
/// arrays and field values, the input's field data, and AchievedReduction; with originalIds,
/// vtkOriginalPointIds (each point's representative) and vtkOriginalCellIds (each triangle's
/// input cell), replacing input arrays of those names, and the field data
/// InputToOutputPointIds (for a vtkPolyData input).
void SetOutput(vtkPolyData* input, const TriangleInput& triangles, const meshsimp::SimplifiedMesh& mesh,
  int outputPointsPrecision, bool originalIds, vtkPolyData* output);

/// A view of the first tuples of array (no copy), which keeps array alive (see SetPrefixOutput).
vtkSmartPointer<vtkDataArray> PrefixView(vtkDataArray* array, vtkIdType tuples);

/**
 * The output of a level whose points and triangles are the first ones of a whole mesh made by
 * SetOutput (a progressive mesh's sequence, points and triangles in the order levels take them):
 * the points, the triangles' offsets and the point and cell arrays (the core's named arrays
 * among them, as the whole has them) are views of the first tuples of the whole's, not copies
 * (each view keeps the whole's array alive through its information, and a deep copy of the
 * level owns its values and lets it go), so that a level costs its corners and not its size;
 * normal arrays, which are recomputed, are copied (mesh must then hold the level's points and
 * triangles). corners: the level's triangles, 3 per triangle (Progressive Mesh writes them
 * into a view of a reused buffer, see vtkProgressiveMesh.cxx). The rest as SetOutput. As for
 * any filter's output, writing into a level's arrays is not allowed: it would change the
 * whole; and vtkDataArray::ShallowCopy of one shares its memory without keeping the whole
 * alive (vtkDataSetAttributes' copies share the arrays themselves and do).
 */
void SetPrefixOutput(vtkPolyData* input, const TriangleInput& triangles, vtkPolyData* whole, vtkIdType points,
  vtkCellArray::ArrayType64* corners, const meshsimp::SimplifiedMesh& mesh, vtkPolyData* output);

/// Every point array of inPD mapped to the mesh's output points by the rule above.
void MapPointData(vtkPointData* inPD, const meshsimp::SimplifiedMesh& mesh, vtkPointData* outPD);

/// Whether input points a and b have the same value in every point array of pd (component by
/// component, exactly (a vtkVariantArray's values as vtkVariant compares them); NaN equals NaN;
/// the global and pedigree ids, which differ between any two points, are not compared): the
/// core's SimplificationOptions::SamePointData, so that two points at one position join only
/// where no array tells them apart (a colour or texture seam, or normals split at a crease,
/// stay open).
bool SamePointData(vtkPointData* pd, vtkIdType a, vtkIdType b);

/// The field data array of the output point each input point became (-1: none), which
/// LoD Interpolation's Exact correspondence reads.
constexpr const char* InputToOutputPointIdsName = "InputToOutputPointIds";

/// Adds InputToOutputPointIds to the output's field data: per point of input, the output point
/// whose sources list it, or that of a listed point at its place (the front end joined them);
/// -1: none.
void AddInputToOutputIds(const meshsimp::SimplifiedMesh& mesh, const meshsimp::TriangleMeshView& input, vtkPolyData* output);

/// Adds a one-value array to the output's field data.
void AddFieldValue(vtkPolyData* output, const char* name, double value);

}

#endif
