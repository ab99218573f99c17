// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the level-of-detail morph's core (LODInterpolation.h): the paper's pairing, the
// surface pairing, the ancestors, the merges' schedule and the frames.
#include "LODInterpolation.h"
#include "SurfaceSearch.h"
#include "TestHelpers.h"
#include "TestMeshes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace
{
using meshsimp::MorphFrame;
using meshsimp::MorphPartners;
using Eigen::Vector3d;

/// Per point of from, the nearest point of to (the lowest id among equals), by brute force.
std::vector<std::int32_t> Nearest(const Mesh& from, const Mesh& to)
{
  std::vector<std::int32_t> nearest(from.Points.size() / 3, -1);
  for (std::size_t a = 0; a < nearest.size(); ++a)
  {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < to.Points.size() / 3; ++b)
    {
      const double d = (from.View().Point(a) - to.View().Point(b)).squaredNorm();
      if (d < best)
      {
        best = d;
        nearest[a] = static_cast<std::int32_t>(b);
      }
    }
  }
  return nearest;
}

/// Grid(n) with its points raised by a gentle bump.
Mesh Bumpy(int n)
{
  Mesh mesh = Grid(n);
  for (std::size_t v = 0; v < mesh.Points.size(); v += 3)
  {
    mesh.Points[v + 2] = 0.05 * std::sin(3.0 * mesh.Points[v]) * std::sin(2.0 * mesh.Points[v + 1]);
  }
  return mesh;
}

/// The frame at t, with its points.
struct Frame
{
  std::vector<double> Points;
  MorphFrame Morphed;
};

Frame MorphAt(const Mesh& detailed, const MorphPartners& partners, double t, double mergeDistance,
  const meshsimp::ExecutionContext& context = {})
{
  Frame frame;
  frame.Points.resize(detailed.Points.size());
  const meshsimp::MergeSchedule merges = meshsimp::ScheduleMerges(detailed.View(), partners, mergeDistance, context);
  meshsimp::Morph(detailed.View(), partners, merges, t, frame.Points.data(), frame.Morphed, context);
  return frame;
}

void PairsNearestVerticesAsThePaper()
{
  // Step 1: each coarse corner takes the detailed corner under it; a second coarse point near the
  // first corner loses to the nearer one. Step 2: every other detailed point takes its nearest
  // coarse point.
  const Mesh detailed = Grid(4);
  Mesh coarse = Grid(1);
  for (std::size_t v = 0; v < coarse.Points.size(); v += 3)
  {
    coarse.Points[v + 2] = 0.1;
  }
  coarse.Points.insert(coarse.Points.end(), { 0.01, 0.0, 0.5 });
  const std::vector<std::int32_t> nearestCoarse = Nearest(detailed, coarse);
  const MorphPartners partners =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), Nearest(coarse, detailed), nearestCoarse);
  CHECK(partners.NumberOfPoints() == 25);
  for (std::int64_t d = 0; d < 25; ++d)
  {
    const std::int32_t c = partners.Coarse[3 * d];
    CHECK(c == nearestCoarse[d] && c < 4 && partners.Weights[3 * d] == 1.0 && partners.Coarse[3 * d + 1] == -1);
    CHECK(Vector3d(partners.Targets.data() + 3 * d) == coarse.View().Point(c));
  }
  // The corner under the second coarse point is the first's (nearer), not the second's.
  CHECK(partners.Coarse[0] == 0);
}

void FrameAtZeroIsTheDetailedMesh()
{
  const Mesh detailed = Bumpy(6);
  const Mesh coarse = Grid(1);
  const MorphPartners partners =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), Nearest(coarse, detailed), Nearest(detailed, coarse));
  const Frame frame = MorphAt(detailed, partners, 0.0, 1.0);
  CHECK(frame.Points == detailed.Points && frame.Morphed.Triangles == detailed.Triangles);
  CHECK(frame.Morphed.NumberOfGroups() == 0);
  for (std::int64_t t = 0; t < frame.Morphed.NumberOfTriangles(); ++t)
  {
    CHECK(frame.Morphed.TriangleSource[t] == t);
  }
  for (std::size_t p = 0; p < detailed.Points.size() / 3; ++p)
  {
    CHECK(frame.Morphed.Root[p] == static_cast<std::int32_t>(p) && frame.Morphed.Displacement[p] == 0.0);
  }
}

