// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the level-of-detail morph's core (LODInterpolation.h): the paper's pairing, the
// surface pairing, and the frames with their merges.
#include "LODInterpolation.h"
#include "TestHelpers.h"
#include "TestMeshes.h"

#include <cmath>
#include <limits>

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
  MorphFrame frame;
  meshsimp::Morph(detailed.View(), partners, 0.0, 1.0, frame);
  CHECK(frame.Points == detailed.Points && frame.Triangles == detailed.Triangles);
  for (std::int64_t t = 0; t < frame.NumberOfTriangles(); ++t)
  {
    CHECK(frame.TriangleSource[t] == t);
  }
  for (std::int64_t p = 0; p < frame.NumberOfPoints(); ++p)
  {
    CHECK(frame.PointOffsets[p + 1] - frame.PointOffsets[p] == 1 && frame.PointSources[frame.PointOffsets[p]] == p);
    CHECK(frame.Displacement[p] == 0.0);
  }
}

void FrameAtOneIsOnTheCoarseVertices()
{
  // Nearest vertices: at t = 1 every detailed point stands on one of the four coarse corners;
  // the coincident ones join (any merge distance above 0), and what is left are triangles
  // between distinct corners.
  const Mesh detailed = Bumpy(6);
  const Mesh coarse = Grid(1);
  const MorphPartners partners =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), Nearest(coarse, detailed), Nearest(detailed, coarse));
  MorphFrame frame;
  meshsimp::Morph(detailed.View(), partners, 1.0, 1e-9, frame);
  CHECK(frame.NumberOfPoints() == 4);
  CHECK(frame.PointOffsets.back() == 49);
  for (std::int64_t p = 0; p < frame.NumberOfPoints(); ++p)
  {
    const Vector3d x(frame.Points.data() + 3 * p);
    CHECK(x.z() == 0.0 && (x.x() == 0.0 || x.x() == 1.0) && (x.y() == 0.0 || x.y() == 1.0));
  }
  CHECK(frame.NumberOfTriangles() > 0 && frame.NumberOfTriangles() < static_cast<std::int64_t>(detailed.Triangles.size() / 3));
  for (std::int64_t t = 0; t < frame.NumberOfTriangles(); ++t)
  {
    const std::int32_t* tri = frame.Triangles.data() + 3 * t;
    CHECK(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0]);
  }
}

void SurfacePointsApproachTheCoarseSurface()
{
  // The bumpy grid onto the flat square beneath: each point goes straight down (the closest
  // point of the square), so its height falls as 1 − t and never rises; at t = 1 the frame lies
  // on the square, with the detailed triangles.
  const Mesh detailed = Bumpy(8);
  const Mesh coarse = Grid(2);
  std::vector<std::int32_t> triangle(detailed.Points.size() / 3, -1);
  std::vector<double> barycentric(detailed.Points.size(), 0.0);
  for (std::size_t d = 0; d < triangle.size(); ++d)
  {
    const Vector3d p = detailed.View().Point(static_cast<std::int64_t>(d));
    for (std::size_t t = 0; t < coarse.Triangles.size() / 3 && triangle[d] < 0; ++t)
    {
      const Vector3d a = coarse.View().Point(coarse.Triangles[3 * t]), b = coarse.View().Point(coarse.Triangles[3 * t + 1]),
                     c = coarse.View().Point(coarse.Triangles[3 * t + 2]);
      const double area = ((b - a).cross(c - a)).z();
      const double u = ((b - p).cross(c - p)).z() / area, v = ((c - p).cross(a - p)).z() / area, w = 1.0 - u - v;
      if (u >= -1e-12 && v >= -1e-12 && w >= -1e-12)
      {
        triangle[d] = static_cast<std::int32_t>(t);
        barycentric[3 * d] = u;
        barycentric[3 * d + 1] = v;
        barycentric[3 * d + 2] = w;
      }
    }
  }
  const MorphPartners partners = meshsimp::PairSurfacePoints(detailed.View(), coarse.View(), triangle, barycentric);
  double previous = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= 10; ++step)
  {
    MorphFrame frame;
    meshsimp::Morph(detailed.View(), partners, 0.1 * step, 0.0, frame);
    CHECK(frame.NumberOfTriangles() == static_cast<std::int64_t>(detailed.Triangles.size() / 3));
    double highest = 0.0;
    for (std::int64_t p = 0; p < frame.NumberOfPoints(); ++p)
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
  // grid joins into one point at its centre and no triangle is left.
  const Mesh detailed = Grid(4);
  const MorphPartners own = meshsimp::PairNearestVertices(detailed.View(), Mesh().View(), {}, {});
  MorphFrame frame;
  meshsimp::Morph(detailed.View(), own, 0.5, 0.3, frame);
  CHECK(frame.Points == detailed.Points && frame.Triangles == detailed.Triangles);
  meshsimp::Morph(detailed.View(), own, 1.0, 0.3, frame);
  CHECK(frame.NumberOfPoints() == 1 && frame.NumberOfTriangles() == 0);
  CHECK((Vector3d(frame.Points.data()) - Vector3d(0.5, 0.5, 0.0)).norm() < 1e-12);
}

void SurvivesBadInput()
{
  // Partners of another mesh, ids out of range, a NaN parameter: the detailed mesh, whole, with
  // the triangles that have an id out of range left out.
  Mesh detailed = Grid(3);
  detailed.Triangles.insert(detailed.Triangles.end(), { 0, 1, 99 });
  const Mesh coarse = Grid(1);
  const MorphPartners wrong = meshsimp::PairNearestVertices(coarse.View(), coarse.View(), { 0, 1, 2, 3 }, {});
  MorphFrame frame;
  meshsimp::Morph(detailed.View(), wrong, 0.7, 0.1, frame);
  CHECK(frame.Points == detailed.Points && frame.NumberOfTriangles() == 18);
  const MorphPartners outOfRange =
    meshsimp::PairNearestVertices(detailed.View(), coarse.View(), { -1, 7, 1000, 2 }, std::vector<std::int32_t>(16, 42));
  meshsimp::Morph(detailed.View(), outOfRange, std::numeric_limits<double>::quiet_NaN(), 0.1, frame);
  CHECK(frame.Points == detailed.Points && frame.NumberOfTriangles() == 18);
  const MorphPartners surface = meshsimp::PairSurfacePoints(detailed.View(), coarse.View(), { 5, -3 }, { 1.0 });
  CHECK(surface.Targets == detailed.Points);
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "PairsNearestVerticesAsThePaper", PairsNearestVerticesAsThePaper },
    { "FrameAtZeroIsTheDetailedMesh", FrameAtZeroIsTheDetailedMesh },
    { "FrameAtOneIsOnTheCoarseVertices", FrameAtOneIsOnTheCoarseVertices },
    { "SurfacePointsApproachTheCoarseSurface", SurfacePointsApproachTheCoarseSurface },
    { "MergesGrowWithTheParameter", MergesGrowWithTheParameter },
    { "SurvivesBadInput", SurvivesBadInput },
  });
}
