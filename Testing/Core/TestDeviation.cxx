// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the two-sided deviation (Deviation.h): distances, both directions, the exact
// settling of walks that stop short, dropped parts, and thread independence.
#include "Deviation.h"
#include "SurfaceSearch.h"

#include "TestHelpers.h"
#include "TestMeshes.h"

#include <cmath>

using meshsimp::SimplifiedMesh;

namespace
{
/// An output made of mesh (input coordinates), each point standing for the input points owner
/// maps to it (representative: the first listed).
SimplifiedMesh Output(const Mesh& mesh, const std::vector<std::int32_t>& owner)
{
  SimplifiedMesh output;
  output.Points = mesh.Points;
  output.Triangles = mesh.Triangles;
  output.TriangleSource.assign(mesh.Triangles.size() / 3, 0);
  const std::int64_t n = static_cast<std::int64_t>(mesh.Points.size() / 3);
  output.SourceOffsets.assign(n + 1, 0);
  for (const std::int32_t p : owner)
  {
    if (p >= 0)
    {
      ++output.SourceOffsets[p + 1];
    }
  }
  for (std::int64_t p = 0; p < n; ++p)
  {
    output.SourceOffsets[p + 1] += output.SourceOffsets[p];
  }
  std::vector<std::int32_t> next(output.SourceOffsets.begin(), output.SourceOffsets.end() - 1);
  output.SourcePoints.resize(output.SourceOffsets.back());
  output.SourceWeights.assign(output.SourcePoints.size(), 0.0);
  for (std::size_t i = 0; i < owner.size(); ++i)
  {
    if (owner[i] >= 0)
    {
      output.SourcePoints[next[owner[i]]++] = static_cast<std::int32_t>(i);
    }
  }
  return output;
}

/// Each point of fine (an n × n grid, flat) to the nearest point of coarse (an m × m grid).
std::vector<std::int32_t> NearestOnCoarseGrid(const Mesh& fine, int m)
{
  std::vector<std::int32_t> owner(fine.Points.size() / 3);
  for (std::size_t i = 0; i < owner.size(); ++i)
  {
    const int x = static_cast<int>(std::lround(fine.Points[3 * i] * m));
    const int y = static_cast<int>(std::lround(fine.Points[3 * i + 1] * m));
    owner[i] = y * (m + 1) + x;
  }
  return owner;
}

double Largest(const std::vector<double>& values)
{
  double largest = 0.0;
  for (const double v : values)
  {
    largest = std::max(largest, v);
  }
  return largest;
}

void PointTriangleDistances()
{
  using V = Eigen::Vector3d;
  const V a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  CHECK(std::abs(meshsimp::PointTriangleDistance(V(0.2, 0.2, 0.5), a, b, c) - 0.5) < 1e-15); // over the inside
  CHECK(std::abs(meshsimp::PointTriangleDistance(V(-3, -4, 0), a, b, c) - 5.0) < 1e-15);     // beyond a corner
  CHECK(std::abs(meshsimp::PointTriangleDistance(V(0.5, -2, 0), a, b, c) - 2.0) < 1e-15);    // beyond an edge
  CHECK(std::abs(meshsimp::PointTriangleDistance(V(1, 1, 0), a, b, c) - std::sqrt(0.5)) < 1e-15);
  // Without area: the nearest of its edges.
  CHECK(std::abs(meshsimp::PointTriangleDistance(V(0.5, 1, 0), a, b, V(2, 0, 0)) - 1.0) < 1e-15);
}

void SeesTheFlattenedPeak()
{
  // A peak of height 0.3 in a 20 × 20 grid, simplified to a flat 4 × 4 grid: every output point
  // lies on the input (its own distance is 0), but the peak stands 0.3 off the output, at the
  // output point that stands for it: one-way distances miss it.
  Mesh input = Grid(20);
  const std::size_t peak = 10 * 21 + 10;
  input.Points[3 * peak + 2] = 0.3;
  const Mesh flat = Grid(4);
  const std::vector<std::int32_t> owner = NearestOnCoarseGrid(input, 4);
  const std::vector<double> values = meshsimp::TwoSidedDeviation(input.View(), Output(flat, owner), {});
  CHECK(values.size() == flat.Points.size() / 3);
  CHECK(std::abs(Largest(values) - 0.3) < 1e-12);
  CHECK(std::abs(values[owner[peak]] - 0.3) < 1e-12);
  CHECK(values[0] < 1e-12); // a corner far from the peak, on the input
}

void SettlesWalksThatStopShort()
{
  // A thin slab simplified to itself, but each bottom point said to stand for its top twin's
  // output point: walks start on the wrong side and stop there (0.01 off), the largest values
  // are measured exactly, and nothing shows more than the true distance, 0.
  const Mesh slab = Slab(8, 0.01);
  const std::int32_t n = static_cast<std::int32_t>(slab.Points.size() / 3);
  std::vector<std::int32_t> owner(n);
  for (std::int32_t i = 0; i < n; ++i)
  {
    owner[i] = i;
  }
  const std::int32_t top = 81; // Slab: the bottom grid's points first, then the top's
  for (std::int32_t i = 0; i < top; ++i)
  {
    owner[i] = top + i;
  }
  const std::vector<double> values = meshsimp::TwoSidedDeviation(slab.View(), Output(slab, owner), {});
  CHECK(Largest(values) < 1e-12);
}

void CountsDroppedParts()
{
  // Two squares 1 apart, and an output of the first only: the second's points, which no output
  // point stands for, are 1 away, counted at the output's nearest point.
  Mesh input = Grid(2);
  const std::int32_t base = static_cast<std::int32_t>(input.Points.size() / 3);
  const Mesh square = Grid(2);
  for (std::size_t i = 0; i < square.Points.size(); i += 3)
  {
    input.Points.insert(input.Points.end(), { square.Points[i], square.Points[i + 1], 1.0 });
  }
  for (const std::int32_t v : square.Triangles)
  {
    input.Triangles.push_back(base + v);
  }
  std::vector<std::int32_t> owner(2 * base, -1);
  for (std::int32_t i = 0; i < base; ++i)
  {
    owner[i] = i;
  }
  const std::vector<double> values = meshsimp::TwoSidedDeviation(input.View(), Output(square, owner), {});
  CHECK(std::abs(Largest(values) - 1.0) < 1e-12);
}

void MeasuresSoupsAsTheirJoinedMesh()
{
  // A soup (each triangle its own three points) of a grid with a peak, and an output that lists
  // one point of each place, as the front end does after joining them: the copies no output
  // point lists are measured too, and the peak is seen.
  Mesh grid = Grid(8);
  grid.Points[3 * (4 * 9 + 4) + 2] = 0.2;
  Mesh soup;
  for (const std::int32_t v : grid.Triangles)
  {
    soup.Points.insert(soup.Points.end(), grid.Points.begin() + 3 * v, grid.Points.begin() + 3 * v + 3);
    soup.Triangles.push_back(static_cast<std::int32_t>(soup.Triangles.size()));
  }
  std::vector<std::int32_t> owner(soup.Points.size() / 3, -1);
  std::vector<bool> seen(grid.Points.size() / 3, false);
  for (std::size_t c = 0; c < grid.Triangles.size(); ++c)
  {
    const std::int32_t v = grid.Triangles[c];
    if (!seen[v] && (v != 4 * 9 + 4 || c > 0))
    {
      seen[v] = true;
      const int x = static_cast<int>(std::lround(grid.Points[3 * v] * 2)), y = static_cast<int>(std::lround(grid.Points[3 * v + 1] * 2));
      owner[c] = y * 3 + x;
    }
  }
  const std::vector<double> values = meshsimp::TwoSidedDeviation(soup.View(), Output(Grid(2), owner), {});
  CHECK(std::abs(Largest(values) - 0.2) < 1e-12);
}

void SameForAnyThreadCount()
{
  Mesh input = Grid(30);
  for (std::size_t i = 0; i < input.Points.size(); i += 3)
  {
    input.Points[i + 2] = 0.05 * std::sin(9.0 * input.Points[i]) * std::cos(7.0 * input.Points[i + 1]);
  }
  const Mesh flat = Grid(5);
  const SimplifiedMesh output = Output(flat, NearestOnCoarseGrid(input, 5));
  const std::vector<double> one = meshsimp::TwoSidedDeviation(input.View(), output, {});
  for (const int threads : { 2, 3, 5 })
  {
    CHECK(meshsimp::TwoSidedDeviation(input.View(), output,
            meshsimp_test::Threaded<meshsimp::ExecutionContext>(threads)) == one);
  }
  CHECK(Largest(one) > 0.04);
}

void StopsWhenAborted()
{
  const Mesh grid = Grid(10);
  meshsimp::ExecutionContext context;
  context.Progress = [](double progress) { return progress < 0.5; };
  CHECK(meshsimp::TwoSidedDeviation(grid.View(), Output(grid, NearestOnCoarseGrid(grid, 10)), context).empty());
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "PointTriangleDistances", PointTriangleDistances },
    { "SeesTheFlattenedPeak", SeesTheFlattenedPeak },
    { "SettlesWalksThatStopShort", SettlesWalksThatStopShort },
    { "CountsDroppedParts", CountsDroppedParts },
    { "MeasuresSoupsAsTheirJoinedMesh", MeasuresSoupsAsTheirJoinedMesh },
    { "SameForAnyThreadCount", SameForAnyThreadCount },
    { "StopsWhenAborted", StopsWhenAborted },
  });
}
