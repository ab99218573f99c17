// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the shared collapse engine (CollapseMesh, CollapseHeap) and of the volume
// triangle collapse core built on it.
#include "CollapseHeap.h"
#include "CollapseLoop.h"
#include "CollapseMesh.h"
#include "PlaneDistanceBound.h"
#include "TestHelpers.h"
#include "TestMeshes.h"
#include "VolumeTriangleCollapse.h"

#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>

using meshsimp::CollapseCheck;
using meshsimp::CollapseHeap;
using meshsimp::CollapseMesh;
using meshsimp::CollapsePlan;
using meshsimp::Corner;
using meshsimp::FanWorkspace;
using meshsimp::VertexClass;

namespace
{
/// The engine over a test mesh, with the engine id of every input point.
struct Engine
{
  CollapseMesh Mesh;
  std::vector<std::int32_t> Id; // input point -> engine vertex

  explicit Engine(const ::Mesh& input)
  {
    meshsimp::CompactMesh compact = meshsimp::MakeCompactMesh(input.View());
    this->Id.assign(input.Points.size() / 3, -1);
    for (std::size_t v = 0; v < compact.InputVertex.size(); ++v)
    {
      this->Id[compact.InputVertex[v]] = static_cast<std::int32_t>(v);
    }
    this->Mesh.Build(std::move(compact));
  }

  CollapsePlan Plan(std::initializer_list<int> inputVertices, const Eigen::Vector3d& x) const
  {
    CollapsePlan plan;
    for (const int v : inputVertices)
    {
      plan.Vertices[plan.Count++] = this->Id[v];
    }
    plan.Position = x;
    return plan;
  }
  Eigen::Vector3d Point(int inputVertex) const { return this->Mesh.Point(this->Id[inputVertex]); }
};

/// Two tetrahedra glued along a triangle's edges: top T, bottom B, equator e0 e1 e2.
Mesh Bipyramid()
{
  Mesh mesh;
  mesh.Points = { 0, 0, 1, 0, 0, -1, 1, 0, 0, -0.5, 0.866, 0, -0.5, -0.866, 0 };
  mesh.Triangles = { 0, 2, 3, 0, 3, 4, 0, 4, 2, 1, 3, 2, 1, 4, 3, 1, 2, 4 };
  return mesh;
}

/// Whether the alive triangles form a closed, consistently oriented 2-manifold (ClosedOriented).
bool ClosedManifold(const CollapseMesh& mesh)
{
  std::vector<std::int32_t> alive;
  for (std::int32_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    if (mesh.IsAlive(t))
    {
      alive.insert(alive.end(), mesh.Triangle(t), mesh.Triangle(t) + 3);
    }
  }
  return ClosedOriented(alive);
}

struct Snapshot
{
  std::vector<Eigen::Vector3d> Points;
  std::vector<std::int32_t> Triangles;
  std::vector<int> Alive, Classes;
  std::vector<std::vector<std::int32_t>> Around;
  bool operator==(const Snapshot& o) const
  {
    return this->Points == o.Points && this->Triangles == o.Triangles && this->Alive == o.Alive &&
      this->Classes == o.Classes && this->Around == o.Around;
  }
};

Snapshot Take(const CollapseMesh& mesh)
{
  Snapshot s;
  for (std::int32_t v = 0; v < mesh.NumberOfPoints(); ++v)
  {
    s.Points.push_back(mesh.Point(v));
    s.Classes.push_back(static_cast<int>(mesh.Class(v)));
    s.Around.push_back(mesh.SortedTrianglesAround(v));
  }
  for (std::int32_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    s.Triangles.insert(s.Triangles.end(), mesh.Triangle(t), mesh.Triangle(t) + 3);
    s.Alive.push_back(mesh.IsAlive(t) ? 1 : 0);
  }
  return s;
}

void HeapOrderAndTieRule()
{
  CollapseHeap heap(6);
  heap.Set(0, 2.0);
  heap.Set(1, 0.0);
  heap.Set(2, 1.0);
  heap.Set(3, 0.0);
  heap.Set(4, 0.0);
  heap.Set(5, 3.0);
  heap.Set(1, 0.0); // cost set again: behind the zero-cost ones waiting (Zhou, Zhang and Cheng §3.5)
  heap.Set(5, 0.5); // decrease-key
  heap.Set(0, 4.0); // increase-key
  heap.Remove(2);
  std::vector<std::int32_t> order;
  while (!heap.Empty())
  {
    order.push_back(heap.Pop());
  }
  CHECK((order == std::vector<std::int32_t>{ 3, 4, 1, 5, 0 }));
  CHECK(!heap.Contains(2));

  // Sequence numbers renumbered when they run out (here after 4) keep the same order.
  CollapseHeap small(6, 4);
  for (const std::pair<std::int32_t, double> set :
    { std::pair<std::int32_t, double>{ 0, 2.0 }, { 1, 0.0 }, { 2, 1.0 }, { 3, 0.0 }, { 4, 0.0 },
      { 5, 3.0 }, { 1, 0.0 }, { 5, 0.5 }, { 0, 4.0 } })
  {
    small.Set(set.first, set.second);
  }
  small.Remove(2);
  order.clear();
  while (!small.Empty())
  {
    order.push_back(small.Pop());
  }
  CHECK((order == std::vector<std::int32_t>{ 3, 4, 1, 5, 0 }));
}

void VertexClasses()
{
  // Grid corners turn by 90° (corners), the rest of the rim is boundary, the inside interior;
  // a fin of a third triangle on an inner edge makes both its ends non-manifold (and locked).
  Mesh grid = Grid(2);
  Engine plain(grid);
  CHECK(plain.Mesh.Class(plain.Id[0]) == VertexClass::Corner);
  CHECK(plain.Mesh.Class(plain.Id[1]) == VertexClass::Boundary);
  CHECK(plain.Mesh.Class(plain.Id[4]) == VertexClass::Interior);
  CHECK(!plain.Mesh.IsLocked(plain.Id[4]));
  grid.Points.insert(grid.Points.end(), { 0.5, 0.5, 1.0 });
  grid.Triangles.insert(grid.Triangles.end(), { 0, 4, 9 }); // edge 0-4 is the first cell's diagonal
  Engine fin(grid);
  CHECK(fin.Mesh.Class(fin.Id[4]) == VertexClass::NonManifold);
  CHECK(fin.Mesh.IsLocked(fin.Id[4]));
  CHECK(fin.Mesh.Class(fin.Id[0]) == VertexClass::NonManifold);

  // A vertex of 500 triangles (its fan sorted rather than scanned): the centre of a disk is
  // interior, of half the disk a boundary vertex (of the disk less one triangle a corner: its
  // border turns back); the capped disk's two centres are interior, and a second fan through the
  // centre makes it non-manifold.
  Mesh disk = Fan(500);
  Engine whole(disk);
  CHECK(whole.Mesh.Class(whole.Id[0]) == VertexClass::Interior);
  CHECK(whole.Mesh.Class(whole.Id[1]) == VertexClass::Boundary);
  disk.Triangles.resize(disk.Triangles.size() - 3);
  Engine cut(disk);
  CHECK(cut.Mesh.Class(cut.Id[0]) == VertexClass::Corner);
  disk.Triangles.resize(3 * 250);
  Engine half(disk);
  CHECK(half.Mesh.Class(half.Id[0]) == VertexClass::Boundary);
  Engine capped(Fan(500, true));
  CHECK(capped.Mesh.Class(capped.Id[0]) == VertexClass::Interior);
  CHECK(capped.Mesh.Class(capped.Id[501]) == VertexClass::Interior);
  CHECK(capped.Mesh.Class(capped.Id[1]) == VertexClass::Interior);
  Mesh bowtie = Fan(500);
  const int apex = static_cast<int>(bowtie.Points.size() / 3);
  bowtie.Points.insert(bowtie.Points.end(), { 0.0, 0.0, 1.0, 0.1, 0.0, 1.0 });
  bowtie.Triangles.insert(bowtie.Triangles.end(), { 0, apex, apex + 1 });
  Engine pinched(bowtie);
  CHECK(pinched.Mesh.Class(pinched.Id[0]) == VertexClass::NonManifold);
}

void FanClassesFromCorners()
{
  // ClassifyFan on corner lists written out, scanned (6 corners) and sorted (40): corner i of a
  // fan through ring vertices 0..d-1 reads (v, i + 1, i); each case breaks the fan one way.
  for (const std::int32_t degree : { 6, 40 })
  {
    const auto fan = [degree](bool closed) {
      std::vector<Corner> corners;
      for (std::int32_t i = 0; i < degree - (closed ? 0 : 1); ++i)
      {
        corners.push_back({ i, (i + 1) % degree, i });
      }
      return corners;
    };
    FanWorkspace work;
    const auto classify = [&work](const std::vector<Corner>& corners, std::int32_t* ends = nullptr) {
      std::int32_t first = -1, last = -1;
      const VertexClass c = meshsimp::ClassifyFan(corners.data(), corners.data() + corners.size(), first, last, work);
      if (ends)
      {
        ends[0] = first;
        ends[1] = last;
      }
      return c;
    };
    std::int32_t ends[2];
    CHECK(classify({}) == VertexClass::NonManifold); // no triangle: no fan
    CHECK(classify(fan(true), ends) == VertexClass::Interior);
    CHECK(ends[0] == -1 && ends[1] == -1);
    std::vector<Corner> shuffled = fan(true); // a closed fan's corners in any order
    std::reverse(shuffled.begin(), shuffled.end());
    std::rotate(shuffled.begin(), shuffled.begin() + 3, shuffled.end());
    std::swap(shuffled[1], shuffled[degree - 2]);
    CHECK(classify(shuffled) == VertexClass::Interior);
    std::vector<Corner> open = fan(false);
    std::rotate(open.begin(), open.begin() + 2, open.end()); // the opening corner anywhere
    CHECK(classify(open, ends) == VertexClass::Boundary);
    CHECK(open[ends[0]].Previous == 0 && open[ends[1]].Next == degree - 1);
    std::vector<Corner> third = fan(true);
    third.push_back({ degree, 1, 0 }); // edge (v, 1) in three triangles
    CHECK(classify(third) == VertexClass::NonManifold);
    std::vector<Corner> flipped = fan(true);
    std::swap(flipped[3].Next, flipped[3].Previous); // one triangle turned over
    CHECK(classify(flipped) == VertexClass::NonManifold);
    std::vector<Corner> twoFans = fan(true);
    twoFans[degree / 2 - 1].Next = 0;          // the ring closes halfway ...
    twoFans.back().Next = degree / 2;          // ... and a second ring through the other half
    CHECK(classify(twoFans) == VertexClass::NonManifold);
    std::vector<Corner> twoOpen = fan(false);
    twoOpen.erase(twoOpen.begin() + degree / 2); // a gap: two open fans
    CHECK(classify(twoOpen) == VertexClass::NonManifold);
  }
}

void LinkConditionRejectsHiddenCycle()
{
  // On the bipyramid the equator vertices e0, e1 share T and B (their triangles' far corners)
  // and e2, which is not: collapsing e0-e1 would close the cycle e0 e1 e2 (Zhou, Zhang and Cheng, Fig. 8).
  Engine e(Bipyramid());
  const Eigen::Vector3d mid = 0.5 * (e.Point(2) + e.Point(3));
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 2, 3 }, mid)) == CollapseCheck::LinkCondition);
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 0, 2, 3 }, e.Point(0))) == CollapseCheck::LinkCondition);
  // The same on a torus whose tube is a triangle: every vertex has six neighbours, and an edge
  // of the tube's ring would close that ring of three.
  Mesh torus;
  const int rings = 16;
  for (int i = 0; i < rings; ++i)
  {
    const double angle = 2.0 * 3.14159265358979323846 * i / rings;
    for (int j = 0; j < 3; ++j)
    {
      const double tube = 2.0 * 3.14159265358979323846 * j / 3;
      const double radius = 2.0 + 0.5 * std::cos(tube);
      torus.Points.insert(torus.Points.end(),
        { radius * std::cos(angle), radius * std::sin(angle), 0.5 * std::sin(tube) });
    }
  }
  for (int i = 0; i < rings; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const int a = 3 * i + j, b = 3 * i + (j + 1) % 3;
      const int c = 3 * ((i + 1) % rings) + j, d = 3 * ((i + 1) % rings) + (j + 1) % 3;
      torus.Triangles.insert(torus.Triangles.end(), { a, c, d, a, d, b });
    }
  }
  Engine ring(torus);
  CHECK(ring.Mesh.Class(ring.Id[0]) == VertexClass::Interior);
  CHECK(ring.Mesh.FirstFailedCheck(ring.Plan({ 0, 1 }, 0.5 * (ring.Point(0) + ring.Point(1)))) ==
    CollapseCheck::LinkCondition);
  CHECK(ring.Mesh.IsLegal(ring.Plan({ 0, 3 }, 0.5 * (ring.Point(0) + ring.Point(3))))); // along: fine
  // A tetrahedron's edges all fail too (nobody may drop below three neighbours).
  Mesh tetra;
  tetra.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  tetra.Triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
  Engine t(tetra);
  CHECK(t.Mesh.FirstFailedCheck(t.Plan({ 0, 1 }, t.Point(0))) == CollapseCheck::LinkCondition);
}

