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

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

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

  /// Sorts values ascending: std::sort on parts concurrently, then merged. Values that compare
  /// equal must be identical (as ids are) for the result not to depend on the thread count.
  template <typename T>
  void Sort(std::vector<T>& values) const
  {
    const std::int64_t n = static_cast<std::int64_t>(values.size());
    const std::int64_t parts = std::min<std::int64_t>(this->Threads > 1 ? this->Threads : 1, n / 16384 + 1);
    const auto at = [&](std::int64_t part) { return values.begin() + n * part / parts; };
    this->For(parts, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t part = first; part < last; ++part)
      {
        std::sort(at(part), at(part + 1));
      }
    }, 30 * n);
    for (std::int64_t width = 1; width < parts; width *= 2)
    {
      for (std::int64_t part = 0; part + width < parts; part += 2 * width)
      {
        std::inplace_merge(at(part), at(part + width), at(std::min(part + 2 * width, parts)));
      }
    }
  }

  /// False when the caller asked to abort.
  bool Report(double progress) const { return !this->Progress || this->Progress(progress); }

  /**
   * Calls f(i, scratch) for every i in [0, n), possibly concurrently, each call with a scratch
   * that no concurrent call uses: the running thread's (scratches[Worker()]), so that chunks go
   * to whichever thread asks first; without Worker, one scratch per part of Threads fixed parts.
   * workPerItem estimates one call's time in nanoseconds. scratches grows to Threads entries.
   */
  template <typename Scratch, typename F>
  void ForEachWithScratch(
    std::vector<Scratch>& scratches, std::int64_t n, std::int64_t workPerItem, F&& f) const
  {
    const std::int64_t threads = this->Threads > 1 ? this->Threads : 1;
    if (scratches.size() < static_cast<std::size_t>(threads))
    {
      scratches.resize(static_cast<std::size_t>(threads));
    }
    if (this->Worker)
    {
      this->For(n, [&](std::int64_t begin, std::int64_t end) {
        Scratch& scratch = scratches[static_cast<std::size_t>(this->Worker())];
        for (std::int64_t i = begin; i < end; ++i)
        {
          f(i, scratch);
        }
      }, workPerItem * n);
      return;
    }
    const std::int64_t parts = n < threads ? n : threads;
    this->For(parts, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t part = first; part < last; ++part)
      {
        Scratch& scratch = scratches[static_cast<std::size_t>(part)];
        for (std::int64_t i = n * part / parts, end = n * (part + 1) / parts; i < end; ++i)
        {
          f(i, scratch);
        }
      }
    }, workPerItem * n);
  }
};

} // namespace meshsimp

#endif
