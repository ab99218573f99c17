// SPDX-License-Identifier: BSD-3-Clause
#include "Deviation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;
constexpr double Infinity = std::numeric_limits<double>::infinity();

double SegmentDistance(const Vec3& x, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::min(1.0, std::max(0.0, (x - a).dot(ab) / length2)) : 0.0;
  return (x - (a + t * ab)).norm();
}

/// The nearest triangle found so far to a point.
struct Nearest
{
  double Distance = Infinity;
  std::int32_t Triangle = -1;

  void Offer(double distance, std::int32_t t)
  {
    if (distance < this->Distance)
    {
      this->Distance = distance;
      this->Triangle = t;
    }
  }
};

/// The triangles around each point: CSR over a flat list of corners (3 per triangle).
struct Stars
{
  std::vector<std::int64_t> Offsets;
  std::vector<std::int32_t> Triangles;

  Stars(std::int64_t points, const std::vector<std::int32_t>& corners)
    : Offsets(points + 1, 0)
    , Triangles(corners.size())
  {
    for (const std::int32_t v : corners)
    {
      ++this->Offsets[v + 1];
    }
    std::partial_sum(this->Offsets.begin(), this->Offsets.end(), this->Offsets.begin());
    std::vector<std::int64_t> next(this->Offsets.begin(), this->Offsets.end() - 1);
    for (std::size_t c = 0; c < corners.size(); ++c)
    {
      this->Triangles[next[corners[c]]++] = static_cast<std::int32_t>(c / 3);
    }
  }
  const std::int32_t* Begin(std::int64_t v) const { return this->Triangles.data() + this->Offsets[v]; }
  const std::int32_t* End(std::int64_t v) const { return this->Triangles.data() + this->Offsets[v + 1]; }
};

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

class Surface;

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

/// One side's triangles: points, corners, the triangles around each point, and an exact
/// search made when first asked for (from any thread).
class Surface
{
public:
  Surface(std::vector<Vec3> points, std::vector<std::int32_t> corners)
    : Points(std::move(points))
    , Corners(std::move(corners))
    , Around(static_cast<std::int64_t>(this->Points.size()), this->Corners)
  {
  }

  std::int64_t NumberOfTriangles() const { return static_cast<std::int64_t>(this->Corners.size() / 3); }
  const Vec3& Corner(std::int32_t t, int k) const { return this->Points[this->Corners[3 * static_cast<std::size_t>(t) + k]]; }
  double Distance(const Vec3& x, std::int32_t t) const
  {
    return PointTriangleDistance(x, this->Corner(t, 0), this->Corner(t, 1), this->Corner(t, 2));
  }
  /// Whether x projects onto the inside of triangle t.
  bool Over(const Vec3& x, std::int32_t t) const
  {
    const Vec3 &a = this->Corner(t, 0), &b = this->Corner(t, 1), &c = this->Corner(t, 2);
    const Vec3 normal = (b - a).cross(c - a);
    return (b - a).cross(x - a).dot(normal) > 0.0 && (c - b).cross(x - b).dot(normal) > 0.0 &&
      (a - c).cross(x - c).dot(normal) > 0.0;
  }
  void Among(const Vec3& x, const std::int32_t* first, const std::int32_t* last, Nearest& best) const
  {
    for (; first != last; ++first)
    {
      best.Offer(this->Distance(x, *first), *first);
    }
  }
  void AroundPoint(const Vec3& x, std::int64_t v, Nearest& best) const
  {
    this->Among(x, this->Around.Begin(v), this->Around.End(v), best);
  }
  /// From the nearest found, to a triangle around one of its corners while one is nearer: a
  /// walk over the surface towards the point, which ends where the point stands over the
  /// nearest triangle's inside.
  void Walk(const Vec3& x, Nearest& best) const
  {
    for (std::int32_t from = -1; best.Triangle >= 0 && best.Triangle != from && best.Distance > 0.0 &&
         !this->Over(x, best.Triangle);)
    {
      from = best.Triangle;
      for (int k = 0; k < 3; ++k)
      {
        this->AroundPoint(x, this->Corners[3 * static_cast<std::size_t>(from) + k], best);
      }
    }
  }
  /// The nearest triangle, exactly.
  Nearest Exact(const Vec3& x) const
  {
    std::call_once(this->GridMade, [this] { this->Grid = std::make_unique<TriangleGrid>(*this); });
    return this->Grid->Find(*this, x);
  }

