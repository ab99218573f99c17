// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the parallel decimation core: bucketing, super-independent rounds, the result
// for any thread count, targets, features, boundaries and locks.
#include "CollapseMesh.h"
#include "ParallelDecimation.h"
#include "Quadric.h"
#include "TestHelpers.h"
#include "TestMeshes.h"

#include <random>
#include <set>

using meshsimp::DecimationVertexType;
using meshsimp::ParallelDecimationOptions;
using meshsimp::ParallelDecimationResult;

namespace
{
ParallelDecimationOptions Reduction(double reduction)
{
  ParallelDecimationOptions options;
  options.Goal.SetReduction(reduction);
  return options;
}

/// Whether the output is a non-empty closed, consistently oriented 2-manifold.
bool Closed(const ParallelDecimationResult& result)
{
  return !result.Triangles.empty() && ClosedOriented(result.Triangles);
}

double Area(const ParallelDecimationResult& r)
{
  double area = 0.0;
  for (std::size_t t = 0; t < r.Triangles.size(); t += 3)
  {
    const Eigen::Vector3d a(&r.Points[3 * r.Triangles[t]]);
    const Eigen::Vector3d b(&r.Points[3 * r.Triangles[t + 1]]);
    const Eigen::Vector3d c(&r.Points[3 * r.Triangles[t + 2]]);
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

/// Whether x is a corner of the unit cube.
bool IsCubeCorner(const double* x)
{
  return (x[0] == 0 || x[0] == 1) && (x[1] == 0 || x[1] == 1) && (x[2] == 0 || x[2] == 1);
}

bool WithinTwoPercent(const ParallelDecimationResult& result)
{
  const double count = static_cast<double>(result.Triangles.size() / 3);
  return std::abs(count - static_cast<double>(result.Report.TargetTriangles)) <=
    0.02 * static_cast<double>(result.Report.TargetTriangles) + 1.0;
}

void BucketFunction()
{
  const double a = 0.02, alpha = 0.8;
  CHECK(meshsimp::BucketPosition(0.0, a, alpha) == 0.0);
  CHECK(std::abs(meshsimp::BucketPosition(1.0, a, alpha) - 1.0) < 1e-12);
  CHECK(std::abs(meshsimp::BucketPosition(a, a, alpha) - alpha) < 1e-12); // eq. (5.8)
  double previous = -1.0;
  for (int i = 0; i <= 1000; ++i)
  {
    const double y = meshsimp::BucketPosition(i / 1000.0, a, alpha);
    CHECK(y > previous);
    previous = y;
  }
  // Without a bend (α <= a) the buckets are proportional.
  CHECK(meshsimp::BucketPosition(0.3, 0.5, 0.5) == 0.3);
}

void BucketOrderKeepsOrderWithinBucketWidth()
{
  // Importances spread over many scales: after the O(N) ordering a vertex of larger importance
  // comes first only when both share a bucket, and within a bucket vertex order is kept. Enough
  // vertices for several parts and coarse buckets of several fine ones each.
  std::mt19937 random(7);
  std::lognormal_distribution<double> spread(0.0, 3.0);
  const int n = 60000;
  std::vector<double> importance(n);
  std::vector<std::int32_t> vertices;
  double largest = 0.0;
  for (int v = 0; v < n; ++v)
  {
    importance[v] = spread(random);
    if (v % 3 != 0)
    {
      vertices.push_back(v);
      largest = std::max(largest, importance[v]);
    }
  }
  std::vector<std::int32_t> order, buckets;
  meshsimp::BucketOrder(importance.data(), vertices, largest, 0.02, 0.8, order, buckets);
  CHECK(order.size() == vertices.size());
  const int bucketCount = static_cast<int>(vertices.size());
  auto bucket = [&](int v) {
    return std::min(bucketCount - 1,
      static_cast<int>(meshsimp::BucketPosition(importance[v] / largest, 0.02, 0.8) * bucketCount));
  };
  for (std::size_t i = 1; i < order.size(); ++i)
  {
    const int p = order[i - 1], q = order[i];
    CHECK(bucket(p) <= bucket(q));
    if (bucket(p) == bucket(q))
    {
      CHECK(p < q);
    }
  }
  std::vector<std::int32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == vertices);
  CHECK(bucket(order.front()) == 0);
  CHECK(importance[order.back()] == largest);

  // The buckets found on three threads give the same order, whole or cut at a limit: the
  // whole buckets that hold the first `limit` vertices.
  std::vector<std::int32_t> threaded;
  meshsimp::BucketOrder(importance.data(), vertices, largest, 0.02, 0.8, threaded, buckets,
    static_cast<std::size_t>(-1), meshsimp_test::Threaded<meshsimp::ExecutionContext>(3));
  CHECK(threaded == order);
  for (const std::size_t limit : { std::size_t(1), std::size_t(100), std::size_t(4000), vertices.size() })
  {
    std::vector<std::int32_t> limited, serialLimited;
    meshsimp::BucketOrder(importance.data(), vertices, largest, 0.02, 0.8, serialLimited, buckets, limit);
    meshsimp::BucketOrder(importance.data(), vertices, largest, 0.02, 0.8, limited, buckets, limit,
      meshsimp_test::Threaded<meshsimp::ExecutionContext>(3));
    CHECK(limited == serialLimited && limited.size() >= limit);
    CHECK(std::equal(limited.begin(), limited.end(), order.begin()));
    CHECK(limited.size() == order.size() || bucket(order[limited.size()]) > bucket(limited.back()));
    CHECK(limit == vertices.size() || limited.size() < order.size());
  }
}

void RoundsAreSuperIndependent()
{
  // In every round no vertex within one edge of a taken vertex is within one edge of another
  // taken one, so their triangles share no edge (Fig. 5-6).
  const Mesh sphere = Sphere(16);
  for (const auto measure : { meshsimp::ImportanceMeasure::Quadric, meshsimp::ImportanceMeasure::AveragePlane })
  {
    ParallelDecimationOptions options = Reduction(0.9);
    options.Measure = measure;
    int rounds = 0, taken = 0;
    options.RoundObserver = [&](const meshsimp::CollapseMesh& mesh, const std::vector<std::int32_t>& chosen) {
      ++rounds;
      taken += static_cast<int>(chosen.size());
      std::vector<int> owner(mesh.NumberOfPoints(), -1);
      std::vector<std::int32_t> around;
      for (std::size_t i = 0; i < chosen.size(); ++i)
      {
        mesh.Neighbours(chosen[i], around);
        around.push_back(chosen[i]);
        for (const std::int32_t w : around)
        {
          CHECK(owner[w] < 0);
          owner[w] = static_cast<int>(i);
        }
      }
    };
    ParallelDecimationResult result;
    CHECK(meshsimp::ParallelDecimation(sphere.View(), options, result));
    CHECK(rounds > 3);
    CHECK(taken > 1000);
    CHECK(WithinTwoPercent(result));
    CHECK(Closed(result));
  }
}

void HugeAndTinyCoordinates()
{
  // Coordinates whose squares overflow (2^600 ≈ 4e180) or underflow (2^-600), and coordinates
  // up to ±2^1023 ≈ ±9e307, whose box diagonal exceeds the largest double, with and without a
  // relative error bound: the mesh is scaled by a power of two, which keeps every rounding, so
  // the result is the unscaled one's, scaled exactly (importance beyond the largest double is
  // infinite).
  const Mesh sphere = Scaled(Sphere(12), 2.0, -0.5); // centred at the origin, radius 1
  for (const bool bound : { false, true })
  {
    ParallelDecimationOptions options = Reduction(0.8);
    if (bound)
    {
      options.Goal.SetMaximumError(0.01, true);
    }
    ParallelDecimationResult reference;
    CHECK(meshsimp::ParallelDecimation(sphere.View(), options, reference));
    CHECK(reference.MovedPoints > 0);
    for (const double factor : { std::ldexp(1.0, 600), std::ldexp(1.0, -600), std::ldexp(1.0, 1023) })
    {
      ParallelDecimationResult result;
      CHECK(meshsimp::ParallelDecimation(Scaled(sphere, factor).View(), options, result));
      CHECK(result.Triangles == reference.Triangles);
      CHECK(result.Points.size() == reference.Points.size());
      for (std::size_t i = 0; i < result.Points.size() && i < reference.Points.size(); ++i)
      {
        CHECK(result.Points[i] == reference.Points[i] * factor);
      }
      const std::vector<double>& importance = *result.PointArray("Importance");
      const std::vector<double>& referenceImportance = *reference.PointArray("Importance");
      for (std::size_t i = 0; i < importance.size() && i < referenceImportance.size(); ++i)
      {
        CHECK(importance[i] == (referenceImportance[i] < 0.0 ? -1.0 : referenceImportance[i] * factor * factor));
      }
      CHECK(!bound || result.Report.MaximumError == reference.Report.MaximumError * factor);
    }
  }
}

void SameResultForAnyThreadCount()
{
  const Mesh sphere = Sphere(16);
  const Mesh grid = Grid(24);
  for (const Mesh* mesh : { &sphere, &grid })
  {
    for (const auto choice : { meshsimp::HalfEdgeChoice::LeastAreaChange, meshsimp::HalfEdgeChoice::ShortestEdge })
    {
      ParallelDecimationOptions options = Reduction(0.8);
      options.Measure = meshsimp::ImportanceMeasure::AveragePlane;
      options.Choice = choice;
      ParallelDecimationResult serial;
      CHECK(meshsimp::ParallelDecimation(mesh->View(), options, serial));
      CHECK(!serial.Triangles.empty());
      for (const int threads : { 2, 4 })
      {
        ParallelDecimationResult other;
        CHECK(meshsimp::ParallelDecimation(mesh->View(), options, other, meshsimp_test::Threaded<meshsimp::ExecutionContext>(threads)));
        CHECK(serial.Points == other.Points);
        CHECK(serial.Triangles == other.Triangles);
        CHECK(*serial.PointArray("Importance") == *other.PointArray("Importance"));
      }
    }
    ParallelDecimationResult serial, threaded, chunked, parts;
    CHECK(meshsimp::ParallelDecimation(mesh->View(), Reduction(0.8), serial));
    CHECK(meshsimp::ParallelDecimation(mesh->View(), Reduction(0.8), threaded, meshsimp_test::Threaded<meshsimp::ExecutionContext>(3)));
    CHECK(serial.Triangles == threaded.Triangles);
    // Small chunks taken in turn (each thread's workspace found by its index), and a context
    // that cannot tell the index (one part per thread).
    CHECK(meshsimp::ParallelDecimation(mesh->View(), Reduction(0.8), chunked, meshsimp_test::Chunked<meshsimp::ExecutionContext>(2, 7)));
    CHECK(serial.Points == chunked.Points && serial.Triangles == chunked.Triangles);
    meshsimp::ExecutionContext noIndex = meshsimp_test::Threaded<meshsimp::ExecutionContext>(3);
    noIndex.Worker = nullptr;
    CHECK(meshsimp::ParallelDecimation(mesh->View(), Reduction(0.8), parts, noIndex));
    CHECK(serial.Points == parts.Points && serial.Triangles == parts.Triangles);
  }
  // A mesh large enough for the set-up, the sorting of a round's set and the compaction of the
  // adjacency to run in several parts: still the serial result.
  const Mesh large = Sphere(84);
  ParallelDecimationResult serial;
  CHECK(meshsimp::ParallelDecimation(large.View(), Reduction(0.9), serial));
  for (const int threads : { 2, 3 })
  {
    ParallelDecimationResult other;
    const auto context = meshsimp_test::Threaded<meshsimp::ExecutionContext>(threads);
    CHECK(meshsimp::ParallelDecimation(large.View(), Reduction(0.9), other, context));
    CHECK(serial.Points == other.Points && serial.Triangles == other.Triangles);
    CHECK(*serial.PointArray("Importance") == *other.PointArray("Importance"));
  }
}

void TargetsAndInputPoints()
{
  // Counts within ±2 % from 0.5 to 0.98; without MoveSurvivors, survivors keep their input
  // coordinates bit for bit.
  const Mesh sphere = Sphere(16);
  for (const double reduction : { 0.5, 0.7, 0.9, 0.95, 0.98 })
  {
    ParallelDecimationResult result;
    ParallelDecimationOptions options = Reduction(reduction);
    options.MoveSurvivors = false;
    CHECK(meshsimp::ParallelDecimation(sphere.View(), options, result));
    CHECK(result.MovedPoints == 0);
    CHECK(WithinTwoPercent(result));
    CHECK(Closed(result));
    CHECK(!StoppedEarly(result));
    const std::vector<std::int32_t> survivors = Survivors(result);
    for (std::size_t p = 0; p < survivors.size(); ++p)
    {
      for (int k = 0; k < 3; ++k)
      {
        CHECK(result.Points[3 * p + k] == sphere.Points[3 * survivors[p] + k]);
      }
    }
  }
  ParallelDecimationOptions count;
  count.Goal.SetTriangleCount(500);
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(sphere.View(), count, result));
  CHECK(result.Report.TargetTriangles == 500);
  CHECK(WithinTwoPercent(result));
}

void MendsOrientationAndDuplicates()
{
  // Turned-over and repeated triangles are mended before the rounds: the sphere reaches 90 %
  // and stays closed and consistently oriented.
  const Mesh sphere = Misoriented(Sphere(16));
  ParallelDecimationOptions options;
  options.Goal.SetTriangleCount(307);
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(sphere.View(), options, result));
  CHECK(WithinTwoPercent(result));
  CHECK(Closed(result));
}