void LinkConditionRejectsPinch()
{
  // A strip of two quads: the middle rung joins two boundary vertices across the interior.
  Mesh strip;
  strip.Points = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 };
  strip.Triangles = { 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4 };
  Engine e(strip);
  const CollapsePlan across = e.Plan({ 1, 4 }, 0.5 * (e.Point(1) + e.Point(4)));
  CHECK(e.Mesh.FirstFailedCheck(across) == CollapseCheck::LinkCondition);
  // Along the boundary the same mesh may collapse.
  CHECK(e.Mesh.IsLegal(e.Plan({ 4, 3 }, e.Point(4))));
}

void FoldOverAndDegenerateRejected()
{
  Engine e(Grid(4)); // vertex 12 is the centre (2, 2) / 4
  const Eigen::Vector3d centre = e.Point(12);
  // Half-edge collapse of the centre onto its neighbour 13: legal.
  CHECK(e.Mesh.IsLegal(e.Plan({ 13, 12 }, e.Point(13))));
  // The same edge collapsed to a point beyond the ring turns triangles over (§5.3 test).
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 13, 12 }, centre + Eigen::Vector3d(-0.6, 0.0, 0.0))) ==
    CollapseCheck::PlaneSide);
  // A point on the line of an opposite edge makes a triangle of zero area: rejected (the
  // plane-side test sees it on the plane).
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 13, 12 }, Eigen::Vector3d(0.25, 0.5, 0.0))) ==
    CollapseCheck::PlaneSide);
  // So is one a hair inside it (1e-13 off the edge (6, 7)), which the plane-side test lets pass.
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 13, 12 }, Eigen::Vector3d(0.375, 0.25 + 1e-13, 0.0))) ==
    CollapseCheck::Degenerate);
  CHECK(e.Mesh.IsLegal(e.Plan({ 13, 12 }, Eigen::Vector3d(0.375, 0.3, 0.0))));

  // Vertex 14 moved onto the line from 13 to 19: the triangle (13, 14, 19) has no area. Collapsed
  // into 13, which stays, the centre leaves that triangle as it is: legal. Moved, vertex 13 would
  // change it: rejected.
  Mesh flat = Grid(4);
  flat.Points[3 * 14] = 0.875;
  flat.Points[3 * 14 + 1] = 0.625;
  Engine d(flat);
  CHECK(d.Mesh.IsLegal(d.Plan({ 13, 12 }, d.Point(13))));
  CHECK(!d.Mesh.IsLegal(d.Plan({ 13, 12 }, 0.5 * (d.Point(12) + d.Point(13)))));
}

void FoldOntoNeighbourRejected()
{
  // A wall triangle (o, q, p) hangs below the rim pq of a top triangle (p, q, w); collapsing o
  // with r (below it) to a point a hair under the top's plane turns the wall triangle by just
  // under 90 degrees, which the plane-side test lets through: laid inwards it would lie back to
  // back with the top triangle (rejected), laid outwards it continues the top (legal).
  Mesh step;
  step.Points = { -1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -1, 0, -0.5, -2 }; // p q w o r
  step.Triangles = { 0, 1, 2, 3, 1, 0, 4, 1, 3, 4, 3, 0 };
  Engine e(step);
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 3, 4 }, Eigen::Vector3d(0.0, 0.1, -1e-9))) ==
    CollapseCheck::FoldAcross);
  CHECK(e.Mesh.IsLegal(e.Plan({ 3, 4 }, Eigen::Vector3d(0.0, -0.1, -1e-9))));
  CHECK(e.Mesh.IsLegal(e.Plan({ 3, 4 }, Eigen::Vector3d(0.0, 0.1, -0.5)))); // turned by 27 degrees
}

void AngleGuardRejectsNewSlivers()
{
  // Collapsing the grid's centre 12 and its neighbour 13 to a point just above vertex 8 makes
  // triangle (7, 8, x) a sliver (an angle of about 2 degrees at 7): allowed without the guard,
  // refused with a 10 degree guard, while the edge's midpoint keeps every angle above 10.
  Engine e(Grid(4));
  const Eigen::Vector3d thin = e.Point(8) + Eigen::Vector3d(0.0, 0.01, 0.0);
  const Eigen::Vector3d middle = 0.5 * (e.Point(12) + e.Point(13));
  CHECK(e.Mesh.IsLegal(e.Plan({ 13, 12 }, thin)));
  e.Mesh.SetMinimumAngle(10.0);
  CollapsePlan sliver = e.Plan({ 13, 12 }, thin);
  CHECK(e.Mesh.FirstFailedCheck(sliver) == CollapseCheck::AngleGuard);
  CHECK(e.Mesh.IsLegal(e.Plan({ 13, 12 }, middle)));
  sliver.GuardAngles = false; // what AngleGuard promises: legal without the guard
  CHECK(e.Mesh.IsLegal(sliver));
}

/// A random plan on an alive triangle: an edge or the triangle, onto its first corner (one time
/// in three) or at a random blend of its corners.
CollapsePlan RandomPlan(const CollapseMesh& mesh, std::mt19937& random)
{
  std::int32_t t = static_cast<std::int32_t>(random() % mesh.NumberOfTriangles());
  while (!mesh.IsAlive(t))
  {
    t = (t + 1) % static_cast<std::int32_t>(mesh.NumberOfTriangles());
  }
  const std::int32_t* tri = mesh.Triangle(t);
  CollapsePlan plan;
  plan.Count = random() % 2 ? 3 : 2;
  std::copy(tri, tri + 3, plan.Vertices);
  std::uniform_real_distribution<double> share(0.0, 1.0);
  double total = 0.0;
  plan.Position.setZero();
  for (int k = 0; k < plan.Count; ++k)
  {
    const double w = share(random);
    plan.Position += w * mesh.Point(tri[k]);
    total += w;
  }
  plan.Position = random() % 3 == 0 ? mesh.Point(tri[0]) : Eigen::Vector3d(plan.Position / total);
  return plan;
}

