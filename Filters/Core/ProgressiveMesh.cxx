// SPDX-License-Identifier: BSD-3-Clause
#include "ProgressiveMesh.h"

#include "CollapseHeap.h"
#include "CollapseLoop.h"
#include "CollapseMesh.h"
#include "Quadric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>

namespace meshsimp
{
namespace
{

/// What the build reads and writes of a vertex at every visit, side by side: a ring gather
/// touches one cache line per neighbour, not one per array.
struct VertexState
{
  std::int32_t Head = -1;     // first corner of the vertex's list (-1: none)
  std::int32_t Triangles = 0; // live triangles at the vertex
  std::uint32_t Stamp = 0;    // the last gather or mark that met the vertex (one counter)
  std::int32_t Slot = 0;      // its entry in the ring of that gather
  VertexClass Class = VertexClass::Interior; // of its fan, fixed by the input (never Corner nor Hinge)
  std::uint8_t Lock = 0; // why it never moves, as a LockReason (0: it may; NonManifold for a fan that is not one)
};

/// (k + 1) % 3 at k and (k + 2) % 3 at k + 1, for the corners after corner k of a triangle.
constexpr int NextInTriangle[4] = { 1, 2, 0, 1 };

/// A neighbour y of the vertex x being measured, with the triangles on the edge xy (two on an
/// interior edge, one on a border edge).
struct RingEntry
{
  std::int32_t Vertex;
  std::int32_t Triangles[2];
  std::int32_t Count;
  double Cost; // of the collapse x -> Vertex (CostRing), infinite where RingCheck refuses it
};

/// x's gathered ring: storage that only grows, so that a gather writes its entries without a
/// capacity check or a construction each; the first Size entries are the ring.
struct RingBuffer
{
  std::vector<RingEntry> Storage;
  std::int32_t Size = 0;
  RingEntry* begin() { return this->Storage.data(); }
  RingEntry* end() { return this->Storage.data() + this->Size; }
  const RingEntry* begin() const { return this->Storage.data(); }
  const RingEntry* end() const { return this->Storage.data() + this->Size; }
  RingEntry& operator[](std::int32_t i) { return this->Storage[i]; }
};

class ProgressiveBuilder
{
public:
  ProgressiveBuilder(const ProgressiveMeshOptions& options, const ExecutionContext& context)
    : Options(options)
    , Context(context)
  {
  }

  bool Run(const TriangleMeshView& input, ProgressiveMesh& sequence);

private:
  void Prepare(PreparedMesh& prepared);
  void BuildFaceQuadrics();
  void AddBorderPlanes(std::int32_t v);
  void MeasureScales();
  template <class Visit>
  void ForEachTriangle(std::int32_t v, Visit&& visit);
  void GatherRing(std::int32_t x);
  CollapseCheck RingCheck(std::int32_t x, const RingEntry& entry) const;
  double Curvature(std::int32_t x, const RingEntry& entry) const;
  void CostRing(std::int32_t x);
  void Measure(std::int32_t x, bool gathered = false);
  bool WouldRepeatTriangle(std::int32_t y, const std::int32_t opposite[2]);
  CollapseCheck Check(std::int32_t x, const RingEntry& entry);
  /// At the coarsest level: what locks the points left and refuses the others' collapses.
  std::string DescribeCoarsest();
  /// The collapse loop's scheduler (CollapseLoop.h): the strict heap, one collapse a step.
  struct StrictHeapScheduler
  {
    ProgressiveBuilder& Builder;
    std::int64_t AliveTriangles() const { return this->Builder.LiveTriangles; }
    bool Step(std::int64_t) { return this->Builder.CollapseTop(); }
    bool Unstick(std::int64_t) { return false; }
    std::string RefusalSummary() { return this->Builder.DescribeCoarsest(); }
  };
  /// Step 4 for the top of the heap; false when the heap is empty.
  bool CollapseTop();
  const RingEntry* Cheapest() const;
  const RingEntry* CheapestLegal(std::int32_t x, const RingEntry& refused);
  bool StillCheapest(std::int32_t x, double cost);
  void Collapse(std::int32_t x, std::int32_t y);
  void UpdateNormal(std::int32_t t);
  void ReleaseBuildState();
  void WriteSequence(const PreparedMesh& prepared, ProgressiveMesh& sequence);

  const ProgressiveMeshOptions& Options;
  const ExecutionContext& Context;
  Frame Coordinates;

