// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering: the clusters of a leaf, their representatives and errors (see OctreeClusterer.h).
#include "OctreeClusterer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace meshsimp
{
namespace octree
{
/// Two vertices whose unit mean normals are more than 140 degrees apart (the cosine) face away
/// from each other, as the two faces of a thin wall or plate do (180 degrees): an edge between
/// them joins nothing, lest their cluster's point sit between the faces and move both. Only
/// edges are tested: a vertex whose normal lies between the faces (on a rounded rim) joins
/// both. The creases of CAD parts (90 degrees) and all but the sharpest ridges of a steep
/// terrain are not cut; a vertex whose normals nearly cancel (a folded fan, by the measure
/// Folded uses) faces no way: none of its edges is cut, so it too may join both faces. Where
/// thin walls meet in non-manifold edges, the tear rules do not part the faces and this rule
/// does; 120 degrees parts them as well but changes more outputs, some for the worse
/// (measured on the corpus; OctreeVertexClustering.md gives the figures).
constexpr float FacingAwayCosine = -0.766f;

Plane Clusterer::BoundaryPlane(
  std::int32_t a, std::int32_t b, std::int32_t triangle, double& weight) const
{
  // Perpendicular to triangle through its boundary edge (a, b) (Zhou, Zhang, Shi and Pan, "A new
  // simplification algorithm for colored or textured polygonal models", §3), weighted by the
  // squared edge length so that it scales like the area-weighted face planes.
  Plane plane;
  weight = 0.0;
  const Vec3 edge = this->P[b] - this->P[a];
  const Vec3 normal = edge.cross(this->TriangleNormals[triangle]);
  const double length = normal.norm();
  if (length > 0.0)
  {
    plane.Normal = normal / length;
    plane.Offset = -plane.Normal.dot(this->P[a]);
    weight = this->Options.BoundaryWeight * edge.squaredNorm();
  }
  return plane;
}

Vec3 Clusterer::PlaceRepresentative(const Quadric& q, const Vec3& centre, const Box& region,
  const std::int32_t* members, std::int32_t count) const
{
  // Eq. (3) when the system is well conditioned and its solution lies in the region (the
  // cluster's cell within the input's box), so that a point never leaves its cell; otherwise
  // the paper's fallback, the weighted centre or one of the cluster's vertices, or the solution
  // clamped into the region, whichever has the least error. Ties keep the centre.
  Vec3 x;
  const bool solved = MinimizeQuadric(q, x);
  if (solved && region.Contains(x))
  {
    return x;
  }
  Vec3 best = centre;
  double bestError = q.Evaluate(centre);
  const double tolerance = 1e-12 * (q.A00 + q.A11 + q.A22);
  const auto consider = [&](const Vec3& candidate) {
    const double error = q.Evaluate(candidate);
    if (error < bestError - tolerance)
    {
      best = candidate;
      bestError = error;
    }
  };
  if (solved)
  {
    consider(region.Clamp(x));
  }
  for (std::int32_t i = 0; i < count; ++i)
  {
    consider(this->P[members[i]]);
  }
  return best;
}

bool Clusterer::Folded(const std::int32_t* members, std::int32_t count) const
{
  // A cluster of several vertices whose area-weighted mean unit normal is shorter than 1/2: its
  // normals spread over more than a half-space (a tip, a thin tube, a folded sheet).
  if (count < 2)
  {
    return false;
  }
  double weight = 0.0;
  Vec3 areaNormal = Vec3::Zero();
  for (std::int32_t i = 0; i < count; ++i)
  {
    weight += this->VertexWeights[members[i]];
    areaNormal += this->VertexAreaNormals[members[i]];
  }
  return !(weight > 0.0) || areaNormal.norm() / weight < 0.5;
}

double Clusterer::Represent(std::int32_t cluster, const Quadric& q, const Box& region,
  const std::int32_t* members, std::int32_t count, Vec3& x) const
{
  // A protruding cluster collapses to its tip, so a leg becomes a cone instead of vanishing
  // into a point inside it; its error then counts the distance of its members to the segment
  // from the ring's centre to the tip. Any other takes the quadric's point (eq. 3, or the
  // fallback).
  const bool folded = this->Folded(members, count);
  std::int32_t tip;
  Vec3 ring;
  const auto member = [this, cluster](std::int32_t v) { return this->InCluster(v, cluster); };
  if (folded && this->ProtrudingTip(member, members, count, tip, ring))
  {
    x = this->P[tip];
    return this->ClusterError(x, members, count, true, &ring);
  }
  x = this->PlaceRepresentative(q, this->ClusterCentre(members, count), region, members, count);
  return this->ClusterError(x, members, count, folded, nullptr);
}

double Clusterer::ClusterError(const Vec3& x, const std::int32_t* members, std::int32_t count,
  bool folded, const Vec3* ring) const
{
  // e1: distance of x to the planes of the related triangles and to the boundary planes.
  double error = 0.0;
  for (std::int32_t i = 0; i < count; ++i)
  {
    const std::int32_t v = members[i];
    const Vec3 offset = x - this->P[v];
    for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c)
    {
      error = std::max(error, std::abs(this->TriangleNormals[c->Triangle].dot(offset)));
    }
    if (!this->Options.BoundaryPlanes || !this->BoundaryVertices[v])
    {
      continue;
    }
    const std::uint8_t* flags = this->BoundaryCorners.data() + this->Adjacency.Offsets[v];
    for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c, ++flags)
    {
      double weight;
      if (*flags & OutgoingBoundaryEdge)
      {
        error = std::max(error, this->BoundaryPlane(v, c->Next, c->Triangle, weight).Distance(x));
      }
      if (*flags & IncomingBoundaryEdge)
      {
        error = std::max(error, this->BoundaryPlane(c->Previous, v, c->Triangle, weight).Distance(x));
      }
    }
  }
  // Planes cannot see a cluster that folds a tip or a thin part onto one point (a finger
  // collapsed to its end keeps every plane distance small): for a folded cluster the distance
  // of its members to x - or to the segment from its ring to x - counts as well.
  if (folded)
  {
    const Vec3 axis = ring ? Vec3(x - *ring) : Vec3::Zero();
    const double length2 = axis.squaredNorm();
    for (std::int32_t i = 0; i < count; ++i)
    {
      const Vec3 offset = this->P[members[i]] - x;
      const double along = length2 > 0.0 ? std::min(std::max(-offset.dot(axis) / length2, 0.0), 1.0) : 0.0;
      error = std::max(error, (offset + along * axis).norm());
    }
  }
  return error;
}

