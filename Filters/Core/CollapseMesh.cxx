// SPDX-License-Identifier: BSD-3-Clause
#include "CollapseMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <numeric>

namespace meshsimp
{

namespace
{
bool Contains(const std::int32_t* tri, std::int32_t v)
{
  return tri[0] == v || tri[1] == v || tri[2] == v;
}

/// Two triangles whose normals are more than 150 degrees apart lie (nearly) back to back.
constexpr double FoldCosine = 0.8660254037844386;
/// The cosine of 30 degrees: a triangle turned by less cannot fold onto a neighbour it met at
/// under 120 degrees, so the fold check is skipped for it.
constexpr double FoldCheckTurnCosine = 0.8660254037844386;

} // namespace

void CollapseMesh::Load(PreparedMesh& prepared, double cornerAngleDegrees, bool lockBorderCorners, const ExecutionContext& context)
{
  this->Build(std::move(prepared.Mesh), cornerAngleDegrees, context);
  this->SetRegions(std::move(prepared.Regions));
  for (std::int32_t v = 0; v < this->NumberOfPoints(); ++v)
  {
    const std::uint8_t lock = prepared.Locks[v];
    if (lock || (lockBorderCorners && this->Class(v) == VertexClass::Corner))
    {
      this->Lock(v, lock == SharedPointLock ? LockReason::SharedPoint : lock ? LockReason::Options : LockReason::BorderCorner);
    }
  }
}

void CollapseMesh::Build(CompactMesh&& mesh, double cornerAngleDegrees, const ExecutionContext& context)
{
  this->Points = std::move(mesh.Points);
  this->Triangles = std::move(mesh.Triangles);
  const std::int32_t n = this->NumberOfPoints();
  const std::int32_t m = static_cast<std::int32_t>(this->Triangles.size() / 3);
  this->Alive.assign(m, 1);
  this->AliveCount = m;
  this->Classes.assign(n, VertexClass::Interior);
  this->Locked.assign(n, 0);
  this->Start.resize(n);
  this->Count.resize(n);
  const VertexTriangleAdjacency& adjacency = mesh.Adjacency;
  this->Refs.resize(adjacency.Corners.size());
  const double cosCorner = std::cos(cornerAngleDegrees * 3.14159265358979323846 / 180.0);
  context.For(n, [&](std::int64_t first, std::int64_t last) {
    FanWorkspace fan;
    for (std::int32_t v = static_cast<std::int32_t>(first); v < last; ++v)
    {
      this->Start[v] = adjacency.Offsets[v];
      this->Count[v] = adjacency.Offsets[v + 1] - adjacency.Offsets[v];
      for (std::int32_t i = adjacency.Offsets[v]; i < adjacency.Offsets[v + 1]; ++i)
      {
        this->Refs[i] = adjacency.Corners[i].Triangle;
      }
      std::int32_t opening = -1, closing = -1;
      VertexClass c = ClassifyFan(adjacency.Begin(v), adjacency.End(v), opening, closing, fan);
      // Where a boundary or a hinge turns sharply at v, v is a corner that stays: a corner of
      // the boundary, a non-manifold (locked) vertex of the hinge.
      const auto turnsSharply = [&](std::int32_t from, std::int32_t to) {
        const Eigen::Vector3d in = this->Points[v] - this->Points[from];
        const Eigen::Vector3d out = this->Points[to] - this->Points[v];
        const double lengths = in.norm() * out.norm();
        return lengths > 0.0 && in.dot(out) < cosCorner * lengths;
      };
      std::int32_t ends[2];
      if (c == VertexClass::Boundary &&
        turnsSharply(adjacency.Begin(v)[opening].Previous, adjacency.Begin(v)[closing].Next))
      {
        // The boundary runs into v along the closing corner's far edge and leaves along the
        // opening corner's: (Previous of opening) -> v -> (Next of closing), by orientation.
        c = VertexClass::Corner;
      }
      else if (c == VertexClass::NonManifold && IsHinge(adjacency.Begin(v), adjacency.End(v), ends, fan) &&
        !turnsSharply(ends[0], ends[1]))
      {
        c = VertexClass::Hinge;
      }
      this->Classes[v] = c;
      this->Locked[v] = c == VertexClass::NonManifold ? static_cast<std::uint8_t>(LockReason::NonManifold) : 0;
    }
  }, 50 * static_cast<std::int64_t>(n));
  this->HasHingeVertices = std::find(this->Classes.begin(), this->Classes.end(), VertexClass::Hinge) != this->Classes.end();
  this->LiveRefs = static_cast<std::int64_t>(this->Refs.size());
  this->Indexed.clear();
  this->Places.reset();
  this->MergedInto.clear();
  for (std::int32_t v = 0; v < n; ++v)
  {
    this->IndexSpan(v);
  }
  this->Scratch.Marks.assign(n, 0);
  this->Scratch.Stamp = 0;
  this->History.clear();
  this->HistoryUndo.clear();
  this->Undone.clear();
  this->UndoneUndo.clear();
  this->Changes.clear();
  this->RemovedTriangles.clear();
  mesh = CompactMesh();
}

void CollapseMesh::SetPoint(std::int32_t v, const Eigen::Vector3d& x)
{
  this->Points[v] = x;
}

Eigen::Vector3d CollapseMesh::Normal(std::int32_t t) const
{
  const std::int32_t* tri = this->Triangle(t);
  const Eigen::Vector3d cross =
    (this->Points[tri[1]] - this->Points[tri[0]]).cross(this->Points[tri[2]] - this->Points[tri[0]]);
  const double length = cross.norm();
  return length > 0.0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
}

double CollapseMesh::Area(std::int32_t t) const
{
  const std::int32_t* tri = this->Triangle(t);
  return 0.5 *
    (this->Points[tri[1]] - this->Points[tri[0]]).cross(this->Points[tri[2]] - this->Points[tri[0]]).norm();
}

std::uint32_t CollapseMesh::NewMarks(std::uint32_t count, CheckScratch& scratch) const
{
  if (scratch.Marks.size() < this->Points.size() ||
    scratch.Stamp > std::numeric_limits<std::uint32_t>::max() - count)
  {
    scratch.Marks.assign(this->Points.size(), 0u);
    scratch.Stamp = 0;
  }
  const std::uint32_t first = scratch.Stamp + 1;
  scratch.Stamp += count;
  return first;
}

void CollapseMesh::Neighbours(std::int32_t v, std::vector<std::int32_t>& out) const
{
  this->Neighbours(v, out, this->Scratch);
}

void CollapseMesh::Neighbours(std::int32_t v, std::vector<std::int32_t>& out, CheckScratch& scratch) const
{
  out.clear();
  const std::uint32_t mark = this->NewMarks(1, scratch);
  scratch.Marks[v] = mark;
  this->ForEachTriangle(v, [&](std::int32_t t) {
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t w = this->Triangles[3 * t + k];
      if (scratch.Marks[w] != mark)
      {
        scratch.Marks[w] = mark;
        out.push_back(w);
      }
    }
  });
}