void ClosesCracks()
{
  // Points split off a closed sphere (zero-width cracks) rejoin before the rounds: the output is
  // the unsplit sphere's, closed.
  const Mesh sphere = Sphere(16);
  std::int64_t copies = 0;
  const Mesh split = SplitOffEvery(sphere, 13, copies);
  ParallelDecimationOptions options;
  options.Goal.SetTriangleCount(307);
  ParallelDecimationResult result, whole;
  CHECK(meshsimp::ParallelDecimation(split.View(), options, result));
  CHECK(meshsimp::ParallelDecimation(sphere.View(), options, whole));
  CHECK(Closed(result) && result.Report.JoinedPoints == copies);
  CHECK(result.Points == whole.Points && result.Triangles == whole.Triangles);
}

void ErrorBoundKeepsBump()
{
  // A 20 × 20 grid (spacing 0.05) with its centre raised by 0.01 (a slope of 11°, no sharp
  // edge): with a bound of 0.001 the flat part and the straight borders simplify away (16
  // triangles left), the bump stays, whatever the thread count.
  Mesh grid = Grid(20);
  grid.Points[3 * (10 * 21 + 10) + 2] = 0.01;
  ParallelDecimationOptions options;
  options.Goal.SetMaximumError(0.001, false);
  ParallelDecimationResult result, threaded;
  CHECK(meshsimp::ParallelDecimation(grid.View(), options, result));
  CHECK(meshsimp::ParallelDecimation(grid.View(), options, threaded, meshsimp_test::Threaded<meshsimp::ExecutionContext>(2)));
  CHECK(result.Points == threaded.Points && result.Triangles == threaded.Triangles);
  CHECK(result.Report.Stop == meshsimp::StopReason::TargetMet && result.Relaxations == 0); // as far as the bound allows
  CHECK(result.Report.MaximumError <= 0.001);
  CHECK(result.Triangles.size() / 3 <= 20); // of 800
  double highest = 0.0;
  for (std::size_t p = 2; p < result.Points.size(); p += 3)
  {
    highest = std::max(highest, result.Points[p]);
  }
  CHECK(highest >= 0.009);
  // With 0.1 the bump goes too; without a bound only the square's two triangles are left. (A
  // vertex that cannot be removed once kept the rest of a small mesh out of every round: the
  // filter stopped at 30 triangles.)
  options.Goal.SetMaximumError(0.1, false);
  CHECK(meshsimp::ParallelDecimation(grid.View(), options, result));
  CHECK(result.Triangles.size() / 3 <= 4 && result.Report.MaximumError <= 0.1);
  options.Goal.SetTriangleCount(0);
  CHECK(meshsimp::ParallelDecimation(grid.View(), options, result));
  CHECK(result.Triangles.size() / 3 == 2);
}