std::int32_t Clusterer::EvaluateLeaf(std::int32_t node, std::int32_t firstCluster,
  Scratch& scratch, double& key, bool& canSplit)
{
  // Clusters the leaf's vertices into clusters firstCluster, firstCluster + 1, ... (the caller
  // reserved one per vertex) and returns how many. Writes only the leaf's own range of the
  // shared arrays, so leaves can be evaluated concurrently.
  OctreeNode& cell = this->Nodes[node];
  const std::int32_t begin = cell.Begin, end = cell.End;

  // Clusters are the connected components of the leaf's vertices (edges inside the leaf only),
  // found by a flood fill from each unlabelled vertex in leaf order, so a cluster's number
  // follows its first vertex. A locked vertex is a component of its own; with regions, only
  // vertices of one region join; an edge between vertices that face away from each other (the
  // faces of a thin wall) joins nothing. The pushes are branch-free but for the facing test, which
  // only candidates reach: whether a neighbour is inside and new is unpredictable.
  const std::uint32_t size = static_cast<std::uint32_t>(end - begin);
  std::vector<std::int32_t>& stack = scratch.Stack;
  std::vector<std::int32_t>& root = scratch.Root; // cluster of each position, in the leaf
  root.assign(size, -1);
  stack.resize(size + 1);
  std::int32_t count = 0;
  const std::int32_t* regions = this->Regions.empty() ? nullptr : this->Regions.data();
  for (std::uint32_t first = 0; first < size; ++first)
  {
    if (root[first] >= 0)
    {
      continue;
    }
    root[first] = count;
    stack[0] = static_cast<std::int32_t>(first);
    for (std::uint32_t top = this->Locked[this->Order[begin + first]] ? 0 : 1; top > 0;)
    {
      const std::int32_t v = this->Order[begin + stack[--top]];
      const Eigen::Vector3f& facing = this->Facing[v];
      for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c)
      {
        for (const std::int32_t w : { c->Next, c->Previous })
        {
          const std::uint32_t at = static_cast<std::uint32_t>(this->Position[w] - begin);
          const std::uint32_t k = at < size ? at : 0;
          const bool fresh = (at < size) & (root[k] < 0) & (this->Locked[w] == 0) &
            (!regions || regions[w] == regions[v]) && this->Facing[w].dot(facing) >= FacingAwayCosine;
          root[k] = fresh ? count : root[k];
          stack[top] = static_cast<std::int32_t>(k);
          top += fresh;
        }
      }
    }
    ++count;
  }

  cell.FirstCluster = firstCluster;
  cell.ClusterCount = count;

  // Members of each cluster (counting sort), their quadric (eq. 6) and representative.
  scratch.Offsets.assign(count + 1, 0);
  for (std::int32_t i = begin; i < end; ++i)
  {
    ++scratch.Offsets[root[i - begin] + 1];
  }
  std::partial_sum(scratch.Offsets.begin(), scratch.Offsets.end(), scratch.Offsets.begin());
  scratch.Fill.assign(scratch.Offsets.begin(), scratch.Offsets.end() - 1);
  scratch.Members.resize(end - begin);
  for (std::int32_t i = begin; i < end; ++i)
  {
    const std::int32_t v = this->Order[i];
    scratch.Members[scratch.Fill[root[i - begin]]++] = v;
    this->VertexCluster[v] = firstCluster + root[i - begin];
  }
  key = 0.0;
  const Box region = this->Region(cell);
  for (std::int32_t c = 0; c < count; ++c)
  {
    const std::int32_t* members = scratch.Members.data() + scratch.Offsets[c];
    const std::int32_t size = scratch.Offsets[c + 1] - scratch.Offsets[c];
    Vec3& x = this->ClusterPositions[firstCluster + c];
    this->ClusterNodes[firstCluster + c] = node;
    if (size == 1)
    {
      x = this->P[members[0]];
      continue; // a lone vertex stays where it is: no error
    }
    key = std::max(key,
      this->Represent(firstCluster + c, this->ClusterQuadric(members, size), region, members, size, x));
  }

  canSplit = CanSplit(cell, count);
  const bool tooLarge = this->Options.MaximumCellSize > 0.0 &&
    this->Options.MaximumCellSize < 1.0 && 2.0 * cell.Half > this->Options.MaximumCellSize;
  const bool tooFull = this->Options.MaximumVerticesPerCell > 0 &&
    end - begin > this->Options.MaximumVerticesPerCell;
  if ((tooLarge && end - begin >= 2) || tooFull)
  {
    key = ForcedSplitKey;
    canSplit = cell.Half > MinimumCellHalfSize && cell.Depth < MaximumDepth;
  }
  return count;
}