int CollapseMesh::HingeEnds(std::int32_t v, std::int32_t ends[2]) const
{
  // v's far edges list each neighbour once per triangle of its edge with v.
  std::vector<std::int32_t> around;
  this->ForEachCorner(v, [&around](std::int32_t, std::int32_t next, std::int32_t previous) {
    around.push_back(next);
    around.push_back(previous);
  });
  std::sort(around.begin(), around.end());
  int found = 0;
  for (std::size_t run = 0, next = 0; run < around.size(); run = next)
  {
    next = std::upper_bound(around.begin() + run, around.end(), around[run]) - around.begin();
    if (next - run >= 3)
    {
      if (found < 2)
      {
        ends[found] = around[run];
      }
      ++found;
    }
  }
  return found;
}

std::int32_t CollapseMesh::Valence(std::int32_t v, CheckScratch& scratch) const
{
  // A manifold fan has as many neighbours as triangles, one more when it is open.
  if (this->Classes[v] == VertexClass::NonManifold || this->Classes[v] == VertexClass::Hinge)
  {
    this->Neighbours(v, scratch.Vertices, scratch);
    return static_cast<std::int32_t>(scratch.Vertices.size());
  }
  return this->Count[v] + (this->OnBoundary(v) ? 1 : 0);
}

void CollapseMesh::Surviving(std::vector<std::int32_t>& used, std::vector<std::int32_t>& triangles,
  std::vector<std::int32_t>& kept) const
{
  const std::int32_t n = this->NumberOfPoints();
  const std::int32_t m = this->NumberOfTriangles();
  std::vector<std::int32_t> index(n, -1);
  for (std::int32_t t = 0; t < m; ++t)
  {
    if (this->Alive[t])
    {
      index[this->Triangles[3 * t]] = index[this->Triangles[3 * t + 1]] = index[this->Triangles[3 * t + 2]] = 0;
    }
  }
  used.clear();
  for (std::int32_t v = 0; v < n; ++v)
  {
    if (index[v] == 0)
    {
      index[v] = static_cast<std::int32_t>(used.size());
      used.push_back(v);
    }
  }
  triangles.clear();
  kept.clear();
  for (std::int32_t t = 0; t < m; ++t)
  {
    if (this->Alive[t])
    {
      for (int k = 0; k < 3; ++k)
      {
        triangles.push_back(index[this->Triangles[3 * t + k]]);
      }
      kept.push_back(t);
    }
  }
}

std::vector<std::int32_t> CollapseMesh::SortedTrianglesAround(std::int32_t v) const
{
  std::vector<std::int32_t> list;
  this->ForEachTriangle(v, [&](std::int32_t t) { list.push_back(t); });
  std::sort(list.begin(), list.end());
  return list;
}

/// What LinkCondition gathers about the edge (m, next), m being the merged vertices as one.
struct CollapseMesh::LinkState
{
  std::uint32_t InSet, Neighbour, Common, NextOnly; // marks: see LinkCondition
  bool MergedOnBoundary = false, MergedOnHinge = false;
  std::int32_t ValenceM = 0, ValenceNext = 0;
  // The far corners of the triangles (m, next, w): the first two here, more (a hinge edge) in
  // the scratch's FarCorners.
  std::int32_t Opposite[2] = { -1, -1 };
  int OppositeCount = 0, CommonCount = 0;
};

bool CollapseMesh::LinkCondition(
  const std::int32_t* merged, int count, std::int32_t next, CheckScratch& scratch) const
{
  // The state is the mesh after merging `merged` into one vertex m (triangles with two of them
  // are gone); the question is whether the edge (m, next) may collapse. Marks: InSet = a merged
  // vertex, Neighbour = a neighbour of m, Common = a neighbour of both m and next, NextOnly = a
  // neighbour of next alone.
  LinkState link;
  link.InSet = this->NewMarks(4, scratch);
  link.Neighbour = link.InSet + 1;
  link.Common = link.InSet + 2;
  link.NextOnly = link.InSet + 3;
  this->MarkMergedNeighbours(merged, count, link, scratch);
  this->ScanAroundNext(next, link, scratch);
  // The checks, in order: triangles on the edge, with distinct far corners (more than two only
  // along a hinge, whose collapse the locks check admitted); the common neighbours are exactly
  // the far corners (the link condition); no two vertices of a boundary or hinge joined across
  // a sheet (a pinch); nobody falls below three neighbours (two on the boundary): the merged
  // vertex keeps m's neighbours but next and next's neighbours but m, the common ones once;
  // each far corner loses one.
  const std::int32_t* opposite = link.Opposite;
  const int sides = link.OppositeCount;
  if (sides == 0 || (sides == 2 && opposite[0] == opposite[1]))
  {
    return false;
  }
  if (link.CommonCount != sides ||
    std::any_of(opposite, opposite + std::min(sides, 2), [&](std::int32_t w) { return scratch.Marks[w] != link.Common; }))
  {
    return false;
  }
  const bool nextOnBoundary = this->OnBoundary(next);
  const bool mergedOnCrease = link.MergedOnBoundary || link.MergedOnHinge;
  if (mergedOnCrease && (nextOnBoundary || this->OnHinge(next)) && sides == 2)
  {
    return false;
  }
  const std::int32_t valenceAfter = (link.ValenceM - 1) + link.ValenceNext - link.CommonCount;
  if (valenceAfter < (link.MergedOnBoundary || nextOnBoundary ? 2 : 3))
  {
    return false;
  }
  const auto losesTooMany = [&](std::int32_t w) {
    return this->Valence(w, scratch) - 1 < (this->OnBoundary(w) ? 2 : 3);
  };
  // A manifold far corner in a tetrahedron (m, next, x, y) has three neighbours, which the
  // valence check refuses; a non-manifold or hinge one needs the check of the far corners.
  const auto manifold = [this](std::int32_t w) {
    return this->Classes[w] != VertexClass::NonManifold && this->Classes[w] != VertexClass::Hinge;
  };
  const bool manifoldFarCorners = sides <= 2 && std::all_of(opposite, opposite + sides, manifold);
  // Valence may reuse the scratch's vertex list and marks, not FarCorners; the far corners'
  // check comes last, as it takes new marks too.
  return std::none_of(opposite, opposite + std::min(sides, 2), losesTooMany) &&
    (manifoldFarCorners ||
      (std::none_of(scratch.FarCorners.begin(), scratch.FarCorners.begin() + std::max(0, sides - 2), losesTooMany) &&
        this->FarCornersKeepApart(merged, count, next, link, scratch)));
}

