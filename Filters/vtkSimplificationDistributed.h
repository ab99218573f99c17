// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationDistributed.h
 * @brief What the filters agree on across the pieces of a composite or distributed input
 * (private to the module): the points pieces share, which stay locked, the totals a target is
 * shared out by, the reductions of values over the processes, and every process's surfaces for
 * a filter that needs them all (Texture Baking). Each function is collective under MPI: every
 * process calls it, in the same order, whatever pieces it holds.
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
 * Every process's surfaces into all, in process order (surfaces alone without MPI): this
 * process's as they are, the others' as copies received; counts: how many each process gave.
 * False on every process where one process's surfaces did not arrive.
 */
bool GatherSurfaces(const std::vector<vtkPolyData*>& surfaces, std::vector<vtkSmartPointer<vtkPolyData>>& all,
  std::vector<std::size_t>& counts);

/// The border round's exchanges (meshsimp::SimplifySharedBorders) over the global controller's
/// processes, or within this one.
meshsimp::BorderExchange MakeBorderExchange();

}

#endif