LeafScan Clusterer::ScanLeaf(std::int32_t node, bool forEntry, std::int32_t countBegin,
  std::int32_t countEnd, Scratch& scratch) const
{
  const OctreeNode& cell = this->Nodes[node];
  const std::int32_t begin = cell.Begin, end = cell.End;
  const bool flips = forEntry && this->Options.PreventFlips;
  const std::uint32_t countSpan = static_cast<std::uint32_t>(countEnd - countBegin);
  const std::uint32_t leafSpan = static_cast<std::uint32_t>(end - begin);
  LeafScan scan;
  std::vector<std::uint8_t>& survives = scratch.Survives;
  std::vector<std::int64_t>& neighbours = scratch.Neighbours;
  survives.assign(forEntry ? cell.ClusterCount : 0, 0);
  neighbours.clear();
  for (std::int32_t i = begin; i < end; ++i)
  {
    const std::int32_t v = this->Order[i];
    const std::int32_t c0 = this->VertexCluster[v];
    for (const Corner* corner = this->Adjacency.Begin(v); corner != this->Adjacency.End(v); ++corner)
    {
      const std::int32_t next = this->Position[corner->Next];
      const std::int32_t previous = this->Position[corner->Previous];
      const std::int32_t c1 = this->VertexCluster[corner->Next];
      const std::int32_t c2 = this->VertexCluster[corner->Previous];
      // Without branches (& rather than &&): these tests are unpredictable.
      const bool distinct = (c0 != c1) & (c1 != c2) & (c0 != c2);

      // The count: each triangle once, from its first corner in the count range.
      const bool nextCounted = static_cast<std::uint32_t>(next - countBegin) < countSpan;
      const bool previousCounted = static_cast<std::uint32_t>(previous - countBegin) < countSpan;
      scan.Surviving += (nextCounted | previousCounted) & !(nextCounted & (next < i)) &
        !(previousCounted & (previous < i)) & distinct;
      if (!forEntry)
      {
        continue;
      }

      // Vanishing clusters: a cluster survives when one of its triangles has three clusters.
      std::uint8_t& survivesFlag = survives[c0 - cell.FirstCluster];
      if (!survivesFlag)
      {
        survivesFlag = distinct ? 1 : 0;
        for (const std::int32_t other : { c1, c2 })
        {
          if (other != c0)
          {
            neighbours.push_back(static_cast<std::int64_t>(c0) << 32 | other);
          }
        }
      }

      // §2.4: clustering must not turn a related triangle against its original normal; tested
      // on the triangles that survive with one corner in the leaf, with the corners outside at
      // their own clusters' current points.
      const bool outside = (static_cast<std::uint32_t>(next - begin) >= leafSpan) &
        (static_cast<std::uint32_t>(previous - begin) >= leafSpan) & (c1 != c2);
      if (flips & outside & !scan.Flipped &&
        this->TriangleNormals[corner->Triangle] != Vec3::Zero())
      {
        const Vec3& x = this->ClusterPositions[c0];
        const Vec3 normal = (this->ClusterPositions[c1] - x).cross(this->ClusterPositions[c2] - x);
        scan.Flipped = normal.dot(this->TriangleNormals[corner->Triangle]) <= 0.0;
      }
    }
  }
  if (std::find(survives.begin(), survives.end(), 0) == survives.end())
  {
    return scan;
  }
  // A cluster none of whose triangles keeps three distinct clusters disappears from the output
  // (a leg or a corner folded onto its neighbours): its vertices end up about as far from the
  // surface as from the nearest neighbouring cluster's point. Refining elsewhere can only
  // bring it back, so this value never grows while the leaf waits in the heap.
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  for (std::int32_t i = begin; i < end; ++i)
  {
    const std::int32_t v = this->Order[i];
    const std::int32_t c = this->VertexCluster[v];
    if (survives[c - cell.FirstCluster])
    {
      continue;
    }
    double nearest = (this->P[v] - this->ClusterPositions[c]).norm();
    bool found = false;
    for (auto k = std::lower_bound(neighbours.begin(), neighbours.end(), static_cast<std::int64_t>(c) << 32);
         k != neighbours.end() && (*k >> 32) == c; ++k)
    {
      const std::int32_t other = static_cast<std::int32_t>(*k & 0xffffffff);
      const double d = (this->P[v] - this->ClusterPositions[other]).norm();
      nearest = found ? std::min(nearest, d) : d;
      found = true;
    }
    scan.Vanishing = std::max(scan.Vanishing, nearest);
  }
  return scan;
}