void AngleGuardFollowsCollapses()
{
  // The angle guard compares a collapse's new angles with the smallest angles around it, which
  // the engine keeps per triangle through collapses, undos and moved points: a mesh that had the
  // guard on throughout judges every plan as one that turns it on only at the end.
  Engine throughout(Sphere(8)), atEnd(Sphere(8));
  throughout.Mesh.SetMinimumAngle(25.0);
  std::mt19937 random(11);
  for (int attempt = 0; attempt < 3000 && throughout.Mesh.NumberOfAliveTriangles() > 60; ++attempt)
  {
    CollapsePlan plan = RandomPlan(throughout.Mesh, random);
    plan.GuardAngles = false;
    if (!throughout.Mesh.IsLegal(plan))
    {
      continue;
    }
    throughout.Mesh.Apply(plan);
    atEnd.Mesh.Apply(plan);
    if (random() % 4 == 0)
    {
      throughout.Mesh.Undo();
      atEnd.Mesh.Undo();
    }
  }
  CHECK(throughout.Mesh.NumberOfAliveTriangles() <= 60);
  // Every point still in use moved a little (SetPoint).
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for (std::int32_t v = 0; v < throughout.Mesh.NumberOfPoints(); ++v)
  {
    if (throughout.Mesh.NumberOfTrianglesAround(v) > 0)
    {
      const Eigen::Vector3d step(jitter(random), jitter(random), jitter(random));
      const Eigen::Vector3d moved = throughout.Mesh.Point(v) + step;
      throughout.Mesh.SetPoint(v, moved);
      atEnd.Mesh.SetPoint(v, moved);
    }
  }
  atEnd.Mesh.SetMinimumAngle(25.0);
  // The guard set before Build, and a mesh built twice, measure the same as one set after.
  CollapseMesh before, twice;
  before.SetMinimumAngle(25.0);
  before.Build(meshsimp::MakeCompactMesh(Sphere(8).View()));
  twice.SetMinimumAngle(25.0);
  twice.Build(meshsimp::MakeCompactMesh(Grid(6).View()));
  twice.Build(meshsimp::MakeCompactMesh(Sphere(8).View()));
  Engine after(Sphere(8));
  after.Mesh.SetMinimumAngle(25.0);
  int guarded = 0, guardedFresh = 0;
  for (int attempt = 0; attempt < 3000; ++attempt)
  {
    const CollapsePlan plan = RandomPlan(throughout.Mesh, random);
    const CollapseCheck failed = throughout.Mesh.FirstFailedCheck(plan);
    CHECK(failed == atEnd.Mesh.FirstFailedCheck(plan));
    guarded += failed == CollapseCheck::AngleGuard ? 1 : 0;
    const CollapsePlan fresh = RandomPlan(after.Mesh, random);
    const CollapseCheck expected = after.Mesh.FirstFailedCheck(fresh);
    CHECK(before.FirstFailedCheck(fresh) == expected && twice.FirstFailedCheck(fresh) == expected);
    guardedFresh += expected == CollapseCheck::AngleGuard ? 1 : 0;
  }
  CHECK(guarded > 50 && guardedFresh > 50);
}

void LockedVerticesStay()
{
  Engine e(Grid(4));
  e.Mesh.Lock(e.Id[12], meshsimp::LockReason::Options);
  // Removes the locked vertex; moves it.
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 13, 12 }, e.Point(13))) == CollapseCheck::Locks);
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 12, 13 }, 0.5 * (e.Point(12) + e.Point(13)))) == CollapseCheck::Locks);
  CHECK(e.Mesh.IsLegal(e.Plan({ 12, 13 }, e.Point(12))));  // keeps it in place
}

void HingeVerticesSlideAlongTheHinge()
{
  // Three pages meet along a hinge of four segments (points 0 .. 4): its inner points never
  // move but merge along the hinge, its ends are locked; point 7 is the first page's beside 2.
  Engine e(Book(4, 1));
  CHECK(e.Mesh.Class(e.Id[2]) == VertexClass::Hinge && !e.Mesh.IsLocked(e.Id[2]));
  CHECK(e.Mesh.Class(e.Id[0]) == VertexClass::NonManifold && e.Mesh.IsLocked(e.Id[0]));
  std::int32_t ends[2];
  const auto [first, last] = std::minmax(e.Id[1], e.Id[3]);
  CHECK(e.Mesh.HingeEnds(e.Id[2], ends) == 2 && ends[0] == first && ends[1] == last);
  // Moved (even along the hinge), merged into a page, a page's border pinched onto the hinge:
  // refused.
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 2, 1 }, 0.5 * (e.Point(1) + e.Point(2)))) == CollapseCheck::Locks);
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 7, 2 }, e.Point(7))) == CollapseCheck::Locks);
  CHECK(e.Mesh.FirstFailedCheck(e.Plan({ 2, 7 }, e.Point(2))) == CollapseCheck::LinkCondition);
  // Along it, down to one segment between the locked ends: three triangles go each time, and no
  // edge gains a triangle.
  for (const auto& [kept, merged] : { std::pair<int, int>{ 1, 2 }, { 0, 1 }, { 4, 3 } })
  {
    const CollapsePlan plan = e.Plan({ kept, merged }, e.Point(kept));
    CHECK(e.Mesh.IsLegal(plan));
    CHECK(e.Mesh.Apply(plan) == 3);
  }
  CHECK(e.Mesh.NumberOfAliveTriangles() == 24 - 9);
  std::vector<std::int32_t> used, triangles, kept;
  e.Mesh.Surviving(used, triangles, kept);
  for (const auto& [edge, count] : TrianglesPerEdge(triangles))
  {
    const bool hinge = std::minmax(used[edge.first], used[edge.second]) == std::minmax(e.Id[0], e.Id[4]);
    CHECK((count == 3) == hinge && count <= 3);
  }
  // A turn of the hinge stays (non-manifold, locked), as a boundary's corner does.
  Mesh bent = Book(4, 1);
  bent.Points[3 * 2 + 2] = 0.8; // hinge point 2 lifted: the hinge turns by 77 degrees there, 39 at 1
  Engine turned(bent);
  CHECK(turned.Mesh.Class(turned.Id[2]) == VertexClass::NonManifold && turned.Mesh.Class(turned.Id[1]) == VertexClass::Hinge);
}

void HingeLoopStaysAComplex()
{
  // Three caps on one circle: any sequence of legal collapses (half-edges and triangles onto a
  // corner, in random orders) keeps a simplicial complex whose edges have at most three
  // triangles, down to where nothing is legal. The loop shrinks to a triangle; there, merging
  // a cap's apex into it made a triangle twice, and merging along it gave an edge four.
  for (unsigned seed = 1; seed <= 20; ++seed)
  {
    Engine e(DoubleBubble(8, 1 + seed % 3));
    std::mt19937 random(seed);
    std::vector<CollapsePlan> plans;
    bool complex = true;
    do
    {
      plans.clear();
      for (std::int32_t t = 0; t < e.Mesh.NumberOfTriangles(); ++t)
      {
        const std::int32_t* tri = e.Mesh.Triangle(t);
        for (int k = 0; t < e.Mesh.NumberOfTriangles() && e.Mesh.IsAlive(t) && k < 3; ++k)
        {
          CollapsePlan edge;
          edge.Count = 2;
          edge.Vertices[0] = tri[k];
          edge.Vertices[1] = tri[(k + 1) % 3];
          edge.Position = e.Mesh.Point(tri[k]);
          CollapsePlan triangle = edge;
          triangle.Count = 3;
          triangle.Vertices[2] = tri[(k + 2) % 3];
          plans.push_back(edge);
          plans.push_back(triangle);
        }
      }
      std::shuffle(plans.begin(), plans.end(), random);
      const auto legal = std::find_if(plans.begin(), plans.end(), [&e](const CollapsePlan& plan) { return e.Mesh.IsLegal(plan); });
      if (legal == plans.end())
      {
        break;
      }
      e.Mesh.Apply(*legal);
      std::vector<std::int32_t> used, triangles, kept;
      e.Mesh.Surviving(used, triangles, kept);
      complex = IsComplex(triangles, 3);
    } while (complex);
    CHECK(complex);
  }
}

void SharedVerticesGetNoNewEdge()
{
  // Vertices shared with another piece (12 and 14, two apart on the grid's middle row) are not
  // joined by a new edge, which the other piece could make too: collapsing 13 into 12 would make
  // (12, 14). A plain lock on 14 allows it, as does a collapse that brings no shared neighbour.
  Engine shared(Grid(4));
  shared.Mesh.Lock(shared.Id[12], meshsimp::LockReason::SharedPoint);
  shared.Mesh.Lock(shared.Id[14], meshsimp::LockReason::SharedPoint);
  CHECK(shared.Mesh.FirstFailedCheck(shared.Plan({ 12, 13 }, shared.Point(12))) ==
    CollapseCheck::SharedEdges);
  CHECK(shared.Mesh.IsLegal(shared.Plan({ 12, 11 }, shared.Point(12))));
  Engine plain(Grid(4));
  plain.Mesh.Lock(plain.Id[12], meshsimp::LockReason::SharedPoint);
  plain.Mesh.Lock(plain.Id[14], meshsimp::LockReason::Options);
  CHECK(plain.Mesh.IsLegal(plain.Plan({ 12, 13 }, plain.Point(12))));
}

void CollapseUndoRedo()
{
  // Random legal edge and triangle collapses on a closed mesh keep it a closed 2-manifold;
  // undoing them all (through several compactions of the adjacency) gives back the same mesh,
  // and replaying them forward the simplified one.
  Engine e(Sphere(8));
  const Snapshot before = Take(e.Mesh);
  std::mt19937 random(7);
  int applied = 0;
  for (int attempt = 0; attempt < 4000 && e.Mesh.NumberOfAliveTriangles() > 40; ++attempt)
  {
    const std::int32_t t = static_cast<std::int32_t>(random() % e.Mesh.NumberOfTriangles());
    if (!e.Mesh.IsAlive(t))
    {
      continue;
    }
    const std::int32_t* tri = e.Mesh.Triangle(t);
    CollapsePlan plan;
    plan.Count = random() % 2 ? 3 : 2;
    std::copy(tri, tri + 3, plan.Vertices);
    plan.Position = e.Mesh.Point(tri[0]);
    for (int k = 1; k < plan.Count; ++k)
    {
      plan.Position += e.Mesh.Point(tri[k]);
    }
    plan.Position /= plan.Count;
    if (!e.Mesh.IsLegal(plan))
    {
      continue;
    }
    const std::int64_t aliveBefore = e.Mesh.NumberOfAliveTriangles();
    const int removed = e.Mesh.Apply(plan);
    CHECK(removed == (plan.Count == 3 ? 4 : 2));
    CHECK(e.Mesh.NumberOfAliveTriangles() == aliveBefore - removed);
    ++applied;
  }
  CHECK(applied > 100);
  CHECK(ClosedManifold(e.Mesh));
  CHECK(static_cast<int>(e.Mesh.Records().size()) == applied);
  const Snapshot after = Take(e.Mesh);
  e.Mesh.Undo();
  CHECK(!(Take(e.Mesh) == after));
  while (!e.Mesh.Records().empty())
  {
    e.Mesh.Undo();
  }
  CHECK(Take(e.Mesh) == before);
  // Replayed forward, the records give the simplified mesh again, bit for bit.
  CHECK(static_cast<int>(e.Mesh.UndoneRecords().size()) == applied);
  while (e.Mesh.Redo())
  {
  }
  CHECK(static_cast<int>(e.Mesh.Records().size()) == applied);
  CHECK(Take(e.Mesh) == after);
}

