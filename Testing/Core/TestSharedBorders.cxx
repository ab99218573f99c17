// SPDX-License-Identifier: BSD-3-Clause
// The border round (SharedBorders.h): pieces of one surface, each simplified with its shared
// points locked, then thinned along their borders together.
#include "SharedBorders.h"
#include "TestMeshes.h"
#include "VolumeTriangleCollapse.h"

#include <cmath>
#include <map>
#include <set>

namespace
{
using Place = std::array<double, 3>;

/// A piece of mesh: the triangles keep says, with points of its own (as a process holds them).
Mesh PieceOf(const Mesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& keep)
{
  Mesh piece;
  std::map<std::int32_t, std::int32_t> local;
  for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      centre += Eigen::Vector3d(mesh.Points.data() + 3 * mesh.Triangles[t + k]) / 3.0;
    }
    if (!keep(centre))
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t v = mesh.Triangles[t + k];
      const auto found = local.emplace(v, static_cast<std::int32_t>(local.size()));
      if (found.second)
      {
        piece.Points.insert(piece.Points.end(), mesh.Points.begin() + 3 * v, mesh.Points.begin() + 3 * v + 3);
      }
      piece.Triangles.push_back(found.first->second);
    }
  }
  return piece;
}

Place PointOf(const std::vector<double>& points, std::int32_t v)
{
  return { points[3 * v], points[3 * v + 1], points[3 * v + 2] };
}

/// Per point of a, SharedPointLock where b has a point at the same place.
std::vector<std::uint8_t> SharedWith(const Mesh& a, const Mesh& b)
{
  std::set<Place> other;
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(b.Points.size() / 3); ++v)
  {
    other.insert(PointOf(b.Points, v));
  }
  std::vector<std::uint8_t> locks(a.Points.size() / 3, 0);
  for (std::size_t v = 0; v < locks.size(); ++v)
  {
    locks[v] = other.count(PointOf(a.Points, static_cast<std::int32_t>(v))) ? meshsimp::SharedPointLock : 0;
  }
  return locks;
}

/// The triangles of each edge of the two results merged at equal places.
std::map<std::pair<Place, Place>, int> MergedEdges(const std::vector<const meshsimp::SimplifiedMesh*>& results)
{
  std::map<std::pair<Place, Place>, int> edges;
  for (const meshsimp::SimplifiedMesh* result : results)
  {
    for (std::size_t t = 0; t < result->Triangles.size(); t += 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        Place a = PointOf(result->Points, result->Triangles[t + k]);
        Place b = PointOf(result->Points, result->Triangles[t + (k + 1) % 3]);
        ++edges[a < b ? std::make_pair(a, b) : std::make_pair(b, a)];
      }
    }
  }
  return edges;
}

/// A closed sphere cut in two, each half simplified with its cut locked.
struct TwoHalves
{
  Mesh Halves[2];
  std::vector<std::uint8_t> Locks[2];
  meshsimp::VolumeCollapseResult Results[2];

  explicit TwoHalves(std::int64_t count)
  {
    const Mesh sphere = Sphere(16);
    this->Halves[0] = PieceOf(sphere, [](const Eigen::Vector3d& c) { return c.z() + 0.3 * c.x() < 0.6; });
    this->Halves[1] = PieceOf(sphere, [](const Eigen::Vector3d& c) { return c.z() + 0.3 * c.x() >= 0.6; });
    for (int i = 0; i < 2; ++i)
    {
      this->Locks[i] = SharedWith(this->Halves[i], this->Halves[1 - i]);
      meshsimp::VolumeCollapseOptions options;
      options.Goal.SetTriangleCount(count);
      options.LockedPoints = this->Locks[i].data();
      CHECK(meshsimp::VolumeTriangleCollapse(this->Halves[i].View(), options, this->Results[i]));
    }
  }
  std::int64_t Triangles() const { return this->Results[0].NumberOfTriangles() + this->Results[1].NumberOfTriangles(); }
  std::int64_t Thin(std::int64_t count)
  {
    meshsimp::PieceBorders first(this->Results[0], this->Halves[0].View(), this->Locks[0].data(), nullptr, 0.0);
    meshsimp::PieceBorders second(this->Results[1], this->Halves[1].View(), this->Locks[1].data(), nullptr, 0.0);
    std::vector<meshsimp::PieceBorders*> pieces{ &first, &second };
    return meshsimp::SimplifySharedBorders(pieces, count, meshsimp::BorderExchange());
  }
};

void ThinsTheCutAndStaysClosed()
{
  TwoHalves halves(300);
  const std::int64_t before = halves.Triangles();
  const std::int64_t cut = std::count(halves.Locks[0].begin(), halves.Locks[0].end(), meshsimp::SharedPointLock);
  CHECK(cut > 30);
  const std::int64_t removed = halves.Thin(40);
  // Each point taken off the cut takes a triangle from each side.
  CHECK(removed == 40);
  CHECK(halves.Triangles() == before - removed);
  const auto edges = MergedEdges({ &halves.Results[0], &halves.Results[1] });
  CHECK(std::all_of(edges.begin(), edges.end(), [](const auto& edge) { return edge.second == 2; }));
}