void MovedSurvivorsFitTheSurface()
{
  // The sphere at 90 %: survivors moved to their quadrics' minimisers bring the output surface
  // nearer the input points (RMS of their distances) than survivors kept in place, with the same
  // triangles, every one still facing outwards.
  const Mesh sphere = Sphere(16);
  ParallelDecimationOptions options = Reduction(0.9);
  options.MoveSurvivors = false;
  ParallelDecimationResult kept, moved;
  CHECK(meshsimp::ParallelDecimation(sphere.View(), options, kept));
  options.MoveSurvivors = true;
  CHECK(meshsimp::ParallelDecimation(sphere.View(), options, moved));
  CHECK(moved.Triangles == kept.Triangles && moved.SourcePoints == kept.SourcePoints);
  CHECK(moved.MovedPoints > moved.NumberOfPoints() / 2);
  auto rms = [&](const ParallelDecimationResult& r) {
    double sum = 0.0;
    for (std::size_t i = 0; i < sphere.Points.size(); i += 3)
    {
      const double d = DistanceToSurface(Eigen::Vector3d(&sphere.Points[i]), r.Points, r.Triangles);
      sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(sphere.Points.size() / 3));
  };
  const double before = rms(kept), after = rms(moved);
  std::printf("sphere at 90 %%: RMS distance %.5f kept, %.5f moved\n", before, after);
  CHECK(after < 0.8 * before);
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (std::size_t t = 0; t < moved.Triangles.size(); t += 3)
  {
    const Eigen::Vector3d a(&moved.Points[3 * moved.Triangles[t]]);
    const Eigen::Vector3d b(&moved.Points[3 * moved.Triangles[t + 1]]);
    const Eigen::Vector3d c(&moved.Points[3 * moved.Triangles[t + 2]]);
    CHECK((b - a).cross(c - a).dot((a + b + c) / 3.0 - centre) > 0.0);
  }
}

