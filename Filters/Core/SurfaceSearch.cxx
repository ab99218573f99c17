// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceSearch.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;
constexpr double Infinity = std::numeric_limits<double>::infinity();

Vec3 ClosestPointOnSegment(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::min(1.0, std::max(0.0, (x - a).dot(ab) / length2)) : 0.0;
  return a + t * ab;
}

/// The closest point of the three edges of (a, b, c), the first of equals.
Vec3 ClosestPointOnEdges(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 candidates[3] = { ClosestPointOnSegment(x, a, b), ClosestPointOnSegment(x, b, c),
    ClosestPointOnSegment(x, c, a) };
  const Vec3* best = candidates;
  for (const Vec3& candidate : candidates)
  {
    best = (x - candidate).norm() < (x - *best).norm() ? &candidate : best;
  }
  return *best;
}

/// Sorts (key, id) pairs by key, ids of equal keys in their order: a radix sort by 16 bits at
/// a time, as many passes as the largest key needs.
void SortByKey(std::vector<std::pair<std::uint64_t, std::int32_t>>& pairs, std::uint64_t largest)
{
  std::vector<std::pair<std::uint64_t, std::int32_t>> sorted(pairs.size());
  for (int shift = 0; shift < 64 && (largest >> shift) > 0; shift += 16)
  {
    std::vector<std::size_t> start(1 << 16 | 1, 0);
    for (const auto& pair : pairs)
    {
      ++start[((pair.first >> shift) & 0xffff) + 1];
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (const auto& pair : pairs)
    {
      sorted[start[(pair.first >> shift) & 0xffff]++] = pair;
    }
    pairs.swap(sorted);
  }
}

} // namespace

/**
 * Exact nearest-triangle queries: the triangles in the non-empty cells of a uniform grid of
 * about their size (sorted by cell key), searched in growing shells of cells around the point
 * until no unexplored cell can hold a nearer one. Triangles that span many cells are kept apart
 * and measured at every query.
 */
class TriangleGrid
{
public:
  explicit TriangleGrid(const Surface& surface);
  Nearest Find(const Surface& surface, const Vec3& x) const;

private:
  static constexpr std::int64_t AxisCells = std::int64_t(1) << 20;
  static constexpr std::int64_t LargeSpan = 4096; // cells: above, a triangle is kept apart
  std::uint64_t Key(std::int64_t i, std::int64_t j, std::int64_t k) const
  {
    return static_cast<std::uint64_t>((i * this->Dims[1] + j) * this->Dims[2] + k);
  }
  std::int64_t CellOf(double x, int axis) const
  {
    const double cell = std::floor((x - this->Origin[axis]) / this->Size);
    return static_cast<std::int64_t>(std::min<double>(std::max(cell, 0.0), static_cast<double>(this->Dims[axis] - 1)));
  }
  void Visit(const Surface& surface, const Vec3& x, std::uint64_t key, Nearest& best) const;

  Vec3 Origin = Vec3::Zero();
  double Size = 1.0;
  std::int64_t Dims[3] = { 1, 1, 1 };
  std::vector<std::uint64_t> Keys;   // sorted, one per non-empty cell
  std::vector<std::int64_t> Offsets; // per key, into Ids
  std::vector<std::int32_t> Ids;
  std::vector<std::int32_t> Large;
};

TriangleGrid::TriangleGrid(const Surface& surface)
{
  // Cells about twice a triangle's typical size, at most 2^20 along an axis.
  const std::int64_t m = surface.NumberOfTriangles();
  Vec3 lower = Vec3::Constant(Infinity), upper = Vec3::Constant(-Infinity);
  double area = 0.0;
  for (std::int32_t t = 0; t < m; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower = lower.cwiseMin(surface.Corner(t, k));
      upper = upper.cwiseMax(surface.Corner(t, k));
    }
    area += 0.5 * (surface.Corner(t, 1) - surface.Corner(t, 0)).cross(surface.Corner(t, 2) - surface.Corner(t, 0)).norm();
  }
  if (m == 0)
  {
    return;
  }
  const double extent = (upper - lower).maxCoeff();
  this->Size = std::max({ 2.0 * std::sqrt(area / static_cast<double>(m)), extent / static_cast<double>(AxisCells - 1),
    std::numeric_limits<double>::min() });
  this->Origin = lower;
  for (int a = 0; a < 3; ++a)
  {
    this->Dims[a] = std::min<std::int64_t>(AxisCells, static_cast<std::int64_t>((upper[a] - lower[a]) / this->Size) + 1);
  }
  // Each triangle in the cells its box meets, as (key, triangle) pairs sorted by key.
  std::vector<std::pair<std::uint64_t, std::int32_t>> pairs;
  pairs.reserve(2 * static_cast<std::size_t>(m));
  for (std::int32_t t = 0; t < m; ++t)
  {
    std::int64_t low[3], high[3], span = 1;
    for (int a = 0; a < 3; ++a)
    {
      const double l = std::min({ surface.Corner(t, 0)[a], surface.Corner(t, 1)[a], surface.Corner(t, 2)[a] });
      const double h = std::max({ surface.Corner(t, 0)[a], surface.Corner(t, 1)[a], surface.Corner(t, 2)[a] });
      low[a] = this->CellOf(l, a);
      high[a] = this->CellOf(h, a);
      span *= high[a] - low[a] + 1;
    }
    if (span > LargeSpan)
    {
      this->Large.push_back(t);
      continue;
    }
    for (std::int64_t i = low[0]; i <= high[0]; ++i)
      for (std::int64_t j = low[1]; j <= high[1]; ++j)
        for (std::int64_t k = low[2]; k <= high[2]; ++k)
          pairs.emplace_back(this->Key(i, j, k), t);
  }
  SortByKey(pairs, this->Key(this->Dims[0] - 1, this->Dims[1] - 1, this->Dims[2] - 1));
  this->Ids.resize(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    if (i == 0 || pairs[i].first != pairs[i - 1].first)
    {
      this->Keys.push_back(pairs[i].first);
      this->Offsets.push_back(static_cast<std::int64_t>(i));
    }
    this->Ids[i] = pairs[i].second;
  }
  this->Offsets.push_back(static_cast<std::int64_t>(pairs.size()));
}

