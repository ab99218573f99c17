// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the appearance-preserving collapse core (AppearancePreservingCollapse.h) and
// the engine's vertex queue it runs on (VertexQueue.h).
#include "AppearancePreservingCollapse.h"
#include "TestHelpers.h"
#include "TestMeshes.h"

#include <iostream>
#include <map>
#include <set>

namespace
{
using meshsimp::AppearanceCollapseOptions;
using meshsimp::AppearanceCollapseResult;
using Eigen::Vector3d;

AppearanceCollapseResult Simplify(const Mesh& mesh, const AppearanceCollapseOptions& options)
{
  AppearanceCollapseResult result;
  CHECK(meshsimp::AppearancePreservingCollapse(mesh.View(), options, result));
  return result;
}

AppearanceCollapseOptions Reduction(double reduction)
{
  AppearanceCollapseOptions options;
  options.Goal.SetReduction(reduction);
  return options;
}

void CurveThroughHandComputedPoints()
{
  // A quarter circle's ends with their outward normals: T1 = n2, T2 = -n1 (eq. 7.7–7.8), the
  // chord's projections (0, 1, 0) and (-1, 0, 0), so f(t) = (-t²/2 - t/2 + 1, -t²/2 + 3t/2, 0)
  // by eq. 7.14: f(0.5) = (0.625, 0.625, 0), bulging out of the chord as the arc does.
  const Vector3d p1(1, 0, 0), p2(0, 1, 0);
  CHECK((meshsimp::CurvePoint(p1, p1, p2, p2, 0.0) - p1).norm() < 1e-15);
  CHECK((meshsimp::CurvePoint(p1, p1, p2, p2, 1.0) - p2).norm() < 1e-15);
  CHECK((meshsimp::CurvePoint(p1, p1, p2, p2, 0.5) - Vector3d(0.625, 0.625, 0)).norm() < 1e-15);
  CHECK((meshsimp::CurvePoint(p1, p1, p2, p2, 0.25) - Vector3d(0.84375, 0.34375, 0)).norm() < 1e-15);
  // The same curve from the other end: t goes to 1 - t.
  CHECK((meshsimp::CurvePoint(p2, p2, p1, p1, 0.75) - Vector3d(0.84375, 0.34375, 0)).norm() < 1e-15);
  // Parallel or opposite normals: no tangent, the chord.
  const Vector3d up(0, 0, 1);
  CHECK((meshsimp::CurvePoint(p1, up, p2, up, 0.3) - (0.7 * p1 + 0.3 * p2)).norm() < 1e-15);
  CHECK((meshsimp::CurvePoint(p1, up, p2, -up, 0.3) - (0.7 * p1 + 0.3 * p2)).norm() < 1e-15);
}

void MeetsCountsAndStaysClosed()
{
  // In both orders, with and without the vertex memory.
  const Mesh sphere = Sphere(12);
  const std::int64_t input = static_cast<std::int64_t>(sphere.Triangles.size() / 3);
  for (const int variant : { 0, 1, 2, 3, 4, 5 })
  {
    const double reduction = variant % 3 == 0 ? 0.5 : variant % 3 == 1 ? 0.9 : 0.98;
    AppearanceCollapseOptions options = Reduction(reduction);
    options.Order = variant < 3 ? meshsimp::AppearanceOrder::Quadric : meshsimp::AppearanceOrder::NormalSpread;
    options.VertexMemory = variant % 2 == 1;
    const AppearanceCollapseResult result = Simplify(sphere, options);
    const double target = std::round(input * (1 - reduction));
    CHECK(std::abs(result.NumberOfTriangles() - target) <= 0.01 * target + 1);
    CHECK(result.Report.Stop == meshsimp::StopReason::TargetMet);
    CHECK(ClosedOriented(result.Triangles));
    const std::vector<double>* importance = result.PointArray("Importance");
    CHECK(importance && static_cast<std::int64_t>(importance->size()) == result.NumberOfPoints());
  }
}

void CubeKeepsCornersAndCreases()
{
  // The cube's corners are extreme and stay; its creases lose points only along their line (an
  // extreme vertex goes only along a sharp edge, onto its extreme neighbour), and faces stay
  // flat: every output point is on the cube's surface, no point leaves a crease.
  const Mesh cube = Cube(8);
  const AppearanceCollapseResult result = Simplify(cube, Reduction(0.9));
  std::set<std::array<double, 3>> points;
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    const double* x = result.Points.data() + 3 * p;
    points.insert({ x[0], x[1], x[2] });
    int onFace = 0;
    for (int k = 0; k < 3; ++k)
    {
      CHECK(x[k] >= -1e-12 && x[k] <= 1 + 1e-12);
      onFace += std::abs(x[k]) < 1e-12 || std::abs(x[k] - 1) < 1e-12 ? 1 : 0;
    }
    CHECK(onFace >= 1);
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    CHECK(points.count({ double(corner & 1), double((corner >> 1) & 1), double((corner >> 2) & 1) }) == 1);
  }
  CHECK(ClosedOriented(result.Triangles));
}

