// SPDX-License-Identifier: BSD-3-Clause
#include "LODInterpolation.h"
#include "SurfaceSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>
#include <utility>

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

/// The parameters t where two adjacent points at D = P_a − P_b apart in the detailed mesh and
/// E = Q_a − Q_b at t = 1 are closer than t · epsilon: f(t) = |D + t G|² − t² epsilon² < 0 with
/// G = E − D, a quadratic A t² + 2 b t + C that is not negative at t = 0 (C = |D|²), so negative
/// on one interval of t > 0, returned as (from, to) (from >= to: none; to infinite: unbounded).
/// Its discriminant b² − A C is epsilon² |D|² − |D × G|² (Lagrange's identity), which keeps its
/// digits where the two terms nearly cancel (a point pair that meets at t = 1 exactly), and the
/// roots come from the cancellation-free pair q / A, C / q.
std::pair<double, double> MergeWindow(const Vec3& D, const Vec3& E, double epsilon)
{
  constexpr double unbounded = std::numeric_limits<double>::infinity();
  const std::pair<double, double> none(unbounded, unbounded);
  const Vec3 G = E - D;
  const double A = G.squaredNorm() - epsilon * epsilon, b = D.dot(G), C = D.squaredNorm();
  const double discriminant = epsilon * epsilon * C - D.cross(G).squaredNorm();
  if (discriminant < 0.0)
  {
    return none;
  }
  const double q = -(b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0) // f(t) = A t²
  {
    return A < 0.0 ? std::make_pair(0.0, unbounded) : none;
  }
  if (A > 0.0) // negative between the roots
  {
    const double first = q / A, second = C / q;
    return { std::min(first, second), std::max(first, second) };
  }
  if (A < 0.0) // negative beyond the larger root (the other is not positive)
  {
    return { std::max(q / A, C / q), unbounded };
  }
  return b < 0.0 ? std::make_pair(C / q, unbounded) : none; // linear: 2 b t + C
}

/**
 * When the triangle (a, b, c) turns over in a geomorph that sends b and c to one place B and a
 * to A: the t in (0, 1) where its normal stands square to its normal at t = 0 (infinite where
 * it never does). With c − b shrinking as (1 − t)(c − b), the normal is (1 − t) times
 * ((b − a) + t ((B − A) − (b − a))) × (c − b), whose part along the first normal n goes
 * linearly from |n|² at t = 0 to ((B − A) × (c − b)) · n at t = 1.
 */
double TurnOver(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& A, const Vec3& B)
{
  const Vec3 normal = (b - a).cross(c - a);
  const double start = normal.squaredNorm(), end = (B - A).cross(c - b).dot(normal);
  return start > 0.0 && end < 0.0 ? start / (start - end) : std::numeric_limits<double>::infinity();
}

/// A scheduled edge while the schedule is sorted.
struct ScheduledEdge
{
  double From, To;
  std::int32_t A, B;
  bool operator<(const ScheduledEdge& other) const
  {
    return std::tie(this->From, this->A, this->B) < std::tie(other.From, other.A, other.B);
  }
};

/// Step 3: each point at (1 − t) P + t Q, and how far that is from P.
void PlacePoints(const TriangleMeshView& detailed, const MorphPartners& partners, double t, double* points,
  std::vector<double>& displacement, const ExecutionContext& context)
{
  const std::int64_t n = detailed.NumberOfPoints;
  const bool moves = partners.NumberOfPoints() == n && t > 0.0;
  displacement.resize(static_cast<std::size_t>(n));
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t d = begin; d < end; ++d)
    {
      const Vec3 p = detailed.Point(d);
      const Vec3 x = moves ? Vec3((1.0 - t) * p + t * Vec3(partners.Targets.data() + 3 * d)) : p;
      std::copy(x.data(), x.data() + 3, points + 3 * d);
      displacement[d] = (x - p).norm();
    }
  }, 4 * n);
}