  // Per vertex.
  std::vector<Eigen::Vector3d> P;
  std::vector<VertexState> Vertices;
  std::vector<std::int32_t> Regions;
  std::vector<Quadric> Quadrics;
  std::vector<double> Weights; // the area behind each quadric
  std::vector<double> Extra; // the extra coordinates, scaled, ExtraDimension per vertex
  // Per corner and triangle.
  std::vector<std::int32_t> Corners;    // 3 per triangle, the current vertices
  std::vector<std::int32_t> NextCorner; // the next corner of the same vertex
  std::vector<Eigen::Vector3f> Normals; // unit, zero when degenerate (floats: for the checks and the curvature)
  std::vector<std::int32_t> RemovedStep;
  std::int64_t LiveTriangles = 0;
  // The sequence.
  std::vector<std::int32_t> Removed, Into;
  std::vector<double> StepError;
  double LengthScale = 1.0, QuadricScale = 0.0; // the weights over their terms' units
  int ExtraDimension = 0;
  CollapseHeap Heap;
  RingBuffer Ring;
  std::vector<std::int32_t> Affected;
  std::vector<std::pair<double, std::int32_t>> Candidates;
  std::uint32_t CurrentStamp = 0;
};

template <class Visit>
void ProgressiveBuilder::ForEachTriangle(std::int32_t v, Visit&& visit)
{
  // Walks v's list, unlinking the corners of removed triangles on the way.
  std::int32_t* link = &this->Vertices[v].Head;
  while (*link >= 0)
  {
    const std::int32_t corner = *link, t = corner / 3;
    if (this->Corners[3 * t] < 0) // removed: see Collapse
    {
      *link = this->NextCorner[corner];
      continue;
    }
    visit(t, corner - 3 * t);
    link = &this->NextCorner[corner];
  }
}

bool ProgressiveBuilder::Run(const TriangleMeshView& input, ProgressiveMesh& sequence)
{
  sequence = ProgressiveMesh();
  PreparedMesh prepared = PrepareMesh(input, this->Options, Normalization::CentreAndDiagonal, this->Context);
  sequence.Report = prepared.Report();
  this->Prepare(prepared);
  if (!this->Context.Report(0.1))
  {
    return false;
  }
  // One ring per vertex: its border planes (which complete its quadric, those of smaller
  // neighbours being in already), then its key.
  const std::int32_t n = static_cast<std::int32_t>(this->P.size());
  for (std::int32_t x = 0; x < n; ++x)
  {
    this->GatherRing(x);
    this->AddBorderPlanes(x);
    this->Measure(x, true);
  }
  StrictHeapScheduler scheduler{ *this };
  const CollapseLoopEnd end = RunCollapseLoop(scheduler, this->Options.StopTriangles, { 0.1, 0.95 }, this->Context);
  if (end.Why == CollapseLoopEnd::Reason::Aborted)
  {
    return false;
  }
  sequence.CoarsestReason = end.Refusals;
  this->ReleaseBuildState();
  this->WriteSequence(prepared, sequence);
  return this->Context.Report(1.0);
}

std::string ProgressiveBuilder::DescribeCoarsest()
{
  // The heap is empty: every point left is fixed, or each of its collapses fails a check. The
  // fixed ones by why, and the others' collapses by the check that refuses them first.
  std::int64_t left = 0;
  std::array<std::int64_t, NumberOfLockReasons> lockedBy{};
  RefusalCounts refused;
  for (std::int32_t x = 0; x < static_cast<std::int32_t>(this->P.size()); ++x)
  {
    if (this->Vertices[x].Triangles == 0)
    {
      continue;
    }
    ++left;
    if (this->Vertices[x].Lock)
    {
      ++lockedBy[LockIndex(static_cast<LockReason>(this->Vertices[x].Lock))];
      continue;
    }
    this->GatherRing(x);
    for (const RingEntry& entry : this->Ring)
    {
      CollapseCheck check = this->RingCheck(x, entry);
      check = check == CollapseCheck::Passed ? this->Check(x, entry) : check;
      ++refused.ByCheck[static_cast<std::size_t>(check)]; // x moves, so never its locks
    }
  }
  return DescribeLeft(left, "points", lockedBy, refused, "half-edge collapses", "would pass every check");
}

void ProgressiveBuilder::Prepare(PreparedMesh& prepared)
{
  // Flat arrays from the prepared mesh: the corner lists, normals, kinds, quadrics and scales.
  CompactMesh& mesh = prepared.Mesh;
  this->Coordinates = prepared;
  this->P = std::move(mesh.Points);
  this->Corners = mesh.Triangles;
  this->Regions = std::move(prepared.Regions);
  const std::size_t n = this->P.size(), m = this->Corners.size() / 3;
  this->Vertices.assign(n, VertexState());
  this->NextCorner.assign(3 * m, -1);
  for (std::size_t c = 3 * m; c-- > 0;)
  {
    const std::int32_t v = this->Corners[c];
    this->NextCorner[c] = this->Vertices[v].Head;
    this->Vertices[v].Head = static_cast<std::int32_t>(c);
    ++this->Vertices[v].Triangles;
  }
  this->RemovedStep.assign(m, -1);
  this->LiveTriangles = static_cast<std::int64_t>(m);
  this->Normals.resize(m);
  for (std::size_t t = 0; t < m; ++t)
  {
    this->UpdateNormal(static_cast<std::int32_t>(t));
  }
  FanWorkspace fanWork;
  for (std::size_t v = 0; v < n; ++v)
  {
    std::int32_t opening = -1, closing = -1;
    const VertexClass fan = ClassifyFan(mesh.Adjacency.Begin(v), mesh.Adjacency.End(v), opening, closing, fanWork);
    this->Vertices[v].Class = fan;
    const LockReason lock = prepared.Locks[v] == SharedPointLock ? LockReason::SharedPoint
      : prepared.Locks[v]                                       ? LockReason::Options
      : fan == VertexClass::NonManifold                         ? LockReason::NonManifold
                                                                : LockReason{};
    this->Vertices[v].Lock = static_cast<std::uint8_t>(lock);
  }
  mesh.Adjacency = VertexTriangleAdjacency(); // the corner lists replace it
  this->ExtraDimension = this->Options.ExtraCoordinates ? std::max(0, this->Options.ExtraDimension) : 0;
  this->Extra.resize(n * this->ExtraDimension);
  const double extraScale = this->Options.AttributeWeight / (this->Options.ExtraScale > 0.0 ? this->Options.ExtraScale : 1.0);
  for (std::size_t v = 0; v < n && this->ExtraDimension > 0; ++v)
  {
    for (int k = 0; k < this->ExtraDimension; ++k)
    {
      const double value = this->Options.ExtraCoordinates[static_cast<std::size_t>(mesh.InputVertex[v]) * this->ExtraDimension + k];
      this->Extra[v * this->ExtraDimension + k] = std::isfinite(value) ? extraScale * value : 0.0;
    }
  }
  this->BuildFaceQuadrics();
  this->MeasureScales();
  this->Heap.Reset(static_cast<std::int32_t>(n));
  for (auto* record : { &this->Removed, &this->Into })
  {
    record->reserve(n); // a collapse per point at most: no doubling past it
  }
  this->StepError.reserve(n);
}

void ProgressiveBuilder::UpdateNormal(std::int32_t t)
{
  const Eigen::Vector3d& a = this->P[this->Corners[3 * t]];
  const Eigen::Vector3d normal = (this->P[this->Corners[3 * t + 1]] - a).cross(this->P[this->Corners[3 * t + 2]] - a);
  const double length = normal.norm();
  this->Normals[t] = length > 0.0 ? Eigen::Vector3f((normal / length).cast<float>()) : Eigen::Vector3f::Zero();
}

void ProgressiveBuilder::BuildFaceQuadrics()
{
  // Garland-Heckbert: each triangle's plane weighted by its area at its corners (the planes along
  // open borders follow in AddBorderPlanes).
  this->Quadrics.assign(this->P.size(), Quadric());
  this->Weights.assign(this->P.size(), 0.0);
  for (std::size_t t = 0; t < this->Normals.size(); ++t)
  {
    const std::int32_t* c = &this->Corners[3 * t];
    const Eigen::Vector3d normal = (this->P[c[1]] - this->P[c[0]]).cross(this->P[c[2]] - this->P[c[0]]);
    const double area = 0.5 * normal.norm();
    const Eigen::Vector3d n = area > 0.0 ? Eigen::Vector3d(normal / (2.0 * area)) : Eigen::Vector3d::Zero();
    const Quadric plane = Quadric::FromPlane(n, -n.dot(this->P[c[0]]), area);
    for (int k = 0; k < 3; ++k)
    {
      this->Quadrics[c[k]] += plane;
      this->Weights[c[k]] += area;
    }
  }
}

void ProgressiveBuilder::AddBorderPlanes(std::int32_t v)
{
  // At each open border edge (v, w) with w > v (v's ring gathered), its border plane
  // (Quadric::FromBorderEdge) at both ends, so that borders keep their shape.
  for (const RingEntry& entry : this->Ring)
  {
    const std::int32_t w = entry.Vertex;
    if (entry.Count != 1 || w < v)
    {
      continue; // not a border edge, or added from its other end
    }
    Quadric plane;
    if (Quadric::FromBorderEdge(this->P[v], this->P[w], this->Normals[entry.Triangles[0]].cast<double>(), plane))
    {
      this->Quadrics[v] += plane;
      this->Quadrics[w] += plane;
    }
  }
}

void ProgressiveBuilder::MeasureScales()
{
  // The units of the cost's terms: the mean L1 edge length and the mean area times the mean
  // squared edge length (the quadric error of one mean triangle one mean edge away).
  double l1 = 0.0, squared = 0.0;
  const double area = std::accumulate(this->Weights.begin(), this->Weights.end(), 0.0) / 3.0;
  const std::size_t m = this->Normals.size();
  for (std::size_t t = 0; t < m; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d d = this->P[this->Corners[3 * t + (k + 1) % 3]] - this->P[this->Corners[3 * t + k]];
      l1 += d.cwiseAbs().sum();
      squared += d.squaredNorm();
    }
  }
  const double edges = std::max<double>(1.0, 3.0 * static_cast<double>(m));
  const double meanLength = l1 > 0.0 ? l1 / edges : 1.0;
  const double unit = (area / std::max<double>(1.0, static_cast<double>(m))) * (squared / edges);
  this->LengthScale = this->Options.LengthWeight / meanLength;
  this->QuadricScale = this->Options.QuadricWeight / (unit > 0.0 ? unit : 1.0);
}

void ProgressiveBuilder::GatherRing(std::int32_t x)
{
  // x's neighbours, each with the triangles on its edge: at most two new ones per triangle.
  const std::uint32_t stamp = ++this->CurrentStamp;
  const std::size_t bound = 2 * static_cast<std::size_t>(this->Vertices[x].Triangles);
  if (this->Ring.Storage.size() < bound)
  {
    this->Ring.Storage.resize(2 * bound);
  }
  RingEntry* ring = this->Ring.Storage.data();
  std::int32_t size = 0;
  this->ForEachTriangle(x, [&](std::int32_t t, int k) {
    for (const int step : { 1, 2 })
    {
      const std::int32_t w = this->Corners[3 * t + NextInTriangle[k + step - 1]];
      VertexState& state = this->Vertices[w];
      if (state.Stamp != stamp)
      {
        state.Stamp = stamp;
        state.Slot = size;
        ring[size++] = { w, { t, -1 }, 1, 0.0 };
      }
      else
      {
        RingEntry& entry = ring[state.Slot];
        entry.Triangles[1] = t;
        ++entry.Count;
      }
    }
  });
  this->Ring.Size = size;
}

CollapseCheck ProgressiveBuilder::RingCheck(std::int32_t x, const RingEntry& entry) const
{
  // The first three checks, which need nothing but the ring (so every candidate is filtered by
  // them before it is costed): the locks and the classes' rule (HalfEdgeRules), the regions, a
  // border vertex only along its border. Named as the collapse engine names its checks
  // (CollapseCheck): a locked vertex fails its locks, a border vertex into the interior or across
  // it the link condition.
  const std::int32_t y = entry.Vertex;
  const VertexClass removed = this->Vertices[x].Class;
  const CollapseRule rule = HalfEdgeRule(removed, this->Vertices[y].Class);
  if (this->Vertices[x].Lock || rule == CollapseRule::Never)
  {
    return this->Vertices[x].Lock ? CollapseCheck::Locks : CollapseCheck::LinkCondition;
  }
  if (!this->Regions.empty() && this->Regions[x] != this->Regions[y])
  {
    return CollapseCheck::Regions;
  }
  return rule == CollapseRule::AlongEdge && !IsOwnEdge(removed, entry.Count) ? CollapseCheck::LinkCondition
                                                                             : CollapseCheck::Passed;
}

double ProgressiveBuilder::Curvature(std::int32_t x, const RingEntry& entry) const
{
  // §4: 1 - N_ABC . N_ABD of the edge's two triangles; on an open border, 1 - d1 . d2 of the
  // border's directions into and out of x (the ring of x is gathered).
  if (entry.Count == 2)
  {
    return 1.0 - static_cast<double>(this->Normals[entry.Triangles[0]].dot(this->Normals[entry.Triangles[1]]));
  }
  // The border's other neighbour: of the ring's single-triangle edges (a border vertex has two),
  // the first, or the last when y's is the first.
  const std::int32_t y = entry.Vertex;
  const RingEntry *first = nullptr, *last = nullptr;
  for (const RingEntry& e : this->Ring)
  {
    first = !first && e.Count == 1 ? &e : first;
    last = e.Count == 1 ? &e : last;
  }
  const RingEntry* otherBorder = first && first->Vertex == y ? (last != first ? last : nullptr) : first;
  if (!otherBorder)
  {
    return 0.0;
  }
  const std::int32_t other = otherBorder->Vertex;
  const Eigen::Vector3d in = (this->P[x] - this->P[other]).normalized(), out = (this->P[y] - this->P[x]).normalized();
  return 1.0 - in.dot(out);
}

void ProgressiveBuilder::CostRing(std::int32_t x)
{
  // Wu and Fei §4: the L1 length and the curvature 1 - N_ABC . N_ABD, weighted; the L1
  // distance of the extra coordinates (§7); beyond the paper, the quadric error of y for x's
  // planes. For every edge of x's gathered ring that RingCheck allows, each term only when it
  // is there (a weight above 0, extra coordinates given), x's quadric read once: the build costs
  // every edge of every top vertex.
  const Quadric quadric = this->Quadrics[x];
  for (RingEntry& entry : this->Ring)
  {
    if (this->RingCheck(x, entry) != CollapseCheck::Passed)
    {
      entry.Cost = std::numeric_limits<double>::infinity();
      continue;
    }
    const std::int32_t y = entry.Vertex;
    double cost = this->LengthScale > 0.0 ? this->LengthScale * (this->P[x] - this->P[y]).cwiseAbs().sum() : 0.0;
    if (this->ExtraDimension > 0)
    {
      double attributes = 0.0; // the extra coordinates come scaled by AttributeWeight
      for (int k = 0; k < this->ExtraDimension; ++k)
      {
        attributes += std::abs(this->Extra[x * this->ExtraDimension + k] - this->Extra[y * this->ExtraDimension + k]);
      }
      cost += attributes;
    }
    if (this->Options.CurvatureWeight > 0.0)
    {
      cost += this->Options.CurvatureWeight * this->Curvature(x, entry);
    }
    if (this->QuadricScale > 0.0)
    {
      cost += this->QuadricScale * quadric.Evaluate(this->P[y]);
    }
    entry.Cost = std::isfinite(cost) ? cost : std::numeric_limits<double>::max();
  }
}

void ProgressiveBuilder::Measure(std::int32_t x, bool gathered)
{
  // Step 2: the vertex's cost is its cheapest allowed edge's; fixed vertices never queue.
  const RingEntry* cheapest = nullptr;
  if (!this->Vertices[x].Lock && this->Vertices[x].Triangles > 0)
  {
    if (!gathered)
    {
      this->GatherRing(x);
    }
    this->CostRing(x);
    cheapest = this->Cheapest();
  }
  if (cheapest)
  {
    this->Heap.Set(x, cheapest->Cost);
  }
  else
  {
    this->Heap.Remove(x);
  }
}

bool ProgressiveBuilder::WouldRepeatTriangle(std::int32_t y, const std::int32_t opposite[2])
{
  // Moving x (whose ring is gathered) onto y repeats a triangle only where x has a triangle
  // (x, a, b) and y one with a and b: a and b are then common neighbours, so (link condition) the edge's opposites. Closed
  // fans are kept from it by their three triangles; this catches it around non-manifold points.
  if (opposite[0] < 0 || opposite[1] < 0)
  {
    return false;
  }
  // x's side from its gathered ring: the triangles on its edge to opposite[0].
  const RingEntry& toFirst = this->Ring[this->Vertices[opposite[0]].Slot];
  bool atX = false;
  for (std::int32_t i = 0; i < std::min(toFirst.Count, 2); ++i)
  {
    const std::int32_t* c = &this->Corners[3 * toFirst.Triangles[i]];
    atX |= c[0] == opposite[1] || c[1] == opposite[1] || c[2] == opposite[1];
  }
  if (!atX)
  {
    return false;
  }
  bool atY = false;
  this->ForEachTriangle(y, [&](std::int32_t t, int) {
    const std::int32_t* c = &this->Corners[3 * t];
    atY |= std::count(c, c + 3, opposite[0]) + std::count(c, c + 3, opposite[1]) == 2;
  });
  return atY;
}

CollapseCheck ProgressiveBuilder::Check(std::int32_t x, const RingEntry& entry)
{
  // The checks after RingCheck's, in order, for an edge that passed those; the ring of x is
  // gathered. Returns the first that fails.
  const std::int32_t y = entry.Vertex;
  std::int32_t opposite[2] = { -1, -1 };
  for (std::int32_t i = 0; i < entry.Count; ++i)
  {
    const std::int32_t* c = &this->Corners[3 * entry.Triangles[i]];
    opposite[i] = c[0] != x && c[0] != y ? c[0] : (c[1] != x && c[1] != y ? c[1] : c[2]);
  }
  if (opposite[0] >= 0 && opposite[0] == opposite[1])
  {
    return CollapseCheck::LinkCondition; // the edge's two triangles share all three points
  }
  if (this->WouldRepeatTriangle(y, opposite))
  {
    return CollapseCheck::LinkCondition;
  }
  const std::uint32_t mark = ++this->CurrentStamp; // the ring keeps its Slot entries
  this->ForEachTriangle(y, [&](std::int32_t t, int) {
    for (int k = 0; k < 3; ++k)
    {
      this->Vertices[this->Corners[3 * t + k]].Stamp = mark;
    }
  });
  // x's other neighbours become y's: none may be one already (the link condition), nor, where y
  // is shared with another piece, shared too (a new edge between two shared points, which the
  // other piece could make as well).
  bool joinsShared = false;
  for (const RingEntry& other : this->Ring)
  {
    const std::int32_t w = other.Vertex;
    if (w != y && w != opposite[0] && w != opposite[1])
    {
      if (this->Vertices[w].Stamp == mark)
      {
        return CollapseCheck::LinkCondition;
      }
      joinsShared = joinsShared || (this->Vertices[y].Lock == static_cast<std::uint8_t>(LockReason::SharedPoint) &&
                                     this->Vertices[w].Lock == static_cast<std::uint8_t>(LockReason::SharedPoint));
    }
  }
  if (joinsShared)
  {
    return CollapseCheck::SharedEdges;
  }
  // A closed fan keeps three triangles, locked or not.
  const auto keeps = [&](std::int32_t v, std::int32_t remaining) {
    return remaining >= (this->Vertices[v].Class == VertexClass::Interior ? 3 : 1);
  };
  if (!keeps(y, this->Vertices[y].Triangles + this->Vertices[x].Triangles - 2 * entry.Count) ||
    (opposite[0] >= 0 && !keeps(opposite[0], this->Vertices[opposite[0]].Triangles - 1)) ||
    (opposite[1] >= 0 && !keeps(opposite[1], this->Vertices[opposite[1]].Triangles - 1)))
  {
    return CollapseCheck::LinkCondition; // a vertex would keep too few triangles
  }
  CollapseCheck changed = CollapseCheck::Passed;
  this->ForEachTriangle(x, [&](std::int32_t t, int k) {
    const std::int32_t a = this->Corners[3 * t + NextInTriangle[k]], b = this->Corners[3 * t + NextInTriangle[k + 1]];
    if (a == y || b == y || changed != CollapseCheck::Passed)
    {
      return;
    }
    const Eigen::Vector3d moved = (this->P[a] - this->P[y]).cross(this->P[b] - this->P[y]);
    const double scale = (this->P[a] - this->P[y]).norm() * (this->P[b] - this->P[y]).norm();
    changed = !(moved.norm() > 1e-12 * scale)                     ? CollapseCheck::Degenerate
      : moved.dot(this->Normals[t].cast<double>()) < 0.0 ? CollapseCheck::PlaneSide
                                                          : CollapseCheck::Passed;
  });
  return changed;
}

bool ProgressiveBuilder::CollapseTop()
{
  // Step 4: the top vertex's candidates in cost order, the first legal one collapsed. A key may
  // be stale (Collapse leaves the ring's keys as they were): one that rose goes back to the heap
  // under its true cost, unchecked, and waits unless it is still the cheapest; so does one whose
  // cheapest edges are illegal. A vertex with no legal edge leaves the heap until a collapse
  // changes its ring.
  while (!this->Heap.Empty())
  {
    const std::int32_t x = this->Heap.Top();
    this->GatherRing(x);
    this->CostRing(x);
    const RingEntry* cheapest = this->Cheapest();
    if (!cheapest)
    {
      this->Heap.Remove(x);
      continue;
    }
    if (!this->StillCheapest(x, cheapest->Cost))
    {
      continue;
    }
    // The others are sorted only when the cheapest is illegal (seldom).
    const RingEntry* legal = this->Check(x, *cheapest) == CollapseCheck::Passed ? cheapest : this->CheapestLegal(x, *cheapest);
    if (!legal)
    {
      this->Heap.Remove(x);
      continue;
    }
    if (this->StillCheapest(x, legal->Cost))
    {
      this->Collapse(x, legal->Vertex);
      return true;
    }
  }
  return false;
}

const RingEntry* ProgressiveBuilder::Cheapest() const
{
  // The costed ring's allowed edge of least (cost, vertex); none when RingCheck refused all.
  const RingEntry* best = nullptr;
  double bestCost = std::numeric_limits<double>::infinity();
  for (const RingEntry& entry : this->Ring)
  {
    if (entry.Cost < bestCost || (best && entry.Cost == bestCost && entry.Vertex < best->Vertex))
    {
      best = &entry;
      bestCost = entry.Cost;
    }
  }
  return best;
}

const RingEntry* ProgressiveBuilder::CheapestLegal(std::int32_t x, const RingEntry& refused)
{
  // The allowed edges other than refused, by (cost, vertex), until one passes Check.
  std::vector<std::pair<double, std::int32_t>>& order = this->Candidates;
  order.clear();
  for (const RingEntry& entry : this->Ring)
  {
    if (&entry != &refused && entry.Cost < std::numeric_limits<double>::infinity())
    {
      order.emplace_back(entry.Cost, entry.Vertex);
    }
  }
  std::sort(order.begin(), order.end());
  for (const auto& candidate : order)
  {
    const RingEntry& entry = this->Ring[this->Vertices[candidate.second].Slot];
    if (this->Check(x, entry) == CollapseCheck::Passed)
    {
      return &entry;
    }
  }
  return nullptr;
}

bool ProgressiveBuilder::StillCheapest(std::int32_t x, double cost)
{
  // The top vertex x costs cost: false when that exceeds its key and, requeued under it, x is no
  // longer on top.
  if (cost > this->Heap.TopCost())
  {
    this->Heap.Set(x, cost);
    return this->Heap.Top() == x;
  }
  return true;
}

void ProgressiveBuilder::Collapse(std::int32_t x, std::int32_t y)
{
  // Step 4: x's triangles on the edge xy are removed, the others move onto y; y takes x's
  // quadric.
  const std::int32_t step = static_cast<std::int32_t>(this->Removed.size());
  const double error = std::sqrt(this->Quadrics[x].Evaluate(this->P[y]) / std::max(this->Weights[x], 1e-300));
  this->StepError.push_back(std::max(this->StepError.empty() ? 0.0 : this->StepError.back(), error));
  this->Removed.push_back(x);
  this->Into.push_back(y);
  std::int32_t corner = this->Vertices[x].Head;
  this->Vertices[x].Head = -1;
  while (corner >= 0)
  {
    const std::int32_t next = this->NextCorner[corner], t = corner / 3;
    const std::int32_t* c = &this->Corners[3 * t];
    if (c[0] >= 0 && (c[0] == y || c[1] == y || c[2] == y))
    {
      this->RemovedStep[t] = step;
      --this->LiveTriangles;
      for (int k = 0; k < 3; ++k)
      {
        --this->Vertices[c[k]].Triangles;
      }
      this->Corners[3 * t] = -1; // the mark walks test: on the triangle's own cache line
    }
    else if (c[0] >= 0)
    {
      this->Corners[corner] = y;
      this->NextCorner[corner] = this->Vertices[y].Head;
      this->Vertices[y].Head = corner;
      --this->Vertices[x].Triangles;
      ++this->Vertices[y].Triangles;
      this->UpdateNormal(t);
    }
    corner = next;
  }
  this->Quadrics[y] += this->Quadrics[x];
  this->Weights[y] += this->Weights[x];
  this->Heap.Remove(x);
  // Step 5, lazily: the keys of y and its ring stay until they reach the top, where CollapseTop
  // costs them anew (and queues a vertex again when its cost rose); only vertices out of the
  // heap (none of their edges was allowed or legal) are measured now, as their ring changed.
  this->Measure(y);
  // Of the ring gathered last (y's by Measure; x's when y is fixed and not measured: either holds
  // every vertex whose ring changed), the vertices out of the heap.
  this->Affected.clear();
  for (const RingEntry& entry : this->Ring)
  {
    if (!this->Heap.Contains(entry.Vertex) && !this->Vertices[entry.Vertex].Lock)
    {
      this->Affected.push_back(entry.Vertex);
    }
  }
  for (const std::int32_t v : this->Affected)
  {
    this->Measure(v); // gathers v's ring: y's is read to the end first
  }
}

void ProgressiveBuilder::ReleaseBuildState()
{
  // What only the build needed goes before the sequence is written, which lowers the peak;
  // WriteSequence takes over NextCorner, Corners and Weights.
  const auto release = [](auto&... values) { (std::decay_t<decltype(values)>().swap(values), ...); };
  release(this->Quadrics, this->Normals, this->Vertices, this->Extra, this->P, this->Regions);
  this->Heap = CollapseHeap();
}

void ProgressiveBuilder::WriteSequence(const PreparedMesh& prepared, ProgressiveMesh& sequence)
{
  // The sequence's arrays reuse the build's buffers of the same type where their sizes allow:
  // pages already mapped, where fresh ones cost more than writing them (see README, Large meshes).
  // Points: those never removed in vertex order, then the removed ones, last removed first.
  const std::int32_t n = static_cast<std::int32_t>(prepared.Mesh.InputVertex.size());
  const std::int32_t collapses = static_cast<std::int32_t>(this->Removed.size());
  std::vector<std::int32_t> index(n, -1);
  for (std::int32_t s = 0; s < collapses; ++s)
  {
    index[this->Removed[s]] = n - 1 - s;
  }
  std::int32_t base = 0;
  for (std::int32_t v = 0; v < n; ++v)
  {
    index[v] = index[v] < 0 ? base++ : index[v];
  }
  sequence.BasePoints = base;
  sequence.InputPoint.resize(n);
  sequence.Parent.assign(n, -1);
  sequence.Error = std::move(this->Weights);
  sequence.Error.assign(n, 0.0);
  for (std::int32_t v = 0; v < n; ++v)
  {
    sequence.InputPoint[index[v]] = prepared.Mesh.InputVertex[v];
  }
  for (std::int32_t s = 0; s < collapses; ++s)
  {
    sequence.Parent[n - 1 - s] = index[this->Into[s]];
    sequence.Error[n - 1 - s] = this->StepError[s] / this->Coordinates.Scale;
  }
  // Triangles: the input corners renumbered, ordered by the point that removes them, by a
  // counting sort (stable: triangle order within a key): key 0 for those never removed, then
  // collapses - step, so the last collapse's triangles come first.
  const std::size_t m = this->RemovedStep.size();
  const auto key = [&](std::size_t t) {
    return this->RemovedStep[t] < 0 ? 0 : static_cast<std::size_t>(collapses - this->RemovedStep[t]);
  };
  std::vector<std::int32_t> start(static_cast<std::size_t>(collapses) + 2, 0), order = std::move(this->Corners);
  order.resize(m);
  for (std::size_t t = 0; t < m; ++t)
  {
    ++start[key(t) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  for (std::size_t t = 0; t < m; ++t)
  {
    order[start[key(t)]++] = static_cast<std::int32_t>(t);
  }
  sequence.Triangles = std::move(this->NextCorner);
  sequence.Triangles.resize(3 * m);
  sequence.InputTriangle.resize(m);
  sequence.RemovedBy.resize(m);
  for (std::size_t i = 0; i < m; ++i)
  {
    const std::int32_t t = order[i];
    for (int k = 0; k < 3; ++k)
    {
      sequence.Triangles[3 * i + k] = index[prepared.Mesh.Triangles[3 * t + k]];
    }
    sequence.InputTriangle[i] = prepared.Mesh.InputTriangle[t];
    sequence.RemovedBy[i] = this->RemovedStep[t] < 0 ? -1 : n - 1 - this->RemovedStep[t];
  }
}

} // namespace

bool BuildProgressiveMesh(const TriangleMeshView& input, const ProgressiveMeshOptions& options,
  ProgressiveMesh& sequence, const ExecutionContext& context)
{
  ProgressiveBuilder builder(options, context);
  return builder.Run(input, sequence);
}

} // namespace meshsimp