void MovedSurvivorsStayOnFlatFaces()
{
  // A block like the benchmark's creased block: its top a cylindrical bump between ramps and a
  // chamfer, meeting at creases on grid lines, at 90 %. A survivor whose planes meet far away
  // moves within its reach along the directions they fix best (2e-5 off the input at most); a
  // straight move towards that point, clamped to the reach, left points 0.02 off the faces.
  Mesh block = Cube(24);
  for (std::size_t i = 0; i < block.Points.size(); i += 3)
  {
    const double x = block.Points[i], y = block.Points[i + 1];
    const double bump = std::sqrt(std::max(0.0, 1.0 - std::pow((x - 0.5) * 6.0, 2.0)));
    const double top = 1.0 + 0.4 * bump - 0.6 * std::max(y - 0.625, 0.0) + 0.15 * std::max(x - 2.0 / 3.0, 0.0);
    block.Points[i + 2] *= top;
  }
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(block.View(), Reduction(0.9), result));
  CHECK(result.MovedPoints > 0);
  double farthest = 0.0;
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    farthest = std::max(farthest, DistanceToSurface(Eigen::Vector3d(&result.Points[3 * p]), block.Points, block.Triangles));
  }
  std::printf("creased block at 90 %%: output points at most %.3g off the input\n", farthest);
  CHECK(farthest < 1e-3);
}