/// Whether v's span lists exactly the alive triangles that hold v.
bool SpanExact(const CollapseMesh& mesh, std::int32_t v)
{
  std::vector<std::int32_t> holding;
  for (std::int32_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    const std::int32_t* tri = mesh.Triangle(t);
    if (mesh.IsAlive(t) && (tri[0] == v || tri[1] == v || tri[2] == v))
    {
      holding.push_back(t);
    }
  }
  return mesh.SortedTrianglesAround(v) == holding &&
    mesh.NumberOfTrianglesAround(v) == static_cast<std::int32_t>(holding.size());
}

void LongSpansStayExact()
{
  // A closed double fan of 600 whose top centre is merged into a rim vertex first: that vertex's
  // new span (600 triangles) is longer than IndexedSpan, so the triangles that leave it later go
  // by the indexed swap. Then rim vertices merge into a rim neighbour in a shuffled order until
  // it falls below IndexedSpan. Each step leaves the long spans exact; undone and replayed, the
  // mesh is restored bit for bit both ways.
  const int n = 600;
  Engine e(Fan(n, true));
  const std::int32_t hub = e.Id[1], bottom = e.Id[n + 1];
  const Snapshot before = Take(e.Mesh);
  CollapsePlan plan = e.Plan({ 1, 0 }, e.Point(1));
  CHECK(e.Mesh.IsLegal(plan));
  e.Mesh.Apply(plan);
  CHECK(e.Mesh.NumberOfTrianglesAround(hub) == n && SpanExact(e.Mesh, hub));
  std::vector<int> rim(n - 1);
  std::iota(rim.begin(), rim.end(), 2);
  std::mt19937 random(7);
  std::shuffle(rim.begin(), rim.end(), random);
  int applied = 0;
  bool exact = true;
  for (std::size_t i = 0; i < rim.size() && e.Mesh.NumberOfTrianglesAround(hub) > 200; ++i)
  {
    const std::int32_t v = e.Id[rim[i]];
    std::vector<std::int32_t> neighbours;
    e.Mesh.Neighbours(v, neighbours);
    neighbours.erase(std::remove_if(neighbours.begin(), neighbours.end(),
                       [&](std::int32_t w) { return w == hub || w == bottom; }),
      neighbours.end());
    if (neighbours.empty())
    {
      continue; // merged already
    }
    plan.Vertices[0] = *std::min_element(neighbours.begin(), neighbours.end());
    plan.Vertices[1] = v;
    plan.Position = e.Mesh.Point(plan.Vertices[0]);
    if (!e.Mesh.IsLegal(plan))
    {
      continue;
    }
    CHECK(e.Mesh.Apply(plan) == 2);
    ++applied;
    exact = exact && SpanExact(e.Mesh, hub) && SpanExact(e.Mesh, bottom);
  }
  CHECK(exact);
  CHECK(applied > 350 && e.Mesh.NumberOfTrianglesAround(hub) <= 200);
  CHECK(ClosedManifold(e.Mesh));
  for (std::int32_t v = 0; v < e.Mesh.NumberOfPoints(); ++v)
  {
    exact = exact && SpanExact(e.Mesh, v);
  }
  CHECK(exact);
  const Snapshot after = Take(e.Mesh);
  while (!e.Mesh.Records().empty())
  {
    e.Mesh.Undo();
    exact = exact && SpanExact(e.Mesh, hub) && SpanExact(e.Mesh, bottom);
  }
  CHECK(exact);
  CHECK(Take(e.Mesh) == before);
  while (e.Mesh.Redo())
  {
  }
  CHECK(Take(e.Mesh) == after);
}

void UndoRestoresFanCentres()
{
  // A closed double fan of 3 000 and, apart, a sphere. Every other rim vertex merges into the
  // next, which takes two triangles from each centre (their spans shrink from 3 000 to 1 500);
  // then the sphere is collapsed to a tenth, which makes the engine compact its spans. Undone,
  // each rim collapse gives the centres their triangles back at their spans' ends, which must
  // move once the compacted array has no room after them. The centres' spans are exact along
  // the way, and the mesh is restored bit for bit both ways.
  const int n = 3000;
  Mesh mesh = Fan(n, true);
  const Mesh sphere = Scaled(Sphere(16), 1.0, 3.0);
  const std::int32_t offset = static_cast<std::int32_t>(mesh.Points.size() / 3);
  mesh.Points.insert(mesh.Points.end(), sphere.Points.begin(), sphere.Points.end());
  for (const std::int32_t v : sphere.Triangles)
  {
    mesh.Triangles.push_back(offset + v);
  }
  Engine e(mesh);
  const std::int32_t top = e.Id[0], bottom = e.Id[n + 1];
  const Snapshot before = Take(e.Mesh);
  for (int i = 0; i + 1 < n; i += 2)
  {
    const CollapsePlan plan = e.Plan({ 2 + i, 1 + i }, e.Point(2 + i));
    CHECK(e.Mesh.IsLegal(plan));
    CHECK(e.Mesh.Apply(plan) == 2);
  }
  CHECK(e.Mesh.NumberOfTrianglesAround(top) == n / 2 && e.Mesh.NumberOfTrianglesAround(bottom) == n / 2);
  const std::int64_t sphereEnd = static_cast<std::int64_t>(sphere.Triangles.size() / 3) / 10 + n;
  for (bool collapsed = true; collapsed && e.Mesh.NumberOfAliveTriangles() > sphereEnd;)
  {
    collapsed = false;
    for (std::int32_t t = 0; t < e.Mesh.NumberOfTriangles() && e.Mesh.NumberOfAliveTriangles() > sphereEnd; ++t)
    {
      const std::int32_t* tri = e.Mesh.Triangle(t);
      if (!e.Mesh.IsAlive(t) || e.Mesh.Point(tri[0]).x() < 2.0)
      {
        continue; // the sphere's triangles only
      }
      CollapsePlan plan;
      plan.Vertices[0] = tri[0];
      plan.Vertices[1] = tri[1];
      plan.Count = 2;
      plan.Position = e.Mesh.Point(tri[0]);
      if (e.Mesh.IsLegal(plan))
      {
        e.Mesh.Apply(plan);
        collapsed = true;
      }
    }
  }
  CHECK(e.Mesh.NumberOfAliveTriangles() <= sphereEnd);
  const Snapshot after = Take(e.Mesh);
  bool exact = true;
  for (int undone = 1; !e.Mesh.Records().empty(); ++undone)
  {
    e.Mesh.Undo();
    if (undone % 50 == 0)
    {
      exact = exact && SpanExact(e.Mesh, top) && SpanExact(e.Mesh, bottom);
    }
  }
  CHECK(exact);
  CHECK(Take(e.Mesh) == before);
  while (e.Mesh.Redo())
  {
  }
  CHECK(Take(e.Mesh) == after);
}

void IndependentCollapsesShareHubsOf(int n)
{
  const Mesh fan = Fan(n, true);
  Engine concurrent(fan), serial(fan);
  std::vector<CollapsePlan> plans;
  for (int i = 0; i < n; i += 4)
  {
    const CollapsePlan plan = serial.Plan({ 1 + i + 1, 1 + i }, serial.Point(1 + i + 1));
    CHECK(serial.Mesh.IsLegal(plan));
    plans.push_back(plan);
  }
  for (const CollapsePlan& plan : plans)
  {
    serial.Mesh.Apply(plan);
  }
  const std::vector<std::int32_t> hubs = { concurrent.Id[0], concurrent.Id[n + 1] };
  CHECK(concurrent.Mesh.ApplyIndependent(plans, meshsimp_test::Threaded<meshsimp::ExecutionContext>(2), hubs) ==
    2 * static_cast<std::int64_t>(plans.size()));
  CHECK(Take(concurrent.Mesh) == Take(serial.Mesh));
  CHECK(concurrent.Mesh.NumberOfTrianglesAround(hubs[0]) == n - n / 4);
  CHECK(concurrent.Mesh.NumberOfTrianglesAround(hubs[1]) == n - n / 4);
  CHECK(ClosedManifold(concurrent.Mesh));
}

void IndependentCollapsesShareHubs()
{
  // Half-edge collapses along the rim of a closed double fan, every fourth rim vertex into its
  // next: their stars share only the two centres. Applied concurrently with the centres shared,
  // they give the mesh the same collapses give one by one; also where the centres' spans are
  // long enough to be indexed.
  for (const int n : { 64, 1200 })
  {
    IndependentCollapsesShareHubsOf(n);
  }
}

void AttributesFollowWeights()
{
  // A value linear in x, interpolated with the weights of a placement at the edge's midpoint,
  // equals x at the new point.
  Engine e(Grid(4));
  std::vector<double> values(e.Mesh.NumberOfPoints());
  for (std::int32_t v = 0; v < e.Mesh.NumberOfPoints(); ++v)
  {
    values[v] = e.Mesh.Point(v).x();
  }
  CollapsePlan plan = e.Plan({ 12, 13 }, 0.5 * (e.Point(12) + e.Point(13)));
  plan.Weights[0] = plan.Weights[1] = 0.5;
  CHECK(e.Mesh.IsLegal(plan));
  e.Mesh.Apply(plan);
  meshsimp::InterpolateAttributes(e.Mesh.Records(), values.data(), 1);
  CHECK(std::abs(values[e.Id[12]] - e.Mesh.Point(e.Id[12]).x()) < 1e-15);
}