/// The mean and the largest distance of the points to the sphere of radius 1/2 around
/// (1/2, 1/2, 1/2), signed (negative inside).
std::pair<double, double> OffSphere(const AppearanceCollapseResult& result)
{
  double sum = 0.0, largest = 0.0;
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    const double off = (Vector3d(result.Points.data() + 3 * p) - Vector3d::Constant(0.5)).norm() - 0.5;
    sum += off;
    largest = std::max(largest, std::abs(off));
  }
  return { sum / static_cast<double>(std::max<std::int64_t>(1, result.NumberOfPoints())), largest };
}

void NewPointsStayOnTheSurface()
{
  // On a sphere at 90 %: the chapter's curve points lie on the sphere, not inside it as the
  // chords' midpoints would (on average within a twentieth of the sagitta of the output's mean
  // edge, at most within the sagitta); the quadric order's least-error points lie outside, by
  // less than the sagitta, so that its triangles straddle the sphere.
  const Mesh sphere = Sphere(16);
  for (const auto order : { meshsimp::AppearanceOrder::Quadric, meshsimp::AppearanceOrder::NormalSpread })
  {
    AppearanceCollapseOptions options = Reduction(0.9);
    options.Order = order;
    const AppearanceCollapseResult result = Simplify(sphere, options);
    // About 2 N triangles of mean edge e cover the sphere: (√3/4) e² · 2 N = π, sagitta e² / 4.
    const double edge2 = 4.0 * 3.14159265358979 / (std::sqrt(3.0) * static_cast<double>(result.NumberOfTriangles()));
    const double sagitta = edge2 / 4.0;
    const std::pair<double, double> off = OffSphere(result);
    if (order == meshsimp::AppearanceOrder::NormalSpread)
    {
      CHECK(std::abs(off.first) < 0.05 * sagitta && off.second < sagitta);
    }
    else
    {
      CHECK(off.first > 0.0 && off.first < sagitta);
    }
  }
}

/// The root mean square of the signed distances to the sphere of radius 1/2 around (1/2, 1/2,
/// 1/2) over the triangles (their corners, edge middles and centres), with the points as they
/// are or moved onto the sphere.
double RmsOffSphere(const AppearanceCollapseResult& result, bool projected)
{
  const Vector3d centre = Vector3d::Constant(0.5);
  const auto point = [&](std::int32_t p) {
    const Vector3d x(result.Points.data() + 3 * static_cast<std::int64_t>(p));
    return projected ? Vector3d(centre + 0.5 * (x - centre).normalized()) : x;
  };
  double sum = 0.0;
  std::int64_t samples = 0;
  for (std::int64_t t = 0; t < result.NumberOfTriangles(); ++t)
  {
    const std::int32_t* tri = result.Triangles.data() + 3 * t;
    const Vector3d a = point(tri[0]), b = point(tri[1]), c = point(tri[2]);
    for (const Vector3d& x : { a, b, c, Vector3d(0.5 * (a + b)), Vector3d(0.5 * (b + c)), Vector3d(0.5 * (c + a)),
           Vector3d((a + b + c) / 3.0) })
    {
      const double off = (x - centre).norm() - 0.5;
      sum += off * off;
      ++samples;
    }
  }
  return std::sqrt(sum / static_cast<double>(std::max<std::int64_t>(1, samples)));
}

