// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the progressive mesh core (ProgressiveMesh.h): the sequence, its levels and
// their guarantees.
#include "ProgressiveMesh.h"
#include "TestHelpers.h"
#include "TestMeshes.h"

#include <numeric>
#include <set>

namespace
{
meshsimp::ProgressiveMesh Build(const Mesh& mesh, meshsimp::ProgressiveMeshOptions options = {})
{
  meshsimp::ProgressiveMesh sequence;
  CHECK(meshsimp::BuildProgressiveMesh(mesh.View(), options, sequence));
  CHECK(sequence.Validate(mesh.View().NumberOfPoints).empty());
  return sequence;
}

meshsimp::SimplifiedMesh Level(const meshsimp::ProgressiveMesh& sequence, const Mesh& mesh, std::int64_t points)
{
  meshsimp::SimplifiedMesh level;
  meshsimp::ExtractLevel(sequence, points, mesh.View(), level);
  return level;
}

/// Whether no two triangles have the same three points (ClosedOriented accepts a triangle and its
/// reverse, the pillow a bad collapse of a tetrahedron leaves).
bool NoDuplicateTriangles(const std::vector<std::int32_t>& triangles)
{
  std::set<std::array<std::int32_t, 3>> seen;
  for (std::size_t t = 0; t < triangles.size(); t += 3)
  {
    std::array<std::int32_t, 3> sorted = { triangles[t], triangles[t + 1], triangles[t + 2] };
    std::sort(sorted.begin(), sorted.end());
    if (!seen.insert(sorted).second)
    {
      return false;
    }
  }
  return true;
}

/// The level's triangles in input point ids, rotated so that the smallest id comes first.
std::multiset<std::array<std::int32_t, 3>> InInputIds(const meshsimp::SimplifiedMesh& level)
{
  std::multiset<std::array<std::int32_t, 3>> triangles;
  for (std::size_t t = 0; t < level.Triangles.size(); t += 3)
  {
    std::array<std::int32_t, 3> ids;
    for (int k = 0; k < 3; ++k)
    {
      ids[k] = level.Representative(level.Triangles[t + k]);
    }
    std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
    triangles.insert(ids);
  }
  return triangles;
}

void FullLevelIsTheInput()
{
  // The level with every point replays the sequence back to the input, bit for bit.
  const Mesh mesh = Sphere(12);
  const meshsimp::ProgressiveMesh sequence = Build(mesh);
  const meshsimp::SimplifiedMesh whole = Level(sequence, mesh, sequence.NumberOfPoints());
  meshsimp::SimplifiedMesh asInput;
  asInput.Triangles = mesh.Triangles;
  asInput.SourceOffsets.clear();
  for (std::int32_t p = 0; p <= static_cast<std::int32_t>(mesh.Points.size() / 3); ++p)
  {
    asInput.SourceOffsets.push_back(p);
    asInput.SourcePoints.push_back(p);
  }
  CHECK(InInputIds(whole) == InInputIds(asInput));
  for (std::int64_t p = 0; p < whole.NumberOfPoints(); ++p)
  {
    CHECK(std::equal(whole.Points.begin() + 3 * p, whole.Points.begin() + 3 * p + 3,
      mesh.Points.begin() + 3 * static_cast<std::size_t>(whole.Representative(p))));
  }
}

void LevelsEqualAReplay()
{
  // Every level equals the collapses replayed one by one on the input's triangles (each removed
  // point replaced by its parent, degenerate triangles dropped), and a closed sphere stays a
  // closed, consistently oriented manifold at every level.
  const Mesh mesh = Sphere(8);
  const meshsimp::ProgressiveMesh sequence = Build(mesh);
  const std::int64_t n = sequence.NumberOfPoints();
  CHECK(sequence.BasePoints >= 4 && sequence.BasePoints < n / 4);
  std::vector<std::int32_t> current(mesh.Triangles.size());
  std::vector<std::int32_t> pointOf(n);
  for (std::int64_t p = 0; p < n; ++p)
  {
    pointOf[sequence.InputPoint[p]] = static_cast<std::int32_t>(p);
  }
  for (std::size_t i = 0; i < current.size(); ++i)
  {
    current[i] = pointOf[mesh.Triangles[i]];
  }
  for (std::int64_t k = n; k >= sequence.BasePoints; --k)
  {
    if (k < n)
    {
      std::replace(current.begin(), current.end(), static_cast<std::int32_t>(k), sequence.Parent[k]);
    }
    meshsimp::SimplifiedMesh replayed;
    for (std::size_t t = 0; t < current.size(); t += 3)
    {
      const std::int32_t* c = &current[t];
      if (c[0] != c[1] && c[1] != c[2] && c[0] != c[2])
      {
        replayed.Triangles.insert(replayed.Triangles.end(), c, c + 3);
      }
    }
    replayed.SourceOffsets.clear();
    for (std::int64_t p = 0; p <= n; ++p)
    {
      replayed.SourceOffsets.push_back(static_cast<std::int32_t>(p));
      replayed.SourcePoints.push_back(static_cast<std::int32_t>(std::min(p, n - 1)));
    }
    const meshsimp::SimplifiedMesh level = Level(sequence, mesh, k);
    CHECK(level.NumberOfPoints() == k);
    CHECK(static_cast<std::int64_t>(level.Triangles.size() / 3) == sequence.TrianglesAt(k));
    CHECK(ValidOutput(level.Points, level.Triangles));
    CHECK(ClosedOriented(level.Triangles) && NoDuplicateTriangles(level.Triangles));
    CHECK(InInputIds(level).size() == replayed.Triangles.size() / 3);
    meshsimp::SimplifiedMesh asSequence = level;
    asSequence.SourcePoints.resize(k);
    std::iota(asSequence.SourcePoints.begin(), asSequence.SourcePoints.end(), 0);
    CHECK(InInputIds(asSequence) == InInputIds(replayed));
  }
}

void TargetsPickLevels()
{
  // A count gives the nearest level (each collapse removes one or two triangles), a reduction
  // the same as its count, a bound the most collapses within it; a count below the coarsest
  // level says why.
  const Mesh mesh = Grid(20);
  const meshsimp::ProgressiveMesh sequence = Build(mesh);
  meshsimp::Target goal;
  goal.SetTriangleCount(200);
  meshsimp::SimplifiedMesh level;
  meshsimp::ExtractTarget(sequence, goal, mesh.View(), level);
  CHECK(std::abs(level.NumberOfTriangles() - 200) <= 1);
  CHECK(level.Report.Stop == meshsimp::StopReason::TargetMet);
  goal.SetReduction(0.75);
  meshsimp::SimplifiedMesh reduced;
  meshsimp::ExtractTarget(sequence, goal, mesh.View(), reduced);
  CHECK(reduced.Triangles == level.Triangles);
  goal.SetTriangleCount(0);
  meshsimp::SimplifiedMesh coarsest;
  meshsimp::ExtractTarget(sequence, goal, mesh.View(), coarsest);
  CHECK(coarsest.NumberOfPoints() == sequence.BasePoints);
  CHECK(coarsest.Report.Stop == meshsimp::StopReason::NothingRemovable && !coarsest.Report.Reason.empty());
  CHECK(level.Report.Reason.empty()); // a target between two levels is no stop
  // A flat grid: every interior collapse is exact, so a zero bound removes interior points,
  // and the border (a straight line between corners) shrinks only along itself.
  goal.SetMaximumError(1e-9, true);
  meshsimp::SimplifiedMesh exact;
  meshsimp::ExtractTarget(sequence, goal, mesh.View(), exact);
  CHECK(exact.NumberOfTriangles() < 800 / 4);
  CHECK(exact.Report.MaximumError <= 1e-9 * std::sqrt(2.0));
}

void BordersAndLocksStay()
{
  // §7: a border point never moves into the interior: at every level each border edge joins
  // two points of the square's outline (a corner may be cut along the border) and no triangle
  // turns over; locked points stay.
  const Mesh mesh = Grid(12);
  std::vector<std::uint8_t> locks(mesh.Points.size() / 3, 0);
  locks[7 * 13 + 6] = 1;
  meshsimp::ProgressiveMeshOptions options;
  options.LockedPoints = locks.data();
  const meshsimp::ProgressiveMesh sequence = Build(mesh, options);
  const auto onOutline = [](const double* p) { return p[0] == 0.0 || p[0] == 1.0 || p[1] == 0.0 || p[1] == 1.0; };
  for (std::int64_t k = sequence.BasePoints; k <= sequence.NumberOfPoints(); k += 17)
  {
    const meshsimp::SimplifiedMesh level = Level(sequence, mesh, k);
    const std::vector<std::int32_t> survivors = Survivors(level);
    CHECK(std::count(survivors.begin(), survivors.end(), 7 * 13 + 6) == 1);
    std::map<std::pair<std::int32_t, std::int32_t>, int> edges;
    for (std::size_t t = 0; t < level.Triangles.size(); t += 3)
    {
      const auto p = [&](int c) { return Eigen::Vector3d(&level.Points[3 * level.Triangles[t + c]]); };
      CHECK((p(1) - p(0)).cross(p(2) - p(0)).z() > 0.0);
      for (int c = 0; c < 3; ++c)
      {
        const std::int32_t a = level.Triangles[t + c], b = level.Triangles[t + (c + 1) % 3];
        ++edges[{ std::min(a, b), std::max(a, b) }];
      }
    }
    for (const auto& edge : edges)
    {
      CHECK(edge.second == 2 ||
        (onOutline(&level.Points[3 * edge.first.first]) && onOutline(&level.Points[3 * edge.first.second])));
    }
  }
}

void SharedPointsGainNoEdge()
{
  // Under MPI the points a piece shares with another are locked; a collapse onto one of them
  // must not join it to another shared point by a new edge, which the other piece could make
  // too (an edge of four triangles). On a grid whose even columns are shared, no level has an
  // edge between two shared points that the input does not have.
  const int n = 12;
  const Mesh mesh = Grid(n);
  std::vector<std::uint8_t> locks(mesh.Points.size() / 3, 0);
  for (std::size_t v = 0; v < locks.size(); ++v)
  {
    locks[v] = (v % (n + 1)) % 2 == 0 ? meshsimp::SharedPointLock : 0;
  }
  const auto sharedEdges = [&](const std::vector<std::int32_t>& triangles, const auto& id) {
    std::set<std::pair<std::int32_t, std::int32_t>> edges;
    for (std::size_t t = 0; t < triangles.size(); t += 3)
    {
      for (int c = 0; c < 3; ++c)
      {
        const std::int32_t a = id(triangles[t + c]), b = id(triangles[t + (c + 1) % 3]);
        if (locks[a] == meshsimp::SharedPointLock && locks[b] == meshsimp::SharedPointLock)
        {
          edges.insert({ std::min(a, b), std::max(a, b) });
        }
      }
    }
    return edges;
  };
  const auto inputEdges = sharedEdges(mesh.Triangles, [](std::int32_t v) { return v; });
  meshsimp::ProgressiveMeshOptions options;
  options.LockedPoints = locks.data();
  const meshsimp::ProgressiveMesh sequence = Build(mesh, options);
  CHECK(sequence.BasePoints < sequence.NumberOfPoints()); // the odd columns still simplify
  for (std::int64_t k = sequence.BasePoints; k <= sequence.NumberOfPoints(); ++k)
  {
    const meshsimp::SimplifiedMesh level = Level(sequence, mesh, k);
    for (const auto& edge : sharedEdges(level.Triangles, [&](std::int32_t p) { return level.Representative(p); }))
    {
      CHECK(inputEdges.count(edge) == 1);
    }
  }
}

void CoarsestSaysWhatStops()
{
  // Past the coarsest level the reason names what stops it, in the collapse engine's words: a
  // closed surface's last collapses break its topology; a grid with every border point locked
  // keeps those (counted by why) and its last inner points' collapses turn triangles over.
  meshsimp::Target goal;
  goal.SetTriangleCount(1);
  meshsimp::SimplifiedMesh level;
  meshsimp::ExtractTarget(Build(Sphere(8)), goal, Sphere(8).View(), level);
  CHECK(level.Report.Stop == meshsimp::StopReason::NothingRemovable);
  CHECK(level.Report.Reason.find("link condition") != std::string::npos);
  const Mesh grid = Grid(6);
  meshsimp::ProgressiveMeshOptions options;
  options.PreserveBoundary = true;
  meshsimp::ExtractTarget(Build(grid, options), goal, grid.View(), level);
  std::printf("%s\n", level.Report.Reason.c_str());
  CHECK(level.Report.Reason.find("24 are locked (all by the options)") != std::string::npos);
}

void LockedClosedFansKeepThree()
{
  // A closed fan keeps three triangles whether its point is locked or not: tetrahedra and closed
  // fans with random locks never leave a triangle and its reverse (a pillow).
  std::mt19937 random(3);
  for (int run = 0; run < 300; ++run)
  {
    const Mesh mesh = Fan(3 + static_cast<int>(random() % 6), true);
    std::vector<std::uint8_t> locks(mesh.Points.size() / 3);
    for (std::uint8_t& lock : locks)
    {
      lock = random() % 3 == 0 ? 1 : 0;
    }
    meshsimp::ProgressiveMeshOptions options;
    options.LockedPoints = locks.data();
    const meshsimp::ProgressiveMesh sequence = Build(mesh, options);
    for (std::int64_t k = sequence.BasePoints; k <= sequence.NumberOfPoints(); ++k)
    {
      const meshsimp::SimplifiedMesh level = Level(sequence, mesh, k);
      CHECK(ClosedOriented(level.Triangles) && NoDuplicateTriangles(level.Triangles));
    }
  }
}

void RegionsNeverMerge()
{
  // Points of different regions never collapse into each other: each level's points keep
  // their input region, and a two-colour grid keeps a point of each colour on every row.
  const Mesh mesh = Grid(10);
  std::vector<std::int32_t> regions(mesh.Points.size() / 3);
  for (std::size_t p = 0; p < regions.size(); ++p)
  {
    regions[p] = mesh.Points[3 * p] < 0.45 ? 0 : 1;
  }
  meshsimp::ProgressiveMeshOptions options;
  options.Regions = regions.data();
  const meshsimp::ProgressiveMesh sequence = Build(mesh, options);
  for (std::int64_t p = sequence.BasePoints; p < sequence.NumberOfPoints(); ++p)
  {
    CHECK(regions[sequence.InputPoint[p]] == regions[sequence.InputPoint[sequence.Parent[p]]]);
  }
}

void ColoursAreExtraCoordinates()
{
  // §7: colours as extra coordinates of the length make collapses across a colour change
  // dearer: with a heavy weight the first collapse joining two colours comes later.
  const Mesh mesh = Grid(16);
  std::vector<double> colour(mesh.Points.size() / 3);
  for (std::size_t p = 0; p < colour.size(); ++p)
  {
    colour[p] = mesh.Points[3 * p] < 0.5 ? 0.0 : 1.0;
  }
  const auto collapsesBeforeMixing = [&](double weight) {
    meshsimp::ProgressiveMeshOptions options;
    options.ExtraCoordinates = colour.data();
    options.ExtraDimension = 1;
    options.AttributeWeight = weight;
    const meshsimp::ProgressiveMesh sequence = Build(mesh, options);
    std::int64_t p = sequence.NumberOfPoints() - 1; // the first collapse's point
    while (p >= sequence.BasePoints &&
      colour[sequence.InputPoint[p]] == colour[sequence.InputPoint[sequence.Parent[p]]])
    {
      --p;
    }
    return sequence.NumberOfPoints() - 1 - p;
  };
  CHECK(collapsesBeforeMixing(100.0) > collapsesBeforeMixing(0.0));
}

void SurvivesDamagedMeshes()
{
  // Damaged meshes (TestMeshes.h) with random locks: a valid sequence, valid levels, locked
  // points kept bit for bit, a closed undamaged mesh closed at every level, the same sequence
  // on any thread count.
  std::mt19937 random(7);
  for (int run = 0; run < 150; ++run)
  {
    bool closed = false;
    const Mesh mesh = DamagedMesh(random, closed);
    const std::vector<std::uint8_t> locks = RandomLocks(random, mesh, meshsimp::SharedPointLock);
    meshsimp::ProgressiveMeshOptions options;
    options.LockedPoints = locks.empty() ? nullptr : locks.data();
    options.PreserveBoundary = random() % 2 == 0;
    options.QuadricWeight = random() % 2 == 0 ? 0.0 : 10.0;
    meshsimp::ProgressiveMesh sequence, threaded;
    CHECK(meshsimp::BuildProgressiveMesh(mesh.View(), options, sequence));
    CHECK(meshsimp::BuildProgressiveMesh(mesh.View(), options, threaded, meshsimp_test::Threaded<meshsimp::ExecutionContext>(2)));
    CHECK(sequence.Validate(mesh.View().NumberOfPoints).empty());
    CHECK(sequence.Parent == threaded.Parent && sequence.Triangles == threaded.Triangles);
    for (const double reduction : { 0.0, 0.5, 0.9, 1.0 })
    {
      meshsimp::Target goal;
      goal.SetReduction(reduction);
      meshsimp::SimplifiedMesh level;
      meshsimp::ExtractTarget(sequence, goal, mesh.View(), level);
      CHECK(ValidOutput(level.Points, level.Triangles));
      CHECK(LockedPointsStay(locks, Survivors(level), level.Points, mesh, closed));
      CHECK(!closed || ClosedOriented(level.Triangles));
      CHECK(NoDuplicateTriangles(level.Triangles));
    }
  }
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "FullLevelIsTheInput", FullLevelIsTheInput },
    { "LevelsEqualAReplay", LevelsEqualAReplay },
    { "TargetsPickLevels", TargetsPickLevels },
    { "BordersAndLocksStay", BordersAndLocksStay },
    { "SharedPointsGainNoEdge", SharedPointsGainNoEdge },
    { "CoarsestSaysWhatStops", CoarsestSaysWhatStops },
    { "LockedClosedFansKeepThree", LockedClosedFansKeepThree },
    { "RegionsNeverMerge", RegionsNeverMerge },
    { "ColoursAreExtraCoordinates", ColoursAreExtraCoordinates },
    { "SurvivesDamagedMeshes", SurvivesDamagedMeshes },
  });
}
