// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering, preparation: the prepared mesh, vertex classes and quadrics (see OctreeClusterer.h).
#include "OctreeClusterer.h"

#include "FanTopology.h"
#include "TriangleMesh.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace meshsimp
{
namespace octree
{
namespace
{
/// Whether the triangles around v form one fan (a disk, or a half-disk along an open border)
/// in which no edge has more than two triangles: the input is a surface at v. Corners that
/// share a far end are joined (union-find over the sorted ends); a fan is one set. ends and
/// parent are scratch.
bool SurfaceVertex(const VertexTriangleAdjacency& adjacency, std::int64_t v,
  std::vector<std::pair<std::int32_t, std::int32_t>>& ends, std::vector<std::int32_t>& parent)
{
  const Corner* first = adjacency.Begin(v);
  const std::int32_t degree = static_cast<std::int32_t>(adjacency.End(v) - first);
  ends.clear();
  for (std::int32_t i = 0; i < degree; ++i)
  {
    ends.emplace_back(first[i].Next, i);
    ends.emplace_back(first[i].Previous, i);
  }
  std::sort(ends.begin(), ends.end());
  parent.resize(degree);
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](std::int32_t i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  std::int32_t fans = degree;
  for (std::size_t k = 0; k < ends.size();)
  {
    std::size_t same = k + 1;
    while (same < ends.size() && ends[same].first == ends[k].first)
    {
      ++same;
    }
    if (same - k > 2)
    {
      return false; // an edge of three or more triangles
    }
    const std::int32_t a = root(ends[k].second), b = root(ends[same - 1].second);
    fans -= a != b ? 1 : 0;
    parent[a] = b;
    k = same;
  }
  return fans == 1;
}
} // namespace

void Clusterer::PrepareGeometry()
{
  // The usable input in normalised coordinates: its box centred at the origin, with a diagonal
  // of 1; its locks and regions.
  this->Prepared = PrepareMesh(this->Input, this->Options, Normalization::CentreAndDiagonal, this->Context);
  const std::int64_t m = static_cast<std::int64_t>(this->Prepared.Mesh.InputTriangle.size());
  this->Start = this->Prepared.Report();
  this->Adjacency = std::move(this->Prepared.Mesh.Adjacency);
  this->P = std::move(this->Prepared.Mesh.Points);
  this->Locked = std::move(this->Prepared.Locks);
  this->Regions = std::move(this->Prepared.Regions);
  this->Bounds = { Vec3::Constant(std::numeric_limits<double>::infinity()),
    Vec3::Constant(-std::numeric_limits<double>::infinity()) };
  for (const Vec3& p : this->P)
  {
    this->Bounds = this->Bounds.Joined({ p, p });
  }

  this->TriangleNormals.assign(m, Vec3::Zero());
  this->TriangleAreas.assign(m, 0.0);
  this->Context.For(m, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t t = b; t < e; ++t)
    {
      const std::int32_t* tri = this->Prepared.Mesh.Triangles.data() + 3 * t;
      const Vec3 cross = (this->P[tri[1]] - this->P[tri[0]]).cross(this->P[tri[2]] - this->P[tri[0]]);
      const double length = cross.norm();
      if (length > 0.0)
      {
        this->TriangleNormals[t] = cross / length;
        this->TriangleAreas[t] = 0.5 * length;
      }
    }
  }, 8 * m);
  // From here on triangles are read at their corners in the adjacency; the list's memory
  // serves the arrays that follow, unless the target keeps every triangle (WriteInput).
  this->KeepsEverything = this->Counting() && this->Prepared.TargetTriangles >= m;
  if (!this->KeepsEverything)
  {
    std::vector<std::int32_t>().swap(this->Prepared.Mesh.Triangles);
  }
}