void PlaneBoundMeasuresMergedPlanes()
{
  // A 2 × 2 grid on z = 0 (unit square, spacing 0.5): the centre (input 4) has only its
  // triangles' plane; the edge midpoint (input 1, on y = 0) also its two boundary edges' plane.
  Engine e(Grid(2));
  meshsimp::PlaneDistanceBound bound;
  bound.Build(e.Mesh);
  const std::int32_t centre = e.Id[4], edge = e.Id[1];
  CHECK(std::abs(bound.Distance(centre, Eigen::Vector3d(0.5, 0.5, 0.3)) - 0.3) < 1e-15);
  CHECK(bound.Distance(centre, Eigen::Vector3d(0.9, 0.1, 0.0)) == 0.0); // in the plane
  CHECK(std::abs(bound.Distance(edge, Eigen::Vector3d(0.5, -0.2, 0.0)) - 0.2) < 1e-15);
  CHECK(std::abs(bound.Distance(edge, Eigen::Vector3d(0.5, 0.1, -0.4)) - 0.4) < 1e-15);
  // Merging the edge midpoint into the centre gives the centre the boundary plane too.
  const CollapsePlan plan = e.Plan({ 4, 1 }, e.Point(4));
  CHECK(std::abs(bound.Distance(plan) - 0.5) < 1e-15); // the border would move in by 0.5
  bound.Merge(plan, 0.25);
  CHECK(bound.Error(centre) == 0.25);
  CHECK(std::abs(bound.Distance(centre, Eigen::Vector3d(0.5, -0.1, 0.0)) - 0.1) < 1e-15);
  CHECK(bound.Distance(edge, Eigen::Vector3d(0.5, -0.1, 0.7)) == 0.0); // merged away: no planes
}

meshsimp::VolumeCollapseResult Collapse(const Mesh& mesh, std::int64_t target)
{
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(target);
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(mesh.View(), options, result));
  return result;
}

void VolumeCollapseKeepsSphereClosed()
{
  const Mesh sphere = Sphere(16); // 3072 triangles
  const meshsimp::VolumeCollapseResult result = Collapse(sphere, 307);
  const std::int64_t count = static_cast<std::int64_t>(result.Triangles.size() / 3);
  CHECK(std::abs(count - 307) <= 3);
  CHECK(!StoppedEarly(result));
  Mesh out;
  out.Points = result.Points;
  out.Triangles = result.Triangles;
  Engine check(out);
  CHECK(ClosedManifold(check.Mesh));
  // Every triangle still faces outwards and the volume stays close to the input's.
  double volume = 0.0;
  bool outward = true;
  for (std::size_t t = 0; t < result.Triangles.size(); t += 3)
  {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k)
    {
      const int v = result.Triangles[t + k];
      p[k] = Eigen::Vector3d(result.Points[3 * v], result.Points[3 * v + 1], result.Points[3 * v + 2]) -
        Eigen::Vector3d::Constant(0.5);
    }
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    outward = outward && normal.dot(p[0] + p[1] + p[2]) > 0.0;
    volume += p[0].dot(p[1].cross(p[2])) / 6.0;
  }
  CHECK(outward);
  const double sphereVolume = 4.0 / 3.0 * 3.14159265358979323846 / 8.0;
  CHECK(std::abs(volume / sphereVolume - 1.0) < 0.05);
  CHECK(result.SquareVolumeError > 0.0);
  CHECK(static_cast<std::int64_t>(result.PointArray("SquareVolumeError")->size()) == result.NumberOfPoints());
  // The sources speak input ids: every input point is merged into exactly one output point,
  // with weights that sum to one (the survivor first, among them).
  std::vector<int> merged(sphere.Points.size() / 3, 0);
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    double sum = 0.0;
    for (std::int32_t i = result.SourceOffsets[p]; i < result.SourceOffsets[p + 1]; ++i)
    {
      ++merged[result.SourcePoints[i]];
      sum += result.SourceWeights[i];
    }
    CHECK(std::abs(sum - 1.0) < 1e-9);
  }
  CHECK(std::all_of(merged.begin(), merged.end(), [](int m) { return m == 1; }));
}

void VolumeCollapseMendsOrientationAndDuplicates()
{
  // Turned-over and repeated triangles are mended before the collapse: the sphere is
  // simplified to its target and comes out closed and consistently oriented.
  const Mesh sphere = Misoriented(Sphere(16)); // 3072 triangles and 280 copies
  const meshsimp::VolumeCollapseResult result = Collapse(sphere, 307);
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 307) <= 3);
  CHECK(ClosedOriented(result.Triangles));
}

void VolumeCollapseClosesCracks()
{
  // Points split off a closed sphere (each one's copy stands for it in every other triangle
  // around it: zero-width cracks) rejoin before the collapse: the output is the unsplit
  // sphere's, closed and oriented.
  const Mesh sphere = Sphere(16);
  std::int64_t copies = 0;
  const Mesh split = SplitOffEvery(sphere, 13, copies);
  const meshsimp::VolumeCollapseResult result = Collapse(split, 307);
  const meshsimp::VolumeCollapseResult whole = Collapse(sphere, 307);
  CHECK(ClosedOriented(result.Triangles) && result.Report.JoinedPoints == copies);
  CHECK(result.Points == whole.Points && result.Triangles == whole.Triangles);

  // A crack whose sides differ in their locks or regions stays open, and so does every crack
  // with CloseCracks off.
  const std::size_t points = split.Points.size() / 3, original = sphere.Points.size() / 3;
  std::vector<std::uint8_t> locks(points, 0);
  std::vector<std::int32_t> regions(points, 0);
  std::fill(locks.begin() + static_cast<std::ptrdiff_t>(original), locks.end(), 1);
  std::fill(regions.begin() + static_cast<std::ptrdiff_t>(original), regions.end(), 1);
  for (int variant = 0; variant < 3; ++variant)
  {
    meshsimp::VolumeCollapseOptions options;
    options.Goal.SetTriangleCount(307);
    options.LockedPoints = variant == 0 ? locks.data() : nullptr;
    options.Regions = variant == 1 ? regions.data() : nullptr;
    options.CloseCracks = variant != 2;
    meshsimp::VolumeCollapseResult apart;
    CHECK(meshsimp::VolumeTriangleCollapse(split.View(), options, apart));
    CHECK(apart.Report.JoinedPoints == 0 && !ClosedOriented(apart.Triangles));
  }
}

void VolumeCollapseBatchesDoNotDependOnThreads()
{
  // Batches of collapses (BatchSize, at most one per 1000 triangles) are evaluated, checked and
  // updated on the context's threads: the same result whatever the threads and their chunks, a
  // closed sphere stays closed, and BatchSize 1 (the strict heap order) gives another result.
  const Mesh sphere = Sphere(48); // 27 648 triangles: batches of up to 27
  auto run = [&](const meshsimp::ExecutionContext& context, int batchSize) {
    meshsimp::VolumeCollapseOptions options;
    options.Goal.SetTriangleCount(2765);
    options.BatchSize = batchSize;
    meshsimp::VolumeCollapseResult result;
    CHECK(meshsimp::VolumeTriangleCollapse(sphere.View(), options, result, context));
    return result;
  };
  const meshsimp::VolumeCollapseResult serial = run({}, 64);
  const meshsimp::VolumeCollapseResult strict = run({}, 1);
  for (const meshsimp::ExecutionContext& context :
    { meshsimp_test::Threaded<meshsimp::ExecutionContext>(2),
      meshsimp_test::Chunked<meshsimp::ExecutionContext>(2, 3) })
  {
    const meshsimp::VolumeCollapseResult threaded = run(context, 64);
    CHECK(threaded.Points == serial.Points && threaded.Triangles == serial.Triangles);
    CHECK(*threaded.PointArray("SquareVolumeError") == *serial.PointArray("SquareVolumeError"));
    CHECK(threaded.SquareVolumeError == serial.SquareVolumeError && threaded.SourceWeights == serial.SourceWeights);
  }
  for (const meshsimp::VolumeCollapseResult* result : { &serial, &strict })
  {
    const std::int64_t count = static_cast<std::int64_t>(result->Triangles.size() / 3);
    CHECK(std::abs(count - 2765) <= 27);
    Mesh out;
    out.Points = result->Points;
    out.Triangles = result->Triangles;
    Engine check(out);
    CHECK(ClosedManifold(check.Mesh));
  }
  CHECK(strict.Points != serial.Points);

  // The same on the other paths a batch takes: a fan's centre (its sums kept by differences),
  // locked points and a kept boundary, an error bound.
  std::vector<std::uint8_t> locks(101 * 101, 0);
  for (std::size_t i = 0; i < locks.size(); i += 3)
  {
    locks[i] = 1;
  }
  meshsimp::VolumeCollapseOptions fanOptions, gridOptions, boundOptions;
  fanOptions.Goal.SetTriangleCount(5000);
  gridOptions.LockedPoints = locks.data();
  gridOptions.PreserveBoundary = true;
  boundOptions.Goal.SetMaximumError(0.01, true);
  const std::pair<Mesh, meshsimp::VolumeCollapseOptions> cases[] = { { Fan(10000, true), fanOptions },
    { Grid(100), gridOptions }, { Sphere(40), boundOptions } };
  for (const auto& [mesh, options] : cases)
  {
    meshsimp::VolumeCollapseResult alone, together;
    CHECK(meshsimp::VolumeTriangleCollapse(mesh.View(), options, alone));
    CHECK(meshsimp::VolumeTriangleCollapse(
      mesh.View(), options, together, meshsimp_test::Chunked<meshsimp::ExecutionContext>(2, 1)));
    CHECK(together.Points == alone.Points && together.Triangles == alone.Triangles);
    CHECK(together.SourcePoints == alone.SourcePoints && together.PointArrays.size() == alone.PointArrays.size());
    CHECK(together.PointArrays.back().Values == alone.PointArrays.back().Values);
    CHECK(alone.Triangles.size() < mesh.Triangles.size() / 2);
  }
}

