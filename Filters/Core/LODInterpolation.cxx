// SPDX-License-Identifier: BSD-3-Clause
#include "LODInterpolation.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;

/// Partners for n detailed points, each its own (no coarse point: it keeps its place and data).
MorphPartners OwnPartners(const TriangleMeshView& detailed)
{
  MorphPartners partners;
  const std::int64_t n = detailed.NumberOfPoints;
  partners.Targets.resize(3 * static_cast<std::size_t>(n));
  partners.Coarse.assign(3 * static_cast<std::size_t>(n), -1);
  partners.Weights.assign(3 * static_cast<std::size_t>(n), 0.0);
  for (std::int64_t d = 0; d < n; ++d)
  {
    const Vec3 p = detailed.Point(d);
    std::copy(p.data(), p.data() + 3, partners.Targets.begin() + 3 * d);
  }
  return partners;
}

bool InRange(std::int64_t id, std::int64_t count)
{
  return id >= 0 && id < count;
}

/// The representative of a's set, the lowest id in it (paths halved on the way).
std::int32_t Find(std::vector<std::int32_t>& parent, std::int32_t a)
{
  while (parent[a] != a)
  {
    parent[a] = parent[parent[a]];
    a = parent[a];
  }
  return a;
}

void Join(std::vector<std::int32_t>& parent, std::int32_t a, std::int32_t b)
{
  a = Find(parent, a);
  b = Find(parent, b);
  if (a != b)
  {
    parent[std::max(a, b)] = std::min(a, b);
  }
}

/// The detailed triangle's corner ids, false where one is out of range.
bool DetailedTriangle(const TriangleMeshView& detailed, std::int64_t t, std::int32_t corner[3])
{
  for (int k = 0; k < 3; ++k)
  {
    const std::int64_t id = detailed.Id(3 * t + k);
    if (!InRange(id, detailed.NumberOfPoints))
    {
      return false;
    }
    corner[k] = static_cast<std::int32_t>(id);
  }
  return true;
}

/// Per detailed point, the representative of its merged set: adjacent points closer than
/// threshold at their frame places are joined.
std::vector<std::int32_t> MergedSets(const TriangleMeshView& detailed, const std::vector<double>& place, double threshold)
{
  std::vector<std::int32_t> parent(static_cast<std::size_t>(detailed.NumberOfPoints));
  std::iota(parent.begin(), parent.end(), 0);
  const double threshold2 = threshold * threshold;
  std::int32_t corner[3];
  for (std::int64_t t = 0; threshold > 0.0 && t < detailed.NumberOfTriangles; ++t)
  {
    if (!DetailedTriangle(detailed, t, corner))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t a = corner[k], b = corner[(k + 1) % 3];
      const Vec3 pa(place.data() + 3 * static_cast<std::int64_t>(a));
      const Vec3 pb(place.data() + 3 * static_cast<std::int64_t>(b));
      if ((pa - pb).squaredNorm() < threshold2)
      {
        Join(parent, a, b);
      }
    }
  }
  for (std::int32_t a = 0; a < static_cast<std::int32_t>(parent.size()); ++a)
  {
    parent[a] = Find(parent, a);
  }
  return parent;
}

/// The output points: one per merged set in the order of their lowest ids, at the mean of their
/// members' places, with the members as sources; returns each detailed point's output id.
std::vector<std::int32_t> WritePoints(const TriangleMeshView& detailed, const std::vector<double>& place,
  const std::vector<std::int32_t>& root, MorphFrame& frame)
{
  const std::int32_t n = static_cast<std::int32_t>(root.size());
  std::vector<std::int32_t> output(root.size(), -1);
  std::vector<std::int32_t> members(root.size(), 0);
  std::int32_t count = 0;
  for (std::int32_t a = 0; a < n; ++a)
  {
    if (root[a] == a)
    {
      output[a] = count++;
    }
    ++members[output[root[a]]];
  }
  frame.PointOffsets.assign(static_cast<std::size_t>(count) + 1, 0);
  for (std::int32_t g = 0; g < count; ++g)
  {
    frame.PointOffsets[g + 1] = frame.PointOffsets[g] + members[g];
  }
  frame.PointSources.resize(root.size());
  frame.Points.assign(3 * static_cast<std::size_t>(count), 0.0);
  std::vector<std::int32_t> filled(frame.PointOffsets.begin(), frame.PointOffsets.end() - 1);
  for (std::int32_t a = 0; a < n; ++a)
  {
    const std::int32_t g = output[root[a]];
    output[a] = g;
    frame.PointSources[filled[g]++] = a;
    for (int k = 0; k < 3; ++k)
    {
      frame.Points[3 * static_cast<std::size_t>(g) + k] += place[3 * static_cast<std::size_t>(a) + k];
    }
  }
  frame.Displacement.resize(static_cast<std::size_t>(count));
  for (std::int32_t g = 0; g < count; ++g)
  {
    for (int k = 0; members[g] > 1 && k < 3; ++k)
    {
      frame.Points[3 * static_cast<std::size_t>(g) + k] /= members[g];
    }
    const Vec3 p(frame.Points.data() + 3 * static_cast<std::int64_t>(g));
    frame.Displacement[g] = (p - detailed.Point(frame.PointSources[frame.PointOffsets[g]])).norm();
  }
  return output;
}
} // namespace