MESHSIMP_RARE_PATH bool CollapseMesh::FarCornersKeepApart(
  const std::int32_t* merged, int count, std::int32_t next, const LinkState& link, CheckScratch& scratch) const
{
  // The link condition's edge part, which neighbour counts cover only for manifold far corners:
  // the far corners are distinct; no two of them x, y span both a triangle (m, x, y) and a
  // triangle (next, x, y) (the two would become one triangle twice); and no far corner w has
  // edges of three or more triangles to both m and next (the merged edge would gain triangles).
  std::vector<std::int32_t>& far = scratch.FarCorners;
  far.resize(static_cast<std::size_t>(std::max(0, link.OppositeCount - 2)));
  far.insert(far.end(), link.Opposite, link.Opposite + std::min(link.OppositeCount, 2));
  std::sort(far.begin(), far.end());
  if (std::adjacent_find(far.begin(), far.end()) != far.end())
  {
    return false;
  }
  const std::uint32_t farMark = this->NewMarks(1, scratch);
  for (const std::int32_t w : far)
  {
    scratch.Marks[w] = farMark;
  }
  // The far edges (x, y) of next's triangles with two far corners, then m's triangles'.
  std::vector<std::int32_t>& pairs = scratch.Vertices;
  pairs.clear();
  this->ForEachTriangle(next, [&](std::int32_t t) {
    const std::int32_t* tri = this->Triangle(t);
    const int k = tri[0] == next ? 0 : tri[1] == next ? 1 : 2;
    const std::int32_t x = tri[(k + 1) % 3], y = tri[(k + 2) % 3];
    if (scratch.Marks[x] == farMark && scratch.Marks[y] == farMark)
    {
      pairs.push_back(std::min(x, y));
      pairs.push_back(std::max(x, y));
    }
  });
  bool closes = false;
  for (int i = 0; i < count && !closes && !pairs.empty(); ++i)
  {
    this->ForEachTriangle(merged[i], [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      const int k = tri[0] == merged[i] ? 0 : tri[1] == merged[i] ? 1 : 2;
      const std::int32_t x = std::min(tri[(k + 1) % 3], tri[(k + 2) % 3]);
      const std::int32_t y = std::max(tri[(k + 1) % 3], tri[(k + 2) % 3]);
      for (std::size_t j = 0; j < pairs.size() && !closes; j += 2)
      {
        closes = pairs[j] == x && pairs[j + 1] == y;
      }
    });
  }
  // Each far corner's triangles with next, and with one merged vertex (m's edge to it); the
  // valence check has overwritten the merged vertices' marks.
  for (std::size_t j = 0; j < far.size() && !closes; ++j)
  {
    int withNext = 0, withMerged = 0;
    this->ForEachTriangle(far[j], [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      withNext += Contains(tri, next) ? 1 : 0;
      withMerged += std::count_if(merged, merged + count, [tri](std::int32_t v) { return Contains(tri, v); }) == 1;
    });
    closes = withNext >= 3 && withMerged >= 3;
  }
  return !closes;
}

void CollapseMesh::MarkMergedNeighbours(
  const std::int32_t* merged, int count, LinkState& link, CheckScratch& scratch) const
{
  // The merged vertices, and m's neighbours (the corners of triangles with one merged vertex).
  for (int i = 0; i < count; ++i)
  {
    scratch.Marks[merged[i]] = link.InSet;
    link.MergedOnBoundary = link.MergedOnBoundary || this->OnBoundary(merged[i]);
    link.MergedOnHinge = link.MergedOnHinge || (this->HasHingeVertices && this->OnHinge(merged[i]));
  }
  for (int i = 0; i < count; ++i)
  {
    this->ForEachTriangle(merged[i], [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      if (this->MergedCount(tri, link.InSet, scratch) != 1)
      {
        return;
      }
      for (int k = 0; k < 3; ++k)
      {
        if (scratch.Marks[tri[k]] != link.InSet && scratch.Marks[tri[k]] != link.Neighbour)
        {
          scratch.Marks[tri[k]] = link.Neighbour;
          ++link.ValenceM;
        }
      }
    });
  }
}