void VolumeCollapseKeepsPlaneAndCorners()
{
  // A flat grid stays flat, and its four corners (sharp boundary turns) stay where they are.
  const meshsimp::VolumeCollapseResult result = Collapse(Grid(16), 51);
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 51) <= 1);
  int corners = 0;
  for (std::size_t i = 0; i < result.Points.size(); i += 3)
  {
    CHECK(result.Points[i + 2] == 0.0);
    const double x = result.Points[i], y = result.Points[i + 1];
    corners += (x == 0.0 || x == 1.0) && (y == 0.0 || y == 1.0) ? 1 : 0;
  }
  CHECK(corners == 4);
}
double LargestRadialDeviation(const meshsimp::VolumeCollapseResult& result)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < result.Points.size(); i += 3)
  {
    largest = std::max(largest, std::abs(std::hypot(result.Points[i], result.Points[i + 1]) - 0.5));
  }
  return largest;
}

void VolumeCollapseKeepsTubeOnItsCylinder()
{
  // On a cylinder an edge along a ruling line collapses without error, a triangle never does:
  // with edge collapses every point stays on the cylinder, with the paper's triangle
  // collapses alone points move inside it.
  const Mesh tube = Tube(32, 33); // 2048 triangles
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(1024);
  options.PreserveBoundary = true;
  meshsimp::VolumeCollapseResult withEdges, trianglesOnly;
  CHECK(meshsimp::VolumeTriangleCollapse(tube.View(), options, withEdges));
  options.EdgeCollapses = false;
  CHECK(meshsimp::VolumeTriangleCollapse(tube.View(), options, trianglesOnly));
  CHECK(std::abs(static_cast<std::int64_t>(withEdges.Triangles.size() / 3) - 1024) <= 10);
  CHECK(std::abs(static_cast<std::int64_t>(trianglesOnly.Triangles.size() / 3) - 1024) <= 10);
  CHECK(LargestRadialDeviation(withEdges) < 1e-9);
  CHECK(LargestRadialDeviation(trianglesOnly) > 1e-3);
}

/// The largest distance from an input point to the output surface and from an output point to
/// the input surface.
double VertexHausdorff(const Mesh& input, const meshsimp::VolumeCollapseResult& result)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < input.Points.size(); i += 3)
  {
    largest = std::max(largest, DistanceToSurface(Eigen::Vector3d(&input.Points[i]), result.Points, result.Triangles));
  }
  for (std::size_t i = 0; i < result.Points.size(); i += 3)
  {
    largest = std::max(largest, DistanceToSurface(Eigen::Vector3d(&result.Points[i]), input.Points, input.Triangles));
  }
  return largest;
}

/// The farthest input point from the volume filter's output at reduction, with the default
/// options and with those that change makes; both outputs must have the same count (within one
/// triangle, the filter's tolerance on small targets).
std::pair<double, double> FarthestWithAndWithout(const Mesh& mesh, double reduction,
  const std::function<void(meshsimp::VolumeCollapseOptions&)>& change)
{
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetReduction(reduction);
  meshsimp::VolumeCollapseResult with, without;
  CHECK(meshsimp::VolumeTriangleCollapse(mesh.View(), options, with));
  change(options);
  CHECK(meshsimp::VolumeTriangleCollapse(mesh.View(), options, without));
  // The same count up to the filter's tolerance of one triangle on small targets.
  const std::int64_t withCount = static_cast<std::int64_t>(with.Triangles.size() / 3);
  const std::int64_t withoutCount = static_cast<std::int64_t>(without.Triangles.size() / 3);
  CHECK(std::abs(withCount - withoutCount) <= 1);
  return { VertexHausdorff(mesh, with), VertexHausdorff(mesh, without) };
}

void VolumeCollapseSurfaceTermKeepsSurfaceClose()
{
  // Ordered by volume alone, collapses on gently curved parts (where the normal factor makes
  // volume cheap) move the surface farther than the surface term lets them: on the CAD fandisk
  // at 70 % the largest distance between the input and output points and surfaces is 3.4 times
  // smaller with the default weight (metro's Hausdorff distance 0.007 % against 0.022 % of the
  // diagonal). (The elephant showed it too, 0.0056 against 0.0081, until the angle guard became
  // a price: the volume order alone then finds 0.0066.)
  const auto [with, without] = FarthestWithAndWithout(ReadData("fandisk.off"), 0.7,
    [](meshsimp::VolumeCollapseOptions& options) { options.SurfaceErrorWeight = 0.0; });
  std::printf("surface term on the fandisk at 70 %%: %g with, %g without\n", with, without);
  CHECK(with < 0.8 * without);
}

/// The largest distance from an output point to the planes of the input triangles with a corner
/// among the input points merged into it (its sources), checked independently of
/// PlaneDistanceBound; for closed inputs (no boundary planes).
double LargestPlaneDistance(const Mesh& input, const meshsimp::VolumeCollapseResult& result)
{
  std::map<std::int32_t, Eigen::Vector3d> outputPoint; // input point -> its output point
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    for (std::int32_t i = result.SourceOffsets[p]; i < result.SourceOffsets[p + 1]; ++i)
    {
      outputPoint[result.SourcePoints[i]] = Eigen::Vector3d(&result.Points[3 * p]);
    }
  }
  const auto find = [](std::int32_t v) { return v; };
  double largest = 0.0;
  for (std::size_t t = 0; t < input.Triangles.size(); t += 3)
  {
    const Eigen::Vector3d a(&input.Points[3 * input.Triangles[t]]), b(&input.Points[3 * input.Triangles[t + 1]]),
      c(&input.Points[3 * input.Triangles[t + 2]]);
    const Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
    for (int k = 0; k < 3; ++k)
    {
      const auto found = outputPoint.find(find(input.Triangles[t + k]));
      if (found != outputPoint.end())
      {
        largest = std::max(largest, std::abs(normal.dot(found->second - a)));
      }
    }
  }
  return largest;
}

void VolumeCollapseKeepsErrorBound()
{
  // With MaximumError (relative to the bounding-box diagonal) the filter simplifies as
  // far as the bound lets it: every output point within the bound of its input planes.
  const Mesh elephant = ReadData("elephant.off");
  meshsimp::VolumeCollapseOptions options;
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(1e300), upper = -lower;
  for (std::size_t i = 0; i < elephant.Points.size(); i += 3)
  {
    lower = lower.cwiseMin(Eigen::Vector3d(&elephant.Points[i]));
    upper = upper.cwiseMax(Eigen::Vector3d(&elephant.Points[i]));
  }
  std::size_t previous = elephant.Triangles.size() / 3;
  for (const double bound : { 0.002, 0.01 })
  {
    options.Goal.SetMaximumError(bound, true);
    meshsimp::VolumeCollapseResult result;
    CHECK(meshsimp::VolumeTriangleCollapse(elephant.View(), options, result));
    const double absolute = bound * (upper - lower).norm(), count = static_cast<double>(result.Triangles.size() / 3);
    CHECK(result.Report.Stop == meshsimp::StopReason::TargetMet); // as far as the bound allows
    CHECK(count < 0.75 * static_cast<double>(previous)); // 5 558, 3 112, 778 triangles
    CHECK(result.Report.MaximumError > 0.5 * absolute && result.Report.MaximumError <= absolute);
    CHECK(LargestPlaneDistance(elephant, result) <= result.Report.MaximumError * (1.0 + 1e-9));
    previous = result.Triangles.size() / 3;
  }
}

void VolumeCollapseReachesSmallTargets()
{
  // Near the end of a small mesh of higher genus (the elephant: genus 3) every triangle's plan
  // can fail the link condition while half-edge collapses still pass: the filter stopped at 58
  // of 56 triangles (99 %), and the cow at 14 of 6 (99.9 %).
  for (const auto& [name, target] : { std::pair<const char*, std::int64_t>{ "elephant.off", 56 }, { "cow.off", 6 } })
  {
    const Mesh mesh = ReadData(name);
    const meshsimp::VolumeCollapseResult result = Collapse(mesh, target);
    const std::int64_t count = static_cast<std::int64_t>(result.Triangles.size() / 3);
    CHECK(!StoppedEarly(result) && std::abs(count - target) <= 1);
  }
}

void VolumeCollapseSaysWhatStopsIt()
{
  // A grid whose points are all locked but every seventh stops far above a target of 10
  // triangles; the reason names what refused the collapses left: the locks, first.
  const Mesh grid = Grid(20);
  std::vector<std::uint8_t> locks(grid.Points.size() / 3, 1);
  for (std::size_t i = 0; i < locks.size(); i += 7)
  {
    locks[i] = 0;
  }
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(10);
  options.LockedPoints = locks.data();
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(grid.View(), options, result));
  CHECK(result.Triangles.size() / 3 > 400);
  CHECK(result.Report.Stop == meshsimp::StopReason::NothingRemovable);
  const std::string& reason = result.Report.Reason;
  CHECK(reason.find(" half-edge collapses left, 100 % would remove or move a point locked by the options") !=
    std::string::npos);
}

void VolumeCollapseNamesTheRuleThatBinds()
{
  // An open grid collapsed towards one triangle stops at its border corners: the reason names
  // them, not "a locked vertex (non-manifold, ...)" on a manifold mesh where nothing was asked
  // to be locked, and the angle guard lowered on the way is not given as what reached the
  // target (issue 45, §4, Wavelet iso-surface at 0.99).
  const meshsimp::VolumeCollapseResult result = Collapse(Grid(20), 1);
  CHECK(result.Report.Stop == meshsimp::StopReason::NothingRemovable);
  const std::string& reason = result.Report.Reason;
  CHECK(reason.find("would remove or move a border corner") != std::string::npos);
  CHECK(reason.find("non-manifold") == std::string::npos && reason.find("options") == std::string::npos);
  for (const std::string& note : result.Report.Notes)
  {
    CHECK(note.find("before the target") == std::string::npos);
  }
}