Quadric Clusterer::ClusterQuadric(const std::int32_t* members, std::int32_t count) const
{
  Quadric q;
  for (std::int32_t i = 0; i < count; ++i)
  {
    q += this->VertexQuadrics[members[i]];
  }
  return q;
}

Vec3 Clusterer::ClusterCentre(const std::int32_t* members, std::int32_t count) const
{
  // Area-weighted centre; the plain mean when the cluster has no area.
  Vec3 sum = Vec3::Zero(), plain = Vec3::Zero();
  double weight = 0.0;
  for (std::int32_t i = 0; i < count; ++i)
  {
    const double w = this->VertexWeights[members[i]];
    sum += w * this->P[members[i]];
    plain += this->P[members[i]];
    weight += w;
  }
  return weight > 0.0 ? Vec3(sum / weight) : Vec3(plain / count);
}

std::int32_t Clusterer::ClusterLeaves(std::vector<NewLeaf>& leaves, std::int32_t first)
{
  // Clustered concurrently (each leaf writes only its range and its reserved ids), then packed
  // from first in list order (the list holds increasing reserved ids, so ids only move down),
  // then scanned concurrently once every leaf has its clusters. Returns the next free id.
  std::int64_t work = 0;
  for (const NewLeaf& leaf : leaves)
  {
    work += 256 * (this->Nodes[leaf.Node].End - this->Nodes[leaf.Node].Begin); // ns per vertex
  }
  const std::int64_t count = static_cast<std::int64_t>(leaves.size());
  this->Context.For(count, [&](std::int64_t b, std::int64_t e) {
    Scratch scratch;
    for (std::int64_t k = b; k < e; ++k)
    {
      NewLeaf& leaf = leaves[k];
      this->EvaluateLeaf(leaf.Node, leaf.FirstCluster, scratch, leaf.Key, leaf.Splittable);
    }
  }, work);
  for (const NewLeaf& leaf : leaves)
  {
    first = this->MoveClusters(leaf.Node, first);
  }
  this->ClusterPositions.resize(first);
  this->ClusterNodes.resize(first);
  this->Context.For(count, [&](std::int64_t b, std::int64_t e) {
    Scratch scratch;
    for (std::int64_t k = b; k < e; ++k)
    {
      NewLeaf& leaf = leaves[k];
      const bool forEntry = leaf.Splittable && leaf.Key != ForcedSplitKey;
      leaf.Scan = this->ScanLeaf(leaf.Node, forEntry, leaf.CountBegin, leaf.CountEnd, scratch);
    }
  }, work);
  return first;
}

std::int32_t Clusterer::MoveClusters(std::int32_t node, std::int32_t first)
{
  // Renumbers the leaf's clusters first, first + 1, ... (never above their current ids, so
  // leaves can be packed in increasing order in place); returns the next free id.
  OctreeNode& cell = this->Nodes[node];
  const std::int32_t shift = cell.FirstCluster - first;
  if (shift != 0)
  {
    for (std::int32_t c = 0; c < cell.ClusterCount; ++c)
    {
      this->ClusterPositions[first + c] = this->ClusterPositions[cell.FirstCluster + c];
      this->ClusterNodes[first + c] = this->ClusterNodes[cell.FirstCluster + c];
    }
    for (std::int32_t i = cell.Begin; i < cell.End; ++i)
    {
      this->VertexCluster[this->Order[i]] -= shift;
    }
    cell.FirstCluster = first;
  }
  return first + cell.ClusterCount;
}

} // namespace octree
} // namespace meshsimp