void CollapseMesh::ScanAroundNext(std::int32_t next, LinkState& link, CheckScratch& scratch) const
{
  // The far corners of the triangles (m, next, w), and next's neighbours: common or its own.
  this->ForEachTriangle(next, [&](std::int32_t t) {
    const std::int32_t* tri = this->Triangle(t);
    const int inside = this->MergedCount(tri, link.InSet, scratch);
    if (inside >= 2)
    {
      return; // gone with the earlier merge
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t w = tri[k];
      if (w == next || scratch.Marks[w] == link.InSet)
      {
        continue;
      }
      if (inside == 1)
      {
        if (link.OppositeCount < 2)
        {
          link.Opposite[link.OppositeCount] = w;
        }
        else
        {
          if (link.OppositeCount == 2)
          {
            scratch.FarCorners.clear();
          }
          scratch.FarCorners.push_back(w);
        }
        ++link.OppositeCount;
      }
      if (scratch.Marks[w] == link.Neighbour)
      {
        scratch.Marks[w] = link.Common;
        ++link.CommonCount;
        ++link.ValenceNext;
      }
      else if (scratch.Marks[w] != link.Common && scratch.Marks[w] != link.NextOnly)
      {
        // Not a neighbour of m: counted once.
        scratch.Marks[w] = link.NextOnly;
        ++link.ValenceNext;
      }
    }
  });
}

template <typename F>
bool CollapseMesh::ForEachChangedTriangle(const CollapsePlan& plan, F&& f) const
{
  for (int i = 0; i < plan.Count; ++i)
  {
    const std::int32_t s = plan.Vertices[i];
    // A vertex that stays where it is (the kept end of a half-edge) changes only the triangles
    // it shares with the other merged vertices, and those are removed.
    if (plan.Position == this->Points[s])
    {
      continue;
    }
    bool ok = true;
    this->ForEachTriangle(s, [&](std::int32_t t) {
      if (!ok)
      {
        return;
      }
      const std::int32_t* tri = this->Triangle(t);
      int inside = 0;
      for (int j = 0; j < plan.Count; ++j)
      {
        inside += Contains(tri, plan.Vertices[j]) ? 1 : 0;
      }
      if (inside > 1)
      {
        return; // removed by the collapse
      }
      const int k = tri[0] == s ? 0 : tri[1] == s ? 1 : 2;
      ok = f(s, t, tri[(k + 1) % 3], tri[(k + 2) % 3]);
    });
    if (!ok)
    {
      return false;
    }
  }
  return true;
}

double CollapseMesh::SmallestNewAngleCosine(const CollapsePlan& plan) const
{
  double worst = -1.0;
  this->ForEachChangedTriangle(plan, [&](std::int32_t, std::int32_t, std::int32_t p, std::int32_t q) {
    worst = std::max(worst, SmallestAngleCosine(plan.Position, this->Points[p], this->Points[q]));
    return true;
  });
  return worst;
}

bool CollapseMesh::FoldsAcross(const CollapsePlan& plan, std::int32_t t, std::int32_t p, std::int32_t q,
  const Eigen::Vector3d& before, const Eigen::Vector3d& after) const
{
  // Whether t, turned from normal before to after, would face against the unchanged triangle
  // across its edge pq (normals over 150 degrees apart) more than it did: a wall triangle laid
  // onto the face at its rim, overlapping it back to back.
  bool folds = false;
  this->ForEachTriangleOnEdge(p, q, [&](std::int32_t n) {
    const std::int32_t* o = this->Triangle(n);
    // t itself, or a neighbour the plan changes too (which the link condition already refuses
    // where it would become t's twin): only unchanged neighbours are compared.
    const bool changed = n == t ||
      std::any_of(plan.Vertices, plan.Vertices + plan.Count, [o](std::int32_t v) { return Contains(o, v); });
    if (changed || folds)
    {
      return;
    }
    const Eigen::Vector3d beside =
      (this->Points[o[1]] - this->Points[o[0]]).cross(this->Points[o[2]] - this->Points[o[0]]);
    const double cosAfter = after.dot(beside) / (after.norm() * beside.norm());
    const double cosBefore = before.dot(beside) / (before.norm() * beside.norm());
    folds = cosAfter < -FoldCosine && cosAfter < cosBefore;
  });
  return folds;
}

CollapseCheck CollapseMesh::ChangedTrianglesCheck(const CollapsePlan& plan) const
{
  const Eigen::Vector3d& x = plan.Position;
  const bool guardAngles = plan.GuardAngles && this->MinimumAngleCosine < 1.0;
  double worstAfter = -1.0; // cosine of the smallest new angle
  CollapseCheck failed = CollapseCheck::Passed;
  this->ForEachChangedTriangle(plan,
    [&](std::int32_t s, std::int32_t t, std::int32_t pId, std::int32_t qId) {
      const Eigen::Vector3d& old = this->Points[s];
      const Eigen::Vector3d& p = this->Points[pId];
      const Eigen::Vector3d& q = this->Points[qId];
      const Eigen::Vector3d edge = q - p;
      const Eigen::Vector3d normal = (p - old).cross(q - old);
      // Franc, "Methods for Polygonal Mesh Simplification", §5.3: the plane through the
      // opposite edge, perpendicular to the triangle.
      const Eigen::Vector3d inward = normal.cross(edge);
      const double sideOld = inward.dot(old - p);
      const double sideNew = inward.dot(x - p);
      if (!(sideOld > 0.0 && sideNew > 0.0) && !(sideOld < 0.0 && sideNew < 0.0))
      {
        failed = CollapseCheck::PlaneSide;
        return false;
      }
      if (guardAngles)
      {
        worstAfter = std::max(worstAfter, SmallestAngleCosine(x, p, q));
      }
      // Degenerate: a new triangle of (almost) zero area. (A turned-over one has failed the
      // plane-side test already: both measure which side of the edge x is on.)
      const Eigen::Vector3d newNormal = (p - x).cross(q - x);
      if (!(newNormal.squaredNorm() > 1e-24 * edge.squaredNorm() * edge.squaredNorm()))
      {
        failed = CollapseCheck::Degenerate;
        return false;
      }
      const double turn = newNormal.dot(normal);
      if (!(turn > FoldCheckTurnCosine * newNormal.norm() * normal.norm()) &&
        this->FoldsAcross(plan, t, pId, qId, normal, newNormal))
      {
        failed = CollapseCheck::FoldAcross;
        return false;
      }
      return true;
    });
  if (failed != CollapseCheck::Passed)
  {
    return failed;
  }
  // The angle guard: no new angle below the minimum unless the neighbourhood had one as small
  // (measured only when a new angle is below the minimum).
  if (!guardAngles || worstAfter <= this->MinimumAngleCosine)
  {
    return CollapseCheck::Passed;
  }
  double worstBefore = -1.0;
  for (int i = 0; i < plan.Count; ++i)
  {
    this->ForEachTriangle(
      plan.Vertices[i], [&](std::int32_t t) { worstBefore = std::max(worstBefore, this->SmallestAngleCosineOf(t)); });
  }
  return worstAfter <= worstBefore ? CollapseCheck::Passed : CollapseCheck::AngleGuard;
}

