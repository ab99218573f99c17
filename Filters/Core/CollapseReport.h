// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CollapseReport.h
 * @brief The collapse engine's vocabulary for what refused a collapse and why a vertex is locked,
 * and the words a report gives them: the ordered checks (CollapseCheck), the lock reasons
 * (LockReason), their counts over a run (RefusalCounts) and their sentences.
 */
#ifndef MeshSimplification_CollapseReport_h
#define MeshSimplification_CollapseReport_h

#include "TriangleMesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace meshsimp
{

/// The checks of IsLegal in the order it runs them (listed at the top of this file); the first
/// that fails names the refusal, so a caller that reacts to it never runs the checks again.
enum class CollapseCheck : std::uint8_t
{
  Passed,        // every check passed
  Plan,          // not two or three distinct vertices, or a position that is not finite
  Locks,         // removes or moves a locked vertex, or moves a hinge vertex off its hinge
  Regions,       // merges vertices of different regions
  LinkCondition, // an edge of three triangles, a hidden cycle, a pinch, a vertex left too few neighbours
  SharedEdges,   // a new edge between two vertices shared with another piece
  PlaneSide,     // a changed triangle turns over (the plane-side test)
  Degenerate,    // a changed triangle of (almost) zero area
  FoldAcross,    // a changed triangle ends back to back with its unchanged neighbour
  AngleGuard     // a new angle below the minimum (SetMinimumAngle); every other check passed
};
constexpr std::size_t NumberOfCollapseChecks = 10; // the values of CollapseCheck
static_assert(static_cast<std::size_t>(CollapseCheck::AngleGuard) + 1 == NumberOfCollapseChecks,
  "NumberOfCollapseChecks counts CollapseCheck's values");
/// Why a vertex is locked, or why a plan fails the locks check, as the user knows the rule.
/// The values are CollapseMesh's lock bytes (0: not locked); SharedPoint is SharedPointLock.
enum class LockReason : std::uint8_t
{
  Options = 1,                   // the caller's options (its locked points, PreserveBoundary)
  SharedPoint = SharedPointLock, // a point shared with another piece of a distributed mesh
  NonManifold,                   // a non-manifold vertex (always locked)
  BorderCorner,                  // the filter's: the border turns there by more than BoundaryCornerAngle
  OffHinge,                      // a plan only: it moves a vertex off its hinge
  Seam                           // the filter's: a border point with a twin at its position (a seam)
};
constexpr std::size_t NumberOfLockReasons = 6;
/// The place of a LockReason in per-reason tables.
constexpr std::size_t LockIndex(LockReason reason)
{
  return static_cast<std::size_t>(reason) - 1;
}

/// How many plans failed each check first (Passed counts legal ones), and the locks check's
/// refusals again by LockReason.
struct RefusalCounts
{
  std::array<std::int64_t, NumberOfCollapseChecks> ByCheck{};
  std::array<std::int64_t, NumberOfLockReasons> ByLock{};
  std::int64_t Total() const;
};

/**
 * The two commonest refusals among counts, with their shares of all the plans counted, for a
 * report: "71 % would remove or move a border corner (...), 25 % would break ...". Plans that
 * passed were refused by a rule of the caller's, which passedText says ("would ..."). Empty
 * when nothing was counted.
 */
std::string DescribeRefusals(const RefusalCounts& counts, const char* passedText);

/// "140 non-manifold, 6 border corners" (or "all non-manifold", or "non-manifold" for one):
/// locked vertices counted by LockReason, for a report.
std::string DescribeLocked(const std::array<std::int64_t, NumberOfLockReasons>& counts);

/**
 * What stops a collapse filter short of its target, as the continuation of its reason:
 * ": of the 120 points left, 8 are locked (8 border corners); of the others' 560 half-edge
 * collapses, 71 % would ..." — left points (noun: "points", "vertices"), the locked ones by
 * reason, and the refusals of the collapses the others were tried with (tried: what they are),
 * whose Passed count passedText says (DescribeRefusals).
 */
std::string DescribeLeft(std::int64_t left, const char* noun, const std::array<std::int64_t, NumberOfLockReasons>& lockedBy,
  const RefusalCounts& refused, const char* tried, const char* passedText);

} // namespace meshsimp

#endif