  const std::vector<Vec3> Points;
  const std::vector<std::int32_t> Corners;
  const Stars Around;

private:
  mutable std::once_flag GridMade;
  mutable std::unique_ptr<TriangleGrid> Grid;
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

/// The input's usable triangles' corners (distinct points in range with finite coordinates),
/// and each input triangle's place among them (-1: not usable).
std::vector<std::int32_t> UsableCorners(const TriangleMeshView& input, std::vector<std::int32_t>& place)
{
  std::vector<std::int32_t> corners;
  corners.reserve(3 * static_cast<std::size_t>(input.NumberOfTriangles));
  place.assign(static_cast<std::size_t>(input.NumberOfTriangles), -1);
  for (std::int64_t t = 0; t < input.NumberOfTriangles; ++t)
  {
    const std::int64_t ids[3] = { input.Id(3 * t), input.Id(3 * t + 1), input.Id(3 * t + 2) };
    bool usable = ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2];
    for (int k = 0; k < 3 && usable; ++k)
    {
      usable = ids[k] >= 0 && ids[k] < input.NumberOfPoints && input.Point(ids[k]).allFinite();
    }
    if (usable)
    {
      place[t] = static_cast<std::int32_t>(corners.size() / 3);
      corners.insert(corners.end(), ids, ids + 3);
    }
  }
  return corners;
}

std::vector<Vec3> InputPoints(const TriangleMeshView& input)
{
  std::vector<Vec3> points(static_cast<std::size_t>(input.NumberOfPoints));
  for (std::int64_t i = 0; i < input.NumberOfPoints; ++i)
  {
    points[i] = input.Point(i);
  }
  return points;
}

std::vector<Vec3> OutputPoints(const SimplifiedMesh& output)
{
  std::vector<Vec3> points(static_cast<std::size_t>(output.NumberOfPoints()));
  for (std::int64_t p = 0; p < output.NumberOfPoints(); ++p)
  {
    points[p] = Vec3(output.Points.data() + 3 * p);
  }
  return points;
}

} // namespace

/// The input side: its points, usable triangles and their adjacency, and its exact search.
struct DeviationInput::Data
{
  explicit Data(const TriangleMeshView& input)
    : Surface(InputPoints(input), UsableCorners(input, this->Usable))
  {
  }
  std::vector<std::int32_t> Usable; // per input triangle, its place among Surface's, or -1
  const meshsimp::Surface Surface;
};

namespace
{
/// The deviation's measurements, one stage each; see the top of Deviation.h. A measure by walks
/// is an upper bound of the distance; an exact one searches a grid of the whole surface.
class DeviationStages
{
public:
  DeviationStages(const DeviationInput::Data& input, const SimplifiedMesh& output)
    : Output(output)
    , Usable(input.Usable)
    , In(input.Surface)
    , Out(OutputPoints(output), output.Triangles)
    , Own(output.NumberOfPoints(), 0.0)
    , OwnNearest(output.NumberOfPoints(), -1)
    , Inside(output.NumberOfTriangles(), 0.0)
    , Stood(In.Points.size(), 0.0)
    , Values(output.NumberOfPoints(), 0.0)
  {
    this->GatherUnlisted();
  }

  /// Output point p to the input, from the input triangles around the points it stands for.
  void MeasureOwn(std::int64_t p, bool exact)
  {
    const Vec3& x = this->Out.Points[p];
    Nearest near;
    for (std::int32_t s = this->Output.SourceOffsets[p]; s < this->Output.SourceOffsets[p + 1] && !exact; ++s)
    {
      this->In.AroundPoint(x, this->Output.SourcePoints[s], near);
    }
    this->Settle(this->In, x, near, exact);
    this->OwnNearest[p] = near.Triangle;
    this->Own[p] = near.Triangle < 0 ? 0.0 : near.Distance;
  }