void CollapseMesh::SetMinimumAngle(double degrees)
{
  this->MinimumAngleCosine = degrees > 0.0 ? std::cos(degrees * 3.14159265358979323846 / 180.0) : 1.0;
}

CollapseCheck CollapseMesh::FirstFailedCheck(const CollapsePlan& plan, CheckScratch& scratch) const
{
  if (plan.Count < 2 || plan.Count > 3 || !plan.Position.allFinite())
  {
    return CollapseCheck::Plan;
  }
  const std::int32_t* v = plan.Vertices;
  if (v[0] == v[1] || (plan.Count == 3 && (v[2] == v[0] || v[2] == v[1])))
  {
    return CollapseCheck::Plan;
  }
  const bool removesLocked =
    std::any_of(v + 1, v + plan.Count, [this](std::int32_t w) { return this->Locked[w] != 0; });
  if (removesLocked || (this->Locked[v[0]] && plan.Position != this->Points[v[0]]) ||
    (this->HasHingeVertices && !this->StaysOnHinges(plan)))
  {
    return CollapseCheck::Locks;
  }
  if (!this->Regions.empty() &&
    (this->Regions[v[1]] != this->Regions[v[0]] || (plan.Count == 3 && this->Regions[v[2]] != this->Regions[v[0]])))
  {
    return CollapseCheck::Regions;
  }
  if (!this->LinkCondition(v, 1, v[1], scratch) ||
    (plan.Count == 3 && !this->LinkCondition(v, 2, v[2], scratch)))
  {
    return CollapseCheck::LinkCondition;
  }
  if (this->HasSharedLocks && this->Locked[v[0]] == SharedPointLock &&
    !this->KeepsSharedEdges(plan, scratch))
  {
    return CollapseCheck::SharedEdges;
  }
  return this->ChangedTrianglesCheck(plan);
}

MESHSIMP_RARE_PATH bool CollapseMesh::StaysOnHinges(const CollapsePlan& plan) const
{
  // A hinge vertex never moves: kept, it stays where it is; merged, it goes along one of its
  // hinge edges (of three or more triangles) to the kept vertex at the other end, which is on
  // the hinge too (a hinge vertex, or a locked end or turn of it).
  const std::int32_t kept = plan.Vertices[0];
  if (this->OnHinge(kept) && plan.Position != this->Points[kept])
  {
    return false;
  }
  for (int i = 1; i < plan.Count; ++i)
  {
    if (!this->OnHinge(plan.Vertices[i]))
    {
      continue;
    }
    if (!IsOwnEdge(VertexClass::Hinge, this->TrianglesOnEdge(kept, plan.Vertices[i])))
    {
      return false;
    }
  }
  return true;
}

bool CollapseMesh::KeepsSharedEdges(const CollapsePlan& plan, CheckScratch& scratch) const
{
  // The kept vertex's neighbours are marked; a shared neighbour of a merged vertex that is not
  // among them would be a new edge between two shared vertices.
  const std::int32_t kept = plan.Vertices[0];
  const std::uint32_t near = this->NewMarks(1, scratch);
  this->ForEachTriangle(kept, [&](std::int32_t t) {
    const std::int32_t* tri = this->Triangle(t);
    scratch.Marks[tri[0]] = scratch.Marks[tri[1]] = scratch.Marks[tri[2]] = near;
  });
  for (int i = 1; i < plan.Count; ++i)
  {
    scratch.Marks[plan.Vertices[i]] = near;
  }
  bool keeps = true;
  for (int i = 1; i < plan.Count && keeps; ++i)
  {
    this->ForEachTriangle(plan.Vertices[i], [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      for (int k = 0; k < 3; ++k)
      {
        keeps = keeps && (this->Locked[tri[k]] != SharedPointLock || scratch.Marks[tri[k]] == near);
      }
    });
  }
  return keeps;
}

void CollapseMesh::SetSpan(std::int32_t v, const std::vector<std::int32_t>& triangles)
{
  const std::int32_t size = static_cast<std::int32_t>(triangles.size());
  this->LiveRefs += size - this->Count[v];
  if (size > this->Count[v])
  {
    this->Start[v] = static_cast<std::int64_t>(this->Refs.size());
    this->Refs.insert(this->Refs.end(), triangles.begin(), triangles.end());
  }
  else
  {
    std::copy(triangles.begin(), triangles.end(), this->Refs.begin() + this->Start[v]);
  }
  this->Count[v] = size;
  this->IndexSpan(v);
}

void CollapseMesh::IndexSpan(std::int32_t v)
{
  if (this->Count[v] <= IndexedSpan)
  {
    if (!this->Indexed.empty())
    {
      this->Indexed[v] = 0;
    }
    return;
  }
  if (this->Indexed.empty())
  {
    // Zeroed by calloc, whose large blocks are fresh pages of zeros never written: only the
    // pages holding a fan's corners take memory, not 12 bytes for every triangle. A place read
    // back is always checked against the span (a zero where none was written is a stale hint).
    this->Indexed.assign(this->Points.size(), 0);
    this->Places.reset(static_cast<std::int32_t*>(std::calloc(this->Triangles.size(), sizeof(std::int32_t))));
    if (!this->Places)
    {
      throw std::bad_alloc();
    }
  }
  this->Indexed[v] = 1;
  const std::int32_t* ids = this->Refs.data() + this->Start[v];
  for (std::int32_t i = 0; i < this->Count[v]; ++i)
  {
    this->PlaceIn(v, ids[i]) = i;
  }
}