/// Step 4's sets: the scheduled edges merging at t joined (each point's root the lowest id of its
/// set), and the sets of two points or more gathered, members ascending.
void JoinScheduled(const MergeSchedule& merges, double t, std::int64_t n, const ExecutionContext& context,
  MorphFrame& frame)
{
  std::vector<std::int32_t>& root = frame.Root;
  root.resize(static_cast<std::size_t>(n));
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    std::iota(root.begin() + begin, root.begin() + end, static_cast<std::int32_t>(begin));
  }, n);
  std::vector<std::uint8_t> touched(static_cast<std::size_t>(n), 0);
  const std::int64_t edges = merges.Consistent() ? merges.SlotOffsets[MergeSchedule::Slot(t) + 1] : 0;
  for (std::int64_t e = 0; e < edges; ++e)
  {
    const std::int32_t a = merges.Ends[2 * e], b = merges.Ends[2 * e + 1];
    if (merges.From[e] < t && t < merges.To[e] && InRange(a, n) && InRange(b, n))
    {
      Join(root, a, b);
      touched[a] = touched[b] = 1;
    }
  }
  // In ascending order a root (the lowest id of its set) comes before its members: one pass
  // finishes every path, numbers the sets and counts their members.
  std::vector<std::int32_t> group(static_cast<std::size_t>(n), -1);
  frame.GroupOffsets.assign(1, 0);
  for (std::int32_t a = 0; a < n; ++a)
  {
    if (touched[a])
    {
      root[a] = root[root[a]];
      if (root[a] == a)
      {
        group[a] = static_cast<std::int32_t>(frame.GroupOffsets.size()) - 1;
        frame.GroupOffsets.push_back(0);
      }
      ++frame.GroupOffsets[group[root[a]] + 1];
    }
  }
  std::partial_sum(frame.GroupOffsets.begin(), frame.GroupOffsets.end(), frame.GroupOffsets.begin());
  frame.GroupMembers.resize(static_cast<std::size_t>(frame.GroupOffsets.back()));
  std::vector<std::int32_t> next(frame.GroupOffsets.begin(), frame.GroupOffsets.end() - 1);
  for (std::int32_t a = 0; a < n; ++a)
  {
    if (touched[a])
    {
      frame.GroupMembers[next[group[root[a]]]++] = a;
    }
  }
}

/// Every merged set at the place of its member nearest to the members' mean (the lowest id of
/// equals): a place on some member's path, so that at t = 1 the set stands on the coarse
/// surface, where a mean of places on a curved surface would not.
void PlaceGroups(const TriangleMeshView& detailed, double* points, const ExecutionContext& context, MorphFrame& frame)
{
  context.For(frame.NumberOfGroups(), [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t g = begin; g < end; ++g)
    {
      const std::int32_t first = frame.GroupOffsets[g], last = frame.GroupOffsets[g + 1];
      const auto place = [&](std::int32_t i) { return Vec3(points + 3 * static_cast<std::int64_t>(frame.GroupMembers[i])); };
      Vec3 mean = Vec3::Zero();
      for (std::int32_t i = first; i < last; ++i)
      {
        mean += place(i);
      }
      mean /= last - first;
      std::int32_t central = first;
      for (std::int32_t i = first + 1; i < last; ++i)
      {
        central = (place(i) - mean).squaredNorm() < (place(central) - mean).squaredNorm() ? i : central;
      }
      const Vec3 at = place(central);
      for (std::int32_t i = first; i < last; ++i)
      {
        const std::int32_t d = frame.GroupMembers[i];
        std::copy(at.data(), at.data() + 3, points + 3 * static_cast<std::int64_t>(d));
        frame.Displacement[d] = (at - detailed.Point(d)).norm();
      }
    }
  }, 30 * static_cast<std::int64_t>(frame.GroupOffsets.back()));
}

/// The detailed triangles on the roots, those with three distinct corners, in their order: each
/// block of triangles kept in place, then the blocks moved together.
void KeepTriangles(const TriangleMeshView& detailed, const ExecutionContext& context, MorphFrame& frame)
{
  const std::int64_t triangles = detailed.NumberOfTriangles;
  const std::int64_t blocks = std::min<std::int64_t>(triangles, 256);
  const auto first = [&](std::int64_t block) { return triangles * block / blocks; };
  frame.Triangles.resize(3 * static_cast<std::size_t>(triangles));
  frame.TriangleSource.resize(static_cast<std::size_t>(triangles));
  std::vector<std::int64_t> kept(static_cast<std::size_t>(blocks), 0);
  context.For(blocks, [&](std::int64_t begin, std::int64_t end) {
    std::int32_t corner[3];
    for (std::int64_t block = begin; block < end; ++block)
    {
      std::int64_t out = first(block);
      for (std::int64_t s = first(block); s < first(block + 1); ++s)
      {
        if (DetailedTriangle(detailed, s, corner))
        {
          const std::int32_t a = frame.Root[corner[0]], b = frame.Root[corner[1]], c = frame.Root[corner[2]];
          if (a != b && b != c && c != a)
          {
            frame.Triangles[3 * out] = a;
            frame.Triangles[3 * out + 1] = b;
            frame.Triangles[3 * out + 2] = c;
            frame.TriangleSource[out++] = static_cast<std::int32_t>(s);
          }
        }
      }
      kept[block] = out - first(block);
    }
  }, 6 * triangles);
  std::int64_t next = 0;
  for (std::int64_t block = 0; block < blocks; ++block)
  {
    const std::int64_t from = first(block);
    if (next != from)
    {
      std::copy_n(frame.Triangles.begin() + 3 * from, 3 * kept[block], frame.Triangles.begin() + 3 * next);
      std::copy_n(frame.TriangleSource.begin() + from, kept[block], frame.TriangleSource.begin() + next);
    }
    next += kept[block];
  }
  frame.Triangles.resize(3 * static_cast<std::size_t>(next));
  frame.TriangleSource.resize(static_cast<std::size_t>(next));
}