void QuadricStepStaysWithin()
{
  // MinimizeQuadricWithin: within the radius, and no worse than the straight move towards the
  // minimiser clamped to the radius; the minimiser itself when it lies within.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    meshsimp::Quadric q;
    for (int k = 0; k < 4; ++k)
    {
      const Eigen::Vector3d n = Eigen::Vector3d(uniform(random), uniform(random), uniform(random)).normalized();
      q += meshsimp::Quadric::FromPlane(n, uniform(random), k == 0 ? 10.0 : 0.1 * (1.0 + uniform(random)));
    }
    const Eigen::Vector3d x0(uniform(random), uniform(random), uniform(random));
    Eigen::Vector3d minimum;
    meshsimp::MinimizeQuadricNear(q, x0, minimum);
    const double radius = 0.5 * (minimum - x0).norm() * (1.0 + uniform(random));
    const Eigen::Vector3d x = meshsimp::MinimizeQuadricWithin(q, x0, radius);
    CHECK((x - x0).norm() <= radius * (1.0 + 1e-9));
    const double distance = (minimum - x0).norm();
    const Eigen::Vector3d straight = distance > radius ? Eigen::Vector3d(x0 + (minimum - x0) * (radius / distance)) : minimum;
    CHECK(q.Evaluate(x) <= q.Evaluate(straight) * (1.0 + 1e-9) + 1e-12);
    if (distance <= radius)
    {
      CHECK((x - minimum).norm() <= 1e-9 * (1.0 + distance));
    }
  }
  // A flat region's quadric: the planes of triangles of one tilted plane, summed (rounding makes
  // its two empty directions tiny but not zero). A point above the plane moves straight down
  // onto it, or the radius towards it, never sideways.
  for (int trial = 0; trial < 50; ++trial)
  {
    const Eigen::Vector3d n = Eigen::Vector3d(uniform(random), uniform(random), uniform(random)).normalized();
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
    meshsimp::Quadric q;
    for (int k = 0; k < 6; ++k)
    {
      const Eigen::Vector3d on = 3.0 * uniform(random) * u + 3.0 * uniform(random) * v;
      q += meshsimp::Quadric::FromPlane(n, -n.dot(on), 1.0 + 0.5 * uniform(random));
    }
    const Eigen::Vector3d x0 = uniform(random) * u + uniform(random) * v + 0.4 * n;
    for (const double radius : { 0.1, 1.0 })
    {
      const Eigen::Vector3d expected = x0 - std::min(radius, 0.4) * n;
      CHECK((meshsimp::MinimizeQuadricWithin(q, x0, radius) - expected).norm() < 1e-9);
    }
  }
}

