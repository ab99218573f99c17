// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SurfaceSearch.h
 * @brief The nearest triangle of a surface to a point: walks over the surface from a guess, and
 * an exact search on a grid of the triangles. Deviation measures with it, LoD Interpolation
 * sends points to the closest point of the coarse surface with it, Texture Baking finds the
 * point of the original that each texel shows.
 */
#ifndef MeshSimplification_SurfaceSearch_h
#define MeshSimplification_SurfaceSearch_h

#include "Execution.h"
#include "TriangleMesh.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <vector>

namespace meshsimp
{
/// The closest point of the triangle (a, b, c) to x, degenerate triangles included (then the
/// closest point of its edges).
Eigen::Vector3d ClosestPointOnTriangle(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// The distance from x to the triangle (a, b, c), degenerate ones included.
double PointTriangleDistance(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// The nearest triangle found so far to a point.
struct Nearest
{
  double Distance = std::numeric_limits<double>::infinity();
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

class TriangleGrid;
class TriangleTree;

/// A triangle surface for nearest-triangle queries: its points, corners, the triangles around
/// each point, and an exact search made when first asked for (from any thread).
class Surface
{
public:
  Surface(std::vector<Eigen::Vector3d> points, std::vector<std::int32_t> corners);
  ~Surface();

  std::int64_t NumberOfTriangles() const { return static_cast<std::int64_t>(this->Corners.size() / 3); }
  const Eigen::Vector3d& Corner(std::int32_t t, int k) const { return this->Points[this->Corners[3 * static_cast<std::size_t>(t) + k]]; }
  double Distance(const Eigen::Vector3d& x, std::int32_t t) const
  {
    return PointTriangleDistance(x, this->Corner(t, 0), this->Corner(t, 1), this->Corner(t, 2));
  }
  /// Whether x projects onto the inside of triangle t.
  bool Over(const Eigen::Vector3d& x, std::int32_t t) const
  {
    const Eigen::Vector3d &a = this->Corner(t, 0), &b = this->Corner(t, 1), &c = this->Corner(t, 2);
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    return (b - a).cross(x - a).dot(normal) > 0.0 && (c - b).cross(x - b).dot(normal) > 0.0 &&
      (a - c).cross(x - c).dot(normal) > 0.0;
  }
  void Among(const Eigen::Vector3d& x, const std::int32_t* first, const std::int32_t* last, Nearest& best) const
  {
    for (; first != last; ++first)
    {
      best.Offer(this->Distance(x, *first), *first);
    }
  }
  void AroundPoint(const Eigen::Vector3d& x, std::int64_t v, Nearest& best) const
  {
    this->Among(x, this->Around.Begin(v), this->Around.End(v), best);
  }
  /// From the nearest found, to a triangle around one of its corners while one is nearer: a
  /// walk over the surface towards the point, which ends where the point stands over the
  /// nearest triangle's inside.
  void Walk(const Eigen::Vector3d& x, Nearest& best) const
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
  /// The nearest triangle, exactly (the grid made at the first call, from any thread).
  Nearest Exact(const Eigen::Vector3d& x) const;
  /// The nearest triangle, exactly, if one is nearer than guess (else guess): a search of a
  /// tree of the triangles' bounding boxes (made at the first call, from any thread) that skips
  /// every box farther than the nearest found so far, so that a close guess (where a walk
  /// ended) leaves it little to visit; and the nearest within guess.Distance only, so that a
  /// guess of that distance and no triangle bounds the search.
  Nearest Nearer(const Eigen::Vector3d& x, Nearest guess) const;
  /// Makes Nearer's tree now, on context's threads (else the first call makes it on its own).
  void PrepareNearer(const ExecutionContext& context) const;

  const std::vector<Eigen::Vector3d> Points;
  const std::vector<std::int32_t> Corners;
  const Stars Around;

private:
  mutable std::once_flag GridMade, TreeMade;
  mutable std::unique_ptr<TriangleGrid> Grid;
  mutable std::unique_ptr<TriangleTree> Tree;
};

/// The triangles of a mesh with distinct, finite corners in range, for nearest-triangle
/// searches; triangle receives the mesh's id of each.
Surface UsableSurface(const TriangleMeshView& mesh, std::vector<std::int32_t>& triangle);

/// The barycentric weights of x (on the triangle a, b, c) in it, clamped to the triangle; a
/// triangle without area: its centre.
Eigen::Vector3d Barycentric(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

} // namespace meshsimp

#endif