void Clusterer::ClassifyVertices()
{
  // Per vertex: its open-border corners (MarkBoundaryCorners), and whether the input is a
  // surface around it (SurfaceVertex); the tear rule judges only surfaces. Most vertices are
  // inside one closed, consistently oriented fan (ClassifyFan's Interior), which answers both
  // at once: a surface vertex without border corners.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  this->BoundaryCorners.assign(this->Adjacency.Corners.size(), 0); // MarkBoundaryCorners rewrites its fans'
  this->BoundaryVertices.resize(n);
  this->Irregular.resize(n);
  this->Context.For(n, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::pair<std::int32_t, std::int32_t>> ends;
    std::vector<std::int32_t> parent;
    FanWorkspace fan;
    std::int32_t opening, closing;
    for (std::int64_t v = b; v < e; ++v)
    {
      std::uint8_t* flags = this->BoundaryCorners.data() + this->Adjacency.Offsets[v];
      if (ClassifyFan(this->Adjacency.Begin(v), this->Adjacency.End(v), opening, closing, fan) == VertexClass::Interior)
      {
        // Every edge paired, one triangle each way round: no border corner (flags stay 0).
        this->BoundaryVertices[v] = 0;
        this->Irregular[v] = 0;
        continue;
      }
      this->BoundaryVertices[v] = MarkBoundaryCorners(this->Adjacency, v, flags) ? 1 : 0;
      this->Irregular[v] = SurfaceVertex(this->Adjacency, v, ends, parent) ? 0 : 1;
    }
  }, 32 * static_cast<std::int64_t>(this->Adjacency.Corners.size()));
}

void Clusterer::PrepareQuadrics()
{
  // Vertex quadrics, gathered per vertex (eq. 6): each triangle gives a third of its
  // area-weighted plane quadric to each corner, each boundary edge half its plane to each end.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  this->VertexQuadrics.resize(n);
  this->VertexWeights.resize(n);
  this->VertexAreaNormals.resize(n);
  this->Facing.resize(n);
  this->Context.For(n, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t v = b; v < e; ++v)
    {
      // Every plane passes through P[v]: the face planes and the boundary planes of v's edges.
      Quadric q;
      double weight = 0.0;
      Vec3 areaNormal = Vec3::Zero();
      for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c)
      {
        const Vec3& normal = this->TriangleNormals[c->Triangle];
        const double third = this->TriangleAreas[c->Triangle] / 3.0;
        q.AddNormal(normal, third);
        weight += third;
        areaNormal += third * normal;
      }
      if (this->Options.BoundaryPlanes && this->BoundaryVertices[v])
      {
        const std::uint8_t* flags = this->BoundaryCorners.data() + this->Adjacency.Offsets[v];
        for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c, ++flags)
        {
          double edgeWeight;
          if (*flags & OutgoingBoundaryEdge)
          {
            const Plane plane = this->BoundaryPlane(static_cast<std::int32_t>(v), c->Next, c->Triangle, edgeWeight);
            q.AddNormal(plane.Normal, 0.5 * edgeWeight);
          }
          if (*flags & IncomingBoundaryEdge)
          {
            const Plane plane = this->BoundaryPlane(c->Previous, static_cast<std::int32_t>(v), c->Triangle, edgeWeight);
            q.AddNormal(plane.Normal, 0.5 * edgeWeight);
          }
        }
      }
      q.ThroughPoint(this->P[v]);
      this->VertexQuadrics[v] = q;
      this->VertexWeights[v] = weight;
      this->VertexAreaNormals[v] = areaNormal;
      const double length = areaNormal.norm(); // a folded fan (by Folded's measure) faces no way
      this->Facing[v] = length > 0.0 && length >= 0.5 * weight ? Eigen::Vector3f((areaNormal / length).cast<float>())
                                                               : Eigen::Vector3f::Zero();
    }
  }, 16 * static_cast<std::int64_t>(this->Adjacency.Corners.size()));
  // Not needed any more: its memory serves the refinement's arrays.
  std::vector<double>().swap(this->TriangleAreas);
}

} // namespace octree
} // namespace meshsimp