std::int32_t& CollapseMesh::PlaceIn(std::int32_t v, std::int32_t t)
{
  const std::int32_t* tri = this->Triangle(t);
  return this->Places[3 * static_cast<std::size_t>(t) + (tri[0] == v ? 0 : tri[1] == v ? 1 : 2)];
}

void CollapseMesh::DropFromSpan(std::int32_t w, std::int32_t t)
{
  std::int32_t* first = this->Refs.data() + this->Start[w];
  std::int32_t* last = first + this->Count[w];
  const bool indexed = !this->Indexed.empty() && this->Indexed[w];
  if (indexed)
  {
    const std::int32_t place = this->PlaceIn(w, t);
    if (place >= 0 && place < this->Count[w] && first[place] == t)
    {
      const std::int32_t moved = *(last - 1);
      first[place] = moved;
      this->PlaceIn(w, moved) = place;
      *(last - 1) = -1; // a free slot for AddToIndexedSpan
      --this->Count[w];
      return;
    }
  }
  std::int32_t* found = std::find(first, last, t); // a span lists a triangle once
  if (found != last)
  {
    std::copy(found + 1, last, found);
    --this->Count[w];
    if (indexed)
    {
      this->IndexSpan(w);
    }
  }
}

void CollapseMesh::AddToIndexedSpan(std::int32_t w, std::int32_t t)
{
  std::int32_t& place = this->PlaceIn(w, t);
  const std::int64_t start = this->Start[w], end = start + this->Count[w];
  if (place >= 0 && place < this->Count[w] && this->Refs[start + place] == t)
  {
    return;
  }
  if (end == static_cast<std::int64_t>(this->Refs.size()) || this->Refs[end] != -1)
  {
    // No free slot after the span: it moves to the end, followed by as many free slots.
    const std::int64_t moved = static_cast<std::int64_t>(this->Refs.size());
    this->Refs.resize(this->Refs.size() + 2 * static_cast<std::size_t>(this->Count[w]) + 1, -1);
    std::copy(this->Refs.begin() + start, this->Refs.begin() + end, this->Refs.begin() + moved);
    this->Start[w] = moved;
  }
  place = this->Count[w]++;
  this->Refs[this->Start[w] + place] = t;
  ++this->LiveRefs;
}

void CollapseMesh::CompactRefs(const ExecutionContext& context)
{
  // Each part of the vertices counts its spans' entries, then copies them from its offset.
  const std::int64_t n = this->NumberOfPoints();
  const std::int64_t parts = std::max<std::int64_t>(1, std::min<std::int64_t>(context.Threads, n / 16384));
  std::vector<std::int64_t> offsets(parts + 1, 0);
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::int64_t entries = 0;
      for (std::int64_t v = n * part / parts, last = n * (part + 1) / parts; v < last; ++v)
      {
        entries += this->Count[v];
      }
      offsets[part + 1] = entries;
    }
  }, n);
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::int32_t> refs(static_cast<std::size_t>(offsets[parts]));
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::int64_t at = offsets[part];
      for (std::int64_t v = n * part / parts, last = n * (part + 1) / parts; v < last; ++v)
      {
        const std::int32_t* span = this->Refs.data() + this->Start[v];
        std::copy(span, span + this->Count[v], refs.data() + at);
        this->Start[v] = at;
        at += this->Count[v];
      }
    }
  }, 4 * offsets[parts] + n);
  this->Refs = std::move(refs);
  this->LiveRefs = static_cast<std::int64_t>(this->Refs.size());
}

int CollapseMesh::Merge(
  const CollapsePlan& plan, std::vector<std::int32_t>& span, bool keepUndo, std::int64_t& droppedRefs)
{
  const std::int32_t kept = plan.Vertices[0];
  for (int i = 1; i < plan.Count && !this->MergedInto.empty(); ++i)
  {
    this->MergedInto[plan.Vertices[i]] = kept; // the plans of concurrent merges are disjoint
  }
  span.clear();
  int removed = 0;
  // A removed triangle leaves the span of its corner outside the plan, so that walks around
  // that vertex do not skip it ever after.
  auto dropFromSpan = [&](std::int32_t w, std::int32_t t) {
    if (!this->Shared.empty() && this->Shared[w])
    {
      return; // ApplyIndependent drops it after the concurrent merges
    }
    const std::int32_t before = this->Count[w];
    this->DropFromSpan(w, t);
    droppedRefs += before - this->Count[w];
  };
  for (int i = 0; i < plan.Count; ++i)
  {
    const std::int32_t s = plan.Vertices[i];
    // A triangle of two merged vertices dies when the first of them walks its span; the second
    // must skip it (its span still lists it).
    this->ForEachTriangle(s, [&](std::int32_t t) {
      if (!this->Alive[t])
      {
        return;
      }
      std::int32_t* tri = this->Triangles.data() + 3 * t;
      int inside = 0;
      for (int j = 0; j < plan.Count; ++j)
      {
        inside += Contains(tri, plan.Vertices[j]) ? 1 : 0;
      }
      if (inside > 1)
      {
        this->Alive[t] = 0;
        ++removed;
        if (keepUndo)
        {
          this->RemovedTriangles.push_back(t);
        }
        for (int k = 0; k < 3; ++k)
        {
          bool outside = true;
          for (int j = 0; j < plan.Count; ++j)
          {
            outside = outside && tri[k] != plan.Vertices[j];
          }
          if (outside)
          {
            dropFromSpan(tri[k], t);
          }
        }
        return;
      }
      if (s != kept)
      {
        const int k = tri[0] == s ? 0 : tri[1] == s ? 1 : 2;
        if (keepUndo)
        {
          this->Changes.push_back(3 * t + k);
          this->Changes.push_back(s);
        }
        tri[k] = kept;
      }
      span.push_back(t);
    });
  }
  this->Points[kept] = plan.Position;
  for (int i = 1; i < plan.Count; ++i)
  {
    const VertexClass c = this->Classes[plan.Vertices[i]];
    // (A hinge vertex keeps its class: the pinch check never joins the boundary to it.)
    if ((c == VertexClass::Corner && this->Classes[kept] != VertexClass::Hinge) ||
      (c == VertexClass::Boundary && this->Classes[kept] == VertexClass::Interior))
    {
      this->Classes[kept] = c;
    }
  }
  return removed;
}