void FrameAtOneIsOnTheCoarseVertices()
{
  // Nearest vertices: at t = 1 every detailed point stands on one of the four coarse corners;
  // the coincident ones join into four sets (any merge distance above 0), and what is left are
  // triangles between distinct corners, on the sets' lowest ids.
  const Mesh detailed = Bumpy(6);
  const Mesh coarse = Grid(1);
  const MorphPartners partners =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), Nearest(coarse, detailed), Nearest(detailed, coarse));
  const Frame frame = MorphAt(detailed, partners, 1.0, 1e-9);
  CHECK(frame.Morphed.NumberOfGroups() == 4 && frame.Morphed.GroupOffsets.back() == 49);
  for (std::size_t p = 0; p < frame.Points.size() / 3; ++p)
  {
    const Vector3d x(frame.Points.data() + 3 * p);
    CHECK(x.z() == 0.0 && (x.x() == 0.0 || x.x() == 1.0) && (x.y() == 0.0 || x.y() == 1.0));
  }
  const std::int64_t triangles = frame.Morphed.NumberOfTriangles();
  CHECK(triangles > 0 && triangles < static_cast<std::int64_t>(detailed.Triangles.size() / 3));
  for (std::int64_t t = 0; t < triangles; ++t)
  {
    const std::int32_t* tri = frame.Morphed.Triangles.data() + 3 * t;
    CHECK(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]);
    CHECK(frame.Morphed.Root[tri[0]] == tri[0] && frame.Morphed.Root[tri[1]] == tri[1] && frame.Morphed.Root[tri[2]] == tri[2]);
  }
}

/// Per point of a unit grid, the corner of Grid(1) in its quadrant.
std::vector<std::int32_t> QuadrantCorners(const Mesh& grid)
{
  std::vector<std::int32_t> corner(grid.Points.size() / 3);
  for (std::size_t d = 0; d < corner.size(); ++d)
  {
    const Vector3d p = grid.View().Point(static_cast<std::int64_t>(d));
    corner[d] = (p.x() < 0.5 ? 0 : 1) + (p.y() < 0.5 ? 0 : 2);
  }
  return corner;
}

void AncestorsGoWhereTheyWent()
{
  // Each detailed point of the grid to the coarse corner of its quadrant: its target is that
  // corner; an unknown ancestor leaves the point in place.
  const Mesh detailed = Grid(4);
  const Mesh coarse = Grid(1);
  std::vector<std::int32_t> ancestor = QuadrantCorners(detailed);
  ancestor[12] = -1;
  const MorphPartners partners = meshsimp::PairAncestors(detailed.View(), coarse.View(), ancestor);
  for (std::int32_t d = 0; d < 25; ++d)
  {
    const Vector3d target(partners.Targets.data() + 3 * d);
    CHECK(target == (d == 12 ? detailed.View().Point(d) : coarse.View().Point(ancestor[d])));
    CHECK(partners.Coarse[3 * d] == ancestor[d] && partners.Weights[3 * d] == (d == 12 ? 0.0 : 1.0));
  }
}

void GeomorphJoinsOnlyWhatMeetsAtOnePoint()
{
  // Each grid point bound for its quadrant's corner; a merge distance larger than the grid: by
  // distance alone everything joins at t = 1, by partner only the points of one corner do, and
  // the triangles left span three corners.
  const Mesh detailed = Grid(4);
  const Mesh coarse = Grid(1);
  const std::vector<std::int32_t> ancestor = QuadrantCorners(detailed);
  const MorphPartners partners = meshsimp::PairAncestors(detailed.View(), coarse.View(), ancestor);
  CHECK(MorphAt(detailed, partners, 1.0, 10.0).Morphed.NumberOfTriangles() == 0);
  Frame frame;
  frame.Points.resize(detailed.Points.size());
  const meshsimp::MergeSchedule merges = meshsimp::ScheduleMerges(detailed.View(), partners, 10.0, {}, true);
  meshsimp::Morph(detailed.View(), partners, merges, 1.0, frame.Points.data(), frame.Morphed);
  CHECK(frame.Morphed.NumberOfGroups() == 4 && frame.Morphed.NumberOfTriangles() > 0);
  for (std::int64_t t = 0; t < frame.Morphed.NumberOfTriangles(); ++t)
  {
    const std::int32_t* corner = frame.Morphed.Triangles.data() + 3 * t;
    CHECK(ancestor[corner[0]] != ancestor[corner[1]] && ancestor[corner[1]] != ancestor[corner[2]] &&
      ancestor[corner[2]] != ancestor[corner[0]]);
  }
}

