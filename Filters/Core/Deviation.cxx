// SPDX-License-Identifier: BSD-3-Clause
#include "Deviation.h"
#include "SurfaceSearch.h"

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

/// Per triangle of a mesh, its place among those listed (-1: not listed).
std::vector<std::int32_t> Places(const std::vector<std::int32_t>& listed, std::int64_t triangles)
{
  std::vector<std::int32_t> place(static_cast<std::size_t>(triangles), -1);
  for (std::size_t s = 0; s < listed.size(); ++s)
  {
    place[listed[s]] = static_cast<std::int32_t>(s);
  }
  return place;
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
    : Data(input, std::vector<std::int32_t>())
  {
  }
  const meshsimp::Surface Surface;
  const std::vector<std::int32_t> Usable; // per input triangle, its place among Surface's, or -1

private:
  /// listed: the usable triangles' input ids, as UsableSurface gives them.
  Data(const TriangleMeshView& input, std::vector<std::int32_t>&& listed)
    : Surface(UsableSurface(input, listed))
    , Usable(Places(listed, input.NumberOfTriangles))
  {
  }
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
