// SPDX-License-Identifier: BSD-3-Clause
// Small synthetic meshes shared by the core unit tests.
#ifndef MeshSimplification_TestMeshes_h
#define MeshSimplification_TestMeshes_h

#include "OFFFile.h"
#include "TestHelpers.h"
#include "TriangleMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

namespace
{
struct Mesh
{
  std::vector<double> Points;
  std::vector<std::int32_t> Triangles;
  meshsimp::TriangleMeshView View() const
  {
    return { this->Points.data(), static_cast<std::int64_t>(this->Points.size() / 3),
      this->Triangles.data(), static_cast<std::int64_t>(this->Triangles.size() / 3) };
  }
};

/// An n × n grid of quads on z = 0 over [0, 1]², two triangles each.
Mesh Grid(int n)
{
  Mesh mesh;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      mesh.Points.insert(mesh.Points.end(), { double(i) / n, double(j) / n, 0.0 });
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.Triangles.insert(mesh.Triangles.end(), { a, b, d, a, d, c });
    }
  }
  return mesh;
}

/// The unit cube [0, 1]³ with each face an n × n grid, outward normals, shared points welded.
Mesh Cube(int n)
{
  Mesh mesh;
  std::map<std::array<int, 3>, std::int32_t> ids; // grid position → point, in first-seen order
  auto point = [&](const Eigen::Vector3d& p) {
    const std::array<int, 3> key = { int(std::lround(p.x() * n)), int(std::lround(p.y() * n)),
      int(std::lround(p.z() * n)) };
    const auto inserted = ids.emplace(key, static_cast<std::int32_t>(ids.size()));
    if (inserted.second)
    {
      mesh.Points.insert(mesh.Points.end(), { p.x(), p.y(), p.z() });
    }
    return inserted.first->second;
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const Eigen::Vector3d normal = Eigen::Vector3d::Unit(axis) * (side ? 1.0 : -1.0);
      const Eigen::Vector3d u = Eigen::Vector3d::Unit((axis + 1) % 3);
      const Eigen::Vector3d v = Eigen::Vector3d::Unit((axis + 2) % 3);
      const Eigen::Vector3d origin = Eigen::Vector3d::Unit(axis) * side;
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          auto at = [&](int a, int b) { return point(origin + u * (double(a) / n) + v * (double(b) / n)); };
          std::int32_t c[4] = { at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) };
          if (u.cross(v).dot(normal) < 0)
          {
            std::swap(c[1], c[3]);
          }
          mesh.Triangles.insert(mesh.Triangles.end(), { c[0], c[1], c[2], c[0], c[2], c[3] });
        }
      }
    }
  }
  return mesh;
}

/// The side of a cylinder of radius 1/2 around the z axis, z in [0, 1]: `around` points per ring,
/// `rings` rings, open at both ends, outward normals.
Mesh Tube(int around, int rings)
{
  Mesh mesh;
  for (int j = 0; j < rings; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const double angle = 2.0 * 3.14159265358979323846 * i / around;
      mesh.Points.insert(mesh.Points.end(), { 0.5 * std::cos(angle), 0.5 * std::sin(angle), double(j) / (rings - 1) });
    }
  }
  for (int j = 0; j + 1 < rings; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const int a = j * around + i, b = j * around + (i + 1) % around, c = a + around, d = b + around;
      mesh.Triangles.insert(mesh.Triangles.end(), { a, b, d, a, d, c });
    }
  }
  return mesh;
}

/// A disk of n triangles around one centre vertex (id 0; the rim 1..n, wavy in z); with closed,
/// the rim is capped by a second fan around a vertex below (id n + 1): both centres of valence n.
Mesh Fan(int n, bool closed = false)
{
  Mesh mesh;
  mesh.Points = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * 3.14159265358979323846 * i / n;
    mesh.Points.insert(mesh.Points.end(), { std::cos(angle), std::sin(angle), 0.01 * std::sin(7 * angle) });
  }
  for (int i = 0; i < n; ++i)
  {
    mesh.Triangles.insert(mesh.Triangles.end(), { 0, 1 + i, 1 + (i + 1) % n });
  }
  if (closed)
  {
    mesh.Points.insert(mesh.Points.end(), { 0.0, 0.0, -0.5 });
    for (int i = 0; i < n; ++i)
    {
      mesh.Triangles.insert(mesh.Triangles.end(), { n + 1, 1 + (i + 1) % n, 1 + i });
    }
  }
  return mesh;
}

/// The mesh with every coordinate shifted, then multiplied by factor (a power of two keeps them
/// exact).
Mesh Scaled(Mesh mesh, double factor, double shift = 0.0)
{
  for (double& c : mesh.Points)
  {
    c = (c + shift) * factor;
  }
  return mesh;
}

/// Whether every output coordinate is finite and inside the input's box (widened by its size).
bool InsideBox(const std::vector<double>& output, const Mesh& input)
{
  double lower = std::numeric_limits<double>::infinity(), upper = -lower;
  for (const double c : input.Points)
  {
    lower = std::min(lower, c);
    upper = std::max(upper, c);
  }
  const double margin = upper - lower;
  return std::all_of(output.begin(), output.end(),
    [&](double c) { return std::isfinite(c) && c >= lower - margin && c <= upper + margin; });
}

/// Cube(n) pushed out onto the sphere of radius 1/2 around the cube's centre.
Mesh Sphere(int n)
{
  Mesh mesh = Cube(n);
  for (std::size_t i = 0; i < mesh.Points.size(); i += 3)
  {
    Eigen::Vector3d p(mesh.Points[i] - 0.5, mesh.Points[i + 1] - 0.5, mesh.Points[i + 2] - 0.5);
    p = 0.5 * p.normalized();
    for (int k = 0; k < 3; ++k)
    {
      mesh.Points[i + k] = p[k] + 0.5;
    }
  }
  return mesh;
}

/// Distance from p to the triangle (a, b, c), by its closest point (Ericson's regions).
double DistanceToTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0)
  {
    return ap.norm();
  }
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3)
  {
    return bp.norm();
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    return (p - (a + d1 / (d1 - d3) * ab)).norm();
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6)
  {
    return cp.norm();
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    return (p - (a + d2 / (d2 - d6) * ac)).norm();
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
  {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double sum = va + vb + vc;
  return (p - (a + vb / sum * ab + vc / sum * ac)).norm();
}

#ifdef MESHSIMPLIFICATION_TEST_DATA
/// A triangle mesh of Testing/Data.
Mesh ReadData(const std::string& name)
{
  meshsimp::PolygonMesh file;
  std::string error;
  CHECK(meshsimp::ReadOFF(MESHSIMPLIFICATION_TEST_DATA "/" + name, file, error));
  Mesh mesh;
  mesh.Points = file.Points;
  mesh.Triangles.assign(file.FaceIds.begin(), file.FaceIds.end());
  return mesh;
}
#endif

/// Distance from p to the nearest of the triangles (3 point ids each) over points (3 each).
double DistanceToSurface(const Eigen::Vector3d& p, const std::vector<double>& points,
  const std::vector<std::int32_t>& triangles)
{
  auto point = [&](std::int32_t i) { return Eigen::Vector3d(&points[3 * static_cast<std::size_t>(i)]); };
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    nearest = std::min(nearest, DistanceToTriangle(p, point(triangles[t]), point(triangles[t + 1]), point(triangles[t + 2])));
  }
  return nearest;
}
} // namespace

#endif