void VolumeCollapseDefaultGuardReachesPlaneTarget()
{
  // The default angle guard (10°) does not stop a flat grid short of a 95 % target, and the
  // grid stays flat.
  const Mesh grid = Grid(32); // 2048 triangles
  meshsimp::VolumeCollapseOptions options;
  CHECK(options.MinimumAngle == 10.0);
  options.Goal.SetTriangleCount(102);
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(grid.View(), options, result));
  CHECK(!StoppedEarly(result));
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 102) <= 1);
  for (std::size_t i = 2; i < result.Points.size(); i += 3)
  {
    CHECK(result.Points[i] == 0.0);
  }
}

void VolumeCollapseLowersGuardRatherThanStop()
{
  // Triangle collapses alone on a bumpy terrain under the strictest guard (30°): the collapses
  // that make angles below it wait at their price, the guard is lowered step by step when it
  // refuses every collapse left, and the target is met; FinalMinimumAngle says how far below
  // the guard the filter went.
  Mesh terrain = Grid(24); // 1152 triangles
  std::mt19937 random(7);
  for (std::size_t i = 2; i < terrain.Points.size(); i += 3)
  {
    terrain.Points[i] = 0.05 * std::uniform_real_distribution<double>(0.0, 1.0)(random);
  }
  meshsimp::VolumeCollapseOptions options;
  options.EdgeCollapses = false;
  options.MinimumAngle = 30.0;
  options.Goal.SetTriangleCount(58);
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(terrain.View(), options, result));
  CHECK(!StoppedEarly(result));
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 58) <= 1);
  CHECK(result.FinalMinimumAngle < 30.0);

  // A guard above 60° (no triangle's smallest angle is larger), even an infinite one, is 60°:
  // it is lowered the same way instead of refusing every collapse for ever.
  options.MinimumAngle = std::numeric_limits<double>::infinity();
  CHECK(meshsimp::VolumeTriangleCollapse(terrain.View(), options, result));
  CHECK(!StoppedEarly(result));
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 58) <= 1);
  CHECK(result.FinalMinimumAngle < 30.0);
}

/// A flat annulus around the origin (radii 0.25 and 0.5), `around` segments by `rings` rings.
Mesh Annulus(int around, int rings)
{
  Mesh mesh;
  for (int j = 0; j <= rings; ++j)
  {
    const double radius = 0.25 + 0.25 * j / rings;
    for (int i = 0; i < around; ++i)
    {
      const double angle = 2.0 * 3.14159265358979323846 * i / around;
      mesh.Points.insert(mesh.Points.end(), { radius * std::cos(angle), radius * std::sin(angle), 0.0 });
    }
  }
  for (int j = 0; j < rings; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const int a = j * around + i, b = j * around + (i + 1) % around, c = a + around, d = b + around;
      mesh.Triangles.insert(mesh.Triangles.end(), { a, b, d, a, d, c });
    }
  }
  return mesh;
}

void VolumeCollapseKeepsHoleRims()
{
  // A chord across a hole's rim, in the surface's own plane, sweeps no volume and leaves every
  // face plane: only the planes through the border edges see it. A flat annulus at 90 %: how
  // far its output reaches into the hole (the deepest point of its edges and triangles inside
  // the inner circle) stays within the sagitta of a 16-gon (0.0048, 1.9 % of the radius): 0.0027
  // with the border planes, 0.0103 by the volume and the face planes alone.
  const Mesh annulus = Annulus(64, 8); // 1024 triangles
  const meshsimp::VolumeCollapseResult result = Collapse(annulus, 102);
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 102) <= 1);
  double deepest = 0.0;
  for (std::size_t t = 0; t < result.Triangles.size(); t += 3)
  {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = Eigen::Vector3d(&result.Points[3 * static_cast<std::size_t>(result.Triangles[t + k])]);
    }
    for (const Eigen::Vector3d& sample : { Eigen::Vector3d((p[0] + p[1] + p[2]) / 3.0),
           Eigen::Vector3d(0.5 * (p[0] + p[1])), Eigen::Vector3d(0.5 * (p[1] + p[2])),
           Eigen::Vector3d(0.5 * (p[2] + p[0])) })
    {
      deepest = std::max(deepest, 0.25 - sample.head<2>().norm());
    }
  }
  std::printf("annulus at 90 %%: the output reaches %g into the hole of radius 0.25\n", deepest);
  CHECK(deepest < 0.25 * (1.0 - std::cos(3.14159265358979323846 / 16.0)));
}

void VolumeCollapseGuardIsAPrice()
{
  // A steep terrain (relief twice its width): thin triangles are its shape. The guard prices
  // them instead of refusing them, so at 95 % the surface stays close to where it is with no
  // guard at all. With placements kept in the input's box (issue 45) the unguarded run's
  // farthest input point came from 0.163 to 0.109 and the guarded one's stayed (0.227, 0.233):
  // the guarded run stays where it was (a bound tighter than the 2 x 0.163 the ratio allowed
  // before), within 2.5 times the unguarded one (as a wall it was 5.0 times a worse one).
  Mesh terrain = Grid(40); // 3200 triangles
  std::mt19937 random(11);
  for (std::size_t i = 2; i < terrain.Points.size(); i += 3)
  {
    const double x = terrain.Points[i - 2], y = terrain.Points[i - 1];
    terrain.Points[i] = 2.0 * std::sin(9.0 * x) * std::cos(7.0 * y) +
      0.1 * std::uniform_real_distribution<double>(0.0, 1.0)(random);
  }
  const auto [with, without] = FarthestWithAndWithout(terrain, 0.95,
    [](meshsimp::VolumeCollapseOptions& options) { options.MinimumAngle = 0.0; });
  std::printf("steep terrain at 95 %%: farthest %g with the guard, %g without\n", with, without);
  CHECK(with < 0.25 && with < 2.5 * without);
}

void VolumeCollapseHugeAndTinyCoordinates()
{
  // Coordinates whose squares overflow (2^600 ≈ 4e180) or underflow (2^-600), and coordinates
  // up to ±2^1023 ≈ ±9e307, whose box diagonal exceeds the largest double: the costs are
  // computed in normalised coordinates, so the target is still met, and the errors, in
  // length⁸, are zero or positive (infinite where they overflow), never NaN.
  const Mesh sphere = Scaled(Sphere(12), 2.0, -0.5); // centred at the origin, radius 1
  for (const double factor : { std::ldexp(1.0, 600), std::ldexp(1.0, -600), std::ldexp(1.0, 1023) })
  {
    const Mesh scaled = Scaled(sphere, factor);
    meshsimp::VolumeCollapseOptions options;
    options.Goal.SetReduction(0.8);
    meshsimp::VolumeCollapseResult result;
    CHECK(meshsimp::VolumeTriangleCollapse(scaled.View(), options, result));
    CHECK(!StoppedEarly(result));
    CHECK(std::abs(static_cast<double>(result.Triangles.size() / 3) - 0.2 * (sphere.Triangles.size() / 3)) <=
      0.01 * (sphere.Triangles.size() / 3) + 1);
    CHECK(InsideBox(result.Points, scaled));
    CHECK(result.SquareVolumeError >= 0.0);
    const std::vector<double>& errors = *result.PointArray("SquareVolumeError");
    CHECK(std::all_of(errors.begin(), errors.end(), [](double e) { return e >= 0.0; }));
  }
}

/// A scheduler for the loop alone: each step removes Rate triangles while it has collapses;
/// Unstick gives it Reserve more (once each), as a lowered guard would.
struct CountingScheduler
{
  std::int64_t Alive = 1000, Rate = 10, Collapsible = 600, Reserve = 0;
  int Unsticks = 0;
  std::int64_t AliveTriangles() const { return this->Alive; }
  bool Step(std::int64_t target)
  {
    if (this->Collapsible <= 0)
    {
      return false;
    }
    const std::int64_t removed = std::min({ this->Rate, this->Collapsible, this->Alive - target });
    this->Alive -= removed;
    this->Collapsible -= removed;
    return true;
  }
  bool Unstick(std::int64_t)
  {
    ++this->Unsticks;
    this->Collapsible += this->Reserve;
    const bool more = this->Reserve > 0;
    this->Reserve = 0;
    return more;
  }
  std::string RefusalSummary() const { return ": of the " + std::to_string(this->Alive) + " left, none"; }
};

void CollapseLoopStopsForTheRightReason()
{
  // Target met exactly; out of collapses (the scheduler's summary kept, a count target judged
  // NothingRemovable, a bound not); unstuck once and met; aborted where the caller said.
  std::vector<double> reported;
  meshsimp::ExecutionContext context;
  context.Progress = [&](double progress) {
    reported.push_back(progress);
    return true;
  };
  CountingScheduler met;
  const meshsimp::CollapseLoopEnd first = meshsimp::RunCollapseLoop(met, 500, { 0.1, 0.9 }, context);
  CHECK(first.Why == meshsimp::CollapseLoopEnd::Reason::TargetMet && met.Alive == 500 && met.Unsticks == 0);
  CHECK(first.Refusals.empty());
  CHECK(reported.size() >= 40 && std::is_sorted(reported.begin(), reported.end()));
  CHECK(reported.front() > 0.1 && std::abs(reported.back() - 0.9) < 1e-12);

  CountingScheduler stuck;
  const meshsimp::CollapseLoopEnd second = meshsimp::RunCollapseLoop(stuck, 100, {}, context);
  CHECK(second.Why == meshsimp::CollapseLoopEnd::Reason::Exhausted && stuck.Alive == 400 && stuck.Unsticks == 1);
  CHECK(second.Refusals == ": of the 400 left, none");
  meshsimp::Outcome counted, bounded;
  second.Judge(counted, false, "nothing is removable");
  second.Judge(bounded, true, "nothing is removable");
  CHECK(counted.Stop == meshsimp::StopReason::NothingRemovable && counted.Reason == "nothing is removable: of the 400 left, none");
  CHECK(bounded.Stop == meshsimp::StopReason::TargetMet && bounded.Reason.empty());

  CountingScheduler unstuck;
  unstuck.Reserve = 1000;
  CHECK(meshsimp::RunCollapseLoop(unstuck, 100, {}, context).Why == meshsimp::CollapseLoopEnd::Reason::TargetMet);
  CHECK(unstuck.Alive == 100 && unstuck.Unsticks == 1);

  context.Progress = [](double progress) { return progress < 0.5; };
  CountingScheduler aborted;
  CHECK(meshsimp::RunCollapseLoop(aborted, 500, {}, context).Why == meshsimp::CollapseLoopEnd::Reason::Aborted);
  CHECK(aborted.Alive > 500 && aborted.Alive <= 760);
}

