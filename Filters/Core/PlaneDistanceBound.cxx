// SPDX-License-Identifier: BSD-3-Clause
#include "PlaneDistanceBound.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace meshsimp
{

void PlaneDistanceBound::Build(const CollapseMesh& mesh)
{
  const std::int32_t n = mesh.NumberOfPoints();
  const std::int32_t m = mesh.NumberOfTriangles();
  this->Planes.assign(m, Eigen::Vector4d::Zero());
  this->EdgePlanes.clear();
  this->EdgePlaneOf.assign(3 * static_cast<std::size_t>(m), -1);
  this->Next.assign(3 * static_cast<std::size_t>(m), -1);
  this->Head.assign(n, -1);
  this->Errors.assign(n, 0.0);
  for (std::int32_t t = 0; t < m; ++t)
  {
    if (!mesh.IsAlive(t))
    {
      continue;
    }
    const std::int32_t* tri = mesh.Triangle(t);
    const Eigen::Vector3d normal = mesh.Normal(t); // zero when degenerate: no constraint
    this->Planes[t] << normal, -normal.dot(mesh.Point(tri[0]));
    for (int k = 0; k < 3; ++k)
    {
      // The corner joins its vertex's list; an edge no other triangle shares gets its plane.
      const std::int32_t corner = 3 * t + k, v = tri[k], w = tri[(k + 1) % 3];
      std::int32_t& head = this->Head[v];
      this->Next[corner] = head < 0 ? corner : this->Next[head];
      if (head < 0)
      {
        head = corner;
      }
      else
      {
        this->Next[head] = corner;
      }
      // Around an interior vertex (a closed fan) every edge has a second triangle.
      int shared = mesh.Class(v) == VertexClass::Interior || mesh.Class(w) == VertexClass::Interior ? 1 : 0;
      if (shared == 0)
      {
        mesh.ForEachTriangleOnEdge(v, w, [&](std::int32_t j) { shared += j != t ? 1 : 0; });
      }
      if (shared > 0)
      {
        continue;
      }
      const Eigen::Vector3d side = (mesh.Point(w) - mesh.Point(v)).cross(normal);
      const double length = side.norm();
      if (length > 0.0)
      {
        this->EdgePlaneOf[corner] = static_cast<std::int32_t>(this->EdgePlanes.size());
        this->EdgePlanes.emplace_back();
        this->EdgePlanes.back() << side / length, -(side / length).dot(mesh.Point(v));
      }
    }
  }
}

double PlaneDistanceBound::Distance(std::int32_t v, const Eigen::Vector3d& x) const
{
  const std::int32_t head = this->Head[v];
  if (head < 0)
  {
    return 0.0;
  }
  const Eigen::Vector4d point(x.x(), x.y(), x.z(), 1.0);
  double largest = 0.0;
  std::int32_t corner = head;
  do
  {
    // The triangle's plane and the boundary planes of the two edges at this corner.
    const std::int32_t t = corner / 3, k = corner % 3;
    largest = std::max(largest, std::abs(this->Planes[t].dot(point)));
    for (const std::int32_t edge : { this->EdgePlaneOf[corner], this->EdgePlaneOf[3 * t + (k + 2) % 3] })
    {
      if (edge >= 0)
      {
        largest = std::max(largest, std::abs(this->EdgePlanes[edge].dot(point)));
      }
    }
    corner = this->Next[corner];
  } while (corner != head);
  return largest;
}

double PlaneDistanceBound::Distance(const CollapsePlan& plan) const
{
  double largest = 0.0;
  for (int i = 0; i < plan.Count; ++i)
  {
    largest = std::max(largest, this->Distance(plan.Vertices[i], plan.Position));
  }
  return largest;
}

void PlaneDistanceBound::Merge(const CollapsePlan& plan, double error)
{
  std::int32_t& kept = this->Head[plan.Vertices[0]];
  for (int i = 1; i < plan.Count; ++i)
  {
    std::int32_t& merged = this->Head[plan.Vertices[i]];
    if (merged < 0)
    {
      continue;
    }
    if (kept < 0)
    {
      kept = merged;
    }
    else
    {
      std::swap(this->Next[kept], this->Next[merged]); // splices the two circular lists
    }
    merged = -1;
  }
  this->Errors[plan.Vertices[0]] = error;
}

void AddPlaneDistances(const PlaneDistanceBound& bound, const std::vector<std::int32_t>& survivors, double toInput,
  SimplifiedMesh& result)
{
  std::vector<double> distance(survivors.size());
  result.Report.MaximumError = 0.0;
  for (std::size_t i = 0; i < survivors.size(); ++i)
  {
    distance[i] = bound.Error(survivors[i]) * toInput;
    result.Report.MaximumError = std::max(result.Report.MaximumError, distance[i]);
  }
  result.AddPointArray("PlaneDistance", std::move(distance));
}

} // namespace meshsimp
