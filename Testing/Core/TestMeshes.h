// SPDX-License-Identifier: BSD-3-Clause
// Small synthetic meshes shared by the core unit tests.
#ifndef MeshSimplification_TestMeshes_h
#define MeshSimplification_TestMeshes_h

#include "OFFFile.h"
#include "TestHelpers.h"
#include "Simplification.h"
#include "TriangleMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <random>
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

/// A closed slab [0, 1]² × [0, thickness]: its top and bottom n × n grids joined by a rim one
/// quad high (a thin wall or plate: each rim edge across the thickness joins the two sides
/// directly), outward normals.
Mesh Slab(int n, double thickness)
{
  Mesh mesh = Grid(n);
  const std::int32_t top = static_cast<std::int32_t>(mesh.Points.size() / 3);
  for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
  {
    std::swap(mesh.Triangles[t + 1], mesh.Triangles[t + 2]); // the bottom faces down
  }
  const Mesh upper = Grid(n);
  for (std::size_t i = 0; i < upper.Points.size(); i += 3)
  {
    mesh.Points.insert(mesh.Points.end(), { upper.Points[i], upper.Points[i + 1], thickness });
  }
  for (const std::int32_t v : upper.Triangles)
  {
    mesh.Triangles.push_back(v + top);
  }
  // The border counter-clockwise seen from above; each step p -> q gets an outward quad.
  std::vector<std::int32_t> border;
  for (int i = 0; i < n; ++i)
    border.push_back(i);
  for (int j = 0; j < n; ++j)
    border.push_back(j * (n + 1) + n);
  for (int i = n; i > 0; --i)
    border.push_back(n * (n + 1) + i);
  for (int j = n; j > 0; --j)
    border.push_back(j * (n + 1));
  for (std::size_t k = 0; k < border.size(); ++k)
  {
    const std::int32_t p = border[k], q = border[(k + 1) % border.size()];
    mesh.Triangles.insert(mesh.Triangles.end(), { p, q, q + top, p, q + top, p + top });
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

/// `pages` strips of `rows` rows meeting along a straight hinge, like the pages of a book at
/// its spine: the hinge is the x axis from 0 to `segments` (points 0 .. segments), page p goes one
/// unit out in the direction at angle 2 pi p / pages around the x axis, `segments` quads per row.
/// Each hinge edge has `pages` triangles; the hinge's ends have open borders, so they are
/// non-manifold, the points between them hinge vertices.
Mesh Book(int segments, int rows, int pages = 3)
{
  Mesh mesh;
  const int columns = segments + 1;
  for (int i = 0; i < columns; ++i)
  {
    mesh.Points.insert(mesh.Points.end(), { static_cast<double>(i), 0.0, 0.0 });
  }
  for (int page = 0; page < pages; ++page)
  {
    const double angle = 2.0 * 3.14159265358979323846 * page / pages;
    for (int r = 1; r <= rows; ++r)
    {
      const double reach = static_cast<double>(r) / rows;
      for (int i = 0; i < columns; ++i)
      {
        mesh.Points.insert(mesh.Points.end(), { static_cast<double>(i), reach * std::cos(angle), reach * std::sin(angle) });
      }
    }
  }
  for (int page = 0; page < pages; ++page)
  {
    for (int r = 1; r <= rows; ++r)
    {
      const int inner = r == 1 ? 0 : columns * (1 + page * rows + r - 2);
      const int outer = columns * (1 + page * rows + r - 1);
      for (int i = 0; i < segments; ++i)
      {
        mesh.Triangles.insert(mesh.Triangles.end(),
          { inner + i, inner + i + 1, outer + i + 1, inner + i, outer + i + 1, outer + i });
      }
    }
  }
  return mesh;
}

/// Three caps on one circle of n points (a closed hinge): a flat disc and two domes, each of
/// `rows` rings, like a double soap bubble's wall and its two outer walls.
Mesh DoubleBubble(int n, int rows)
{
  Mesh mesh;
  for (int i = 0; i < n; ++i)
  {
    const double angle = 2.0 * 3.14159265358979323846 * i / n;
    mesh.Points.insert(mesh.Points.end(), { std::cos(angle), std::sin(angle), 0.0 });
  }
  for (const double height : { 0.0, 1.0, -1.0 })
  {
    std::vector<int> previous(n);
    std::iota(previous.begin(), previous.end(), 0);
    for (int r = 1; r < rows; ++r)
    {
      const double radius = 1.0 - static_cast<double>(r) / rows;
      std::vector<int> ring(n);
      for (int i = 0; i < n; ++i)
      {
        const double angle = 2.0 * 3.14159265358979323846 * (i + 0.5 * r) / n;
        ring[i] = static_cast<int>(mesh.Points.size() / 3);
        mesh.Points.insert(mesh.Points.end(),
          { radius * std::cos(angle), radius * std::sin(angle), height * std::sqrt(1.0 - radius * radius) });
      }
      for (int i = 0; i < n; ++i)
      {
        const int j = (i + 1) % n;
        mesh.Triangles.insert(mesh.Triangles.end(), { previous[i], previous[j], ring[i], previous[j], ring[j], ring[i] });
      }
      previous = ring;
    }
    const int centre = static_cast<int>(mesh.Points.size() / 3);
    mesh.Points.insert(mesh.Points.end(), { 0.0, 0.0, height });
    for (int i = 0; i < n; ++i)
    {
      mesh.Triangles.insert(mesh.Triangles.end(), { previous[i], previous[(i + 1) % n], centre });
    }
  }
  return mesh;
}

/// How many triangles of the list hold each edge (keyed by its ends, the smaller first).
std::map<std::pair<std::int32_t, std::int32_t>, int> TrianglesPerEdge(const std::vector<std::int32_t>& triangles)
{
  std::map<std::pair<std::int32_t, std::int32_t>, int> edges;
  for (std::size_t t = 0; t < triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t a = triangles[t + k], b = triangles[t + (k + 1) % 3];
      ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  }
  return edges;
}

/// Whether the triangles are a simplicial complex with edges of at most `most` triangles: no
/// triangle repeats another's corners or has a corner twice.
bool IsComplex(const std::vector<std::int32_t>& triangles, int most)
{
  std::vector<std::array<std::int32_t, 3>> sorted;
  for (std::size_t t = 0; t < triangles.size(); t += 3)
  {
    std::array<std::int32_t, 3> corners{ triangles[t], triangles[t + 1], triangles[t + 2] };
    std::sort(corners.begin(), corners.end());
    if (corners[0] == corners[1] || corners[1] == corners[2])
    {
      return false;
    }
    sorted.push_back(corners);
  }
  std::sort(sorted.begin(), sorted.end());
  const auto edges = TrianglesPerEdge(triangles);
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() &&
    std::all_of(edges.begin(), edges.end(), [most](const auto& edge) { return edge.second <= most; });
}

/// Whether a simplified Book(segments, rows, pages) still is one: every triangle on one page
/// (its points on the page or the hinge), the pages joined along the whole hinge (its edges,
/// exactly on the x axis, add up to `segments`) and nowhere else.
bool StaysInBook(const std::vector<double>& points, const std::vector<std::int32_t>& triangles, int segments, int pages = 3)
{
  const auto onHinge = [&points](std::int32_t v) { return points[3 * v + 1] == 0.0 && points[3 * v + 2] == 0.0; };
  // The page of a point (-1: the hinge, -2: none), allowing a placed point's rounding.
  const auto pageOf = [&](std::int32_t v) {
    if (onHinge(v))
    {
      return -1;
    }
    for (int page = 0; page < pages; ++page)
    {
      const double angle = 2.0 * 3.14159265358979323846 * page / pages;
      const double y = points[3 * v + 1], z = points[3 * v + 2];
      if (std::abs(z * std::cos(angle) - y * std::sin(angle)) < 1e-12 && y * std::cos(angle) + z * std::sin(angle) > 0.0)
      {
        return page;
      }
    }
    return -2;
  };
  bool onePage = true;
  for (std::size_t t = 0; t < triangles.size(); t += 3)
  {
    int page = -1;
    for (int k = 0; k < 3; ++k)
    {
      const int own = pageOf(triangles[t + k]);
      onePage = onePage && own != -2 && (own == -1 || page == -1 || own == page);
      page = own >= 0 ? own : page;
    }
  }
  double hingeLength = 0.0;
  bool joinedOnHinge = true;
  for (const auto& [edge, count] : TrianglesPerEdge(triangles))
  {
    const bool hinge = count == pages && onHinge(edge.first) && onHinge(edge.second);
    hingeLength += hinge ? std::abs(points[3 * edge.first] - points[3 * edge.second]) : 0.0;
    joinedOnHinge = joinedOnHinge && (hinge || count <= 2);
  }
  return onePage && joinedOnHinge && IsComplex(triangles, pages) && std::abs(hingeLength - segments) < 1e-9;
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

/// mesh as scans and exported CAD files come: every fifth triangle turned over and every
/// eleventh given again at the end (every other copy turned over too).
Mesh Misoriented(Mesh mesh)
{
  const std::size_t triangles = mesh.Triangles.size() / 3;
  for (std::size_t t = 0; t < triangles; ++t)
  {
    std::int32_t* tri = mesh.Triangles.data() + 3 * t;
    if (t % 5 == 0)
    {
      std::swap(tri[1], tri[2]);
    }
    if (t % 11 == 0)
    {
      const std::int32_t a = tri[0], b = tri[1], c = tri[2];
      const bool turn = (t / 11) % 2 == 1;
      mesh.Triangles.insert(mesh.Triangles.end(), { a, turn ? c : b, turn ? b : c });
    }
  }
  return mesh;
}

/// mesh with point v split off, as damaged scans have it: a copy of v at the same position
/// stands for v in every other triangle around it, so each of v's edges is a zero-width crack.
Mesh SplitOff(Mesh mesh, std::int32_t v)
{
  const auto copy = static_cast<std::int32_t>(mesh.Points.size() / 3);
  mesh.Points.insert(mesh.Points.end(), { mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] });
  bool other = false;
  for (std::int32_t& id : mesh.Triangles)
  {
    if (id == v && (other = !other))
    {
      id = copy;
    }
  }
  return mesh;
}

/// mesh with every step-th point split off (SplitOff); copies counts them.
Mesh SplitOffEvery(Mesh mesh, std::int32_t step, std::int64_t& copies)
{
  copies = 0;
  for (std::int32_t v = 0, n = static_cast<std::int32_t>(mesh.Points.size() / 3); v < n; v += step, ++copies)
  {
    mesh = SplitOff(mesh, v);
  }
  return mesh;
}

/// Both meshes as one, each with its own points.
Mesh Both(Mesh first, const Mesh& second)
{
  const auto offset = static_cast<std::int32_t>(first.Points.size() / 3);
  first.Points.insert(first.Points.end(), second.Points.begin(), second.Points.end());
  for (const std::int32_t v : second.Triangles)
  {
    first.Triangles.push_back(v + offset);
  }
  return first;
}

/// The mesh with each quad's other diagonal (Grid's triangles (a, b, d), (a, d, c) become
/// (a, b, c), (b, d, c)).
Mesh Mirrored(Mesh mesh)
{
  for (std::size_t t = 0; t + 5 < mesh.Triangles.size(); t += 6)
  {
    const std::int32_t a = mesh.Triangles[t], b = mesh.Triangles[t + 1], d = mesh.Triangles[t + 2],
                       c = mesh.Triangles[t + 5];
    const std::int32_t quad[6] = { a, b, c, b, d, c };
    std::copy(quad, quad + 6, mesh.Triangles.begin() + static_cast<std::ptrdiff_t>(t));
  }
  return mesh;
}

/// The mesh as a soup: every triangle with its own copies of its points.
Mesh Soup(const Mesh& mesh)
{
  Mesh soup;
  for (const std::int32_t v : mesh.Triangles)
  {
    soup.Points.insert(soup.Points.end(), { mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] });
    soup.Triangles.push_back(static_cast<std::int32_t>(soup.Triangles.size()));
  }
  return soup;
}

/// The mesh with every triangle turned over.
Mesh TurnedOver(Mesh mesh)
{
  for (std::size_t t = 0; t < mesh.Triangles.size(); t += 3)
  {
    std::swap(mesh.Triangles[t + 1], mesh.Triangles[t + 2]);
  }
  return mesh;
}

/// Grid(n) stored as two halves, the right one (x >= 1/2) with its own copies of the middle
/// column's points: a zero-width crack along x = 1/2 (n even).
Mesh Halves(int n)
{
  Mesh halves = Grid(n);
  std::vector<std::int32_t> copyOf(halves.Points.size() / 3, -1);
  for (std::size_t t = 0; t < halves.Triangles.size(); t += 3)
  {
    const bool right = std::all_of(halves.Triangles.begin() + t, halves.Triangles.begin() + t + 3,
      [&](std::int32_t v) { return halves.Points[3 * v] >= 0.5; });
    for (std::size_t k = t; k < t + 3 && right; ++k)
    {
      std::int32_t& v = halves.Triangles[k];
      if (halves.Points[3 * v] == 0.5)
      {
        if (copyOf[v] < 0)
        {
          copyOf[v] = static_cast<std::int32_t>(halves.Points.size() / 3);
          halves.Points.insert(halves.Points.end(), { 0.5, halves.Points[3 * v + 1], 0.0 });
        }
        v = copyOf[v];
      }
    }
  }
  return halves;
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

/// A mesh for robustness tests, drawn from random: a sphere, cube, grid, tube, fan (up to 1 250
/// triangles around one vertex) or a triangle soup (repeated, coincident and zero points), then
/// damaged by up to four of: holes, duplicate triangles, flipped triangles, fins on edges
/// (non-manifold), welded vertices (pinches), a NaN or infinite coordinate, noise, coincident
/// points, a scale far from 1, a flattened axis; and at times a bad index. closed tells whether
/// the result is an undamaged sphere or cube (a closed 2-manifold).
Mesh DamagedMesh(std::mt19937& random, bool& closed)
{
  auto pick = [&random](int n) { return static_cast<int>(random() % static_cast<unsigned>(n)); };
  auto unit = [&random] { return std::uniform_real_distribution<double>(0.0, 1.0)(random); };
  Mesh mesh;
  const int kind = pick(7);
  closed = kind < 2;
  switch (kind)
  {
    case 0: mesh = Sphere(2 + pick(12)); break;
    case 1: mesh = Cube(1 + pick(8)); break;
    case 2: mesh = Grid(1 + pick(20)); break;
    case 3: mesh = Tube(3 + pick(12), 2 + pick(10)); break;
    case 4: mesh = Fan(3 + pick(80), pick(2) == 0); break;
    case 5: mesh = Fan(250 + pick(1000), pick(2) == 0); break;
    default:
    {
      const int points = 3 + pick(60), triangles = 1 + pick(200);
      for (int i = 0; i < 3 * points; ++i)
      {
        mesh.Points.push_back(pick(7) == 0 ? 0.0 : 2.0 * unit() - 1.0);
      }
      for (int i = 0; i < 3 * triangles; ++i)
      {
        mesh.Triangles.push_back(pick(points));
      }
    }
  }
  for (int damage = pick(5); damage > 0; --damage)
  {
    closed = false;
    const int points = static_cast<int>(mesh.Points.size() / 3);
    const int triangles = static_cast<int>(mesh.Triangles.size() / 3);
    if (triangles == 0)
    {
      break;
    }
    auto corner = [&](int t, int k) -> std::int32_t& { return mesh.Triangles[3 * static_cast<std::size_t>(t) + k]; };
    switch (pick(10))
    {
      case 0: // holes
        for (int k = pick(triangles / 4 + 1); k >= 0 && mesh.Triangles.size() > 3; --k)
        {
          const auto t = mesh.Triangles.begin() + 3 * pick(static_cast<int>(mesh.Triangles.size() / 3));
          mesh.Triangles.erase(t, t + 3);
        }
        break;
      case 1: // duplicate triangles
        for (int k = pick(5); k >= 0; --k)
        {
          const int t = pick(triangles);
          mesh.Triangles.insert(mesh.Triangles.end(), { corner(t, 0), corner(t, 1), corner(t, 2) });
        }
        break;
      case 2: // flipped triangles
        for (int k = pick(triangles / 3 + 1); k >= 0; --k)
        {
          const int t = pick(triangles);
          std::swap(corner(t, 0), corner(t, 1));
        }
        break;
      case 3: // fins: a third triangle on an edge, to a new point
        for (int k = pick(5), added = points; k >= 0; --k, ++added)
        {
          const int t = pick(triangles);
          mesh.Points.insert(mesh.Points.end(), { unit(), unit(), unit() });
          mesh.Triangles.insert(mesh.Triangles.end(), { corner(t, 0), corner(t, 1), added });
        }
        break;
      case 4: // welded vertices
        for (int k = pick(4); k >= 0; --k)
        {
          const int from = pick(points), to = pick(points);
          std::replace(mesh.Triangles.begin(), mesh.Triangles.end(), from, to);
        }
        break;
      case 5: // a NaN or infinite coordinate
        mesh.Points[pick(3 * points)] =
          pick(2) == 0 ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
        break;
      case 6: // noise, of 1 down to 1e-7
      {
        const double size = std::pow(10.0, -pick(8));
        for (double& c : mesh.Points)
        {
          c += size * (unit() - 0.5);
        }
        break;
      }
      case 7: // coincident points
        for (int k = pick(points / 3 + 1); k >= 0; --k)
        {
          const int a = pick(points), b = pick(points);
          std::copy_n(mesh.Points.begin() + 3 * b, 3, mesh.Points.begin() + 3 * a);
        }
        break;
      case 8: // a scale of 2^-100 to 2^100
      {
        const double factor = std::ldexp(pick(2) == 0 ? 1.0 : 3.3, pick(200) - 100);
        for (double& c : mesh.Points)
        {
          c *= factor;
        }
        break;
      }
      default: // a flattened axis
        for (std::size_t i = pick(3); i < mesh.Points.size(); i += 3)
        {
          mesh.Points[i] = 0.0;
        }
    }
  }
  if (pick(10) == 0)
  {
    closed = false;
    mesh.Triangles[pick(static_cast<int>(mesh.Triangles.size()))] = pick(2) == 0 ? -1 : 1 << 20;
  }
  return mesh;
}

/// Whether every output triangle has three distinct corners among the output points, which are
/// finite.
bool ValidOutput(const std::vector<double>& points, const std::vector<std::int32_t>& triangles)
{
  const std::int32_t count = static_cast<std::int32_t>(points.size() / 3);
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    const std::int32_t* tri = triangles.data() + t;
    if (std::any_of(tri, tri + 3, [count](std::int32_t v) { return v < 0 || v >= count; }) ||
      tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
    {
      return false;
    }
  }
  return std::all_of(points.begin(), points.end(), [](double c) { return std::isfinite(c); }) &&
    triangles.size() % 3 == 0;
}

/// Whether every directed edge of the triangles is used once and its reverse once: a closed,
/// consistently oriented 2-manifold.
bool ClosedOriented(const std::vector<std::int32_t>& triangles)
{
  std::map<std::pair<std::int32_t, std::int32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++uses[{ triangles[t + k], triangles[t + (k + 1) % 3] }];
    }
  }
  return std::all_of(uses.begin(), uses.end(), [&uses](const auto& edge) {
    const auto reverse = uses.find({ edge.first.second, edge.first.first });
    return edge.second == 1 && reverse != uses.end() && reverse->second == 1;
  });
}