void PointsSettleAcrossTheSurface()
{
  // A sphere coloured by octants at 90 %: the colour's borders hold the points, whose triangles
  // would cut under the sphere; moved out along their normals at the end, the triangles straddle
  // it and lie nearer to it than with their points on it.
  const Mesh sphere = Sphere(16);
  std::vector<double> colour(sphere.Points.size() / 3);
  for (std::size_t v = 0; v < colour.size(); ++v)
  {
    int side = 0;
    for (int k = 0; k < 3; ++k)
    {
      side += sphere.Points[3 * v + k] < 0.5 ? 1 : 0;
    }
    colour[v] = side % 2;
  }
  AppearanceCollapseOptions options = Reduction(0.9);
  options.AttributeCoordinates = colour.data();
  options.AttributeDimension = 1;
  const AppearanceCollapseResult result = Simplify(sphere, options);
  CHECK(OffSphere(result).first > 0.0);
  CHECK(RmsOffSphere(result, false) < 0.8 * RmsOffSphere(result, true));
}

/// Per output point, the attribute its sources blend to (values: one per input point).
std::vector<double> Blended(const AppearanceCollapseResult& result, const std::vector<double>& values)
{
  std::vector<double> blended(static_cast<std::size_t>(result.NumberOfPoints()), 0.0);
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    for (std::int32_t s = result.SourceOffsets[p]; s < result.SourceOffsets[p + 1]; ++s)
    {
      blended[p] += result.SourceWeights[s] * values[result.SourcePoints[s]];
    }
  }
  return blended;
}

void TwoColoursKeepTheirBorder()
{
  // A bumpy grid coloured 0 left of x = 0.5 and 1 right of it: with the colour in the order, fewer
  // output points carry a blend of the two than with the geometry alone, and the colour's
  // border keeps points on it.
  Mesh grid = Grid(40);
  std::vector<double> colour(grid.Points.size() / 3);
  for (std::size_t v = 0; v < colour.size(); ++v)
  {
    grid.Points[3 * v + 2] = 0.02 * std::sin(11.0 * grid.Points[3 * v]) * std::sin(13.0 * grid.Points[3 * v + 1]);
    colour[v] = grid.Points[3 * v] < 0.5 ? 0.0 : 1.0;
  }
  std::int64_t mixed[2] = { 0, 0 };
  for (const int weighted : { 0, 1 })
  {
    AppearanceCollapseOptions options = Reduction(0.95);
    options.AttributeCoordinates = colour.data();
    options.AttributeDimension = 1;
    options.AttributeWeight = weighted;
    const AppearanceCollapseResult result = Simplify(grid, options);
    for (const double value : Blended(result, colour))
    {
      mixed[weighted] += value > 0.05 && value < 0.95 ? 1 : 0;
    }
  }
  CHECK(mixed[1] < mixed[0]);
}

void SliverKeepsTheFieldsFinite()
{
  // A bumpy grid with one triangle split at a point on its edge's middle, lifted a millionth of a
  // millionth or not at all: a sliver that fixes no gradient. Its field is constant, and no
  // error turns into NaN (which scored every contraction at its corners 0, so that one point
  // swallowed its surroundings: 140 input points in one output point).
  for (const double lift : { 1e-12, 0.0 })
  {
    Mesh grid;
    const int n = 40;
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        grid.Points.insert(grid.Points.end(),
          { double(i) / n, double(j) / n, 0.05 * std::sin(6.0 * i / n) * std::cos(5.0 * j / n) });
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
        if (i == n / 2 && j == n / 2)
        {
          const std::int32_t p = static_cast<std::int32_t>(grid.Points.size() / 3);
          for (int k = 0; k < 3; ++k)
          {
            grid.Points.push_back(0.5 * (grid.Points[3 * a + k] + grid.Points[3 * b + k]) + (k == 1 ? lift : 0.0));
          }
          grid.Triangles.insert(grid.Triangles.end(), { a, b, p, a, p, d, p, b, d, a, d, c });
        }
        else
        {
          grid.Triangles.insert(grid.Triangles.end(), { a, b, d, a, d, c });
        }
      }
    }
    std::vector<double> values;
    for (std::size_t v = 0; v < grid.Points.size(); v += 3)
    {
      values.insert(values.end(), { grid.Points[v], 0.5, grid.Points[v + 1] > 0.5 ? 1.0 : 0.0 });
    }
    AppearanceCollapseOptions options = Reduction(0.5);
    options.AttributeCoordinates = values.data();
    options.AttributeDimension = 3;
    const AppearanceCollapseResult result = Simplify(grid, options);
    std::int32_t largest = 0;
    for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
    {
      largest = std::max(largest, result.SourceOffsets[p + 1] - result.SourceOffsets[p]);
    }
    CHECK(largest < 20);
  }
}

