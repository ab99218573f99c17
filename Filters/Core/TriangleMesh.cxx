// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleMesh.h"

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
  // Bit k of mask[t]: edge (k, k+1) of triangle t belongs to no other triangle.
  std::vector<std::uint8_t> mask(mesh.NumberOfTriangles, 0);
  context.For(mesh.NumberOfTriangles, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t t = begin; t < end; ++t)
    {
      if (!usable[t])
      {
        continue;
      }
      const std::int32_t* tri = mesh.Triangles + 3 * t;
      for (int k = 0; k < 3; ++k)
      {
        const std::int32_t a = tri[k], b = tri[(k + 1) % 3];
        int uses = 0;
        for (const std::int32_t* s = adjacency.Begin(a); s != adjacency.End(a) && uses < 2; ++s)
        {
          const std::int32_t* other = mesh.Triangles + 3 * static_cast<std::int64_t>(*s);
          uses += (other[0] == b || other[1] == b || other[2] == b) ? 1 : 0;
        }
        mask[t] |= uses == 1 ? (1 << k) : 0;
      }
    }
  });
  std::vector<BoundaryEdge> edges;
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    for (int k = 0; k < 3 && mask[t]; ++k)
    {
      if (mask[t] & (1 << k))
      {
        edges.push_back({ mesh.Triangles[3 * t + k], mesh.Triangles[3 * t + (k + 1) % 3],
          static_cast<std::int32_t>(t) });
      }
    }
  }
  return edges;
}

} // namespace meshsimp
