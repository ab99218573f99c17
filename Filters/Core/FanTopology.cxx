// SPDX-License-Identifier: BSD-3-Clause
#include "FanTopology.h"

#include <algorithm>

namespace meshsimp
{
namespace
{

/// The common case, without the workspace: the walk from corner 0 along each corner's first
/// successor comes back to corner 0 after exactly degree steps. The walk is deterministic, so it
/// met every corner once; a corner that shared its previous vertex with another would have been
/// skipped by the first match, and one that shared its next vertex would have been met twice.
/// Each corner thus has exactly one successor and one predecessor, in one cycle: the full
/// classification's Interior. Short lists only, as the scan is quadratic.
bool IsOneClosedFan(const Corner* first, std::int32_t degree)
{
  std::int32_t corner = 0;
  for (std::int32_t step = 1; step <= degree; ++step)
  {
    const std::int32_t next = first[corner].Next;
    std::int32_t successor = 0;
    while (successor < degree && first[successor].Previous != next)
    {
      ++successor;
    }
    if (successor == degree)
    {
      return false; // an open fan, or no fan
    }
    if (successor == 0)
    {
      return step == degree;
    }
    corner = successor;
  }
  return false; // a cycle that does not pass through corner 0
}

} // namespace

VertexClass ClassifyFan(
  const Corner* first, const Corner* last, std::int32_t& fanFirst, std::int32_t& fanLast, FanWorkspace& work)
{
  const std::int32_t degree = static_cast<std::int32_t>(last - first);
  if (degree == 0)
  {
    return VertexClass::NonManifold; // no fan at all
  }
  if (degree <= FanLookup::ScanLimit && IsOneClosedFan(first, degree))
  {
    fanFirst = fanLast = -1;
    return VertexClass::Interior;
  }
  const auto previousAt = [first](std::int32_t i) { return first[i].Previous; };
  work.ByPrevious.Reset(degree, previousAt);
  work.Successor.resize(degree);
  work.Reached.assign(degree, 0);
  // Each corner's successor, found once: more than one candidate, or a corner that succeeds two
  // others, means an edge of three triangles or of two in one orientation. A corner with no
  // successor closes the fan, one that succeeds none opens it: one of each at most.
  std::int32_t opening = -1, closing = -1;
  for (std::int32_t i = 0; i < degree; ++i)
  {
    int holders = 0;
    const std::int32_t successor = work.ByPrevious.Find(first[i].Next, previousAt, &holders);
    const bool severalCandidates = holders > 1;
    const bool reachedTwice = successor >= 0 && work.Reached[successor] > 0;
    const bool secondClosing = successor < 0 && closing >= 0;
    if (severalCandidates || reachedTwice || secondClosing)
    {
      return VertexClass::NonManifold;
    }
    work.Successor[i] = successor;
    if (successor >= 0)
    {
      work.Reached[successor] = 1;
    }
    closing = successor < 0 ? i : closing;
  }
  for (std::int32_t i = 0; i < degree; ++i)
  {
    if (!work.Reached[i])
    {
      if (opening >= 0)
      {
        return VertexClass::NonManifold;
      }
      opening = i;
    }
  }
  if ((opening < 0) != (closing < 0))
  {
    return VertexClass::NonManifold;
  }
  // One fan when the walk from the opening (or any corner) reaches every corner; the successors
  // are one-to-one, so the walk ends at the closing corner or back where it started.
  const std::int32_t start = opening >= 0 ? opening : 0;
  std::int32_t visited = 1;
  for (std::int32_t c = work.Successor[start]; c >= 0 && c != start; c = work.Successor[c])
  {
    ++visited;
  }
  if (visited != degree)
  {
    return VertexClass::NonManifold; // several fans
  }
  fanFirst = opening;
  fanLast = closing;
  return opening >= 0 ? VertexClass::Boundary : VertexClass::Interior;
}

bool IsHinge(const Corner* first, const Corner* last, std::int32_t ends[2], FanWorkspace& work)
{
  // The link's edges (next, previous), one per corner, listed at both ends and sorted by vertex:
  // a run of 2 is a vertex inside a fan, the two hinge ends have runs of k >= 3, a run of 1
  // would be an open border.
  const std::int32_t degree = static_cast<std::int32_t>(last - first);
  work.Ends.clear();
  for (std::int32_t i = 0; i < degree; ++i)
  {
    work.Ends.emplace_back(first[i].Next, i);
    work.Ends.emplace_back(first[i].Previous, i);
  }
  std::sort(work.Ends.begin(), work.Ends.end());
  std::int32_t found = 0, pages = 0;
  for (std::size_t run = 0, next = 0; run < work.Ends.size(); run = next)
  {
    for (next = run + 1; next < work.Ends.size() && work.Ends[next].first == work.Ends[run].first; ++next)
    {
    }
    const std::int32_t size = static_cast<std::int32_t>(next - run);
    if (size == 2)
    {
      continue;
    }
    if (size < 3 || found == 2 || (found == 1 && size != pages))
    {
      return false;
    }
    ends[found++] = work.Ends[run].first;
    pages = size;
  }
  if (found != 2)
  {
    return false;
  }
  // Every page walked from ends[0], corner by corner through vertices of two corners, must
  // arrive at ends[1], and the pages together must use every corner once.
  const auto cornersOf = [&work](std::int32_t w) {
    return std::equal_range(work.Ends.begin(), work.Ends.end(), std::make_pair(w, std::int32_t(-1)),
      [](const std::pair<std::int32_t, std::int32_t>& a, const std::pair<std::int32_t, std::int32_t>& b) {
        return a.first < b.first;
      });
  };
  work.Reached.assign(degree, 0);
  std::int32_t used = 0;
  const auto starts = cornersOf(ends[0]);
  for (auto start = starts.first; start != starts.second; ++start)
  {
    std::int32_t corner = start->second, at = ends[0];
    while (true)
    {
      if (work.Reached[corner])
      {
        return false;
      }
      work.Reached[corner] = 1;
      ++used;
      at = first[corner].Next == at ? first[corner].Previous : first[corner].Next;
      if (at == ends[1])
      {
        break;
      }
      const auto both = cornersOf(at); // two corners: the one just used and the next
      if (at == ends[0] || both.second - both.first != 2)
      {
        return false;
      }
      corner = both.first->second == corner ? (both.first + 1)->second : both.first->second;
    }
  }
  return used == degree;
}

} // namespace meshsimp
