// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationRanges.h
 * @brief An output array's ranges computed on the filter's threads and left where VTK's range
 * queries look first (private to the module).
 */
#ifndef vtkSimplificationRanges_h
#define vtkSimplificationRanges_h

#include "Execution.h"

class vtkDataArray;
class vtkPolyData;

namespace vtkSimplification
{

/// Computes, in one pass on the context's threads, what vtkDataArray::GetRange and
/// GetFiniteRange return for every component and, for an array of several components, for the
/// tuples' L2 norm, the values VTK computes itself (NaN left out; the finite ranges also leave
/// out infinities), and stores them in the array's information under the keys those queries
/// read before computing (PER_COMPONENT and PER_FINITE_COMPONENT with COMPONENT_RANGE,
/// L2_NORM_RANGE, L2_NORM_FINITE_RANGE). Call it after the array's last write: the array's next
/// Modified() removes them, as it removes ranges VTK cached, but a write through a raw pointer
/// after the call would leave them stale. Empty arrays, and arrays not stored as one block of
/// tuples of a standard numeric type, are left alone.
void RecordRanges(vtkDataArray* array, const meshsimp::ExecutionContext& context);

/// RecordRanges for the arrays of output that a filter wrote: its points' and its point and
/// cell data's, but those it shares with input (whose information is the input's to keep).
void RecordOutputRanges(vtkPolyData* input, vtkPolyData* output, const meshsimp::ExecutionContext& context);

}

#endif
