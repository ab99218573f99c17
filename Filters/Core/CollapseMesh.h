// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CollapseMesh.h
 * @brief The shared collapse engine: a mutable triangle mesh with edge and triangle collapse,
 * the checks every collapse must pass, collapse records and their undo (vertex split).
 *
 * Storage is flat: points, 3 vertex ids per triangle, an alive flag per triangle, and per vertex
 * a span {start, count} into one array of incident triangle ids. A collapse writes the merged
 * vertex's new span at the end of that array (old spans become garbage, compacted when it
 * doubles) and takes the removed triangles out of their other corners' spans, so that spans list
 * alive triangles only. A span keeps its order when a triangle leaves it, except a span of more
 * than IndexedSpan triangles (the centre of a fan): its triangles' places in it are indexed, and
 * the last one takes the leaving one's place, so that a fan is not simplified in quadratic time.
 * Undo gives such a span its triangles back at its end, into free slots (-1) that follow it: a
 * span that has none moves to the end of the array with as many free slots as it has triangles,
 * so that a fan is not restored in quadratic time either.
 *
 * A collapse merges a connected set of two vertices (an edge, or a half-edge when the position is
 * one end point) or three (a triangle, as in Zhou, Zhang and Cheng's volume-variation
 * simplification) into the first of them, the kept vertex, at a
 * new position. Triangles with two of the merged vertices disappear: the two around an edge, or
 * the triangle and its up-to-three edge neighbours. Every collapse leaves a CollapseRecord with
 * the attribute weights (value(kept) := Σ weight_i · value(vertex_i)) and, unless records are
 * trimmed, what Undo() needs to split the vertex again.
 *
 * The checks (IsLegal; FirstFailedCheck names the first that fails, CollapseCheck) are those of
 * the decimators built on the engine, in the order they run (the plan itself first: two or three
 * distinct vertices, a finite position):
 * - locks: a locked vertex is never removed or moved (non-manifold vertices are always locked);
 *   a hinge vertex (where three or more sheets meet along a chain of edges) never moves either,
 *   but may be merged along its hinge into the vertex at the other end of a hinge edge, so that
 *   a hinge only loses vertices, like a polyline;
 * - regions (SetRegions): no collapse merges vertices of different regions, so that the border
 *   between two values of a label or colour array stays sharp;
 * - the link condition, collapse by collapse: the common neighbours of the two sides are exactly
 *   the far corners of their shared triangles (two, one on a boundary, k on a hinge), so no edge
 *   gains triangles and no "hidden cycle" (Zhou, Zhang and Cheng, "Mesh simplification by
 *   volume variation with feature preserving", Fig. 8) is closed, and on a hinge no two of the
 *   far corners span triangles with both sides; two vertices of a boundary or hinge are not
 *   joined across a sheet; no vertex falls below three neighbours;
 * - shared edges: no collapse joins two vertices locked as shared with another piece of a
 *   distributed mesh by an edge they did not have (the other piece might make the same edge,
 *   and the merged pieces would get an edge of four triangles);
 * - then, triangle by triangle of those the plan changes, the next three (so the first failure
 *   is that of the first such triangle to fail one):
 * - no fold-over, by the plane-side test of Franc, "Methods for Polygonal Mesh Simplification",
 *   §5.3: the new position stays on the inner side of the plane through every opposite edge
 *   perpendicular to its triangle;
 * - no degenerate triangle: every changed triangle keeps a non-zero area (a merged vertex that
 *   stays where it is, the kept end of a half-edge, changes none of its own);
 * - no fold against a neighbour: a changed triangle that turns by over 30 degrees may not end
 *   back to back (normals over 150 degrees apart) with the unchanged triangle across its far
 *   edge, nor more so where it already was (the plane-side test lets a turn of up to 90 degrees
 *   through, which on exact CAD geometry lays a wall triangle flat onto the face at its rim);
 * - last, optionally (SetMinimumAngle), no new angle below a minimum unless the collapsed
 *   neighbourhood already had one as small, so simplification does not breed slivers (each
 *   triangle's smallest angle is kept from then on, so the neighbourhood's is looked up).
 */
#ifndef MeshSimplification_CollapseMesh_h
#define MeshSimplification_CollapseMesh_h

#include "CollapseReport.h"
#include "Execution.h"
#include "FanTopology.h"
#include "Simplification.h"
#include "TriangleMesh.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace meshsimp
{

// The prefetch helpers are always inlined: GCC judges a function whose only effect is a prefetch
// to have none, and drops the calls to it that it did not inline.
#if defined(__GNUC__) || defined(__clang__)
#define MESHSIMP_PREFETCH_HELPER __attribute__((always_inline)) inline
#else
#define MESHSIMP_PREFETCH_HELPER inline
#endif

/// For a function on a path most meshes never take (hinges, say): kept out of line, and calls
/// to it taken as unlikely, so that it costs the common path nothing (GCC and Clang only).
#if defined(__GNUC__) || defined(__clang__)
#define MESHSIMP_RARE_PATH __attribute__((noinline, cold))
#else
#define MESHSIMP_RARE_PATH
#endif

/// A hint to start loading the cache line holding p; it changes no result (GCC and Clang only).
MESHSIMP_PREFETCH_HELPER void Prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  static_cast<void>(p);
#endif
}

/// One collapse: the kept vertex, the one or two merged into it, and the attribute weights
/// (40 bytes: a decimation to 1 % keeps about one per input vertex).
struct CollapseRecord
{
  std::int32_t Kept = -1;
  std::int32_t Removed[2] = { -1, -1 };
  double Weights[3] = { 1.0, 0.0, 0.0 }; // kept, Removed[0], Removed[1]
};

/// What undoing a collapse needs besides its record: the kept vertex's position and class, and
/// spans into CollapseMesh's change and removed-triangle lists.
struct CollapseUndo
{
  Eigen::Vector3d KeptPosition = Eigen::Vector3d::Zero(); // before the collapse
  Eigen::Vector3d NewPosition = Eigen::Vector3d::Zero();  // after it
  VertexClass KeptClass = VertexClass::Interior;          // before the collapse
  std::int32_t FirstChange = 0, ChangeCount = 0;
  std::int32_t FirstRemovedTriangle = 0, RemovedTriangleCount = 0;
};

/// A proposed collapse: Vertices[0] is kept, Vertices[1 .. Count) are merged into it.
struct CollapsePlan
{
  std::int32_t Vertices[3] = { -1, -1, -1 };
  int Count = 0;
  Eigen::Vector3d Position = Eigen::Vector3d::Zero();
  double Weights[3] = { 1.0, 0.0, 0.0 };
  /// Whether the angle guard (SetMinimumAngle) applies to this collapse; a policy may waive it
  /// for collapses that do not change the surface.
  bool GuardAngles = true;
};

/// Releases what std::calloc gave (the deleter of CollapseMesh's span places).
struct FreeMemory
{
  void operator()(void* memory) const { std::free(memory); }
};

class CollapseMesh
{
public:
  /// Working marks of the checks. IsLegal uses the mesh's own; threads that check collapses
  /// concurrently pass one each.
  struct CheckScratch
  {
    std::vector<std::uint32_t> Marks;
    std::uint32_t Stamp = 0;
    std::vector<std::int32_t> Vertices;
    std::vector<std::int32_t> FarCorners; // of a hinge edge, past the first two
  };

  /**
   * Takes a compact mesh's points, triangles and adjacency (moved out of it). A boundary vertex
   * whose two boundary edges turn by more than cornerAngleDegrees is a Corner; a vertex inside a
   * hinge (IsHinge) is a Hinge, unless its hinge turns so (then it stays NonManifold, locked).
   * The vertices are classified on the context's threads.
   */
  void Build(CompactMesh&& mesh, double cornerAngleDegrees = 60.0, const ExecutionContext& context = {});
  /// Build on a prepared mesh (moved out of it) with its regions and locks: the options' points
  /// (Options), points shared with another piece (SharedPoint) and, with lockBorderCorners,
  /// the border corners (BorderCorner).
  void Load(PreparedMesh& prepared, double cornerAngleDegrees, bool lockBorderCorners, const ExecutionContext& context);

  std::int32_t NumberOfPoints() const { return static_cast<std::int32_t>(this->Points.size()); }
  std::int32_t NumberOfTriangles() const { return static_cast<std::int32_t>(this->Alive.size()); }
  std::int64_t NumberOfAliveTriangles() const { return this->AliveCount; }
  bool IsAlive(std::int32_t t) const { return this->Alive[t] != 0; }
  const std::int32_t* Triangle(std::int32_t t) const { return this->Triangles.data() + 3 * t; }
  const Eigen::Vector3d& Point(std::int32_t v) const { return this->Points[v]; }
  /// Moves v (while an angle guard is set, also re-measures v's triangles: then not concurrently
  /// with a neighbour).
  void SetPoint(std::int32_t v, const Eigen::Vector3d& x);

  VertexClass Class(std::int32_t v) const { return this->Classes[v]; }
  bool OnBoundary(std::int32_t v) const
  {
    return this->Classes[v] == VertexClass::Boundary || this->Classes[v] == VertexClass::Corner;
  }
  bool OnHinge(std::int32_t v) const { return this->Classes[v] == VertexClass::Hinge; }
  /// Whether any vertex is a hinge vertex (then its rules apply; meshes without run as before).
  bool HasHinges() const { return this->HasHingeVertices; }
  /// How many hinge edges (of three or more triangles) v has: two for a hinge vertex. The
  /// vertices at their other ends go to ends in increasing order, the first two of them.
  int HingeEnds(std::int32_t v, std::int32_t ends[2]) const;
  bool IsLocked(std::int32_t v) const { return this->Locked[v] != 0; }
  /// Why the locked vertex v is locked (never OffHinge).
  LockReason WhyLocked(std::int32_t v) const { return static_cast<LockReason>(this->Locked[v]); }
  /// Counts plan's first failed check in counts, and for the locks check its LockReason: the
  /// first locked vertex it removes, else the locked one it moves, else the hinge rule.
  void CountRefusal(const CollapsePlan& plan, CollapseCheck failed, RefusalCounts& counts) const;
  /// Locks v for reason; SharedPoint: v is also in another piece of a distributed mesh (see
  /// IsLegal). A non-manifold vertex, locked by Build, keeps that reason unless it is shared.
  void Lock(std::int32_t v, LockReason reason)
  {
    if (this->WhyLocked(v) != LockReason::NonManifold || reason == LockReason::SharedPoint)
    {
      this->Locked[v] = static_cast<std::uint8_t>(reason);
    }
    this->HasSharedLocks = this->HasSharedLocks || reason == LockReason::SharedPoint;
  }

  /**
   * Memory hints for walking the triangles around each vertex of a list, in order: at position
   * i, the span place (start, count) of the vertex PrefetchDistance further on, and the span of
   * the one half as far, whose place has arrived by then. Walking the stars of vertices spread
   * over a mesh larger than the caches otherwise waits on two dependent misses per vertex.
   * Entries below zero are skipped. No effect on results.
   */
  static constexpr std::int64_t PrefetchDistance = 16;
  MESHSIMP_PREFETCH_HELPER void PrefetchStars(const std::int32_t* vertices, std::int64_t i, std::int64_t end) const
  {
    if (i + PrefetchDistance < end && vertices[i + PrefetchDistance] >= 0)
    {
      this->PrefetchPlace(vertices[i + PrefetchDistance]);
    }
    if (i + PrefetchDistance / 2 < end && vertices[i + PrefetchDistance / 2] >= 0)
    {
      this->PrefetchSpan(vertices[i + PrefetchDistance / 2]);
    }
  }
  /// The first of PrefetchStars' hints alone: v's span place, for a walk that reads only counts.
  MESHSIMP_PREFETCH_HELPER void PrefetchPlace(std::int32_t v) const
  {
    Prefetch(this->Start.data() + v);
    Prefetch(this->Count.data() + v);
  }

  /// Spans longer than this keep an index of their triangles' places (see the top of the file).
  static constexpr std::int32_t IndexedSpan = 256;

  /// The number of alive triangles with the edge (u, w).
  int TrianglesOnEdge(std::int32_t u, std::int32_t w) const
  {
    int count = 0;
    this->ForEachTriangleOnEdge(u, w, [&count](std::int32_t) { ++count; });
    return count;
  }

  /// The number of alive triangles around v.
  std::int32_t NumberOfTrianglesAround(std::int32_t v) const { return this->Count[v]; }

  /// Calls f(t) for every alive triangle around v (spans hold alive triangles only).
  template <typename F>
  void ForEachTriangle(std::int32_t v, F&& f) const
  {
    const std::int32_t* ids = this->Refs.data() + this->Start[v];
    for (std::int32_t i = 0, n = this->Count[v]; i < n; ++i)
    {
      f(ids[i]);
    }
  }

  /// Calls f(t) for every alive triangle with the edge (u, w), found around the end with fewer
  /// triangles (a fan's centre may have thousands).
  template <typename F>
  void ForEachTriangleOnEdge(std::int32_t u, std::int32_t w, F&& f) const
  {
    if (this->Count[w] < this->Count[u])
    {
      std::swap(u, w);
    }
    this->ForEachTriangle(u, [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      if (tri[0] == w || tri[1] == w || tri[2] == w)
      {
        f(t);
      }
    });
  }

  /// Calls f(t, next, previous) for every alive triangle t around v with its corners after and
  /// before v (in the triangle's orientation).
  template <typename F>
  void ForEachCorner(std::int32_t v, F&& f) const
  {
    this->ForEachTriangle(v, [&](std::int32_t t) {
      const std::int32_t* tri = this->Triangle(t);
      const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      f(t, tri[k == 2 ? 0 : k + 1], tri[k == 0 ? 2 : k - 1]);
    });
  }

  /// The unit normal (zero when degenerate) and area of triangle t at the current points.
  Eigen::Vector3d Normal(std::int32_t t) const;
  double Area(std::int32_t t) const;

  /// Whether the plan passes every check listed at the top of this file.
  bool IsLegal(const CollapsePlan& plan) const { return this->IsLegal(plan, this->Scratch); }
  /// The same with the caller's scratch: concurrent calls read the mesh only.
  bool IsLegal(const CollapsePlan& plan, CheckScratch& scratch) const
  {
    return this->FirstFailedCheck(plan, scratch) == CollapseCheck::Passed;
  }
  /// The first check the plan fails, or Passed. AngleGuard means that the same plan with
  /// GuardAngles off is legal.
  CollapseCheck FirstFailedCheck(const CollapsePlan& plan, CheckScratch& scratch) const;
  CollapseCheck FirstFailedCheck(const CollapsePlan& plan) const
  {
    return this->FirstFailedCheck(plan, this->Scratch);
  }

  /// The angle guard's minimum in degrees; 0 (default) turns it off.
  void SetMinimumAngle(double degrees);
  /// The cosine of the smallest angle among the triangles the plan keeps but changes, at its
  /// position: the angle guard's measure (-1 when it changes none).
  double SmallestNewAngleCosine(const CollapsePlan& plan) const;

  /// One region id per vertex (see IsLegal), or none (empty, the default).
  void SetRegions(std::vector<std::int32_t> regions) { this->Regions = std::move(regions); }

  /// Room for count records (a hint: the list grows past it as it must).
  /// From now on, keeps for each removed vertex the vertex it was merged into (MergedInto), for
  /// a caller that keeps no records (ApplyIndependent records none).
  void TrackMerges() { this->MergedInto.assign(this->Points.size(), -1); }
  /// Per vertex the one it was last merged into, or -1 (kept, or TrackMerges was not called).
  const std::vector<std::int32_t>& MergeTargets() const { return this->MergedInto; }
  void ReserveRecords(std::int64_t count) { this->History.reserve(static_cast<std::size_t>(std::max<std::int64_t>(0, count))); }

  /**
   * Applies a legal plan and appends its record. Returns the number of triangles removed.
   * With keepUndo false nothing is kept to undo it (less memory), and Undo stops there.
   */
  int Apply(const CollapsePlan& plan, bool keepUndo = true);

  /// Splits the vertex of the last record again: points, triangles, classes and adjacency are
  /// as before that collapse (adjacency spans may list triangles in another order). The record
  /// moves to the redo list, so that the progressive mesh can be replayed both ways. Nothing
  /// happens when the last collapse kept no undo (Apply's keepUndo, ApplyIndependent).
  void Undo();

  /// Collapses again the last undone record (forward replay); false when none is left.
  bool Redo();

  /// Records undone and not replayed yet, the next one to Redo last.
  const std::vector<CollapseRecord>& UndoneRecords() const { return this->Undone; }

  const std::vector<CollapseRecord>& Records() const { return this->History; }

  /// Sorted ids of the alive triangles around v (for tests and comparisons).
  std::vector<std::int32_t> SortedTrianglesAround(std::int32_t v) const;

  /// The neighbouring vertices of v that share an alive triangle with it (unsorted, unique).
  void Neighbours(std::int32_t v, std::vector<std::int32_t>& out) const;

  /**
   * What is left: the vertices of the alive triangles in vertex order (used), and the alive
   * triangles in triangle order (their ids in kept) as 3 indices each into used.
   */
  void Surviving(std::vector<std::int32_t>& used, std::vector<std::int32_t>& triangles,
    std::vector<std::int32_t>& kept) const;

  /// The number of neighbours of v.
  std::int32_t Valence(std::int32_t v) const { return this->Valence(v, this->Scratch); }

  /// For a report of what is left: counts the vertices with triangles (returned) and the locked
  /// ones among them by LockReason (into lockedBy), and calls f(v) for each of the others.
  template <typename F>
  std::int64_t ForEachUnlockedLeft(std::array<std::int64_t, NumberOfLockReasons>& lockedBy, F&& f) const
  {
    std::int64_t left = 0;
    for (std::int32_t v = 0; v < this->NumberOfPoints(); ++v)
    {
      if (this->NumberOfTrianglesAround(v) == 0)
      {
        continue;
      }
      ++left;
      if (this->IsLocked(v))
      {
        ++lockedBy[LockIndex(this->WhyLocked(v))];
        continue;
      }
      f(v);
    }
    return left;
  }

  /**
   * Applies plans that touch disjoint neighbourhoods (no vertex within one edge of a plan's
   * vertices is within one edge of another's, e.g. the half-edge collapses of a super-independent
   * vertex set), concurrently through the context. The vertices listed in shared are the
   * exception: they may neighbour the vertices of several plans, but be none of them; the
   * triangles the plans remove leave their spans after the concurrent part. No records are kept,
   * so Undo cannot reach past such a batch. Returns the number of triangles removed.
   */
  std::int64_t ApplyIndependent(const std::vector<CollapsePlan>& plans, const ExecutionContext& context,
    const std::vector<std::int32_t>& shared = {});

private:
  std::int32_t Valence(std::int32_t v, CheckScratch& scratch) const;
  void Neighbours(std::int32_t v, std::vector<std::int32_t>& out, CheckScratch& scratch) const;
  bool LinkCondition(const std::int32_t* merged, int count, std::int32_t next, CheckScratch& scratch) const;
  /// LinkCondition's stages: the merged vertices and their neighbours marked; the triangles
  /// around next scanned for the edge's far corners and the common neighbours.
  struct LinkState;
  void MarkMergedNeighbours(const std::int32_t* merged, int count, LinkState& link, CheckScratch& scratch) const;
  void ScanAroundNext(std::int32_t next, LinkState& link, CheckScratch& scratch) const;
  /// How many corners of a triangle carry the mark.
  static int MergedCount(const std::int32_t* tri, std::uint32_t mark, const CheckScratch& scratch)
  {
    return (scratch.Marks[tri[0]] == mark) + (scratch.Marks[tri[1]] == mark) + (scratch.Marks[tri[2]] == mark);
  }
  /// The collapse itself: triangles, alive flags, the kept point and class, removed triangles
  /// taken out of their other corners' spans (droppedRefs counts them); the kept vertex's new
  /// triangles go to span (its span and the merged vertices' are not set). Returns the number of
  /// triangles removed.
  int Merge(const CollapsePlan& plan, std::vector<std::int32_t>& span, bool keepUndo,
    std::int64_t& droppedRefs);
  /// The checks on the triangles the plan changes: PlaneSide, Degenerate, FoldAcross, AngleGuard.
  CollapseCheck ChangedTrianglesCheck(const CollapsePlan& plan) const;
  /// Calls f(s, t, p, q) for each triangle t the plan keeps but changes: s its merged vertex
  /// that moves, p and q its other corners in order; f returns false to stop, and so does this.
  template <typename F>
  bool ForEachChangedTriangle(const CollapsePlan& plan, F&& f) const;
  /// Whether triangle t, turned from normal before to after by the plan, would lie back to back
  /// with the unchanged triangle across its edge pq (see ChangedTrianglesCheck).
  bool FoldsAcross(const CollapsePlan& plan, std::int32_t t, std::int32_t p, std::int32_t q,
    const Eigen::Vector3d& before, const Eigen::Vector3d& after) const;
  /// The link condition's part that neighbour counts cover only for manifold far corners (on a
  /// hinge edge, or where a far corner is a hinge or non-manifold vertex).
  bool FarCornersKeepApart(const std::int32_t* merged, int count, std::int32_t next, const LinkState& link,
    CheckScratch& scratch) const;
  /// The hinge rule of the locks check (see the top of this file).
  bool StaysOnHinges(const CollapsePlan& plan) const;
  /// No new edge between the kept vertex and another shared one, when the kept one is shared.
  bool KeepsSharedEdges(const CollapsePlan& plan, CheckScratch& scratch) const;
  void SetSpan(std::int32_t v, const std::vector<std::int32_t>& triangles);
  /// Indexes the places in v's span when it is longer than IndexedSpan (after it was written).
  void IndexSpan(std::int32_t v);
  /// The entry of Places for t's corner at v.
  std::int32_t& PlaceIn(std::int32_t v, std::int32_t t);
  /// Takes t out of w's span (see the top of the file).
  void DropFromSpan(std::int32_t w, std::int32_t t);
  /// The cosine of t's smallest angle at its current points: measured when the angle guard
  /// reads it (rarely: only where a new angle is below the minimum), not kept per triangle.
  double SmallestAngleCosineOf(std::int32_t t) const
  {
    const std::int32_t* tri = this->Triangle(t);
    return SmallestAngleCosine(this->Points[tri[0]], this->Points[tri[1]], this->Points[tri[2]]);
  }
  /// Adds t at the end of w's indexed span (see the top of the file), unless it is there.
  void AddToIndexedSpan(std::int32_t w, std::int32_t t);
  /// Refs rewritten with only the live spans, in vertex order (by parts concurrently).
  void CompactRefs(const ExecutionContext& context = {});
  MESHSIMP_PREFETCH_HELPER void PrefetchSpan(std::int32_t v) const { Prefetch(this->Refs.data() + this->Start[v]); }

  std::vector<Eigen::Vector3d> Points;
  std::vector<std::int32_t> Triangles; // 3 per triangle
  std::vector<std::uint8_t> Alive;
  std::int64_t AliveCount = 0;
  std::vector<VertexClass> Classes;
  std::vector<std::uint8_t> Locked; // 0 or a LockReason
  bool HasSharedLocks = false;
  bool HasHingeVertices = false; // see HasHinges
  std::vector<std::int64_t> Start; // per vertex, into Refs (which grows past 2^31 entries on
                                   // inputs of over 238 million triangles before a compaction)
  std::vector<std::int32_t> Count;
  std::vector<std::int32_t> Refs;
  std::int64_t LiveRefs = 0;
  // Where spans are indexed (IndexSpan): per vertex whether its span is, and per triangle corner
  // its place in the span of the corner's vertex; both empty until a span needs it.
  std::vector<std::uint8_t> Indexed;
  std::unique_ptr<std::int32_t[], FreeMemory> Places; // 3 per triangle, see IndexSpan
  std::vector<std::uint8_t> Shared; // ApplyIndependent: spans updated after the concurrent merges

  double MinimumAngleCosine = 1.0;
  std::vector<std::int32_t> Regions;
  std::vector<std::int32_t> MergedInto; // see TrackMerges

  std::vector<CollapseRecord> History;
  std::vector<CollapseUndo> HistoryUndo; // of the last HistoryUndo.size() records of History
  std::vector<CollapseRecord> Undone;
  std::vector<CollapseUndo> UndoneUndo; // one per Undone record
  std::vector<std::int32_t> Changes;          // per change: corner (3 t + k), old vertex
  std::vector<std::int32_t> RemovedTriangles;

  /// count fresh mark values (the first returned): values no vertex carries yet in scratch.
  std::uint32_t NewMarks(std::uint32_t count, CheckScratch& scratch) const;

  // The checks' own scratch: a vertex carries a mark when Marks[v] equals it.
  mutable CheckScratch Scratch;
  std::vector<std::int32_t> Span;
};

/// Replays the records' attribute weights over a table of point values (components per point,
/// indexed like the mesh's points): afterwards each kept vertex holds its interpolated value.
void InterpolateAttributes(
  const std::vector<CollapseRecord>& records, double* values, int components);

} // namespace meshsimp

#endif
