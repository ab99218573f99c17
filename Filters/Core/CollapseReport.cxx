// SPDX-License-Identifier: BSD-3-Clause
#include "CollapseReport.h"

#include <algorithm>
#include <numeric>
#include <sstream>

namespace meshsimp
{

std::int64_t RefusalCounts::Total() const
{
  return std::accumulate(this->ByCheck.begin(), this->ByCheck.end(), std::int64_t(0));
}

std::string DescribeRefusals(const RefusalCounts& counts, const char* passedText)
{
  // One text per CollapseCheck, in its order (Passed is the caller's), and the locks check's
  // per LockReason instead of its own.
  static const char* const CheckText[] = { nullptr,
    "are not valid plans (a repeated vertex or a position that is not finite)", nullptr,
    "would merge two regions of the border array", "would break the surface's topology (link condition)",
    "would make a new edge between two vertices on a piece border", "would turn a triangle over",
    "would leave a triangle without area", "would fold a triangle onto its neighbour",
    "would make a new angle below the angle guard" };
  static_assert(sizeof(CheckText) / sizeof(CheckText[0]) == NumberOfCollapseChecks, "one text per CollapseCheck");
  static const char* const LockText[] = {
    "would remove or move a point locked by the options (PreserveBoundary or the locked points)",
    "would remove or move a point shared with another piece", "would remove or move a non-manifold vertex",
    "would remove or move a border corner (the border turns there by more than BoundaryCornerAngle)",
    "would move a vertex off its hinge (an edge of three or more triangles)",
    "would remove or move a seam point (a border point with a twin at its position)" };
  static_assert(sizeof(LockText) / sizeof(LockText[0]) == NumberOfLockReasons, "one text per LockReason");
  std::vector<std::pair<std::int64_t, const char*>> refusals;
  for (std::size_t c = 0; c < NumberOfCollapseChecks; ++c)
  {
    if (c != static_cast<std::size_t>(CollapseCheck::Locks))
    {
      refusals.emplace_back(counts.ByCheck[c], c == 0 ? passedText : CheckText[c]);
    }
  }
  for (std::size_t r = 0; r < NumberOfLockReasons; ++r)
  {
    refusals.emplace_back(counts.ByLock[r], LockText[r]);
  }
  std::stable_sort(refusals.begin(), refusals.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const std::int64_t total = counts.Total();
  std::ostringstream text;
  for (std::size_t i = 0; i < 2 && total > 0 && refusals[i].first > 0; ++i)
  {
    const std::int64_t percent = std::llround(100.0 * refusals[i].first / total);
    text << (i > 0 ? ", " : "") << (percent > 0 ? std::to_string(percent) : std::string("<1")) << " % "
         << refusals[i].second;
  }
  return text.str();
}

std::string DescribeLocked(const std::array<std::int64_t, NumberOfLockReasons>& counts)
{
  static const char* const Name[] = { "by the options", "shared with another piece", "non-manifold",
    "border corners", "", "on seams" };
  static_assert(sizeof(Name) / sizeof(Name[0]) == NumberOfLockReasons, "one name per LockReason");
  const auto kinds = std::count_if(counts.begin(), counts.end(), [](std::int64_t c) { return c > 0; });
  std::ostringstream text;
  for (std::size_t r = 0; r < NumberOfLockReasons; ++r)
  {
    if (counts[r] > 0)
    {
      const std::string count = kinds > 1 ? std::to_string(counts[r]) + ' ' : counts[r] > 1 ? "all " : "";
      text << (text.tellp() > 0 ? ", " : "") << count << Name[r];
    }
  }
  return text.str();
}

std::string DescribeLeft(std::int64_t left, const char* noun, const std::array<std::int64_t, NumberOfLockReasons>& lockedBy,
  const RefusalCounts& refused, const char* tried, const char* passedText)
{
  const std::int64_t locked = std::accumulate(lockedBy.begin(), lockedBy.end(), std::int64_t(0));
  const std::int64_t collapses = refused.Total();
  std::string text = ": of the " + std::to_string(left) + " " + noun + " left, " + std::to_string(locked) +
    (locked == 1 ? " is locked" : " are locked") + (locked > 0 ? " (" + DescribeLocked(lockedBy) + ")" : std::string());
  return collapses == 0 ? text
                        : text + "; of the others' " + std::to_string(collapses) + " " + tried + ", " +
      DescribeRefusals(refused, passedText);
}

} // namespace meshsimp