int CollapseMesh::Apply(const CollapsePlan& plan, bool keepUndo)
{
  this->Undone.clear(); // a new collapse ends the replay of undone ones
  this->UndoneUndo.clear();
  CollapseRecord record;
  const std::int32_t kept = plan.Vertices[0];
  record.Kept = kept;
  for (int i = 1; i < plan.Count; ++i)
  {
    record.Removed[i - 1] = plan.Vertices[i];
  }
  std::copy(plan.Weights, plan.Weights + 3, record.Weights);
  CollapseUndo undo;
  undo.KeptPosition = this->Points[kept];
  undo.NewPosition = plan.Position;
  undo.KeptClass = this->Classes[kept];
  undo.FirstChange = static_cast<std::int32_t>(this->Changes.size());
  undo.FirstRemovedTriangle = static_cast<std::int32_t>(this->RemovedTriangles.size());

  std::int64_t dropped = 0;
  const int removed = this->Merge(plan, this->Span, keepUndo, dropped);
  this->AliveCount -= removed;
  this->LiveRefs -= dropped;
  for (int i = 1; i < plan.Count; ++i)
  {
    this->LiveRefs -= this->Count[plan.Vertices[i]];
    this->Count[plan.Vertices[i]] = 0;
    this->IndexSpan(plan.Vertices[i]);
  }
  this->SetSpan(kept, this->Span);
  undo.ChangeCount = static_cast<std::int32_t>(this->Changes.size()) / 2 - undo.FirstChange / 2;
  undo.RemovedTriangleCount =
    static_cast<std::int32_t>(this->RemovedTriangles.size()) - undo.FirstRemovedTriangle;
  this->History.push_back(record);
  if (keepUndo)
  {
    this->HistoryUndo.push_back(undo);
  }
  else
  {
    // No undo reaches past this collapse: what earlier ones kept for it is freed.
    this->HistoryUndo.clear();
    this->Changes.clear();
    this->RemovedTriangles.clear();
  }
  if (static_cast<std::int64_t>(this->Refs.size()) > 2 * this->LiveRefs + 4096)
  {
    this->CompactRefs();
  }
  return removed;
}

std::int64_t CollapseMesh::ApplyIndependent(
  const std::vector<CollapsePlan>& plans, const ExecutionContext& context, const std::vector<std::int32_t>& shared)
{
  // Each kept vertex's new span goes to its own slice of one block, sized by the merged
  // vertices' spans together, and the block is appended to Refs once: the concurrent merges
  // write disjoint triangles, points and slices.
  const std::int64_t count = static_cast<std::int64_t>(plans.size());
  std::vector<std::int64_t> offsets(count + 1, 0);
  for (std::int64_t i = 0; i < count; ++i)
  {
    std::int64_t room = 0;
    for (int j = 0; j < plans[i].Count; ++j)
    {
      room += this->Count[plans[i].Vertices[j]];
    }
    offsets[i + 1] = offsets[i] + room;
  }
  std::vector<std::int32_t> block(offsets[count]);
  std::vector<std::int32_t> sizes(count), removedCounts(count);
  std::vector<std::int64_t> droppedRefs(count, 0);
  if (!shared.empty())
  {
    this->Shared.resize(this->Points.size(), 0);
  }
  for (const std::int32_t w : shared)
  {
    this->Shared[w] = 1;
  }
  context.For(count, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::int32_t> span;
    for (std::int64_t i = begin; i < end; ++i)
    {
      // The merged vertices' spans a few plans ahead, as PrefetchStars.
      for (int j = 0; i + PrefetchDistance < end && j < plans[i + PrefetchDistance].Count; ++j)
      {
        this->PrefetchPlace(plans[i + PrefetchDistance].Vertices[j]);
      }
      for (int j = 0; i + PrefetchDistance / 2 < end && j < plans[i + PrefetchDistance / 2].Count; ++j)
      {
        this->PrefetchSpan(plans[i + PrefetchDistance / 2].Vertices[j]);
      }
      removedCounts[i] = this->Merge(plans[i], span, false, droppedRefs[i]);
      std::copy(span.begin(), span.end(), block.begin() + offsets[i]);
      sizes[i] = static_cast<std::int32_t>(span.size());
    }
  }, 8 * offsets[count]);

  const std::int64_t base = static_cast<std::int64_t>(this->Refs.size());
  this->Refs.insert(this->Refs.end(), block.begin(), block.end());
  std::int64_t removed = 0;
  for (std::int64_t i = 0; i < count; ++i)
  {
    const CollapsePlan& plan = plans[i];
    for (int j = 1; j < plan.Count; ++j)
    {
      this->LiveRefs -= this->Count[plan.Vertices[j]];
      this->Count[plan.Vertices[j]] = 0;
      this->IndexSpan(plan.Vertices[j]);
    }
    const std::int32_t kept = plan.Vertices[0];
    this->LiveRefs += sizes[i] - this->Count[kept];
    this->Start[kept] = base + offsets[i];
    this->Count[kept] = sizes[i];
    this->IndexSpan(kept);
    this->LiveRefs -= droppedRefs[i];
    removed += removedCounts[i];
  }
  this->AliveCount -= removed;
  // The shared vertices' spans lose their dead triangles (order kept) after all the merges.
  for (const std::int32_t w : shared)
  {
    std::int32_t* first = this->Refs.data() + this->Start[w];
    std::int32_t* last = first + this->Count[w];
    std::int32_t* end = std::remove_if(first, last, [this](std::int32_t t) { return !this->Alive[t]; });
    this->LiveRefs -= last - end;
    this->Count[w] = static_cast<std::int32_t>(end - first);
    this->Shared[w] = 0;
    this->IndexSpan(w);
  }
  this->Undone.clear();
  this->UndoneUndo.clear();
  this->HistoryUndo.clear(); // no undo reaches past a batch: what earlier ones kept is freed
  this->Changes.clear();
  this->RemovedTriangles.clear();
  if (static_cast<std::int64_t>(this->Refs.size()) > 2 * this->LiveRefs + 4096)
  {
    this->CompactRefs(context);
  }
  return removed;
}

