// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationDistributed.h
 * @brief What the filters agree on across the pieces of a composite or distributed input
 * (private to the module): the points pieces share, which stay locked, and the totals a target
 * is shared out by. Each function is collective under MPI: every process calls it once per
 * execution, whatever pieces it holds.
 */
#ifndef vtkSimplificationDistributed_h
#define vtkSimplificationDistributed_h

#include "SharedBorders.h"
#include "vtkSimplificationInput.h"
#include "vtkSmartPointer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

class vtkPolyData;

namespace vtkSimplification
{

/// Whether a global controller of several processes runs this execution (MPI).
bool IsDistributed();

/**
 * The points each piece shares with another piece of the same key, on another process or on
 * this one: its border points whose coordinates are on such a piece's border too. locks[i]
 * flags them meshsimp::SharedPointLock in piece i (sized to its points when any is found, else
 * empty); a null piece (one that could not be read) has none. Locked, they keep the pieces'
 * common border as it is, so the simplified pieces still fit together without cracks; the
 * collapse filters also join no two of them by a new edge, which the other piece could make too
 * (an edge of four triangles once the pieces are merged).
 */
void LockSharedPoints(const std::vector<const TriangleInput*>& pieces, const std::vector<vtkIdType>& keys,
  std::vector<std::vector<std::uint8_t>>& locks);

/// The whole input: its triangles (as extracted, over every piece of every process) and the
/// diagonal of the bounding box of its points.
struct Totals
{
  double Triangles = 0.0;
  double Diagonal = 0.0;
};
Totals GatherTotals(const std::vector<const TriangleInput*>& pieces);

/// The sum of value over the processes (value itself without MPI).
double SumOverProcesses(double value);

/// The largest of each value over the processes, in place (unchanged without MPI).
void MaximumOverProcesses(unsigned char* values, vtkIdType count);

/**
 * Every process's surfaces, in process order (surfaces alone without MPI): this process's as
 * they are, the others' as copies received. first: where this process's begin.
 */
std::vector<vtkSmartPointer<vtkPolyData>> GatherSurfaces(const std::vector<vtkPolyData*>& surfaces, std::size_t& first);

/// The border round's exchanges (meshsimp::SimplifySharedBorders) over the global controller's
/// processes, or within this one.
meshsimp::BorderExchange MakeBorderExchange();

}

#endif