  /// The inside of output triangle t to the input: its centre and its edges' middles (it can
  /// stand off the input where its corners do not: across a hole, a handle), from the input
  /// triangle it comes from and its corners' nearest.
  void MeasureInside(std::int32_t t, bool exact)
  {
    const Vec3 c[3] = { this->Out.Corner(t, 0), this->Out.Corner(t, 1), this->Out.Corner(t, 2) };
    const Vec3 samples[4] = { (c[0] + c[1] + c[2]) / 3.0, 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0]) };
    const std::int32_t source = this->Usable[this->Output.TriangleSource[t]];
    double largest = 0.0;
    for (const Vec3& z : samples)
    {
      Nearest near;
      for (int k = 0; k < 3 && !exact; ++k)
      {
        const std::int32_t from = this->OwnNearest[this->Out.Corners[3 * static_cast<std::size_t>(t) + k]];
        if (from >= 0)
        {
          near.Offer(this->In.Distance(z, from), from);
        }
      }
      if (source >= 0 && !exact)
      {
        near.Offer(this->In.Distance(z, source), source);
      }
      this->Settle(this->In, z, near, exact);
      largest = std::max(largest, near.Triangle < 0 ? 0.0 : near.Distance);
    }
    this->Inside[t] = largest;
  }

  /// The input points p stands for to the output, from p's triangles.
  void MeasureStood(std::int64_t p, bool exact)
  {
    for (std::int32_t s = this->Output.SourceOffsets[p]; s < this->Output.SourceOffsets[p + 1]; ++s)
    {
      const std::int32_t i = this->Output.SourcePoints[s];
      const Vec3& y = this->In.Points[i];
      Nearest near;
      if (!exact)
      {
        this->Out.AroundPoint(y, p, near);
      }
      this->Settle(this->Out, y, near, exact);
      this->Stood[i] = near.Triangle < 0 ? (y - this->Out.Points[p]).norm() : near.Distance;
    }
  }

  /// p's value: the largest of its own, its triangles' insides and its input points'.
  void Gather(std::int64_t p)
  {
    double largest = this->Own[p];
    for (const std::int32_t* t = this->Out.Around.Begin(p); t != this->Out.Around.End(p); ++t)
    {
      largest = std::max(largest, this->Inside[*t]);
    }
    for (std::int32_t s = this->Output.SourceOffsets[p]; s < this->Output.SourceOffsets[p + 1]; ++s)
    {
      largest = std::max(largest, this->Stood[this->Output.SourcePoints[s]]);
    }
    this->Values[p] = largest;
  }

  /// p measured exactly: its own, its triangles' insides and its input points.
  void Settle(std::int64_t p)
  {
    this->MeasureOwn(p, true);
    for (const std::int32_t* t = this->Out.Around.Begin(p); t != this->Out.Around.End(p); ++t)
    {
      this->MeasureInside(*t, true);
    }
    this->MeasureStood(p, true);
    this->Gather(p);
  }

  /// The unlisted input points: exactly, concurrently, each counted at the output point nearest
  /// to where it lands.
  void MeasureUnlisted(const ExecutionContext& context)
  {
    if (this->Out.NumberOfTriangles() == 0)
    {
      return;
    }
    std::vector<std::pair<double, std::int32_t>> landed(this->Unlisted.size());
    context.For(static_cast<std::int64_t>(this->Unlisted.size()), [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t d = begin; d < end; ++d)
      {
        const Vec3& y = this->In.Points[this->Unlisted[d]];
        const Nearest near = this->Out.Exact(y);
        std::int32_t corner = this->Out.Corners[3 * static_cast<std::size_t>(near.Triangle)];
        for (int k = 1; k < 3; ++k)
        {
          const std::int32_t q = this->Out.Corners[3 * static_cast<std::size_t>(near.Triangle) + k];
          corner = (this->Out.Points[q] - y).norm() < (this->Out.Points[corner] - y).norm() ? q : corner;
        }
        landed[d] = { near.Distance, corner };
      }
    }, 5000 * static_cast<std::int64_t>(this->Unlisted.size()));
    for (const auto& [distance, corner] : landed)
    {
      this->Values[corner] = std::max(this->Values[corner], distance);
    }
  }

  std::vector<double>& Result() { return this->Values; }
  const Stars& OutputStars() const { return this->Out.Around; }

private:
  /// A walk from near, or the exact nearest (also where near has no triangle to start from).
  void Settle(const Surface& surface, const Vec3& x, Nearest& near, bool exact) const
  {
    if (exact || near.Triangle < 0)
    {
      near = surface.NumberOfTriangles() > 0 ? surface.Exact(x) : Nearest();
      return;
    }
    surface.Walk(x, near);
  }

  /// The usable input points that no output point stands for (a part the algorithm dropped, a
  /// point the front end joined with another at its place).
  void GatherUnlisted()
  {
    std::vector<bool> listed(this->In.Points.size(), false);
    for (const std::int32_t source : this->Output.SourcePoints)
    {
      listed[source] = true;
    }
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(listed.size()); ++i)
    {
      if (!listed[i] && this->In.Around.Begin(i) != this->In.Around.End(i))
      {
        this->Unlisted.push_back(i);
      }
    }
  }

  const SimplifiedMesh& Output;
  std::vector<std::int32_t> Unlisted;
  const std::vector<std::int32_t>& Usable; // per input triangle, its place among In's, or -1
  const Surface& In;
  const Surface Out;
  std::vector<double> Own;
  std::vector<std::int32_t> OwnNearest;
  std::vector<double> Inside;
  std::vector<double> Stood; // per input point, to the output
  std::vector<double> Values;
};
} // namespace