/// The edges that can change a frame's sets: of the edges that stay merged up to t = 1 once they
/// merge, in order, only those that join two sets the earlier ones left apart (at any t where it
/// merges, the earlier edges that connect its ends merge too); every edge that merges for a
/// while only.
std::vector<ScheduledEdge> SpanningEdges(const std::vector<ScheduledEdge>& edges, std::int64_t n)
{
  std::vector<std::int32_t> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<ScheduledEdge> spanning;
  for (const ScheduledEdge& edge : edges)
  {
    const std::int32_t a = Find(parent, edge.A), b = Find(parent, edge.B);
    const bool stays = edge.To > 1.0;
    if (!stays || a != b)
    {
      spanning.push_back(edge);
    }
    if (stays)
    {
      Join(parent, a, b);
    }
  }
  return spanning;
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
  const std::vector<std::int32_t>& listed, const ExecutionContext& context)
{
  MorphPartners partners = OwnPartners(detailed);
  std::vector<std::int32_t> triangle; // per triangle of the search, its coarse triangle
  const Surface surface = UsableSurface(coarse, triangle);
  if (surface.NumberOfTriangles() == 0)
  {
    return partners;
  }
  const std::int64_t count = listed.empty() ? detailed.NumberOfPoints : static_cast<std::int64_t>(listed.size());
  context.For(count, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i)
    {
      const std::int64_t d = listed.empty() ? i : listed[i];
      if (!InRange(d, detailed.NumberOfPoints))
      {
        continue;
      }
      const Vec3 x = detailed.Point(d);
      const Nearest near = x.allFinite() ? surface.Exact(x) : Nearest();
      if (near.Triangle < 0)
      {
        continue;
      }
      const std::int64_t t = triangle[near.Triangle];
      const Vec3 corner[3] = { surface.Corner(near.Triangle, 0), surface.Corner(near.Triangle, 1), surface.Corner(near.Triangle, 2) };
      const Vec3 target = ClosestPointOnTriangle(x, corner[0], corner[1], corner[2]);
      const Vec3 weights = Barycentric(target, corner[0], corner[1], corner[2]);
      std::copy(target.data(), target.data() + 3, partners.Targets.begin() + 3 * d);
      std::copy(weights.data(), weights.data() + 3, partners.Weights.begin() + 3 * d);
      for (int k = 0; k < 3; ++k)
      {
        partners.Coarse[3 * d + k] = static_cast<std::int32_t>(coarse.Id(3 * t + k));
      }
    }
  }, 3000 * count);
  return partners;
}

MorphPartners PairAncestors(
  const TriangleMeshView& detailed, const TriangleMeshView& coarse, const std::vector<std::int32_t>& ancestor)
{
  MorphPartners partners = OwnPartners(detailed);
  for (std::int64_t d = 0; d < detailed.NumberOfPoints && d < static_cast<std::int64_t>(ancestor.size()); ++d)
  {
    const std::int32_t c = ancestor[d];
    if (InRange(c, coarse.NumberOfPoints))
    {
      const Vec3 p = coarse.Point(c);
      std::copy(p.data(), p.data() + 3, partners.Targets.begin() + 3 * d);
      partners.Coarse[3 * d] = c;
      partners.Weights[3 * d] = 1.0;
    }
  }
  return partners;
}