/// Locks for a robustness run: none a third of the time, else about one point in six, half of
/// them shared (meshsimp::SharedPointLock, given as its value).
std::vector<std::uint8_t> RandomLocks(std::mt19937& random, const Mesh& mesh, std::uint8_t shared)
{
  std::vector<std::uint8_t> locks;
  if (random() % 3 != 0)
  {
    for (std::size_t i = 0; i < mesh.Points.size() / 3; ++i)
    {
      locks.push_back(random() % 6 != 0 ? 0 : random() % 2 == 0 ? 1 : shared);
    }
  }
  return locks;
}

/// Whether each output point (source: its input point) that is locked keeps its input
/// coordinates bit for bit; with everyUsed, also whether every locked point of the input's
/// triangles is in the output.
bool LockedPointsStay(const std::vector<std::uint8_t>& locks, const std::vector<std::int32_t>& source,
  const std::vector<double>& points, const Mesh& input, bool everyUsed)
{
  if (locks.empty())
  {
    return true;
  }
  std::vector<std::uint8_t> present(locks.size(), 0);
  for (std::size_t i = 0; i < source.size(); ++i)
  {
    present[source[i]] = 1;
    if (locks[source[i]] && !std::equal(points.begin() + 3 * i, points.begin() + 3 * i + 3,
                              input.Points.begin() + 3 * static_cast<std::size_t>(source[i])))
    {
      return false;
    }
  }
  return !everyUsed || std::none_of(input.Triangles.begin(), input.Triangles.end(), [&](std::int32_t v) {
    return v >= 0 && v < static_cast<std::int32_t>(locks.size()) && locks[v] && !present[v];
  });
}