void TriangleGrid::Visit(const Surface& surface, const Vec3& x, std::uint64_t key, Nearest& best) const
{
  const auto found = std::lower_bound(this->Keys.begin(), this->Keys.end(), key);
  if (found != this->Keys.end() && *found == key)
  {
    const std::size_t cell = static_cast<std::size_t>(found - this->Keys.begin());
    surface.Among(x, this->Ids.data() + this->Offsets[cell], this->Ids.data() + this->Offsets[cell + 1], best);
  }
}

Nearest TriangleGrid::Find(const Surface& surface, const Vec3& x) const
{
  Nearest best;
  surface.Among(x, this->Large.data(), this->Large.data() + this->Large.size(), best);
  if (this->Keys.empty())
  {
    return best;
  }
  const std::int64_t c[3] = { this->CellOf(x[0], 0), this->CellOf(x[1], 1), this->CellOf(x[2], 2) };
  for (std::int64_t r = 0;; ++r)
  {
    // The shell of cells r away (Chebyshev) from x's cell.
    for (std::int64_t i = std::max<std::int64_t>(0, c[0] - r); i <= std::min(this->Dims[0] - 1, c[0] + r); ++i)
      for (std::int64_t j = std::max<std::int64_t>(0, c[1] - r); j <= std::min(this->Dims[1] - 1, c[1] + r); ++j)
      {
        if (std::abs(i - c[0]) == r || std::abs(j - c[1]) == r)
        {
          for (std::int64_t k = std::max<std::int64_t>(0, c[2] - r); k <= std::min(this->Dims[2] - 1, c[2] + r); ++k)
          {
            this->Visit(surface, x, this->Key(i, j, k), best);
          }
          continue;
        }
        for (const std::int64_t k : { c[2] - r, c[2] + r })
        {
          if (k >= 0 && k < this->Dims[2])
          {
            this->Visit(surface, x, this->Key(i, j, k), best);
          }
        }
      }
    // Every unexplored cell lies beyond the shell along some axis: no nearer than that slab.
    double beyond = Infinity;
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] - r > 0)
      {
        beyond = std::min(beyond, x[a] - (this->Origin[a] + static_cast<double>(c[a] - r) * this->Size));
      }
      if (c[a] + r < this->Dims[a] - 1)
      {
        beyond = std::min(beyond, this->Origin[a] + static_cast<double>(c[a] + r + 1) * this->Size - x[a]);
      }
    }
    if (best.Distance <= std::max(0.0, beyond) || std::isinf(beyond))
    {
      return best;
    }
  }
}

/**
 * Nearest-triangle queries that start from a bound: a tree of bounding boxes over the
 * triangles (each node splits its triangles at the median of their centres along its longest
 * axis, down to leaves of a few), searched nearer child first and skipping every box farther
 * than the nearest found so far. Nodes are stored flat, a node's two children next to each
 * other and after it. The top of the tree is split on one thread, the subtrees below it on all;
 * the tree's shape, and so every answer, does not depend on the thread count.
 */