MergeSchedule ScheduleMerges(const TriangleMeshView& detailed, const MorphPartners& partners, double mergeDistance,
  const ExecutionContext& context, bool samePartnerOnly)
{
  const std::int64_t n = detailed.NumberOfPoints, triangles = detailed.NumberOfTriangles;
  const bool paired = partners.NumberOfPoints() == n;
  const double epsilon = std::isfinite(mergeDistance) ? std::max(0.0, mergeDistance) : 0.0;
  const auto samePartner = [&](std::int32_t a, std::int32_t b) {
    return paired && partners.Coarse[3 * static_cast<std::size_t>(a)] >= 0 &&
      partners.Coarse[3 * static_cast<std::size_t>(a)] == partners.Coarse[3 * static_cast<std::size_t>(b)] &&
      partners.Weights[3 * static_cast<std::size_t>(a)] == 1.0 && partners.Weights[3 * static_cast<std::size_t>(b)] == 1.0;
  };
  const auto target = [&](std::int32_t d) { return paired ? Vec3(partners.Targets.data() + 3 * static_cast<std::int64_t>(d)) : detailed.Point(d); };
  // Each block of triangles lists its edges' windows, the blocks in order.
  const std::int64_t blocks = std::min<std::int64_t>(triangles, 256);
  std::vector<std::vector<ScheduledEdge>> found(static_cast<std::size_t>(blocks));
  context.For(blocks, [&](std::int64_t begin, std::int64_t end) {
    std::int32_t corner[3];
    for (std::int64_t block = begin; (epsilon > 0.0 || samePartnerOnly) && block < end; ++block)
    {
      for (std::int64_t s = triangles * block / blocks, last = triangles * (block + 1) / blocks; s < last; ++s)
      {
        if (!DetailedTriangle(detailed, s, corner))
        {
          continue;
        }
        for (int k = 0; k < 3; ++k)
        {
          const std::int32_t a = std::min(corner[k], corner[(k + 1) % 3]), b = std::max(corner[k], corner[(k + 1) % 3]);
          auto [from, to] = MergeWindow(detailed.Point(a) - detailed.Point(b), target(a) - target(b), epsilon);
          if (samePartnerOnly && samePartner(a, b))
          {
            // The triangle vanishes at t = 1: its edge joins before it would turn over, at the
            // latest at t = 1, where its ends meet, and its ends, closing in on one point, stay
            // joined.
            const std::int32_t opposite = corner[(k + 2) % 3];
            from = std::min({ from, std::nextafter(1.0, 0.0),
              TurnOver(detailed.Point(opposite), detailed.Point(corner[k]), detailed.Point(corner[(k + 1) % 3]),
                target(opposite), target(corner[k])) });
            to = std::numeric_limits<double>::infinity();
          }
          if (a != b && from < 1.0 && to > std::max(0.0, from) && (!samePartnerOnly || samePartner(a, b)))
          {
            found[block].push_back({ std::max(0.0, from), to, a, b });
          }
        }
      }
    }
  }, 20 * triangles);
  std::vector<ScheduledEdge> edges;
  for (const std::vector<ScheduledEdge>& block : found)
  {
    edges.insert(edges.end(), block.begin(), block.end());
  }
  context.Sort(edges); // an edge of two triangles is found twice, with the same window
  edges.erase(std::unique(edges.begin(), edges.end(),
                [](const ScheduledEdge& x, const ScheduledEdge& y) { return x.A == y.A && x.B == y.B && x.From == y.From; }),
    edges.end());
  std::vector<ScheduledEdge> spanning = SpanningEdges(edges, n);
  std::sort(spanning.begin(), spanning.end(), [](const ScheduledEdge& x, const ScheduledEdge& y) {
    return std::make_tuple(MergeSchedule::Slot(x.From), x.A, x.B) < std::make_tuple(MergeSchedule::Slot(y.From), y.A, y.B);
  });
  MergeSchedule schedule;
  for (const ScheduledEdge& edge : spanning)
  {
    schedule.Ends.insert(schedule.Ends.end(), { edge.A, edge.B });
    schedule.From.push_back(edge.From);
    schedule.To.push_back(edge.To);
    ++schedule.SlotOffsets[MergeSchedule::Slot(edge.From) + 1];
  }
  std::partial_sum(schedule.SlotOffsets.begin(), schedule.SlotOffsets.end(), schedule.SlotOffsets.begin());
  return schedule;
}

void Morph(const TriangleMeshView& detailed, const MorphPartners& partners, const MergeSchedule& merges, double t,
  double* points, MorphFrame& frame, const ExecutionContext& context)
{
  t = std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : 0.0;
  PlacePoints(detailed, partners, t, points, frame.Displacement, context);
  JoinScheduled(merges, t, detailed.NumberOfPoints, context, frame);
  PlaceGroups(detailed, points, context, frame);
  KeepTriangles(detailed, context, frame);
}

} // namespace meshsimp
