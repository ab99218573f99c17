// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationThreads.h
 * @brief The worker pool the filters run their cores on (private to the module): the core's
 * ExecutionContext with real threads, progress and abort.
 */
#ifndef vtkSimplificationThreads_h
#define vtkSimplificationThreads_h

#include "Execution.h"

class vtkAlgorithm;

namespace vtkSimplification
{

/// Threads (0 = all cores) of a worker pool that lives as long as the context, so that filters
/// working in rounds do not start threads for every loop (VTK's SMP setting is untouched);
/// progress and abort through the algorithm.
meshsimp::ExecutionContext MakeExecutionContext(vtkAlgorithm* algorithm, int numberOfThreads);

/// The number of threads MakeExecutionContext uses.
int ResolveThreadCount(int numberOfThreads);

}

#endif