class TriangleTree
{
public:
  TriangleTree(const Surface& surface, const ExecutionContext& context);
  void Nearer(const Surface& surface, const Vec3& x, Nearest& best) const;

private:
  static constexpr std::int32_t LeafSize = 4;
  struct Node
  {
    Eigen::AlignedBox3d Box;
    std::int32_t First = 0; // a leaf's first triangle in Order, or an inner node's first child
    std::int32_t Count = 0; // a leaf's triangles; 0 for an inner node
  };
  /// A triangle's centre next to its id, so that each split reorders them in place.
  struct Entry
  {
    Vec3 Centre;
    std::int32_t Triangle;
  };
  /// A node still to split, with its range of entries.
  struct Pending
  {
    std::int32_t Node, Begin, End;
  };

  /// Splits the range of nodes[root.Node] down to leaves, appending the nodes made; a range of
  /// at most deferBelow entries (above a leaf's) is added to deferred instead, when not null.
  static void Split(std::vector<Entry>& entries, std::vector<Node>& nodes, Pending root, std::int32_t deferBelow,
    std::vector<Pending>* deferred);
  /// The box of node n from its triangles or its children's boxes.
  void Box(const Surface& surface, std::size_t n);

  std::vector<Node> Nodes;
  std::vector<std::int32_t> Order;
};

void TriangleTree::Split(std::vector<Entry>& entries, std::vector<Node>& nodes, Pending root,
  std::int32_t deferBelow, std::vector<Pending>* deferred)
{
  std::vector<Pending> pending = { root };
  while (!pending.empty())
  {
    const Pending range = pending.back();
    pending.pop_back();
    if (range.End - range.Begin <= LeafSize)
    {
      nodes[range.Node].First = range.Begin;
      nodes[range.Node].Count = range.End - range.Begin;
      continue;
    }
    if (deferred && range.End - range.Begin <= deferBelow)
    {
      deferred->push_back(range);
      continue;
    }
    Eigen::AlignedBox3d middles;
    for (std::int32_t i = range.Begin; i < range.End; ++i)
    {
      middles.extend(entries[i].Centre);
    }
    int axis = 0;
    middles.sizes().maxCoeff(&axis);
    const std::int32_t middle = range.Begin + (range.End - range.Begin) / 2;
    std::nth_element(entries.begin() + range.Begin, entries.begin() + middle, entries.begin() + range.End,
      [axis](const Entry& a, const Entry& b) {
        return a.Centre[axis] < b.Centre[axis] || (a.Centre[axis] == b.Centre[axis] && a.Triangle < b.Triangle);
      });
    const auto first = static_cast<std::int32_t>(nodes.size());
    nodes[range.Node].First = first;
    nodes.resize(nodes.size() + 2);
    pending.push_back({ first, range.Begin, middle });
    pending.push_back({ first + 1, middle, range.End });
  }
}

void TriangleTree::Box(const Surface& surface, std::size_t n)
{
  Node& node = this->Nodes[n];
  if (node.Count == 0)
  {
    node.Box = this->Nodes[node.First].Box.merged(this->Nodes[node.First + 1].Box);
    return;
  }
  for (std::int32_t i = node.First; i < node.First + node.Count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      node.Box.extend(surface.Corner(this->Order[i], k));
    }
  }
}

TriangleTree::TriangleTree(const Surface& surface, const ExecutionContext& context)
  : Order(static_cast<std::size_t>(surface.NumberOfTriangles()))
{
  const auto n = static_cast<std::int32_t>(this->Order.size());
  if (n == 0)
  {
    return;
  }
  std::vector<Entry> entries(this->Order.size());
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (auto t = static_cast<std::int32_t>(begin); t < end; ++t)
    {
      entries[t] = { (surface.Corner(t, 0) + surface.Corner(t, 1) + surface.Corner(t, 2)) / 3.0, t };
    }
  }, 10 * static_cast<std::int64_t>(n));
  // 1. The top of the tree, down to ranges small enough to share among the threads.
  this->Nodes.resize(1);
  std::vector<Pending> deferred;
  const std::int32_t share = context.Threads > 1 ? n / (4 * context.Threads) : 0;
  Split(entries, this->Nodes, { 0, 0, n }, share, &deferred);
  const std::size_t top = this->Nodes.size();
  // 2. The subtrees below it, concurrently, each into nodes of its own (its root first).
  std::vector<std::vector<Node>> subtrees(deferred.size());
  context.For(static_cast<std::int64_t>(deferred.size()), [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t d = begin; d < end; ++d)
    {
      subtrees[d].resize(1);
      Split(entries, subtrees[d], { 0, deferred[d].Begin, deferred[d].End }, 0, nullptr);
    }
  }, 200 * static_cast<std::int64_t>(n));
  std::transform(entries.begin(), entries.end(), this->Order.begin(), [](const Entry& entry) { return entry.Triangle; });
  // 3. Each subtree after the top, its root in the place the top gave it.
  std::vector<std::size_t> offsets(deferred.size() + 1, top);
  for (std::size_t d = 0; d < deferred.size(); ++d)
  {
    offsets[d + 1] = offsets[d] + subtrees[d].size() - 1;
  }
  this->Nodes.resize(offsets.back());
  context.For(static_cast<std::int64_t>(deferred.size()), [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t d = begin; d < end; ++d)
    {
      const auto moved = [&](Node node) {
        node.First += node.Count > 0 ? 0 : static_cast<std::int32_t>(offsets[d]) - 1;
        return node;
      };
      this->Nodes[deferred[d].Node] = moved(subtrees[d][0]);
      std::transform(subtrees[d].begin() + 1, subtrees[d].end(), this->Nodes.begin() + offsets[d], moved);
      for (std::size_t node = offsets[d + 1]; node-- > offsets[d];)
      {
        this->Box(surface, node);
      }
    }
  }, 50 * static_cast<std::int64_t>(n));
  // 4. The boxes of the top, bottom up (children come after their parent).
  for (std::size_t node = top; node-- > 0;)
  {
    this->Box(surface, node);
  }
}