/// Random targets for a robustness run of a collapse filter's options: a reduction (0 or 1 a
/// fifth of the time), at times a count of under 10 triangles, boundaries preserved or not, an
/// error bound a quarter of the time, and the given locks.
template <typename Options>
void RandomTargets(std::mt19937& random, Options& options, const std::vector<std::uint8_t>& locks)
{
  const double reduction = random() % 5 == 0 ? (random() % 2) * 1.0 : (random() % 100) / 100.0;
  const std::int64_t count = random() % 6 == 0 ? static_cast<std::int64_t>(random() % 10) : -1;
  options.PreserveBoundary = random() % 2 == 0;
  options.LockedPoints = locks.empty() ? nullptr : locks.data();
  const double bound = random() % 4 == 0 ? 0.001 * (random() % 100) : -1.0;
  options.Goal.SetReduction(reduction);
  if (bound >= 0.0)
  {
    options.Goal.SetMaximumError(bound, true);
  }
  else if (count >= 0)
  {
    options.Goal.SetTriangleCount(count);
  }
}

/// The representative (surviving) input point of each output point.
inline std::vector<std::int32_t> Survivors(const meshsimp::SimplifiedMesh& mesh)
{
  std::vector<std::int32_t> survivors;
  for (std::int64_t p = 0; p < mesh.NumberOfPoints(); ++p)
  {
    survivors.push_back(mesh.Representative(p));
  }
  return survivors;
}