void HighValenceVertex()
{
  // A closed double fan: two vertices of 10 000 triangles each, which every rim vertex
  // neighbours. The centres are hubs that the stars of a round may share (only them: the stars
  // share no edge, the paper's super-independence), so a round takes many rim vertices instead
  // of one (5 000 rounds before); the stars of the centres are matched by sorting, not by a
  // quadratic scan.
  const Mesh fan = Fan(10000, true);
  ParallelDecimationOptions options = Reduction(0.5);
  int largestRound = 0;
  bool independent = true;
  options.RoundObserver = [&](const meshsimp::CollapseMesh& mesh, const std::vector<std::int32_t>& chosen) {
    largestRound = std::max(largestRound, static_cast<int>(chosen.size()));
    std::set<std::pair<int, int>> edges;
    for (const std::int32_t v : chosen)
    {
      std::set<std::pair<int, int>> star;
      mesh.ForEachTriangle(v, [&](std::int32_t t) {
        const std::int32_t* tri = mesh.Triangle(t);
        for (int k = 0; k < 3; ++k)
        {
          star.insert({ std::min(tri[k], tri[(k + 1) % 3]), std::max(tri[k], tri[(k + 1) % 3]) });
        }
      });
      for (const auto& edge : star)
      {
        independent = independent && edges.insert(edge).second;
      }
    }
  };
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(fan.View(), options, result));
  CHECK(independent);
  CHECK(largestRound > 100);
  CHECK(result.Rounds < 100);
  CHECK(WithinTwoPercent(result));
  CHECK(Closed(result));
  CHECK(!StoppedEarly(result));
  options.RoundObserver = nullptr;
  ParallelDecimationResult threaded;
  CHECK(meshsimp::ParallelDecimation(fan.View(), options, threaded, meshsimp_test::Threaded<meshsimp::ExecutionContext>(2)));
  CHECK(threaded.Triangles == result.Triangles && threaded.Points == result.Points);
}

void CubeKeepsCornersAndEdges()
{
  // Corners (three sharp edges) stay; edge vertices go only along their edge, so the cube's
  // shape is exact: the area stays 6.
  const Mesh cube = Cube(8);
  for (const auto measure : { meshsimp::ImportanceMeasure::Quadric, meshsimp::ImportanceMeasure::AveragePlane })
  {
    ParallelDecimationOptions options = Reduction(0.9);
    options.Measure = measure;
    ParallelDecimationResult result;
    CHECK(meshsimp::ParallelDecimation(cube.View(), options, result));
    CHECK(WithinTwoPercent(result));
    CHECK(Closed(result));
    CHECK(std::abs(Area(result) - 6.0) < 1e-9);
    int corners = 0;
    for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
    {
      const double* x = &result.Points[3 * p];
      if (IsCubeCorner(x))
      {
        ++corners;
        CHECK((*result.PointArray("VertexType"))[p] == static_cast<double>(DecimationVertexType::Corner));
        CHECK((*result.PointArray("Importance"))[p] == -1.0);
      }
    }
    CHECK(corners == 8);
  }
}

void AnglesStayWhereRaisingThemFails()
{
  // A cube whose points are all locked but its corners: under the default angles nothing is
  // removable; raised to 180 degrees the corners would go, still far above the target, so the
  // angles are not raised and the cube keeps its corners and its area.
  const Mesh cube = Cube(4);
  std::vector<std::uint8_t> locks(cube.Points.size() / 3, 1);
  for (std::size_t v = 0; v < locks.size(); ++v)
  {
    locks[v] = IsCubeCorner(&cube.Points[3 * v]) ? 0 : 1;
  }
  ParallelDecimationOptions options = Reduction(0.9);
  options.LockedPoints = locks.data();
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(cube.View(), options, result));
  CHECK(result.Report.Stop == meshsimp::StopReason::NothingRemovable);
  CHECK(result.Relaxations == 0);
  CHECK(result.NumberOfTriangles() == static_cast<std::int64_t>(cube.Triangles.size() / 3));
  CHECK(std::abs(Area(result) - 6.0) < 1e-9);
  // The note gives the raised run's count and this output's, which differ (issue 45: "still
  // stopped at 218 triangles" read as this output's count).
  CHECK(result.Report.Notes.size() == 1 && result.Report.Notes[0].find("were left at their values") != std::string::npos &&
    result.Report.Notes[0].find(" reached only 176 triangles, where this output has " +
      std::to_string(result.NumberOfTriangles())) != std::string::npos);
  // What stops it, as the user knows the rules: the points the options lock, by kind.
  CHECK(result.Report.Reason.find(" are locked (all by the options)") != std::string::npos);
  // Where the raised angles reach the target within its tolerance (175 asked, 3 of slack), their
  // result stays.
  ParallelDecimationOptions count;
  count.Goal.SetTriangleCount(175);
  count.LockedPoints = locks.data();
  ParallelDecimationResult reached;
  CHECK(meshsimp::ParallelDecimation(cube.View(), count, reached));
  CHECK(reached.Relaxations > 0 && reached.NumberOfTriangles() == 176);
}

