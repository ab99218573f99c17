// SPDX-License-Identifier: BSD-3-Clause
#include "ProgressiveSequence.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace meshsimp
{

std::int64_t ProgressiveMesh::TrianglesAt(std::int64_t points) const
{
  return std::lower_bound(this->RemovedBy.begin(), this->RemovedBy.end(), points) - this->RemovedBy.begin();
}

std::vector<double> ProgressiveMesh::CollapseLevel(std::int64_t points) const
{
  const std::int64_t n = this->NumberOfPoints(), collapses = this->NumberOfCollapses();
  std::vector<double> level(std::min(points, n), 1.0);
  for (std::int64_t p = this->BasePoints; p < static_cast<std::int64_t>(level.size()); ++p)
  {
    level[p] = static_cast<double>(n - 1 - p) / static_cast<double>(collapses); // collapses before its own
  }
  return level;
}

std::string ProgressiveMesh::Validate(std::int64_t inputPoints) const
{
  // The checks in order, the first failure named.
  const std::int64_t n = this->NumberOfPoints(), m = static_cast<std::int64_t>(this->RemovedBy.size());
  if (static_cast<std::int64_t>(this->InputPoint.size()) != n || static_cast<std::int64_t>(this->Error.size()) != n ||
    static_cast<std::int64_t>(this->Triangles.size()) != 3 * m || static_cast<std::int64_t>(this->InputTriangle.size()) != m)
  {
    return "its arrays differ in length";
  }
  for (std::int64_t p = 0; p < n; ++p)
  {
    const bool base = p < this->BasePoints;
    if (this->InputPoint[p] < 0 || this->InputPoint[p] >= inputPoints || (base ? this->Parent[p] != -1 : (this->Parent[p] < 0 || this->Parent[p] >= p)))
    {
      return "point " + std::to_string(p) + " has no valid parent (each removed point's Parent is a smaller index)";
    }
    if (!(this->Error[p] >= 0.0) || !std::isfinite(this->Error[p]) ||
      (p > this->BasePoints && this->Error[p] > this->Error[p - 1]))
    {
      return "its CollapseError does not fall with the point index";
    }
  }
  for (std::int64_t i = 0; i < m; ++i)
  {
    if ((i > 0 && this->RemovedBy[i] < this->RemovedBy[i - 1]) || this->RemovedBy[i] < -1 || this->RemovedBy[i] >= n ||
      (this->RemovedBy[i] >= 0 && this->RemovedBy[i] < this->BasePoints))
    {
      return "its triangles are not ordered by RemovedAt";
    }
    for (int k = 0; k < 3; ++k)
    {
      if (this->Triangles[3 * i + k] < 0 || this->Triangles[3 * i + k] >= n)
      {
        return "triangle " + std::to_string(i) + " has a corner out of range";
      }
    }
  }
  return {};
}

std::int64_t LevelFor(const ProgressiveMesh& sequence, const Target& goal, Outcome& outcome)
{
  const std::int64_t n = sequence.NumberOfPoints(), base = sequence.BasePoints;
  if (goal.Bounded())
  {
    // The most collapses whose running error stays within the bound.
    const double bound = goal.RelativeError ? goal.MaximumError * goal.UnitLength(outcome.Diagonal) : goal.MaximumError;
    const auto first = sequence.Error.begin() + base;
    const std::int64_t k = base + (std::partition_point(first, sequence.Error.end(), [bound](double e) { return e > bound; }) - first);
    outcome.MaximumError = k < n ? sequence.Error[k] : 0.0;
    return k;
  }
  const std::int64_t target = goal.TriangleCountFor(outcome.UsableTriangles);
  outcome.TargetTriangles = target;
  std::int64_t low = base, high = n; // the first level with at least target triangles
  while (low < high)
  {
    const std::int64_t middle = low + (high - low) / 2;
    if (sequence.TrianglesAt(middle) >= target)
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  std::int64_t k = low;
  if (k > base && target - sequence.TrianglesAt(k - 1) < sequence.TrianglesAt(k) - target)
  {
    k -= 1;
  }
  if (k == base && sequence.TrianglesAt(k) > target + goal.Slack(target))
  {
    outcome.Stop = StopReason::NothingRemovable;
    outcome.Reason = "no collapse that keeps the mesh valid is left (the coarsest level of the sequence)" +
      sequence.CoarsestReason;
  }
  outcome.MaximumError = k < n ? sequence.Error[k] : 0.0;
  return k;
}

std::vector<std::int32_t> LevelAncestors(const ProgressiveMesh& sequence, std::int64_t points)
{
  // Parents have smaller indices, so one pass upwards from points gives every removed point's.
  const std::int64_t n = sequence.NumberOfPoints(), k = std::min(std::max(points, sequence.BasePoints), n);
  std::vector<std::int32_t> ancestor(n - k);
  for (std::int64_t p = k; p < n; ++p)
  {
    const std::int32_t parent = sequence.Parent[p];
    ancestor[p - k] = parent < k ? parent : ancestor[parent - k];
  }
  return ancestor;
}

void ListLevelSources(const ProgressiveMesh& sequence, std::int64_t points, SimplifiedMesh& level)
{
  const std::vector<std::int32_t> ancestor = LevelAncestors(sequence, points);
  const std::int64_t n = sequence.NumberOfPoints(), k = n - static_cast<std::int64_t>(ancestor.size());
  level.SourceOffsets.assign(k + 1, 0);
  for (std::int64_t p = 0; p < k; ++p)
  {
    level.SourceOffsets[p + 1] = 1;
  }
  for (const std::int32_t a : ancestor)
  {
    ++level.SourceOffsets[a + 1];
  }
  std::partial_sum(level.SourceOffsets.begin(), level.SourceOffsets.end(), level.SourceOffsets.begin());
  level.SourcePoints.resize(n);
  level.SourceWeights.assign(n, 0.0);
  std::vector<std::int32_t> next(level.SourceOffsets.begin(), level.SourceOffsets.end() - 1);
  for (std::int64_t p = 0; p < n; ++p)
  {
    const std::int32_t owner = p < k ? static_cast<std::int32_t>(p) : ancestor[p - k];
    level.SourceWeights[next[owner]] = p < k ? 1.0 : 0.0;
    level.SourcePoints[next[owner]++] = sequence.InputPoint[p];
  }
}

void ExtractLevel(const ProgressiveMesh& sequence, std::int64_t points, const TriangleMeshView& input,
  SimplifiedMesh& level)
{
  const std::int64_t n = sequence.NumberOfPoints(), k = std::min(std::max(points, sequence.BasePoints), n);
  const std::int64_t m = sequence.TrianglesAt(k);
  level.Triangles.resize(3 * m);
  LevelCorners(sequence, k, level.Triangles.data());
  level.TriangleSource.assign(sequence.InputTriangle.begin(), sequence.InputTriangle.begin() + m);
  level.Points.resize(3 * k);
  level.SourceOffsets.resize(k + 1);
  level.SourcePoints.assign(sequence.InputPoint.begin(), sequence.InputPoint.begin() + k);
  level.SourceWeights.assign(k, 1.0);
  for (std::int64_t p = 0; p < k; ++p)
  {
    const Eigen::Vector3d x = input.Point(sequence.InputPoint[p]);
    std::copy(x.data(), x.data() + 3, level.Points.begin() + 3 * p);
    level.SourceOffsets[p + 1] = static_cast<std::int32_t>(p + 1);
  }
  level.AddPointArray("CollapseLevel", sequence.CollapseLevel(k));
  level.FieldValues.emplace_back("LevelTriangles", static_cast<double>(m));
  level.FieldValues.emplace_back("LevelPoints", static_cast<double>(k));
}

void ExtractTarget(const ProgressiveMesh& sequence, const Target& goal, const TriangleMeshView& input,
  SimplifiedMesh& level)
{
  Outcome outcome = sequence.Report;
  const std::int64_t points = LevelFor(sequence, goal, outcome);
  ExtractLevel(sequence, points, input, level);
  level.Report = outcome;
}

} // namespace meshsimp