void TriangleTree::Nearer(const Surface& surface, const Vec3& x, Nearest& best) const
{
  if (this->Nodes.empty())
  {
    return;
  }
  std::int32_t stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    if (node.Box.squaredExteriorDistance(x) >= best.Distance * best.Distance)
    {
      continue;
    }
    if (node.Count > 0)
    {
      surface.Among(x, this->Order.data() + node.First, this->Order.data() + node.First + node.Count, best);
      continue;
    }
    // The nearer child is searched first (pushed last).
    const double near[2] = { this->Nodes[node.First].Box.squaredExteriorDistance(x),
      this->Nodes[node.First + 1].Box.squaredExteriorDistance(x) };
    const int nearer = near[1] < near[0] ? 1 : 0;
    stack[top++] = node.First + 1 - nearer;
    stack[top++] = node.First + nearer;
  }
}

Vec3 ClosestPointOnTriangle(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // By the Voronoi regions of the corners, edges and face (as in Ericson, "Real-Time Collision
  // Detection", 5.1.5); a triangle without area is its three edges.
  const Vec3 ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= 0.0)
  {
    return ClosestPointOnEdges(x, a, b, c);
  }
  const Vec3 ap = x - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const Vec3 bp = x - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return a + ab * (d1 / (d1 - d3));
  }
  const Vec3 cp = x - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return a + ac * (d2 / (d2 - d6));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  if (!(va + vb + vc > 0.0))
  {
    return ClosestPointOnEdges(x, a, b, c);
  }
  const double scale = 1.0 / (va + vb + vc);
  return a + ab * (vb * scale) + ac * (vc * scale);
}

double PointTriangleDistance(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  return (x - ClosestPointOnTriangle(x, a, b, c)).norm();
}

void Surface::PrepareNearer(const ExecutionContext& context) const
{
  std::call_once(this->TreeMade, [this, &context] { this->Tree = std::make_unique<TriangleTree>(*this, context); });
}

Nearest Surface::Nearer(const Vec3& x, Nearest guess) const
{
  this->PrepareNearer(ExecutionContext());
  this->Tree->Nearer(*this, x, guess);
  return guess;
}

Surface::Surface(std::vector<Vec3> points, std::vector<std::int32_t> corners)
  : Points(std::move(points))
  , Corners(std::move(corners))
  , Around(static_cast<std::int64_t>(this->Points.size()), this->Corners)
{
}

Surface::~Surface() = default;

Nearest Surface::Exact(const Vec3& x) const
{
  std::call_once(this->GridMade, [this] { this->Grid = std::make_unique<TriangleGrid>(*this); });
  return this->Grid->Find(*this, x);
}

Surface UsableSurface(const TriangleMeshView& mesh, std::vector<std::int32_t>& triangle)
{
  std::vector<Vec3> points(static_cast<std::size_t>(mesh.NumberOfPoints));
  for (std::int64_t p = 0; p < mesh.NumberOfPoints; ++p)
  {
    points[p] = mesh.Point(p);
  }
  std::vector<std::int32_t> corners;
  triangle.clear();
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    if (UsableTriangle(mesh, t))
    {
      for (int k = 0; k < 3; ++k)
      {
        corners.push_back(static_cast<std::int32_t>(mesh.Id(3 * t + k)));
      }
      triangle.push_back(static_cast<std::int32_t>(t));
    }
  }
  return Surface(std::move(points), std::move(corners));
}

Vec3 Barycentric(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 u = b - a, v = c - a, w = x - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
  const double det = uu * vv - uv * uv;
  if (!(det > 0.0))
  {
    return Vec3::Constant(1.0 / 3.0);
  }
  const double beta = (vv * wu - uv * wv) / det, gamma = (uu * wv - uv * wu) / det;
  const Vec3 weights = Vec3(1.0 - beta - gamma, beta, gamma).cwiseMax(0.0);
  return weights / weights.sum();
}

} // namespace meshsimp
