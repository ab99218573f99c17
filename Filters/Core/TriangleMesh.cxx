// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleMesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace meshsimp
{
namespace
{
/// The input's arrays with their element types fixed, so the loops below need no per-element
/// test of which arrays the view holds.
template <typename PointType, typename IdType>
struct TypedView
{
  const PointType* Points;
  const IdType* Ids;
  std::int64_t NumberOfPoints, NumberOfTriangles;
  Eigen::Vector3d Point(std::int64_t i) const
  {
    return { static_cast<double>(this->Points[3 * i]), static_cast<double>(this->Points[3 * i + 1]),
      static_cast<double>(this->Points[3 * i + 2]) };
  }
  std::int64_t Id(std::int64_t i) const { return static_cast<std::int64_t>(this->Ids[i]); }
};

/// Which triangles are usable: three distinct ids in range, three finite corners. Counts the
/// non-finite points into mesh.
template <typename View>
std::vector<std::uint8_t> MarkUsable(const View& input, CompactMesh& mesh, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  std::vector<std::uint8_t> finite(n);
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      finite[v] = input.Point(v).allFinite() ? 1 : 0;
    }
  });
  mesh.NonFinitePoints = std::count(finite.begin(), finite.end(), std::uint8_t(0));
  std::vector<std::uint8_t> usable(m);
  context.For(m, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t t = begin; t < end; ++t)
    {
      const std::int64_t tri[3] = { input.Id(3 * t), input.Id(3 * t + 1), input.Id(3 * t + 2) };
      bool ok = tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2];
      for (int k = 0; k < 3 && ok; ++k)
      {
        ok = tri[k] >= 0 && tri[k] < n && finite[tri[k]];
      }
      usable[t] = ok ? 1 : 0;
    }
  });
  return usable;
}

/// The Morton code (of a grid of 2^bits cells a side over the box) of each used vertex, -1 for
/// the others; any: whether a vertex is used at all.
template <typename View>
std::vector<std::int32_t> MortonCodes(const View& input, const std::vector<std::int32_t>& vertexOf,
  const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool any, int bits, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints;
  const std::int32_t side = 1 << bits;
  // A box wider than the largest double (coordinates near ±1.8e308) is gridded at half scale,
  // which is exact; any other at its own.
  const double shrink = any && !std::isfinite((hi - lo).maxCoeff()) ? 0.5 : 1.0;
  const double extent = any ? (shrink * hi - shrink * lo).maxCoeff() : 0.0;
  const double toCell = extent > 0.0 ? side / extent : 0.0;
  const Eigen::Vector3d corner = 0.5 * (shrink * lo + shrink * hi) - Eigen::Vector3d::Constant(0.5 * extent);
  std::vector<std::int32_t> code(n, -1);
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      if (vertexOf[v] < 0)
      {
        continue;
      }
      const Eigen::Vector3d cell = (shrink * input.Point(v) - corner) * toCell;
      std::int32_t morton = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        // Spread the (at most 7) bits of the cell index to every third bit.
        std::uint32_t i = static_cast<std::uint32_t>(
          std::min(std::max(static_cast<std::int32_t>(cell[axis]), 0), side - 1));
        i = (i | (i << 8)) & 0x0300F00Fu;
        i = (i | (i << 4)) & 0x030C30C3u;
        i = (i | (i << 2)) & 0x09249249u;
        morton |= static_cast<std::int32_t>(i << axis);
      }
      code[v] = morton;
    }
  });
  return code;
}

/// The used vertices in the Morton order of a coarse grid over their bounding cube (input order
/// within a cell): mesh's InputVertex, Points and box; vertexOf maps input points to them (-1:
/// unused).
template <typename View>
void OrderVertices(const View& input, const std::vector<std::uint8_t>& usable, CompactMesh& mesh,
  std::vector<std::int32_t>& vertexOf, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  vertexOf.assign(n, -1); // used vertices are marked 0 first
  for (std::int64_t t = 0; t < m; ++t)
  {
    for (int k = 0; k < 3 && usable[t]; ++k)
    {
      vertexOf[input.Id(3 * t + k)] = 0;
    }
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  std::int64_t used = 0;
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (vertexOf[v] == 0)
    {
      lo = lo.cwiseMin(input.Point(v));
      hi = hi.cwiseMax(input.Point(v));
      ++used;
    }
  }
  if (used > 0)
  {
    mesh.Lower = lo;
    mesh.Upper = hi;
  }
  // Morton code of each used vertex's cell in a grid of about one cell per vertex, then a
  // counting sort by code that keeps input order inside a cell.
  int bits = 1;
  while (bits < 7 && (std::int64_t(1) << (3 * (bits + 1))) <= used)
  {
    ++bits;
  }
  const std::vector<std::int32_t> code = MortonCodes(input, vertexOf, lo, hi, used > 0, bits, context);
  std::vector<std::int32_t> start((std::size_t(1) << (3 * bits)) + 1, 0);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (code[v] >= 0)
    {
      ++start[code[v] + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  mesh.InputVertex.resize(used);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (code[v] >= 0)
    {
      vertexOf[v] = start[code[v]]++;
      mesh.InputVertex[vertexOf[v]] = static_cast<std::int32_t>(v);
    }
  }
  mesh.Points.resize(used);
  context.For(used, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      mesh.Points[v] = input.Point(mesh.InputVertex[v]);
    }
  });
}