/// Whether the run stopped before its count target.
inline bool StoppedEarly(const meshsimp::SimplifiedMesh& mesh)
{
  return mesh.Report.Stop != meshsimp::StopReason::TargetMet;
}

/// The result of simplify(result, context) on one thread, checked to be a valid output and to be
/// the same on two threads and with chunks of 5 items taken in turn by three.
template <typename Context, typename Result, typename Simplify>
Result SameOnAnyThreads(Simplify&& simplify)
{
  Result serial, threaded, turns;
  CHECK(simplify(serial, Context()));
  CHECK(simplify(threaded, meshsimp_test::Threaded<Context>(2)));
  CHECK(simplify(turns, meshsimp_test::Chunked<Context>(3, 5)));
  CHECK(ValidOutput(serial.Points, serial.Triangles));
  CHECK(serial.Points == threaded.Points && serial.Triangles == threaded.Triangles);
  CHECK(serial.Points == turns.Points && serial.Triangles == turns.Triangles);
  return serial;
}

/// What a collapse filter's run on a damaged mesh must give: locked points that stay (all of
/// them when the mesh is an undamaged closed one, which also stays closed), and a count within
/// tolerance (a share of the usable triangles, at least 2) of the target, unless the filter
/// stopped early or ran under an error bound.
template <typename Result>
void CheckCollapseRun(const Result& result, const Mesh& mesh, bool closed,
  const std::vector<std::uint8_t>& locks, bool bounded, double tolerance)
{
  CHECK(result.SourceOffsets.size() * 3 == result.Points.size() + 3);
  CHECK(result.TriangleSource.size() * 3 == result.Triangles.size());
  CHECK(LockedPointsStay(locks, Survivors(result), result.Points, mesh, closed));
  CHECK(!closed || ClosedOriented(result.Triangles));
  const double count = static_cast<double>(result.Triangles.size() / 3);
  CHECK(StoppedEarly(result) || bounded ||
    std::abs(count - result.Report.TargetTriangles) <= std::max(2.0, tolerance * result.Report.UsableTriangles));
}