void CollapseMesh::Undo()
{
  if (this->HistoryUndo.empty())
  {
    return;
  }
  const CollapseRecord record = this->History.back();
  const CollapseUndo undo = this->HistoryUndo.back();
  this->History.pop_back();
  this->HistoryUndo.pop_back();
  this->Undone.push_back(record);
  this->UndoneUndo.push_back(undo);
  const std::int32_t kept = record.Kept;
  for (int i = 0; i < 2 && !this->MergedInto.empty(); ++i)
  {
    if (record.Removed[i] >= 0)
    {
      this->MergedInto[record.Removed[i]] = -1;
    }
  }
  // Candidates for the restored spans: the kept vertex's triangles and the revived ones.
  std::vector<std::int32_t> candidates;
  this->ForEachTriangle(kept, [&](std::int32_t t) { candidates.push_back(t); });
  for (std::int32_t i = 0; i < undo.RemovedTriangleCount; ++i)
  {
    const std::int32_t t = this->RemovedTriangles[undo.FirstRemovedTriangle + i];
    this->Alive[t] = 1;
    candidates.push_back(t);
  }
  this->AliveCount += undo.RemovedTriangleCount;
  for (std::int32_t i = undo.ChangeCount - 1; i >= 0; --i)
  {
    const std::int32_t* change = this->Changes.data() + undo.FirstChange + 2 * i;
    this->Triangles[change[0]] = change[1];
  }
  this->Points[kept] = undo.KeptPosition;
  this->Classes[kept] = undo.KeptClass;

  std::vector<std::int32_t> span;
  for (const std::int32_t v : { kept, record.Removed[0], record.Removed[1] })
  {
    if (v < 0)
    {
      continue;
    }
    span.clear();
    for (const std::int32_t t : candidates)
    {
      if (Contains(this->Triangle(t), v))
      {
        span.push_back(t);
      }
    }
    this->SetSpan(v, span);
  }
  // The revived triangles' other corners may have lost them in a compaction.
  for (std::int32_t i = 0; i < undo.RemovedTriangleCount; ++i)
  {
    const std::int32_t t = this->RemovedTriangles[undo.FirstRemovedTriangle + i];
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t w = this->Triangles[3 * t + k];
      if (w == kept || w == record.Removed[0] || w == record.Removed[1])
      {
        continue;
      }
      if (!this->Indexed.empty() && this->Indexed[w])
      {
        this->AddToIndexedSpan(w, t);
        continue;
      }
      const std::int32_t* first = this->Refs.data() + this->Start[w];
      if (std::find(first, first + this->Count[w], t) == first + this->Count[w])
      {
        span.assign(first, first + this->Count[w]);
        span.push_back(t);
        this->SetSpan(w, span);
      }
    }
  }
  this->Changes.resize(undo.FirstChange);
  this->RemovedTriangles.resize(undo.FirstRemovedTriangle);
}

bool CollapseMesh::Redo()
{
  if (this->Undone.empty())
  {
    return false;
  }
  const CollapseRecord record = this->Undone.back();
  const CollapseUndo undo = this->UndoneUndo.back();
  this->Undone.pop_back();
  this->UndoneUndo.pop_back();
  CollapsePlan plan;
  plan.Vertices[plan.Count++] = record.Kept;
  for (const std::int32_t removed : record.Removed)
  {
    if (removed >= 0)
    {
      plan.Vertices[plan.Count++] = removed;
    }
  }
  plan.Position = undo.NewPosition;
  std::copy(record.Weights, record.Weights + 3, plan.Weights);
  std::vector<CollapseRecord> undone;
  std::vector<CollapseUndo> undoneUndo;
  undone.swap(this->Undone); // Apply starts a new branch; this replay continues the old one
  undoneUndo.swap(this->UndoneUndo);
  this->Apply(plan);
  undone.swap(this->Undone);
  undoneUndo.swap(this->UndoneUndo);
  return true;
}

void CollapseMesh::CountRefusal(const CollapsePlan& plan, CollapseCheck failed, RefusalCounts& counts) const
{
  ++counts.ByCheck[static_cast<std::size_t>(failed)];
  if (failed != CollapseCheck::Locks)
  {
    return;
  }
  LockReason reason = LockReason::OffHinge;
  const std::int32_t* v = plan.Vertices;
  const std::int32_t* removed = std::find_if(v + 1, v + plan.Count, [this](std::int32_t w) { return this->Locked[w] != 0; });
  if (removed != v + plan.Count)
  {
    reason = this->WhyLocked(*removed);
  }
  else if (this->Locked[v[0]] && plan.Position != this->Points[v[0]])
  {
    reason = this->WhyLocked(v[0]);
  }
  ++counts.ByLock[LockIndex(reason)];
}

void InterpolateAttributes(const std::vector<CollapseRecord>& records, double* values, int components)
{
  for (const CollapseRecord& r : records)
  {
    double* kept = values + static_cast<std::int64_t>(r.Kept) * components;
    for (int c = 0; c < components; ++c)
    {
      double value = r.Weights[0] * kept[c];
      for (int i = 0; i < 2; ++i)
      {
        if (r.Removed[i] >= 0)
        {
          value += r.Weights[i + 1] * values[static_cast<std::int64_t>(r.Removed[i]) * components + c];
        }
      }
      kept[c] = value;
    }
  }
}

} // namespace meshsimp