void BoundariesAndLocks()
{
  const Mesh grid = Grid(20);
  auto onBorder = [](const double* x) { return x[0] == 0 || x[0] == 1 || x[1] == 0 || x[1] == 1; };
  // Boundary vertices collapse only along the boundary: the square stays a square.
  ParallelDecimationResult free;
  CHECK(meshsimp::ParallelDecimation(grid.View(), Reduction(0.9), free));
  CHECK(WithinTwoPercent(free));
  CHECK(std::abs(Area(free) - 1.0) < 1e-9);
  // PreserveBoundary keeps every boundary point.
  ParallelDecimationOptions preserve = Reduction(0.8);
  preserve.PreserveBoundary = true;
  ParallelDecimationResult kept;
  CHECK(meshsimp::ParallelDecimation(grid.View(), preserve, kept));
  int border = 0;
  for (std::int64_t p = 0; p < kept.NumberOfPoints(); ++p)
  {
    border += onBorder(&kept.Points[3 * p]) ? 1 : 0;
  }
  CHECK(border == 80);
  // Locked points stay.
  std::vector<std::uint8_t> locks(grid.Points.size() / 3, 0);
  for (std::size_t v = 0; v < locks.size(); v += 7)
  {
    locks[v] = 1;
  }
  ParallelDecimationOptions locked = Reduction(0.8);
  locked.LockedPoints = locks.data();
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(grid.View(), locked, result));
  std::vector<bool> present(locks.size(), false);
  for (const std::int32_t source : Survivors(result))
  {
    present[source] = true;
  }
  for (std::size_t v = 0; v < locks.size(); ++v)
  {
    CHECK(!locks[v] || present[v]);
  }
  // Every point locked but every seventh: far above the target, and the reason counts the
  // locked points and names what refuses the others' collapses.
  std::fill(locks.begin(), locks.end(), 1);
  for (std::size_t v = 0; v < locks.size(); v += 7)
  {
    locks[v] = 0;
  }
  ParallelDecimationResult stuck;
  CHECK(meshsimp::ParallelDecimation(grid.View(), locked, stuck));
  CHECK(stuck.Report.Stop == meshsimp::StopReason::NothingRemovable);
  // 441 points, 63 of them free.
  CHECK(stuck.Report.Reason.find(" vertices left, 378 are locked (all by the options); of the others' ") !=
    std::string::npos);
}

void SimplifiesAlongHinges()
{
  // A book of three pages of 72 triangles each: with its 11 inner hinge points locked the filter
  // stopped at 39 triangles for 12; removing them along the hinge, it reaches the target (and
  // the ones before) and the pages stay flat and joined at their hinge.
  // A removal along a hinge of k pages takes k triangles, not two: counts are met within one
  // such removal (k - 1 triangles), with three pages and with eight.
  const auto decimate = [](const Mesh& mesh, std::int64_t target) {
    ParallelDecimationOptions options;
    options.Goal.SetTriangleCount(target);
    ParallelDecimationResult result;
    CHECK(meshsimp::ParallelDecimation(mesh.View(), options, result));
    return result;
  };
  for (const int pages : { 3, 8 })
  {
    for (const std::int64_t target : { 150, 101, 60, 41, 12 })
    {
      const ParallelDecimationResult result = decimate(Book(12, 3, pages), target * pages / 3);
      CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - target * pages / 3) <= pages - 1);
      CHECK(StaysInBook(result.Points, result.Triangles, 12, pages));
    }
  }
  // A closed hinge: the loop of three caps stays a complex down to a small count.
  for (const std::int64_t target : { 40, 16, 8 })
  {
    CHECK(IsComplex(decimate(DoubleBubble(16, 3), target).Triangles, 3));
  }
}

void ProgressAndAbort()
{
  const Mesh sphere = Sphere(12);
  meshsimp::ExecutionContext context;
  std::vector<double> reports;
  context.Progress = [&](double p) {
    reports.push_back(p);
    return true;
  };
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(sphere.View(), Reduction(0.9), result, context));
  CHECK(reports.size() >= 3);
  CHECK(std::is_sorted(reports.begin(), reports.end()));
  CHECK(reports.back() == 1.0);
  meshsimp::ExecutionContext abort;
  abort.Progress = [](double p) { return p < 0.01; };
  CHECK(!meshsimp::ParallelDecimation(sphere.View(), Reduction(0.9), result, abort));
}