/// The cut's points (x = 0.5) of SeamsStayClosed's grid pair up, and each sheet's edges along
/// the cut are the other's: no crack; fewer than half of the seam's points are left, and the
/// count is met (below a fifth of the input's triangles).
void CheckSeamClosed(const AppearanceCollapseResult& result, std::size_t seamPoints, std::size_t inputTriangles)
{
  // The cut's points pair up, and each sheet's edges along the cut are the other's: no crack.
  using Position = std::array<double, 3>;
  std::map<Position, int> seen;
  std::set<std::pair<Position, Position>> sides[2];
  for (std::int64_t t = 0; t < result.NumberOfTriangles(); ++t)
  {
    const std::int32_t* tri = result.Triangles.data() + 3 * t;
    Position x[3];
    double centre = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double* p = result.Points.data() + 3 * static_cast<std::int64_t>(tri[k]);
      x[k] = { p[0], p[1], p[2] };
      centre += p[0] / 3.0;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (x[k][0] == 0.5 && x[(k + 1) % 3][0] == 0.5)
      {
        sides[centre > 0.5 ? 1 : 0].insert(std::minmax(x[k], x[(k + 1) % 3]));
      }
    }
  }
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    const double* x = result.Points.data() + 3 * p;
    if (x[0] == 0.5)
    {
      ++seen[{ x[0], x[1], x[2] }];
    }
  }
  for (const auto& pair : seen)
  {
    CHECK(pair.second == 2);
  }
  CHECK(!sides[0].empty() && sides[0] == sides[1]);
  // The seam's points slide along it as the others go: fewer than half of them are left.
  CHECK(2 * seen.size() < seamPoints);
  CHECK(result.NumberOfTriangles() < static_cast<std::int64_t>(inputTriangles) / 5);
}


void SeamsStayClosed()
{
  // A grid cut along x = 0.5 into two sheets with their own copies of the cut's points (a
  // texture seam: the copies' data differ, so they are not joined). The copies go in twins,
  // along the cut, so the sheets still meet.
  Mesh grid = Grid(20);
  const std::int32_t n = static_cast<std::int32_t>(grid.Points.size() / 3);
  std::map<std::int32_t, std::int32_t> copy;
  for (std::size_t t = 0; t < grid.Triangles.size(); t += 3)
  {
    double centre = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      centre += grid.Points[3 * grid.Triangles[t + k]] / 3.0;
    }
    for (int k = 0; k < 3 && centre > 0.5; ++k)
    {
      const std::int32_t v = grid.Triangles[t + k];
      if (grid.Points[3 * v] == 0.5)
      {
        const auto found = copy.emplace(v, n + static_cast<std::int32_t>(copy.size()));
        if (found.second)
        {
          grid.Points.insert(grid.Points.end(), grid.Points.begin() + 3 * v, grid.Points.begin() + 3 * v + 3);
        }
        grid.Triangles[t + k] = found.first->second;
      }
    }
  }
  for (const auto order : { meshsimp::AppearanceOrder::Quadric, meshsimp::AppearanceOrder::NormalSpread })
  {
    AppearanceCollapseOptions options = Reduction(0.9);
    options.Order = order;
    options.SamePointData = [](std::int64_t, std::int64_t) { return false; };
    CheckSeamClosed(Simplify(grid, options), copy.size(), grid.Triangles.size() / 3);
  }
}

void RelaxesTheNormalDeviation()
{
  // No normal may turn at all (MaximumNormalDeviation 0): before a count target the limit is
  // raised a step at a time, with a note, until the count is met; under a bound it is not.
  const Mesh sphere = Sphere(12);
  AppearanceCollapseOptions options = Reduction(0.9);
  options.MaximumNormalDeviation = 0.0;
  const AppearanceCollapseResult result = Simplify(sphere, options);
  const double target = std::round(0.1 * static_cast<double>(sphere.Triangles.size() / 3));
  CHECK(std::abs(result.NumberOfTriangles() - target) <= 0.01 * target + 1);
  CHECK(result.Report.Notes.size() == 1 && result.Report.Notes[0].find("MaximumNormalDeviation was raised") == 0);
  options.Goal.SetMaximumError(0.05, true);
  CHECK(Simplify(sphere, options).Report.Notes.empty());
}

