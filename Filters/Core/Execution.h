// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Execution.h
 * @brief How a core algorithm runs: an injected parallel-for, progress and abort.
 *
 * The core never creates threads itself. The VTK layer passes a ParallelFor on a pool of real
 * threads (vtkMeshSimplificationHelpers); tests and plain C++ users may leave it empty (serial).
 * Work split by ParallelFor must write disjoint outputs so results do not depend on the
 * thread count.
 */
#ifndef MeshSimplification_Execution_h
#define MeshSimplification_Execution_h

#include <cstdint>
#include <functional>

namespace meshsimp
{

struct ExecutionContext
{
  /// Calls body(begin, end) over sub-ranges covering [0, n), possibly concurrently; work
  /// estimates the whole loop's single-thread time in nanoseconds (an order of magnitude is
  /// enough), so that an implementation can run small loops inline rather than wake threads.
  std::function<void(std::int64_t n, std::int64_t work,
    const std::function<void(std::int64_t, std::int64_t)>& body)>
    ParallelFor;
  /// How many bodies ParallelFor may run at once. Algorithms whose bodies need large scratch
  /// keep one per thread (see Worker), or else split their work into this many parts.
  int Threads = 1;
  /// The index in [0, Threads) of the thread that runs the calling body, so that a body can use
  /// that thread's scratch without a lock. Empty when ParallelFor cannot tell.
  std::function<int()> Worker;
  /// Receives progress in [0, 1]; returns false when the caller wants to abort.
  std::function<bool(double)> Progress;

  void For(std::int64_t n, const std::function<void(std::int64_t, std::int64_t)>& body,
    std::int64_t work = -1) const
  {
    if (n <= 0)
    {
      return;
    }
    if (this->ParallelFor)
    {
      this->ParallelFor(n, work < 0 ? n : work, body);
    }
    else
    {
      body(0, n);
    }
  }

  /// False when the caller asked to abort.
  bool Report(double progress) const { return !this->Progress || this->Progress(progress); }
};

} // namespace meshsimp

#endif