/// Triangles by their lowest vertex (counting sort, input order among equals), corners kept,
/// and each vertex's corners (counting sort by vertex) in the same two passes, over parts of
/// the triangles concurrently: each part counts its own, then writes from cursors that start
/// after the earlier parts' entries, so the result is the same for any number of parts.
template <typename View>
void OrderTriangles(const View& input, const std::vector<std::uint8_t>& usable,
  const std::vector<std::int32_t>& vertexOf, CompactMesh& mesh, const ExecutionContext& context)
{
  const std::int64_t m = input.NumberOfTriangles;
  const std::int64_t used = static_cast<std::int64_t>(mesh.Points.size());
  const std::int64_t parts = std::max<std::int64_t>(1, std::min<std::int64_t>(context.Threads, m / 65536));
  std::vector<std::vector<std::int32_t>> nextTriangle(parts), nextCorner(parts);
  auto forEachUsable = [&](std::int64_t part, auto&& f) {
    for (std::int64_t t = m * part / parts, end = m * (part + 1) / parts; t < end; ++t)
    {
      if (usable[t])
      {
        f(t, vertexOf[input.Id(3 * t)], vertexOf[input.Id(3 * t + 1)], vertexOf[input.Id(3 * t + 2)]);
      }
    }
  };
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::vector<std::int32_t>& triangles = nextTriangle[part];
      std::vector<std::int32_t>& corners = nextCorner[part];
      triangles.assign(used, 0);
      corners.assign(used, 0);
      forEachUsable(part, [&](std::int64_t, std::int32_t a, std::int32_t b, std::int32_t c) {
        ++triangles[std::min({ a, b, c })];
        ++corners[a];
        ++corners[b];
        ++corners[c];
      });
    }
  }, 10 * m);
  // Counts become cursors: per vertex, the parts in order.
  VertexTriangleAdjacency& adjacency = mesh.Adjacency;
  adjacency.Offsets.resize(used + 1);
  std::int32_t triangleCount = 0, cornerCount = 0;
  for (std::int64_t v = 0; v < used; ++v)
  {
    adjacency.Offsets[v] = cornerCount;
    for (std::int64_t part = 0; part < parts; ++part)
    {
      const std::int32_t triangles = nextTriangle[part][v], corners = nextCorner[part][v];
      nextTriangle[part][v] = triangleCount;
      nextCorner[part][v] = cornerCount;
      triangleCount += triangles;
      cornerCount += corners;
    }
  }
  adjacency.Offsets[used] = cornerCount;
  mesh.InputTriangle.resize(triangleCount);
  mesh.Triangles.resize(3 * static_cast<std::size_t>(triangleCount));
  adjacency.Corners.resize(cornerCount);
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::vector<std::int32_t>& triangles = nextTriangle[part];
      std::vector<std::int32_t>& corners = nextCorner[part];
      forEachUsable(part, [&](std::int64_t t, std::int32_t a, std::int32_t b, std::int32_t c) {
        const std::int32_t slot = triangles[std::min({ a, b, c })]++;
        mesh.InputTriangle[slot] = static_cast<std::int32_t>(t);
        mesh.Triangles[3 * static_cast<std::size_t>(slot)] = a;
        mesh.Triangles[3 * static_cast<std::size_t>(slot) + 1] = b;
        mesh.Triangles[3 * static_cast<std::size_t>(slot) + 2] = c;
        adjacency.Corners[corners[a]++] = { slot, b, c };
        adjacency.Corners[corners[b]++] = { slot, c, a };
        adjacency.Corners[corners[c]++] = { slot, a, b };
      });
    }
  }, 30 * m);
}

template <typename PointType, typename IdType>
CompactMesh BuildCompactMesh(const TypedView<PointType, IdType>& input, const ExecutionContext& context)
{
  CompactMesh mesh;
  const std::vector<std::uint8_t> usable = MarkUsable(input, mesh, context);
  std::vector<std::int32_t> vertexOf;
  OrderVertices(input, usable, mesh, vertexOf, context);
  OrderTriangles(input, usable, vertexOf, mesh, context);
  return mesh;
}
} // namespace

CompactMesh MakeCompactMesh(const TriangleMeshView& input, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  if (input.Points)
  {
    return input.Triangles
      ? BuildCompactMesh(TypedView<double, std::int32_t>{ input.Points, input.Triangles, n, m }, context)
      : BuildCompactMesh(TypedView<double, long long>{ input.Points, input.Triangles64, n, m }, context);
  }
  return input.Triangles
    ? BuildCompactMesh(TypedView<float, std::int32_t>{ input.FloatPoints, input.Triangles, n, m }, context)
    : BuildCompactMesh(TypedView<float, long long>{ input.FloatPoints, input.Triangles64, n, m }, context);
}

} // namespace meshsimp