void MemoryMakesPasses()
{
  // With the vertex memory the queue is run in passes; without, in one.
  const Mesh sphere = Sphere(10);
  AppearanceCollapseOptions options = Reduction(0.8);
  options.VertexMemory = true;
  CHECK(Simplify(sphere, options).Passes > 1);
  options.VertexMemory = false;
  CHECK(Simplify(sphere, options).Passes == 1);
}

void KeepsErrorBound()
{
  // Under a bound, every output point within it of its planes.
  const Mesh sphere = Sphere(12);
  AppearanceCollapseOptions options;
  options.Goal.SetMaximumError(0.01, true);
  const AppearanceCollapseResult result = Simplify(sphere, options);
  const std::vector<double>* distance = result.PointArray("PlaneDistance");
  CHECK(distance && !distance->empty());
  for (std::size_t i = 0; distance && i < distance->size(); ++i)
  {
    CHECK((*distance)[i] <= 0.01 * result.Report.Diagonal * (1 + 1e-9));
  }
  CHECK(result.NumberOfTriangles() < static_cast<std::int64_t>(sphere.Triangles.size() / 3));
}

void ReportsProgressAndAborts()
{
  const Mesh sphere = Sphere(12);
  std::vector<double> reported;
  meshsimp::ExecutionContext context;
  context.Progress = [&](double progress) {
    reported.push_back(progress);
    return true;
  };
  AppearanceCollapseResult result;
  CHECK(meshsimp::AppearancePreservingCollapse(sphere.View(), Reduction(0.9), result, context));
  CHECK(reported.size() >= 3 && reported.back() == 1.0 && std::is_sorted(reported.begin(), reported.end()));
  context.Progress = [](double progress) { return progress < 0.5; };
  CHECK(!meshsimp::AppearancePreservingCollapse(sphere.View(), Reduction(0.9), result, context));
  CHECK(result.Report.Stop == meshsimp::StopReason::Aborted);
}

void SurvivesDamagedMeshes()
{
  // Damaged meshes (TestMeshes.h) under random options and locks: a valid output, the same with
  // one thread, two, and small chunks taken in turn; locked points stay, bit for bit; an
  // undamaged closed mesh stays closed; the count target is met unless the filter stopped early.
  std::mt19937 random(3);
  for (int run = 0; run < 80; ++run)
  {
    bool closed = false;
    const Mesh mesh = DamagedMesh(random, closed);
    const std::vector<std::uint8_t> locks = RandomLocks(random, mesh, meshsimp::SharedPointLock);
    AppearanceCollapseOptions options;
    RandomTargets(random, options, locks);
    options.VertexMemory = random() % 2 == 0;
    options.ExtremeAngle = 30.0 * (1 + random() % 4);
    const AppearanceCollapseResult result = SameOnAnyThreads<meshsimp::ExecutionContext, AppearanceCollapseResult>(
      [&](AppearanceCollapseResult& out, const meshsimp::ExecutionContext& context) {
        return meshsimp::AppearancePreservingCollapse(mesh.View(), options, out, context);
      });
    CheckCollapseRun(result, mesh, closed, locks, options.Goal.Bounded(), 0.01);
  }
}
}

int main()
{
  return meshsimp_test::RunTests({
    { "CurveThroughHandComputedPoints", CurveThroughHandComputedPoints },
    { "MeetsCountsAndStaysClosed", MeetsCountsAndStaysClosed },
    { "CubeKeepsCornersAndCreases", CubeKeepsCornersAndCreases },
    { "NewPointsStayOnTheSurface", NewPointsStayOnTheSurface },
    { "PointsSettleAcrossTheSurface", PointsSettleAcrossTheSurface },
    { "TwoColoursKeepTheirBorder", TwoColoursKeepTheirBorder },
    { "SliverKeepsTheFieldsFinite", SliverKeepsTheFieldsFinite },
    { "SeamsStayClosed", SeamsStayClosed },
    { "RelaxesTheNormalDeviation", RelaxesTheNormalDeviation },
    { "MemoryMakesPasses", MemoryMakesPasses },
    { "KeepsErrorBound", KeepsErrorBound },
    { "ReportsProgressAndAborts", ReportsProgressAndAborts },
    { "SurvivesDamagedMeshes", SurvivesDamagedMeshes },
  });
}