void VolumeCollapseReportsProgressAndAborts()
{
  // Progress rises from the set-up to the end; a caller that says stop gets false at once.
  const Mesh sphere = Sphere(16);
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(100);
  std::vector<double> reported;
  meshsimp::ExecutionContext context;
  context.Progress = [&](double progress) {
    reported.push_back(progress);
    return true;
  };
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(sphere.View(), options, result, context));
  CHECK(reported.size() >= 3 && reported.back() == 1.0);
  CHECK(std::is_sorted(reported.begin(), reported.end()));
  reported.clear();
  context.Progress = [&](double progress) {
    reported.push_back(progress);
    return progress < 0.5;
  };
  CHECK(!meshsimp::VolumeTriangleCollapse(sphere.View(), options, result, context));
  CHECK(!reported.empty() && reported.back() >= 0.5 && reported.back() < 1.0);
}
void VolumeCollapseSimplifiesFan()
{
  // A disk fanned around one vertex (a triangulated polygon): every triangle has two boundary
  // corners, and §3.5's collapse onto its boundary edge would leave a rim vertex with two
  // neighbours, so no such collapse is legal. Collapsing the boundary edge alone reaches the
  // target; the paper's triangle collapses alone stop early.
  const Mesh fan = Fan(2000);
  meshsimp::VolumeCollapseOptions options;
  options.Goal.SetTriangleCount(1000);
  meshsimp::VolumeCollapseResult result;
  CHECK(meshsimp::VolumeTriangleCollapse(fan.View(), options, result));
  CHECK(!StoppedEarly(result));
  CHECK(std::abs(static_cast<std::int64_t>(result.Triangles.size() / 3) - 1000) <= 10);
  for (std::size_t i = 0; i < result.Points.size(); i += 3)
  {
    CHECK(std::hypot(result.Points[i], result.Points[i + 1]) <= 1.0 + 1e-9); // inside the rim
  }
  options.EdgeCollapses = false;
  CHECK(meshsimp::VolumeTriangleCollapse(fan.View(), options, result));
  CHECK(StoppedEarly(result));
}

void VolumeCollapseSimplifiesAlongHinges()
{
  // A book of three pages of 72 triangles each: with its 11 inner hinge points locked the filter
  // stopped at 36 triangles for 12; sliding them along the hinge, it reaches the target and the
  // pages stay flat and joined along the whole hinge.
  const meshsimp::VolumeCollapseResult result = Collapse(Book(12, 3), 12);
  CHECK(result.Triangles.size() / 3 <= 12);
  CHECK(StaysInBook(result.Points, result.Triangles, 12));
  // A collapse along a hinge of k pages removes k + 2 triangles, not at most four: counts are
  // still met within one, with three pages and with five.
  for (const int pages : { 3, 5 })
  {
    for (const std::int64_t target : { 150, 101, 60, 41 })
    {
      const meshsimp::VolumeCollapseResult partial = Collapse(Book(12, 3, pages), target * pages / 3);
      CHECK(std::abs(static_cast<std::int64_t>(partial.Triangles.size() / 3) - target * pages / 3) <= 1);
      CHECK(StaysInBook(partial.Points, partial.Triangles, 12, pages));
    }
  }
  // A closed hinge: the loop of three caps stays a complex (no edge of four triangles, no
  // triangle twice) down to a small count.
  for (const std::int64_t target : { 40, 12, 4 })
  {
    const meshsimp::VolumeCollapseResult loop = Collapse(DoubleBubble(16, 3), target);
    CHECK(IsComplex(loop.Triangles, 3));
  }
}

void VolumeCollapseSurvivesDamagedMeshes()
{
  // Damaged meshes (TestMeshes.h: soups with repeated and coincident points, duplicate,
  // degenerate and non-manifold triangles, holes, pinches, NaN, far scales) under random options
  // and locks: a valid output, the same with one thread, two, and small chunks taken in turn;
  // locked points stay, bit for bit; an undamaged closed mesh stays closed; the count target is
  // met unless the filter stopped early.
  std::mt19937 random(1);
  for (int run = 0; run < 150; ++run)
  {
    bool closed = false;
    const Mesh mesh = DamagedMesh(random, closed);
    const std::vector<std::uint8_t> locks = RandomLocks(random, mesh, meshsimp::SharedPointLock);
    meshsimp::VolumeCollapseOptions options;
    RandomTargets(random, options, locks);
    options.MinimumAngle = 5.0 * (random() % 3);
    options.EdgeCollapses = random() % 4 != 0;
    random(); // was KeepUndo: the cases stay those of the earlier runs
    options.UseShapeFactor = random() % 2 == 0;
    options.UseNormalFactor = random() % 2 == 0;
    options.UseVolumeWeights = random() % 2 == 0;
    options.BatchSize = random() % 2 == 0 ? 64 : 1 + static_cast<int>(random() % 8);
    const meshsimp::VolumeCollapseResult result =
      SameOnAnyThreads<meshsimp::ExecutionContext, meshsimp::VolumeCollapseResult>(
        [&](meshsimp::VolumeCollapseResult& out, const meshsimp::ExecutionContext& context) {
          return meshsimp::VolumeTriangleCollapse(mesh.View(), options, out, context);
        });
    CHECK(static_cast<std::int64_t>(result.TriangleSource.size()) <= result.Report.UsableTriangles);
    CheckCollapseRun(result, mesh, closed, locks, options.Goal.Bounded(), 0.01);
  }
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "HeapOrderAndTieRule", HeapOrderAndTieRule },
    { "VertexClasses", VertexClasses },
    { "FanClassesFromCorners", FanClassesFromCorners },
    { "LinkConditionRejectsHiddenCycle", LinkConditionRejectsHiddenCycle },
    { "LinkConditionRejectsPinch", LinkConditionRejectsPinch },
    { "FoldOverAndDegenerateRejected", FoldOverAndDegenerateRejected },
    { "FoldOntoNeighbourRejected", FoldOntoNeighbourRejected },
    { "AngleGuardRejectsNewSlivers", AngleGuardRejectsNewSlivers },
    { "AngleGuardFollowsCollapses", AngleGuardFollowsCollapses },
    { "LockedVerticesStay", LockedVerticesStay },
    { "HingeVerticesSlideAlongTheHinge", HingeVerticesSlideAlongTheHinge },
    { "HingeLoopStaysAComplex", HingeLoopStaysAComplex },
    { "SharedVerticesGetNoNewEdge", SharedVerticesGetNoNewEdge },
    { "CollapseUndoRedo", CollapseUndoRedo },
    { "IndependentCollapsesShareHubs", IndependentCollapsesShareHubs },
    { "LongSpansStayExact", LongSpansStayExact },
    { "UndoRestoresFanCentres", UndoRestoresFanCentres },
    { "AttributesFollowWeights", AttributesFollowWeights },
    { "PlaneBoundMeasuresMergedPlanes", PlaneBoundMeasuresMergedPlanes },
    { "VolumeCollapseKeepsSphereClosed", VolumeCollapseKeepsSphereClosed },
    { "VolumeCollapseMendsOrientationAndDuplicates", VolumeCollapseMendsOrientationAndDuplicates },
    { "VolumeCollapseClosesCracks", VolumeCollapseClosesCracks },
    { "VolumeCollapseBatchesDoNotDependOnThreads", VolumeCollapseBatchesDoNotDependOnThreads },
    { "VolumeCollapseKeepsPlaneAndCorners", VolumeCollapseKeepsPlaneAndCorners },
    { "VolumeCollapseKeepsTubeOnItsCylinder", VolumeCollapseKeepsTubeOnItsCylinder },
    { "VolumeCollapseSurfaceTermKeepsSurfaceClose", VolumeCollapseSurfaceTermKeepsSurfaceClose },
    { "VolumeCollapseKeepsErrorBound", VolumeCollapseKeepsErrorBound },
    { "VolumeCollapseReachesSmallTargets", VolumeCollapseReachesSmallTargets },
    { "VolumeCollapseSaysWhatStopsIt", VolumeCollapseSaysWhatStopsIt },
    { "VolumeCollapseNamesTheRuleThatBinds", VolumeCollapseNamesTheRuleThatBinds },
    { "VolumeCollapseDefaultGuardReachesPlaneTarget", VolumeCollapseDefaultGuardReachesPlaneTarget },
    { "VolumeCollapseLowersGuardRatherThanStop", VolumeCollapseLowersGuardRatherThanStop },
    { "VolumeCollapseKeepsHoleRims", VolumeCollapseKeepsHoleRims },
    { "VolumeCollapseGuardIsAPrice", VolumeCollapseGuardIsAPrice },
    { "VolumeCollapseHugeAndTinyCoordinates", VolumeCollapseHugeAndTinyCoordinates },
    { "CollapseLoopStopsForTheRightReason", CollapseLoopStopsForTheRightReason },
    { "VolumeCollapseReportsProgressAndAborts", VolumeCollapseReportsProgressAndAborts },
    { "VolumeCollapseSimplifiesFan", VolumeCollapseSimplifiesFan },
    { "VolumeCollapseSimplifiesAlongHinges", VolumeCollapseSimplifiesAlongHinges },
    { "VolumeCollapseSurvivesDamagedMeshes", VolumeCollapseSurvivesDamagedMeshes },
  });
}