void VanishingTriangleJoinsBeforeItTurnsOver()
{
  // A geomorph sends b and c to the origin and a from above it to below: the triangle (a, b, c)
  // lies flat at t = 0.5 and would turn over after it. Its edge (b, c) joins there, whatever the
  // merge distance (none here), so no frame shows it turned; before, it stands as it was.
  Mesh detailed;
  detailed.Points = { 0, 1, 0, -1, 0, 0, 1, 0, 0 };
  detailed.Triangles = { 0, 1, 2 };
  Mesh coarse;
  coarse.Points = { 0, 0, 0, 0, -1, 0 };
  const MorphPartners partners = meshsimp::PairAncestors(detailed.View(), coarse.View(), { 1, 0, 0 });
  const meshsimp::MergeSchedule merges = meshsimp::ScheduleMerges(detailed.View(), partners, 0.0, {}, true);
  for (const double t : { 0.25, 0.49, 0.51, 0.75, 1.0 })
  {
    Frame frame;
    frame.Points.resize(detailed.Points.size());
    meshsimp::Morph(detailed.View(), partners, merges, t, frame.Points.data(), frame.Morphed);
    CHECK(frame.Morphed.NumberOfTriangles() == (t < 0.5 ? 1 : 0));
    CHECK(t < 0.5 || (frame.Morphed.NumberOfGroups() == 1 && frame.Morphed.Root[2] == 1));
  }
  // Where a stays above the edge the triangle only flattens: its edge joins at t = 1, where its
  // ends meet, and not before.
  const MorphPartners above = meshsimp::PairAncestors(detailed.View(), Mesh{ { 0, 0, 0, 0, 1, 0 }, {} }.View(), { 1, 0, 0 });
  const meshsimp::MergeSchedule atOne = meshsimp::ScheduleMerges(detailed.View(), above, 0.0, {}, true);
  for (const double t : { 0.99, 1.0 })
  {
    Frame frame;
    frame.Points.resize(detailed.Points.size());
    meshsimp::Morph(detailed.View(), above, atOne, t, frame.Points.data(), frame.Morphed);
    CHECK(frame.Morphed.NumberOfTriangles() == (t < 1.0 ? 1 : 0));
  }
}