void DegenerateInputs()
{
  // Nothing usable, a lone triangle, a target of zero: a result, no crash.
  Mesh empty;
  ParallelDecimationResult result;
  CHECK(meshsimp::ParallelDecimation(empty.View(), Reduction(0.5), result));
  CHECK(result.Triangles.empty());
  Mesh single;
  single.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  single.Triangles = { 0, 1, 2 };
  CHECK(meshsimp::ParallelDecimation(single.View(), Reduction(0.9), result));
  CHECK(result.Triangles.size() == 3); // every vertex is a corner of the boundary
  CHECK(StoppedEarly(result));
  const Mesh sphere = Sphere(6);
  CHECK(meshsimp::ParallelDecimation(sphere.View(), Reduction(1.0), result));
  CHECK(StoppedEarly(result));
  CHECK(Closed(result));
  CHECK(result.Triangles.size() / 3 >= 4);
}
void SurvivesDamagedMeshes()
{
  // Damaged meshes (TestMeshes.h) under random options and locks: a valid output, the same with
  // one thread, two, and small chunks taken in turn; locked points stay, bit for bit; an
  // undamaged closed mesh stays closed; the count target is met unless the filter stopped early.
  std::mt19937 random(3);
  for (int run = 0; run < 150; ++run)
  {
    bool closed = false;
    const Mesh mesh = DamagedMesh(random, closed);
    const std::vector<std::uint8_t> locks = RandomLocks(random, mesh, meshsimp::SharedPointLock);
    ParallelDecimationOptions options;
    RandomTargets(random, options, locks);
    options.Measure = random() % 2 == 0 ? meshsimp::ImportanceMeasure::Quadric : meshsimp::ImportanceMeasure::AveragePlane;
    options.Choice = random() % 2 == 0 ? meshsimp::HalfEdgeChoice::LeastAreaChange : meshsimp::HalfEdgeChoice::ShortestEdge;
    options.MoveSurvivors = random() % 2 == 0;
    options.FeatureAngle = random() % 4 == 0 ? 0.0 : 75.0;
    options.MaximumNormalDeviation = random() % 4 == 0 ? 0.0 : 90.0;
    options.RoundFraction = random() % 3 == 0 ? 1.0 : 0.1;
    const ParallelDecimationResult result =
      SameOnAnyThreads<meshsimp::ExecutionContext, ParallelDecimationResult>(
        [&](ParallelDecimationResult& out, const meshsimp::ExecutionContext& context) {
          return meshsimp::ParallelDecimation(mesh.View(), options, out, context);
        });
    CheckCollapseRun(result, mesh, closed, locks, options.Goal.Bounded(), 0.02);
  }
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "BucketFunction", BucketFunction },
    { "BucketOrderKeepsOrderWithinBucketWidth", BucketOrderKeepsOrderWithinBucketWidth },
    { "RoundsAreSuperIndependent", RoundsAreSuperIndependent },
    { "MendsOrientationAndDuplicates", MendsOrientationAndDuplicates },
    { "ClosesCracks", ClosesCracks },
    { "SameResultForAnyThreadCount", SameResultForAnyThreadCount },
    { "HugeAndTinyCoordinates", HugeAndTinyCoordinates },
    { "TargetsAndInputPoints", TargetsAndInputPoints },
    { "MovedSurvivorsFitTheSurface", MovedSurvivorsFitTheSurface },
    { "ErrorBoundKeepsBump", ErrorBoundKeepsBump },
    { "MovedSurvivorsStayOnFlatFaces", MovedSurvivorsStayOnFlatFaces },
    { "QuadricStepStaysWithin", QuadricStepStaysWithin },
    { "HighValenceVertex", HighValenceVertex },
    { "CubeKeepsCornersAndEdges", CubeKeepsCornersAndEdges },
    { "BoundariesAndLocks", BoundariesAndLocks },
    { "AnglesStayWhereRaisingThemFails", AnglesStayWhereRaisingThemFails },
    { "SimplifiesAlongHinges", SimplifiesAlongHinges },
    { "ProgressAndAbort", ProgressAndAbort },
    { "DegenerateInputs", DegenerateInputs },
    { "SurvivesDamagedMeshes", SurvivesDamagedMeshes },
  });
}
