// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleMesh.h"

#include <algorithm>
#include <cmath>

namespace meshsimp
{

bool IsUsableTriangle(const TriangleMeshView& mesh, std::int64_t t)
{
  const std::int32_t* tri = mesh.Triangles + 3 * t;
  for (int k = 0; k < 3; ++k)
  {
    if (tri[k] < 0 || tri[k] >= mesh.NumberOfPoints)
    {
      return false;
    }
    const double* p = mesh.Points + 3 * static_cast<std::int64_t>(tri[k]);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return false;
    }
  }
  return tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2];
}

void VertexTriangleAdjacency::Build(
  const TriangleMeshView& mesh, const std::vector<std::uint8_t>& usable)
{
  this->Offsets.assign(mesh.NumberOfPoints + 1, 0);
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    if (usable[t])
    {
      for (int k = 0; k < 3; ++k)
      {
        ++this->Offsets[mesh.Triangles[3 * t + k] + 1];
      }
    }
  }
  for (std::int64_t v = 0; v < mesh.NumberOfPoints; ++v)
  {
    this->Offsets[v + 1] += this->Offsets[v];
  }
  this->Triangles.resize(this->Offsets.back());
  std::vector<std::int32_t> fill(this->Offsets.begin(), this->Offsets.end() - 1);
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    if (usable[t])
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Triangles[fill[mesh.Triangles[3 * t + k]]++] = static_cast<std::int32_t>(t);
      }
    }
  }
}

std::vector<BoundaryEdge> FindBoundaryEdges(const TriangleMeshView& mesh,
  const std::vector<std::uint8_t>& usable, const VertexTriangleAdjacency& adjacency,
  const ExecutionContext& context)
{
  // Edge (a, b) of triangle t, with a = t[k] and b = t[k + 1], is a boundary edge when no other
  // triangle around a contains b. Vertex a decides for the edges that start at it, so each
  // flag has one writer and vertices can be processed concurrently.
  std::vector<std::uint8_t> isBoundary(3 * mesh.NumberOfTriangles, 0);
  context.For(mesh.NumberOfPoints, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::int32_t> next, previous; // the other corners of each triangle around a
    for (std::int64_t a = begin; a < end; ++a)
    {
      const std::int32_t* first = adjacency.Begin(a);
      const std::size_t degree = static_cast<std::size_t>(adjacency.End(a) - first);
      next.resize(degree);
      previous.resize(degree);
      for (std::size_t i = 0; i < degree; ++i)
      {
        const std::int32_t* tri = mesh.Triangles + 3 * static_cast<std::int64_t>(first[i]);
        const int k = tri[0] == a ? 0 : tri[1] == a ? 1 : 2;
        next[i] = tri[(k + 1) % 3];
        previous[i] = tri[(k + 2) % 3];
      }
      for (std::size_t i = 0; i < degree; ++i)
      {
        // Common case first: a consistently oriented neighbour triangle has b as its previous
        // corner, so the edge is shared. Otherwise count every triangle around a with b.
        const std::int32_t b = next[i];
        if (std::find(previous.begin(), previous.end(), b) != previous.end())
        {
          continue;
        }
        if (std::count(next.begin(), next.end(), b) == 1)
        {
          const std::int32_t* tri = mesh.Triangles + 3 * static_cast<std::int64_t>(first[i]);
          isBoundary[3 * static_cast<std::int64_t>(first[i]) + (tri[0] == a ? 0 : tri[1] == a ? 1 : 2)] = 1;
        }
      }
    }
  });
  std::vector<BoundaryEdge> edges;
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (usable[t] && isBoundary[3 * t + k])
      {
        edges.push_back({ mesh.Triangles[3 * t + k], mesh.Triangles[3 * t + (k + 1) % 3],
          static_cast<std::int32_t>(t) });
      }
    }
  }
  return edges;
}

} // namespace meshsimp