/// Output edges that are open (one triangle) or non-manifold (three or more) although no input
/// edge of that kind maps onto them (VertexToPoint): the tears a clustering made.
inline std::array<std::int64_t, 2> NewTears(const std::vector<std::int32_t>& input,
  const std::vector<std::int32_t>& output, const std::vector<std::int32_t>& vertexToPoint)
{
  using Edge = std::pair<std::int32_t, std::int32_t>;
  const auto count = [](const std::vector<std::int32_t>& triangles, const std::vector<std::int32_t>* map) {
    const std::map<Edge, int> edges = TrianglesPerEdge(triangles);
    std::map<Edge, int> mapped; // an input edge's kind at its image, 1 (open) or 3 (more than two)
    for (const auto& edge : edges)
    {
      const std::int32_t a = map ? (*map)[edge.first.first] : edge.first.first;
      const std::int32_t b = map ? (*map)[edge.first.second] : edge.first.second;
      if (a >= 0 && b >= 0 && a != b && edge.second != 2)
      {
        mapped[{ std::min(a, b), std::max(a, b) }] |= edge.second == 1 ? 1 : 2;
      }
    }
    return mapped;
  };
  const std::map<Edge, int> before = count(input, &vertexToPoint), after = count(output, nullptr);
  std::array<std::int64_t, 2> tears = { 0, 0 };
  for (const auto& edge : after)
  {
    const auto found = before.find(edge.first);
    const int had = found == before.end() ? 0 : found->second;
    tears[0] += (edge.second & 1) && !(had & 1) ? 1 : 0;
    tears[1] += (edge.second & 2) && !(had & 2) ? 1 : 0;
  }
  return tears;
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