void MovesNoPointAndKeepsSources()
{
  TwoHalves halves(300);
  halves.Thin(30);
  for (int i = 0; i < 2; ++i)
  {
    const meshsimp::SimplifiedMesh& result = halves.Results[i];
    std::set<Place> input;
    for (std::int32_t v = 0; v < static_cast<std::int32_t>(halves.Halves[i].Points.size() / 3); ++v)
    {
      input.insert(PointOf(halves.Halves[i].Points, v));
    }
    std::vector<int> listed(halves.Halves[i].Points.size() / 3, 0);
    for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
    {
      double weights = 0.0;
      for (std::int32_t s = result.SourceOffsets[p]; s < result.SourceOffsets[p + 1]; ++s)
      {
        weights += result.SourceWeights[s];
        ++listed[result.SourcePoints[s]];
      }
      CHECK(std::abs(weights - 1.0) < 1e-9);
      // Shared points never move: each stands where its representative is.
      const std::int32_t source = result.Representative(p);
      if (halves.Locks[i][source] == meshsimp::SharedPointLock)
      {
        CHECK(PointOf(result.Points, static_cast<std::int32_t>(p)) == PointOf(halves.Halves[i].Points, source));
      }
    }
    // The removed points are listed by the point they went into, every input point at most once.
    CHECK(std::all_of(listed.begin(), listed.end(), [](int n) { return n <= 1; }));
    CHECK(static_cast<std::size_t>(result.SourcePoints.size()) == halves.Halves[i].Points.size() / 3);
    CHECK(static_cast<std::int64_t>(result.TriangleSource.size()) == result.NumberOfTriangles());
  }
}

void TheCutIsNoBorder()
{
  // The cut between pieces is no border of the surface: no interior point is merged into a point
  // of the cut, which the volume filter's border rule (Zhou, Zhang and Cheng §3.5) would do on
  // a border (there it is mostly refused, and the triangles along the cut stay); a triangle
  // along the cut collapses its edge off the cut instead. A bumpy grid whose every border point
  // is shared (a piece inside others) ends with less volume error than with the same points
  // locked as the user locks them.
  Mesh grid = Grid(24);
  for (std::size_t v = 0; v < grid.Points.size(); v += 3)
  {
    grid.Points[v + 2] = 0.05 * std::sin(9.0 * grid.Points[v]) * std::cos(7.0 * grid.Points[v + 1]);
  }
  std::vector<std::uint8_t> shared(grid.Points.size() / 3, 0), locked(shared.size(), 0);
  for (std::size_t v = 0; v < shared.size(); ++v)
  {
    const double x = grid.Points[3 * v], y = grid.Points[3 * v + 1];
    const bool border = x == 0.0 || y == 0.0 || x == 1.0 || y == 1.0;
    shared[v] = border ? meshsimp::SharedPointLock : 0;
    locked[v] = border ? 1 : 0;
  }
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(150);
  options.LockedPoints = shared.data();
  meshsimp::VolumeCollapseResult cut, border;
  CHECK(meshsimp::VolumeTriangleCollapse(grid.View(), options, cut));
  options.LockedPoints = locked.data();
  CHECK(meshsimp::VolumeTriangleCollapse(grid.View(), options, border));
  CHECK(cut.NumberOfTriangles() == 150 && border.NumberOfTriangles() == 150);
  CHECK(cut.SquareVolumeError < 0.9 * border.SquareVolumeError);
  std::int64_t drawn = 0;
  for (std::int64_t p = 0; p < cut.NumberOfPoints(); ++p)
  {
    if (shared[cut.Representative(p)] == meshsimp::SharedPointLock)
    {
      for (std::int32_t s = cut.SourceOffsets[p]; s < cut.SourceOffsets[p + 1]; ++s)
      {
        drawn += shared[cut.SourcePoints[s]] == meshsimp::SharedPointLock ? 0 : 1;
      }
    }
  }
  CHECK(drawn == 0);
}

void StopsWhereTheCutCannotThin()
{
  // Asked for more than the cut can give, the round stops with the pieces still closed.
  TwoHalves halves(300);
  const std::int64_t removed = halves.Thin(100000);
  CHECK(removed > 0 && removed < 100000);
  const auto edges = MergedEdges({ &halves.Results[0], &halves.Results[1] });
  CHECK(std::all_of(edges.begin(), edges.end(), [](const auto& edge) { return edge.second == 2; }));
}

void ComposesTwoSimplifications()
{
  // first: three input points into two output points; second: the two into one.
  meshsimp::SimplifiedMesh first, second;
  first.Points = { 0, 0, 0, 1, 0, 0 };
  first.SourceOffsets = { 0, 2, 3 };
  first.SourcePoints = { 4, 7, 9 };
  first.SourceWeights = { 0.5, 0.5, 1.0 };
  first.TriangleSource = { 11, 12 };
  first.Report.UsableTriangles = 20;
  second.Points = { 0.5, 0, 0 };
  second.SourceOffsets = { 0, 2 };
  second.SourcePoints = { 1, 0 };
  second.SourceWeights = { 0.25, 0.75 };
  second.TriangleSource = { 1 };
  second.Report.Stop = meshsimp::StopReason::NothingRemovable;
  meshsimp::ComposeSources(first, std::move(second));
  CHECK((first.SourcePoints == std::vector<std::int32_t>{ 9, 4, 7 }));
  CHECK((first.SourceWeights == std::vector<double>{ 0.25, 0.375, 0.375 }));
  CHECK((first.TriangleSource == std::vector<std::int32_t>{ 12 }));
  CHECK(first.Report.UsableTriangles == 20 && first.Report.Stop == meshsimp::StopReason::NothingRemovable);
}
}

int main()
{
  return meshsimp_test::RunTests({
    { "ThinsTheCutAndStaysClosed", ThinsTheCutAndStaysClosed },
    { "MovesNoPointAndKeepsSources", MovesNoPointAndKeepsSources },
    { "TheCutIsNoBorder", TheCutIsNoBorder },
    { "StopsWhereTheCutCannotThin", StopsWhereTheCutCannotThin },
    { "ComposesTwoSimplifications", ComposesTwoSimplifications },
  });
}
