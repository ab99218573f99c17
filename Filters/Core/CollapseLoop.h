// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CollapseLoop.h
 * @brief The one collapse loop of every decimating filter: it collapses until a triangle count
 * is met or nothing is left to try, reports progress, stops at an abort, and says why it
 * stopped, with what refused the collapses left.
 *
 * What to collapse, in which order and how many at once is the scheduler's: the strict heap of
 * Progressive Mesh (one vertex's cheapest legal edge at a time), the batches of disjoint
 * neighbourhoods of Volume Triangle Collapse, the rounds of independent sets of Parallel
 * Decimation. Each asks its policy (the cost and placement of a collapse, the checks of the
 * collapse engine, an error bound as an extra filter) and records what it did. As in OpenMesh's
 * Decimater and CGAL's edge_collapse, the loop around them is written once; a scheduler is a
 * class with
 * - `std::int64_t AliveTriangles() const`: the triangles left;
 * - `bool Step(std::int64_t target)`: one step towards target (a collapse, a batch, a round);
 *   false when it had nothing to try (an empty heap, a round that removed nothing);
 * - `bool Unstick(std::int64_t target)`: after such a step, whether something is left to try
 *   (a guard lowered, a selection window widened, a last resort taken);
 * - `std::string RefusalSummary()`: when nothing is, what refuses the collapses left, as the
 *   continuation of a report's sentence (": of the N vertices left, ...").
 */
#ifndef MeshSimplification_CollapseLoop_h
#define MeshSimplification_CollapseLoop_h

#include "Execution.h"
#include "Simplification.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace meshsimp
{

/// How a collapse loop ended.
struct CollapseLoopEnd
{
  enum class Reason : std::uint8_t
  {
    TargetMet, // at most the target's triangles are left
    Exhausted, // the scheduler had nothing left to try before the target
    Aborted    // the caller asked to stop (the mesh is as the last step left it)
  };
  Reason Why = Reason::TargetMet;
  /// Exhausted: the scheduler's RefusalSummary, taken as the loop stopped.
  std::string Refusals;

  /// The stop in report: a loop that ran out of collapses before a count target (not under an
  /// error bound, whose end that is) stopped because nothing was removable, which nothingLeft
  /// says ("no collapse is left that keeps the mesh valid"), followed by the refusals.
  void Judge(Outcome& report, bool bounded, const std::string& nothingLeft) const
  {
    if (this->Why == Reason::Exhausted && !bounded && report.Stop == StopReason::TargetMet)
    {
      report.Stop = StopReason::NothingRemovable;
      report.Reason = nothingLeft + this->Refusals;
    }
  }
};

/// The share of a filter's progress bar a loop covers, from Begin (before its first collapse) to
/// End (the target met).
struct ProgressSpan
{
  double Begin = 0.0, End = 1.0;
};

/**
 * Runs scheduler's steps until at most target triangles are left (see the top of the file).
 * Progress is reported as the share of the triangles to remove that are gone, each time that
 * share has grown by 1/256 or more (so a step of any size costs one comparison), and an abort
 * seen there ends the loop at once.
 */
template <class Scheduler>
CollapseLoopEnd RunCollapseLoop(
  Scheduler& scheduler, std::int64_t target, ProgressSpan span, const ExecutionContext& context)
{
  constexpr std::int64_t Reports = 256;
  const std::int64_t start = scheduler.AliveTriangles();
  const std::int64_t toRemove = std::max<std::int64_t>(1, start - target);
  const std::int64_t every = std::max<std::int64_t>(1, toRemove / Reports);
  std::int64_t nextReport = start - every;
  CollapseLoopEnd end;
  while (scheduler.AliveTriangles() > target)
  {
    if (!scheduler.Step(target) && !scheduler.Unstick(target))
    {
      end.Why = CollapseLoopEnd::Reason::Exhausted;
      end.Refusals = scheduler.RefusalSummary();
      return end;
    }
    const std::int64_t alive = scheduler.AliveTriangles();
    if (alive <= nextReport)
    {
      const double done = std::min(1.0, static_cast<double>(start - alive) / static_cast<double>(toRemove));
      if (!context.Report(span.Begin + (span.End - span.Begin) * done))
      {
        end.Why = CollapseLoopEnd::Reason::Aborted;
        return end;
      }
      nextReport = alive - every;
    }
  }
  return end;
}

} // namespace meshsimp

#endif