void ScheduleMergesAsADirectTest()
{
  // Random partners on a bumpy grid: at every t the scheduled sets are those of joining every
  // pair of adjacent points closer than t times the merge distance at their frame places.
  const Mesh detailed = Bumpy(12);
  MorphPartners partners = meshsimp::PairNearestVertices(detailed.View(), Mesh().View(), {}, {});
  std::uint32_t seed = 7;
  for (double& x : partners.Targets)
  {
    seed = seed * 1664525u + 1013904223u;
    x += 0.2 * (static_cast<double>(seed >> 8) / (1u << 24) - 0.5);
  }
  const double epsilon = 0.12;
  for (int step = 0; step <= 20; ++step)
  {
    const double t = 0.05 * step;
    const Frame frame = MorphAt(detailed, partners, t, epsilon);
    std::vector<std::int32_t> root(detailed.Points.size() / 3);
    std::iota(root.begin(), root.end(), 0);
    std::vector<double> place(detailed.Points.size());
    for (std::size_t i = 0; i < place.size(); ++i)
    {
      place[i] = (1.0 - t) * detailed.Points[i] + t * partners.Targets[i];
    }
    const auto find = [&](std::int32_t a) {
      while (root[a] != a)
      {
        a = root[a];
      }
      return a;
    };
    for (std::size_t k = 0; k < detailed.Triangles.size(); ++k)
    {
      const std::int32_t a = detailed.Triangles[k], b = detailed.Triangles[k % 3 == 2 ? k - 2 : k + 1];
      if ((Vector3d(place.data() + 3 * a) - Vector3d(place.data() + 3 * b)).norm() < t * epsilon)
      {
        const std::int32_t ra = find(a), rb = find(b);
        root[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
    for (std::size_t p = 0; p < root.size(); ++p)
    {
      CHECK(frame.Morphed.Root[p] == find(static_cast<std::int32_t>(p)));
    }
  }
}

void SurfacePointsAreTheClosest()
{
  // Against brute force over the coarse triangles, for points above, below and beside a bumpy
  // coarse grid, some listed only.
  const Mesh coarse = Bumpy(5);
  Mesh detailed = Bumpy(13);
  for (std::size_t i = 2; i < detailed.Points.size(); i += 3)
  {
    detailed.Points[i] += 0.3 * std::cos(7.0 * static_cast<double>(i)) + (i % 9 == 2 ? 2.0 : 0.0);
  }
  const std::vector<std::int32_t> listed = { 0, 17, 45, 120, 168 };
  for (const bool some : { false, true })
  {
    const MorphPartners partners = meshsimp::PairSurfacePoints(detailed.View(), coarse.View(), some ? listed : std::vector<std::int32_t>(),
      meshsimp_test::Threaded<meshsimp::ExecutionContext>(3));
    for (std::int64_t d = 0; d < partners.NumberOfPoints(); ++d)
    {
      const Vector3d x = detailed.View().Point(d), target(partners.Targets.data() + 3 * d);
      if (some && std::find(listed.begin(), listed.end(), d) == listed.end())
      {
        CHECK(target == x && partners.Coarse[3 * d] == -1);
        continue;
      }
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t t = 0; t < coarse.Triangles.size(); t += 3)
      {
        best = std::min(best, meshsimp::PointTriangleDistance(x, coarse.View().Point(coarse.Triangles[t]),
                                coarse.View().Point(coarse.Triangles[t + 1]), coarse.View().Point(coarse.Triangles[t + 2])));
      }
      CHECK(std::abs((x - target).norm() - best) < 1e-12);
    }
  }
}

void SameFrameOnAnyThreads()
{
  // The merges' schedule and the frame do not depend on how many threads make them.
  const Mesh detailed = Bumpy(40);
  MorphPartners partners = meshsimp::PairNearestVertices(detailed.View(), Mesh().View(), {}, {});
  for (std::size_t i = 2; i < partners.Targets.size(); i += 3)
  {
    partners.Targets[i] = 0.0;
  }
  const Frame serial = MorphAt(detailed, partners, 0.8, 0.05);
  for (const int threads : { 2, 3, 7 })
  {
    const Frame threaded = MorphAt(detailed, partners, 0.8, 0.05, meshsimp_test::Threaded<meshsimp::ExecutionContext>(threads));
    CHECK(threaded.Points == serial.Points && threaded.Morphed.Triangles == serial.Morphed.Triangles);
    CHECK(threaded.Morphed.GroupMembers == serial.Morphed.GroupMembers && threaded.Morphed.Displacement == serial.Morphed.Displacement);
  }
  CHECK(serial.Morphed.NumberOfGroups() > 0);
}

void SurfacePointsApproachTheCoarseSurface()
{
  // The bumpy grid onto the flat square beneath: each point goes straight down (the closest
  // point of the square), so its height falls as 1 − t and never rises; at t = 1 the frame lies
  // on the square, with the detailed triangles.
  const Mesh detailed = Bumpy(8);
  const Mesh coarse = Grid(2);
  const MorphPartners partners = meshsimp::PairSurfacePoints(detailed.View(), coarse.View());
  for (std::int64_t d = 0; d < partners.NumberOfPoints(); ++d)
  {
    // The target is the blend of its triangle's corners with the weights.
    Vector3d blend = Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      CHECK(partners.Coarse[3 * d + k] >= 0 && partners.Weights[3 * d + k] >= 0.0);
      blend += partners.Weights[3 * d + k] * coarse.View().Point(partners.Coarse[3 * d + k]);
    }
    CHECK((blend - Vector3d(partners.Targets.data() + 3 * d)).norm() < 1e-12);
  }
  double previous = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= 10; ++step)
  {
    const Frame frame = MorphAt(detailed, partners, 0.1 * step, 0.0);
    CHECK(frame.Morphed.NumberOfTriangles() == static_cast<std::int64_t>(detailed.Triangles.size() / 3));
    double highest = 0.0;
    for (std::int64_t p = 0; p < static_cast<std::int64_t>(frame.Points.size() / 3); ++p)
    {
      const Vector3d x(frame.Points.data() + 3 * p), original = detailed.View().Point(p);
      CHECK(std::abs(x.x() - original.x()) < 1e-12 && std::abs(x.y() - original.y()) < 1e-12);
      CHECK(std::abs(x.z() - (1.0 - 0.1 * step) * original.z()) < 1e-12);
      highest = std::max(highest, std::abs(x.z()));
    }
    CHECK(highest <= previous);
    previous = highest;
  }
  CHECK(previous < 1e-12);
}