double PointTriangleDistance(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // The closest point by the Voronoi regions of the corners, edges and face (as in Ericson,
  // "Real-Time Collision Detection", 5.1.5); a triangle without area is its three edges.
  const Vec3 ab = b - a, ac = c - a;
  if (ab.cross(ac).squaredNorm() <= 0.0)
  {
    return std::min({ SegmentDistance(x, a, b), SegmentDistance(x, b, c), SegmentDistance(x, c, a) });
  }
  const Vec3 ap = x - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return ap.norm();
  }
  const Vec3 bp = x - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return bp.norm();
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    return (x - (a + ab * (d1 / (d1 - d3)))).norm();
  }
  const Vec3 cp = x - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return cp.norm();
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    return (x - (a + ac * (d2 / (d2 - d6)))).norm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
  {
    return (x - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
  }
  if (!(va + vb + vc > 0.0))
  {
    return std::min({ SegmentDistance(x, a, b), SegmentDistance(x, b, c), SegmentDistance(x, c, a) });
  }
  const double scale = 1.0 / (va + vb + vc);
  return (x - (a + ab * (vb * scale) + ac * (vc * scale))).norm();
}

DeviationInput::DeviationInput(const TriangleMeshView& input)
  : Impl(new Data(input))
{
}

DeviationInput::~DeviationInput() = default;

std::vector<double> TwoSidedDeviation(
  const TriangleMeshView& input, const SimplifiedMesh& output, const ExecutionContext& context)
{
  return TwoSidedDeviation(DeviationInput(input), output, context);
}

std::vector<double> TwoSidedDeviation(
  const DeviationInput& input, const SimplifiedMesh& output, const ExecutionContext& context)
{
  DeviationStages stages(*input.Impl, output);
  const std::int64_t n = output.NumberOfPoints(), m = output.NumberOfTriangles();
  // 1. By walks, concurrently, in steps for the progress bar and Abort (80 % of it).
  struct Stage
  {
    std::int64_t Count;
    std::int64_t Work; // nanoseconds per item, about
    std::function<void(std::int64_t)> Run;
  };
  const std::int64_t perPoint = static_cast<std::int64_t>(input.Impl->Surface.Points.size()) / std::max<std::int64_t>(1, n) + 1;
  const Stage walks[] = { { n, 300 * perPoint, [&](std::int64_t p) { stages.MeasureOwn(p, false); } },
    { m, 1000, [&](std::int64_t t) { stages.MeasureInside(static_cast<std::int32_t>(t), false); } },
    { n, 300 * perPoint, [&](std::int64_t p) { stages.MeasureStood(p, false); } },
    { n, 100, [&](std::int64_t p) { stages.Gather(p); } } };
  constexpr std::int64_t Steps = 8;
  for (std::size_t w = 0; w < 4; ++w)
  {
    for (std::int64_t step = 0; step < Steps; ++step)
    {
      const std::int64_t first = walks[w].Count * step / Steps, last = walks[w].Count * (step + 1) / Steps;
      context.For(last - first, [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t i = first + begin; i < first + end; ++i)
        {
          walks[w].Run(i);
        }
      }, walks[w].Work * (last - first));
      if (!context.Report(0.8 * static_cast<double>(Steps * w + step + 1) / (4 * Steps)))
      {
        return {};
      }
    }
  }
  // 2. A walk may stop short where a surface folds back, and only overestimates: the largest
  // values are measured exactly, from the top, until the next cannot exceed the largest exact.
  std::vector<double>& values = stages.Result();
  std::vector<std::int64_t> order(n);
  std::iota(order.begin(), order.end(), std::int64_t(0));
  std::stable_sort(order.begin(), order.end(), [&values](std::int64_t a, std::int64_t b) { return values[a] > values[b]; });
  double settled = 0.0;
  for (std::size_t i = 0; i < order.size() && values[order[i]] > settled; ++i)
  {
    stages.Settle(order[i]);
    settled = std::max(settled, values[order[i]]);
  }
  if (!context.Report(0.9))
  {
    return {};
  }
  // 3. The input points that no output point stands for.
  stages.MeasureUnlisted(context);
  return context.Report(1.0) ? values : std::vector<double>();
}

} // namespace meshsimp