MorphPartners PairNearestVertices(const TriangleMeshView& detailed, const TriangleMeshView& coarse,
  const std::vector<std::int32_t>& nearestDetailed, const std::vector<std::int32_t>& nearestCoarse)
{
  MorphPartners partners = OwnPartners(detailed);
  // Step 1: each coarse point's nearest detailed point takes it (the nearest chooser wins).
  std::vector<std::int32_t> chosen(static_cast<std::size_t>(detailed.NumberOfPoints), -1);
  std::vector<double> distance(chosen.size(), 0.0);
  for (std::int64_t c = 0; c < coarse.NumberOfPoints && c < static_cast<std::int64_t>(nearestDetailed.size()); ++c)
  {
    const std::int32_t d = nearestDetailed[c];
    if (!InRange(d, detailed.NumberOfPoints))
    {
      continue;
    }
    const double to = (coarse.Point(c) - detailed.Point(d)).squaredNorm();
    if (chosen[d] < 0 || to < distance[d])
    {
      chosen[d] = static_cast<std::int32_t>(c);
      distance[d] = to;
    }
  }
  // Step 2: the others take their nearest coarse point.
  for (std::int64_t d = 0; d < detailed.NumberOfPoints; ++d)
  {
    const std::int64_t c = chosen[d] >= 0 ? chosen[d]
      : d < static_cast<std::int64_t>(nearestCoarse.size()) ? nearestCoarse[d]
                                                           : -1;
    if (!InRange(c, coarse.NumberOfPoints))
    {
      continue;
    }
    const Vec3 p = coarse.Point(c);
    std::copy(p.data(), p.data() + 3, partners.Targets.begin() + 3 * d);
    partners.Coarse[3 * d] = static_cast<std::int32_t>(c);
    partners.Weights[3 * d] = 1.0;
  }
  return partners;
}

MorphPartners PairSurfacePoints(const TriangleMeshView& detailed, const TriangleMeshView& coarse,
  const std::vector<std::int32_t>& triangle, const std::vector<double>& barycentric)
{
  MorphPartners partners = OwnPartners(detailed);
  for (std::int64_t d = 0; d < detailed.NumberOfPoints && d < static_cast<std::int64_t>(triangle.size()) &&
       3 * d + 2 < static_cast<std::int64_t>(barycentric.size());
       ++d)
  {
    const std::int64_t t = triangle[d];
    if (!InRange(t, coarse.NumberOfTriangles))
    {
      continue;
    }
    std::int64_t ids[3];
    double weights[3], sum = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = coarse.Id(3 * t + k);
      weights[k] = std::max(0.0, barycentric[3 * d + k]);
      sum += weights[k];
    }
    if (!(sum > 0.0) || !InRange(ids[0], coarse.NumberOfPoints) || !InRange(ids[1], coarse.NumberOfPoints) ||
      !InRange(ids[2], coarse.NumberOfPoints))
    {
      continue;
    }
    Vec3 target = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
    {
      partners.Coarse[3 * d + k] = static_cast<std::int32_t>(ids[k]);
      partners.Weights[3 * d + k] = weights[k] / sum;
      target += partners.Weights[3 * d + k] * coarse.Point(ids[k]);
    }
    std::copy(target.data(), target.data() + 3, partners.Targets.begin() + 3 * d);
  }
  return partners;
}

void Morph(const TriangleMeshView& detailed, const MorphPartners& partners, double t, double mergeDistance,
  MorphFrame& frame)
{
  frame = MorphFrame();
  t = std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : 0.0;
  const std::int64_t n = detailed.NumberOfPoints;
  const bool paired = partners.NumberOfPoints() == n;
  // Step 3: each point on its way to its partner.
  std::vector<double> place(3 * static_cast<std::size_t>(n));
  for (std::int64_t d = 0; d < n; ++d)
  {
    const Vec3 p = detailed.Point(d);
    const Vec3 x = paired && t > 0.0 ? Vec3((1.0 - t) * p + t * Vec3(partners.Targets.data() + 3 * d)) : p;
    std::copy(x.data(), x.data() + 3, place.begin() + 3 * d);
  }
  // Step 4: close neighbours join, triangles left without area go.
  const double threshold = std::isfinite(mergeDistance) ? t * std::max(0.0, mergeDistance) : 0.0;
  const std::vector<std::int32_t> output = WritePoints(detailed, place, MergedSets(detailed, place, threshold), frame);
  std::int32_t corner[3];
  for (std::int64_t s = 0; s < detailed.NumberOfTriangles; ++s)
  {
    if (!DetailedTriangle(detailed, s, corner))
    {
      continue;
    }
    const std::int32_t a = output[corner[0]], b = output[corner[1]], c = output[corner[2]];
    if (a != b && b != c && c != a)
    {
      frame.Triangles.insert(frame.Triangles.end(), { a, b, c });
      frame.TriangleSource.push_back(static_cast<std::int32_t>(s));
    }
  }
}

} // namespace meshsimp