void MergesGrowWithTheParameter()
{
  // Each point its own partner, a merge distance of 0.3 on a grid of edges 0.25: at t = 0.5 the
  // threshold is 0.15 and nothing joins; at t = 1 every edge is shorter than it, so the whole
  // grid joins into one set at its centre and no triangle is left.
  const Mesh detailed = Grid(4);
  const MorphPartners own = meshsimp::PairNearestVertices(detailed.View(), Mesh().View(), {}, {});
  Frame frame = MorphAt(detailed, own, 0.5, 0.3);
  CHECK(frame.Points == detailed.Points && frame.Morphed.Triangles == detailed.Triangles);
  frame = MorphAt(detailed, own, 1.0, 0.3);
  CHECK(frame.Morphed.NumberOfGroups() == 1 && frame.Morphed.GroupOffsets.back() == 25 && frame.Morphed.NumberOfTriangles() == 0);
  for (std::size_t p = 0; p < 25; ++p)
  {
    CHECK((Vector3d(frame.Points.data() + 3 * p) - Vector3d(0.5, 0.5, 0.0)).norm() < 1e-12);
  }
}

void SurvivesBadInput()
{
  // Partners and a schedule of another mesh, ids out of range, a NaN parameter: the detailed
  // mesh, whole, with the triangles that have an id out of range left out.
  Mesh detailed = Grid(3);
  detailed.Triangles.insert(detailed.Triangles.end(), { 0, 1, 99 });
  const Mesh coarse = Grid(1);
  const MorphPartners wrong = meshsimp::PairNearestVertices(coarse.View(), coarse.View(), { 0, 1, 2, 3 }, {});
  Frame frame = MorphAt(detailed, wrong, 0.7, 0.1);
  CHECK(frame.Points == detailed.Points && frame.Morphed.NumberOfTriangles() == 18);
  const MorphPartners outOfRange =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), { -1, 7, 1000, 2 }, std::vector<std::int32_t>(16, 42));
  frame = MorphAt(detailed, outOfRange, std::numeric_limits<double>::quiet_NaN(), 0.1);
  CHECK(frame.Points == detailed.Points && frame.Morphed.NumberOfTriangles() == 18);
  Mesh broken = Grid(1);
  broken.Triangles = { 0, 0, 1, 0, 1, 7 }; // a repeated corner, an id out of range: no usable triangle
  const MorphPartners surface = meshsimp::PairSurfacePoints(detailed.View(), broken.View(), { 5, -3, 99 });
  CHECK(surface.Targets == detailed.Points);
  const MorphPartners ancestors = meshsimp::PairAncestors(detailed.View(), coarse.View(), { 4, -1, 1 << 30 });
  CHECK(ancestors.Targets == detailed.Points);
  meshsimp::MergeSchedule foreign;
  foreign.Ends = { 3, 500, -2, 1 };
  foreign.From = { 0.0, 0.0 };
  foreign.To = { 2.0, 2.0 };
  foreign.SlotOffsets.assign(meshsimp::MergeSchedule::Slots + 1, 2);
  foreign.SlotOffsets[0] = 0;
  meshsimp::Morph(detailed.View(), wrong, foreign, 0.5, frame.Points.data(), frame.Morphed);
  CHECK(frame.Points == detailed.Points && frame.Morphed.NumberOfGroups() == 0);
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "PairsNearestVerticesAsThePaper", PairsNearestVerticesAsThePaper },
    { "FrameAtZeroIsTheDetailedMesh", FrameAtZeroIsTheDetailedMesh },
    { "FrameAtOneIsOnTheCoarseVertices", FrameAtOneIsOnTheCoarseVertices },
    { "AncestorsGoWhereTheyWent", AncestorsGoWhereTheyWent },
    { "GeomorphJoinsOnlyWhatMeetsAtOnePoint", GeomorphJoinsOnlyWhatMeetsAtOnePoint },
    { "VanishingTriangleJoinsBeforeItTurnsOver", VanishingTriangleJoinsBeforeItTurnsOver },
    { "ScheduleMergesAsADirectTest", ScheduleMergesAsADirectTest },
    { "SurfacePointsAreTheClosest", SurfacePointsAreTheClosest },
    { "SameFrameOnAnyThreads", SameFrameOnAnyThreads },
    { "SurfacePointsApproachTheCoarseSurface", SurfacePointsApproachTheCoarseSurface },
    { "MergesGrowWithTheParameter", MergesGrowWithTheParameter },
    { "SurvivesBadInput", SurvivesBadInput },
  });
}
