// SPDX-License-Identifier: BSD-3-Clause
#include "ParallelDecimation.h"

#include "CollapseLoop.h"
#include "CollapseMesh.h"
#include "PlaneDistanceBound.h"
#include "Quadric.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace meshsimp
{

double BucketPosition(double x, double a, double alpha)
{
  x = std::min(1.0, std::max(0.0, x));
  if (!(alpha > a) || !(a > 0.0) || !(alpha < 1.0))
  {
    return x; // no bend: plain proportional buckets
  }
  const double k = a * (1.0 - alpha) / (alpha - a); // eq. (5.13)
  return (1.0 + k) * x / (x + k);                    // eq. (5.6), C = 1 + k
}

namespace
{
/// BucketOrder's working layout: each vertex's bucket, and a histogram of coarse buckets (at
/// most 4096, `shift` bits each) per part of the vertices.
struct Buckets
{
  std::int32_t Count = 1, CoarseCount = 1;
  int Shift = 0;
  std::int64_t Parts = 1;
  std::vector<std::int64_t> Coarse; // Parts × CoarseCount
};

/// Finds every vertex's bucket (into bucketOf) and the per-part coarse histograms, concurrently.
Buckets FillBuckets(const double* importance, const std::vector<std::int32_t>& vertices, double largest,
  double a, double alpha, std::int32_t* bucketOf, const ExecutionContext& context)
{
  Buckets buckets;
  const std::size_t count = vertices.size();
  buckets.Count = static_cast<std::int32_t>(std::max<std::size_t>(1, count));
  while (((buckets.Count - 1) >> buckets.Shift) >= 4096)
  {
    ++buckets.Shift;
  }
  buckets.CoarseCount = ((buckets.Count - 1) >> buckets.Shift) + 1;
  buckets.Parts =
    std::max<std::int64_t>(1, std::min<std::int64_t>(context.Threads, static_cast<std::int64_t>(count) / 4096));
  buckets.Coarse.assign(static_cast<std::size_t>(buckets.Parts * buckets.CoarseCount), 0);
  const std::int64_t parts = buckets.Parts, size = static_cast<std::int64_t>(count);
  context.For(parts, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t part = first; part < last; ++part)
    {
      std::int64_t* histogram = buckets.Coarse.data() + part * buckets.CoarseCount;
      for (std::int64_t i = size * part / parts, end = size * (part + 1) / parts; i < end; ++i)
      {
        const double x = largest > 0.0 ? importance[vertices[i]] / largest : 0.0;
        bucketOf[i] = std::min(buckets.Count - 1, static_cast<std::int32_t>(BucketPosition(x, a, alpha) * buckets.Count));
        ++histogram[bucketOf[i] >> buckets.Shift];
      }
    }
  }, 10 * size);
  return buckets;
}

/// The coarse bucket where the first `limit` vertices end.
std::int32_t LastCoarseBucket(const Buckets& buckets, std::size_t limit)
{
  std::int64_t total = 0;
  for (std::int32_t c = 0; c < buckets.CoarseCount; ++c)
  {
    for (std::int64_t part = 0; part < buckets.Parts; ++part)
    {
      total += buckets.Coarse[part * buckets.CoarseCount + c];
    }
    if (static_cast<std::size_t>(total) >= limit)
    {
      return c;
    }
  }
  return buckets.CoarseCount - 1;
}
}

void BucketOrder(const double* importance, const std::vector<std::int32_t>& vertices, double largest,
  double a, double alpha, std::vector<std::int32_t>& order, std::vector<std::int32_t>& work,
  std::size_t limit, const ExecutionContext& context)
{
  // One bucket per vertex on average; a counting sort by bucket, stable in the given order. The
  // buckets are found concurrently, with a histogram of coarse buckets per part, which tells the
  // ones that hold the first `limit` vertices: only their vertices are gathered (each part's in
  // its place, concurrently), counted and placed, in a table of those buckets alone. work is
  // working memory, grown but never shrunk (no refill each round).
  const std::size_t count = vertices.size();
  work.resize(std::max(work.size(), count));
  const Buckets buckets = FillBuckets(importance, vertices, largest, a, alpha, work.data(), context);
  const std::int32_t lastCoarse = LastCoarseBucket(buckets, limit);
  const std::int64_t parts = buckets.Parts;
  std::vector<std::int64_t> gatheredAt(static_cast<std::size_t>(parts) + 1, 0);
  for (std::int64_t part = 0; part < parts; ++part)
  {
    const std::int64_t* histogram = buckets.Coarse.data() + part * buckets.CoarseCount;
    gatheredAt[part + 1] = gatheredAt[part] + std::accumulate(histogram, histogram + lastCoarse + 1, std::int64_t(0));
  }
  const std::int32_t range =
    static_cast<std::int32_t>(std::min<std::int64_t>(buckets.Count, std::int64_t(lastCoarse + 1) << buckets.Shift));
  const std::int64_t gathered = gatheredAt[parts];
  work.resize(std::max(work.size(), count + static_cast<std::size_t>(range) + 1 + 2 * static_cast<std::size_t>(gathered)));
  const std::int32_t* bucketOf = work.data();
  std::int32_t* table = work.data() + count;
  std::fill(table, table + range + 1, 0);
  std::int32_t* gatheredBucket = table + range + 1;
  std::int32_t* gatheredVertex = gatheredBucket + gathered;
  context.For(parts, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t part = first; part < last; ++part)
    {
      std::int64_t at = gatheredAt[part];
      const std::int64_t size = static_cast<std::int64_t>(count);
      for (std::int64_t i = size * part / parts, end = size * (part + 1) / parts; i < end; ++i)
      {
        if (bucketOf[i] < range)
        {
          gatheredBucket[at] = bucketOf[i];
          gatheredVertex[at++] = vertices[i];
        }
      }
    }
  }, 2 * static_cast<std::int64_t>(count));
  for (std::int64_t j = 0; j < gathered; ++j)
  {
    ++table[gatheredBucket[j] + 1];
  }
  std::int32_t lastBucket = range - 1; // the last bucket needed for the first `limit` vertices
  for (std::int32_t b = 0; b < range; ++b)
  {
    table[b + 1] += table[b];
    if (static_cast<std::size_t>(table[b + 1]) >= limit)
    {
      lastBucket = b;
      break;
    }
  }
  order.resize(static_cast<std::size_t>(table[lastBucket + 1]));
  for (std::int64_t j = 0; j < gathered; ++j)
  {
    if (gatheredBucket[j] <= lastBucket)
    {
      order[table[gatheredBucket[j]]++] = gatheredVertex[j];
    }
  }
}

namespace
{
using Vec3 = Eigen::Vector3d;
constexpr double Pi = 3.14159265358979323846;
constexpr double Never = std::numeric_limits<double>::infinity();
constexpr double RelaxationStep = 15.0; // degrees
/// Candidates whose neighbourhoods SelectRound gathers at once.
constexpr std::int64_t RingBlock = 16384;
/// A vertex of at least this many triangles (the centre of a fan) is a hub: the stars of one
/// round's vertices may share it (only it: no edge), and it survives no collapse, so that a
/// round is not limited to one vertex around it.
constexpr std::int32_t HubTriangles = 32;

/// One edge (v, W) around a vertex v: the triangle where W follows v and the one where W precedes
/// it (-1 when missing: a boundary edge).
struct StarEdge
{
  std::int32_t W, After, Before;
};

/// What the analysis of one vertex found: its type, importance and the neighbours it may collapse
/// into along its boundary or sharp edges.
struct VertexState
{
  DecimationVertexType Type = DecimationVertexType::Complex;
  double Importance = Never;
  std::int32_t Along[2] = { -1, -1 };
  std::int32_t Best = -1; // Quadric: the neighbour of least half-edge error
};

/// One triangle around a vertex v: its corners after and before v, and the cross product of
/// their offsets from v (the normal times twice the area) with its length.
struct StarTriangle
{
  Vec3 Cross;
  double Length;
  std::int32_t Id, Next, Previous;
};

/// Per-thread working memory.
struct Workspace
{
  std::vector<StarTriangle> Star;
  std::vector<StarEdge> Edges;
  FanLookup Nexts; // the edges' far vertices, by vertex
  CollapseMesh::CheckScratch Scratch;
  struct Option
  {
    double Score;
    double Length; // squared; breaks ties, so flat regions do not grow hubs of high valence
    std::int32_t Target;
  };
  std::vector<Option> Options;
};

/// Calls f(u) for each neighbour u a vertex may collapse into: any, for a simple vertex (its
/// star's edges in the workspace); else the two along its boundary or crease.
template <typename F>
void ForEachTarget(const VertexState& state, const Workspace& work, F&& f)
{
  if (state.Type == DecimationVertexType::Simple)
  {
    for (const StarEdge& e : work.Edges)
    {
      f(e.W);
    }
    return;
  }
  f(state.Along[0]);
  f(state.Along[1]);
}

double DistanceToLine(const Vec3& p, const Vec3& a, const Vec3& b)
{
  // Eq. (5.4): the height of the parallelogram over a–b through p.
  const Vec3 q = b - a;
  const double length = q.norm();
  return length > 0.0 ? q.cross(p - a).norm() / length : (p - a).norm();
}

class Decimator
{
public:
  /// mayRelax: whether FeatureAngle and MaximumNormalDeviation may be raised when no vertex is
  /// removable before the target (Unstick).
  Decimator(const ParallelDecimationOptions& options, const ExecutionContext& context, bool mayRelax)
    : Options(options)
    , Context(context)
    , MayRelax(mayRelax)
  {
    this->SetAngles(options.FeatureAngle, options.MaximumNormalDeviation);
  }

  bool Run(const TriangleMeshView& input, ParallelDecimationResult& result);

private:
  void CollectStar(std::int32_t v, Workspace& work) const;
  /// The type, the importance of eq. (5.1)–(5.4) and the special neighbours of v, with v's star
  /// left in the workspace (collected unless starCollected says it is there already).
  VertexState Analyze(std::int32_t v, Workspace& work, bool starCollected = false) const;
  /// Analyze for a hinge vertex.
  VertexState AnalyzeHinge(std::int32_t v, Workspace& work, bool starCollected) const;
  /// Analyze with the importance of the chosen measure.
  VertexState Evaluate(std::int32_t v, Workspace& work, bool starCollected = false) const;
  /// The engine's PrefetchStars, and the quadric the evaluation of a listed vertex reads first.
  MESHSIMP_PREFETCH_HELPER void PrefetchAhead(const std::int32_t* vertices, std::int64_t i, std::int64_t end) const
  {
    this->Mesh.PrefetchStars(vertices, i, end);
    const std::int64_t near = i + CollapseMesh::PrefetchDistance / 2;
    if (!this->Quadrics.empty() && near < end && vertices[near] >= 0)
    {
      Prefetch(this->Quadrics.data() + vertices[near]);
    }
  }
  /// The round's stamp in Owner and Touched.
  std::uint8_t RoundStamp() const { return static_cast<std::uint8_t>((this->Round - 1) % 255 + 1); }
  bool IsHub(std::int32_t v) const { return this->Mesh.NumberOfTrianglesAround(v) >= HubTriangles; }
  /// The quadric error of collapsing v into u.
  double HalfEdgeError(std::int32_t v, std::int32_t u) const;
  /// Quadric: v's own planes, from its star in the workspace.
  void InitializeQuadric(std::int32_t v, const Workspace& work);
  /// Half the change of area when v collapses into u (its star in the workspace), or -1 when a
  /// remaining triangle would turn by more than the deviation limit or degenerate (§5.3).
  double AreaChange(std::int32_t u, const Workspace& work) const;
  /// How many triangles removing v takes: one on a boundary, two inside, k along a hinge of k
  /// pages.
  int TrianglesRemovedWith(std::int32_t v) const;
  /// The legal half-edge v collapses along, and with a bound the survivor's distance after it.
  bool Plan(std::int32_t v, Workspace& work, CollapsePlan& plan, double& distance) const;
  /// Fills chosen with the round's set; true when the window covered every candidate.
  bool SelectRound(std::int64_t need, double fraction, std::vector<std::int32_t>& chosen);
  /// SelectRound's stages: the live vertices and the candidates among them (returns their
  /// largest importance); a block of candidates' rings; the free ones of the block taken.
  double GatherCandidates();
  void GatherRings(std::int64_t first, std::int64_t count);
  void TakeFree(std::int64_t first, std::int64_t count, std::int64_t need, std::int64_t& expected,
    std::vector<std::int32_t>& chosen);
  /// The prepared mesh in the engine with its locks and bound; returns the count.
  std::int64_t Prepare(const TriangleMeshView& input, ParallelDecimationResult& result);
  /// Step 1–2 of §5.5: every vertex's type and importance (MeasureAll), or the listed ones'
  /// (nullptr: all; -1 entries are skipped); Measure writes one vertex's.
  void MeasureAll();
  void MeasureList(const std::int32_t* vertices, std::int64_t count);
  void Measure(std::int32_t v, Workspace& work, bool starCollected);
  /// The listed vertices after a round (see the body).
  void Reevaluate(const std::int32_t* vertices, std::int64_t count);
  /// Steps 3–7 of §5.5 on the collapse loop (CollapseLoop.h), with the scheduler below; false
  /// when aborted.
  bool RemoveToTarget(std::int64_t target, ParallelDecimationResult& result);
  /// The loop's scheduler: rounds of super-independent vertex sets, removed concurrently.
  struct RoundScheduler
  {
    Decimator& Owner;
    ParallelDecimationResult& Result;
    double Fraction;            // of the candidates a round's window covers
    bool CoveredAll = false;    // whether the last round's window covered every candidate
    std::int64_t AliveTriangles() const { return this->Owner.Mesh.NumberOfAliveTriangles(); }
    bool Step(std::int64_t target)
    {
      return this->Owner.RemoveRound(target, this->Fraction, this->CoveredAll, this->Result);
    }
    bool Unstick(std::int64_t) { return this->Owner.Unstick(this->CoveredAll, this->Fraction, this->Result); }
    std::string RefusalSummary() const { return this->Owner.RefusalSummary(); }
  };
  /// One round: the set (SelectRound), its plans, the changes listed (with what a survivor
  /// inherits), the removals and the re-evaluation around them; false when it removed nothing
  /// (coveredAll: whether its window, that fraction of the candidates, covered them all).
  bool RemoveRound(std::int64_t target, double fraction, bool& coveredAll, ParallelDecimationResult& result);
  void PlanRound();
  void ListChanges();
  void Inherit(std::int32_t v, std::int64_t i);
  /// What to do when a round removed nothing (see the body); false when nothing is left to try.
  bool Unstick(bool all, double& fraction, ParallelDecimationResult& result);
  /// The outcome: why it stopped where it did, and the relaxations' note.
  void Judge(ParallelDecimationResult& result) const;
  /// ": of the N vertices left, L are locked ...; of the others' M half-edge collapses, x % would
  /// ..." for a stop short of the target.
  std::string RefusalSummary() const;
  /// MoveSurvivors: each survivor to its quadric's point of least error, where that turns no
  /// triangle too far. Returns the number moved.
  std::int64_t MoveSurvivors();
  void Output(const TriangleMeshView& input, ParallelDecimationResult& result) const;

  /// Runs f(i, workspace) for i in [0, count) with one workspace per thread (the checks' marks
  /// are as large as the mesh, so they are kept): ExecutionContext::ForEachWithScratch.
  template <typename F>
  void ForEachInParts(std::int64_t count, std::int64_t workPerItem, F&& f)
  {
    this->Context.ForEachWithScratch(this->Workspaces, count, workPerItem, std::forward<F>(f));
  }

  /// The angles in force (raised by relaxation) and their cosines.
  void SetAngles(double feature, double deviation)
  {
    this->FeatureAngle = std::min(180.0, std::max(0.0, feature));
    this->DeviationAngle = std::min(180.0, std::max(0.0, deviation));
    this->CosFeature = std::cos(this->FeatureAngle * Pi / 180.0);
    this->CosDeviation = std::cos(this->DeviationAngle * Pi / 180.0);
  }

  const ParallelDecimationOptions& Options;
  const ExecutionContext& Context;
  double FeatureAngle = 0.0, DeviationAngle = 0.0, CosFeature = 1.0, CosDeviation = 1.0;
  CollapseMesh Mesh;
  Frame Normalised; // Scale a power of two: mesh coordinates = input coordinates · Scale; the box
  PlaneDistanceBound Bound;
  double BoundLimit = -1.0; // MaximumError in input units; < 0: no bound
  std::vector<std::int32_t> InputVertex, InputTriangle;
  std::vector<double> Importance;
  std::vector<double> Accumulated;  // AveragePlane: importance inherited from removed vertices
  std::vector<Quadric> Quadrics;    // Quadric: the planes around each vertex and its merged ones
  std::vector<double> OwnError;     // Q_v(p_v)
  std::vector<DecimationVertexType> Types;
  std::vector<std::uint8_t> Stuck; // no legal collapse since the last change around it
  std::vector<std::uint8_t> Owner; // round stamp of the vertices near a taken one
  std::vector<std::uint8_t> Touched; // round stamp of the hubs near a taken one
  std::vector<std::int32_t> SharedHubs; // those hubs, in the order they were reached
  std::vector<std::uint32_t> Listed; // round stamp of the vertices listed for re-evaluation
  std::vector<std::int32_t> Into;    // the survivor of the removal that listed the vertex
  std::vector<std::int32_t> BestTarget; // Quadric: the neighbour of least half-edge error
  std::vector<std::uint8_t> Updated; // importance updated without a full evaluation since its last
  std::uint32_t Round = 0;
  std::vector<std::int32_t> Live, NextLive, Order, Sorted, Buckets;
  std::vector<std::int64_t> RingStart; // SelectRound: each candidate's slice of Rings
  std::vector<std::int32_t> Rings;
  std::vector<std::uint8_t> Gone; // removed by a collapse
  std::vector<std::uint8_t> Moved; // moved by MoveSurvivors
  std::vector<Workspace> Workspaces; // one per thread
  // A round's lists: the chosen vertices, their plans (and bound distances) where they have
  // one, the plans applied, the changed vertices by removal (Slices into Neighbours).
  std::vector<std::int32_t> Chosen, Neighbours;
  std::vector<std::int64_t> Slices;
  std::vector<double> Distances;
  std::vector<CollapsePlan> Plans, Applied;
  std::vector<std::uint8_t> Planned;
  CollapseLoopEnd LoopEnd; // how the rounds ended (its refusals taken before survivors move)
  const bool MayRelax;
};

void Decimator::CollectStar(std::int32_t v, Workspace& work) const
{
  // The triangles around v, and the edges (v, w) with the triangles on either side: the edge to
  // a triangle's next corner is the edge to another's previous corner (an open fan leaves one of
  // each unmatched).
  const std::size_t count = static_cast<std::size_t>(this->Mesh.NumberOfTrianglesAround(v));
  work.Star.resize(count);
  work.Edges.resize(count);
  const Vec3& p = this->Mesh.Point(v);
  std::size_t slot = 0;
  this->Mesh.ForEachCorner(v, [&](std::int32_t t, std::int32_t next, std::int32_t previous) {
    StarTriangle& star = work.Star[slot];
    star.Id = t;
    star.Next = next;
    star.Previous = previous;
    star.Cross = (this->Mesh.Point(star.Next) - p).cross(this->Mesh.Point(star.Previous) - p);
    star.Length = star.Cross.norm();
    work.Edges[slot] = { star.Next, static_cast<std::int32_t>(slot), -1 };
    ++slot;
  });
  // Each triangle's previous corner is matched to the (first) edge of that far vertex.
  const auto nextAt = [&work](std::int32_t i) { return work.Edges[i].W; };
  work.Nexts.Reset(static_cast<std::int32_t>(count), nextAt);
  for (std::size_t j = 0; j < count; ++j)
  {
    const std::int32_t previous = work.Star[j].Previous;
    const std::int32_t found = work.Nexts.Find(previous, nextAt);
    if (found >= 0)
    {
      work.Edges[found].Before = static_cast<std::int32_t>(j);
    }
    else
    {
      work.Edges.push_back({ previous, -1, static_cast<std::int32_t>(j) });
    }
  }
}

double Decimator::HalfEdgeError(std::int32_t v, std::int32_t u) const
{
  // (Q_v + Q_u)(p_u), with Q_u(p_u) kept per vertex.
  return this->Quadrics[v].Evaluate(this->Mesh.Point(u)) + this->OwnError[u];
}

VertexState Decimator::Evaluate(std::int32_t v, Workspace& work, bool starCollected) const
{
  VertexState state = this->Analyze(v, work, starCollected);
  if (state.Importance == Never)
  {
    return state;
  }
  if (this->Options.Measure == ImportanceMeasure::Quadric)
  {
    // The least error of a half-edge the vertex may collapse along, as a distance.
    double best = Never;
    ForEachTarget(state, work, [&](std::int32_t u) {
      if (this->IsHub(u))
      {
        return;
      }
      const double error = this->HalfEdgeError(v, u);
      if (error < best || (error == best && u < state.Best))
      {
        best = error;
        state.Best = u;
      }
    });
    state.Importance = std::sqrt(best);
  }
  else
  {
    state.Importance += this->Accumulated[v];
  }
  return state;
}

VertexState Decimator::Analyze(std::int32_t v, Workspace& work, bool starCollected) const
{
  VertexState state;
  const VertexClass c = this->Mesh.Class(v);
  if (c == VertexClass::NonManifold)
  {
    return state; // complex
  }
  state.Type = DecimationVertexType::Corner;
  if (this->Mesh.IsLocked(v) || c == VertexClass::Corner)
  {
    return state;
  }
  if (c == VertexClass::Hinge)
  {
    return this->AnalyzeHinge(v, work, starCollected);
  }
  if (!starCollected)
  {
    this->CollectStar(v, work);
  }
  if (work.Star.empty())
  {
    return state;
  }
  int sharp = 0, open = 0;
  for (const StarEdge& e : work.Edges)
  {
    if (e.After < 0 || e.Before < 0)
    {
      if (open < 2)
      {
        state.Along[open] = e.W;
      }
      ++open;
      continue;
    }
    const StarTriangle& a = work.Star[e.After];
    const StarTriangle& b = work.Star[e.Before];
    const double lengths = a.Length * b.Length;
    if (lengths > 0.0 && a.Cross.dot(b.Cross) < this->CosFeature * lengths)
    {
      if (open == 0 && sharp < 2)
      {
        state.Along[sharp] = e.W;
      }
      ++sharp;
    }
  }
  const Vec3& p = this->Mesh.Point(v);
  if (open > 0)
  {
    // A boundary vertex with sharp edges inside is a corner, as one whose fan is not one strip.
    if (open != 2 || sharp > 0)
    {
      state.Along[0] = state.Along[1] = -1;
      return state;
    }
    state.Type = DecimationVertexType::Boundary;
    state.Importance =
      DistanceToLine(p, this->Mesh.Point(state.Along[0]), this->Mesh.Point(state.Along[1]));
    return state;
  }
  if (sharp == 2)
  {
    state.Type = DecimationVertexType::InteriorEdge;
    state.Importance =
      DistanceToLine(p, this->Mesh.Point(state.Along[0]), this->Mesh.Point(state.Along[1]));
    return state;
  }
  if (sharp != 0)
  {
    state.Along[0] = state.Along[1] = -1;
    return state; // corner
  }
  state.Type = DecimationVertexType::Simple;
  if (this->Options.Measure == ImportanceMeasure::Quadric)
  {
    state.Importance = 0.0; // Evaluate measures it from the half-edges
    return state;
  }
  // Eq. (5.1)–(5.3): the plane of the area-weighted normal through the area-weighted centre.
  // The cross product is the normal times twice the area.
  Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
  double area = 0.0;
  for (const StarTriangle& star : work.Star)
  {
    const double a = star.Length;
    normal += star.Cross;
    centre += a * (p + this->Mesh.Point(star.Next) + this->Mesh.Point(star.Previous)) / 3.0;
    area += a;
  }
  const double length = normal.norm();
  state.Importance = length > 0.0 && area > 0.0 ? std::abs(normal.dot(p - centre / area)) / length : 0.0;
  return state;
}

VertexState Decimator::AnalyzeHinge(std::int32_t v, Workspace& work, bool starCollected) const
{
  // Where sheets meet (CollapseMesh: a hinge vertex never moves), v goes along the hinge onto
  // one of its two ends, as a vertex on a sharp edge goes along the edge.
  VertexState state;
  state.Type = DecimationVertexType::Corner;
  if (!starCollected)
  {
    this->CollectStar(v, work);
  }
  if (this->Mesh.HingeEnds(v, state.Along) != 2)
  {
    state.Along[0] = state.Along[1] = -1;
    return state;
  }
  state.Type = DecimationVertexType::InteriorEdge;
  state.Importance =
    DistanceToLine(this->Mesh.Point(v), this->Mesh.Point(state.Along[0]), this->Mesh.Point(state.Along[1]));
  return state;
}

double Decimator::AreaChange(std::int32_t u, const Workspace& work) const
{
  const Vec3& target = this->Mesh.Point(u);
  double before = 0.0, after = 0.0;
  for (const StarTriangle& star : work.Star)
  {
    before += star.Length;
    if (star.Next == u || star.Previous == u)
    {
      continue; // removed by the collapse
    }
    const Vec3 moved = (this->Mesh.Point(star.Next) - target).cross(this->Mesh.Point(star.Previous) - target);
    const double newLength = moved.norm();
    if (!(newLength > 0.0) || moved.dot(star.Cross) < this->CosDeviation * newLength * star.Length)
    {
      return -1.0;
    }
    after += newLength;
  }
  return 0.5 * std::abs(after - before);
}

int Decimator::TrianglesRemovedWith(std::int32_t v) const
{
  if (this->Mesh.OnHinge(v))
  {
    std::int32_t ends[2];
    return this->Mesh.HingeEnds(v, ends) > 0 ? this->Mesh.TrianglesOnEdge(v, ends[0]) : 2;
  }
  return this->Types[v] == DecimationVertexType::Boundary ? 1 : 2;
}

bool Decimator::Plan(std::int32_t v, Workspace& work, CollapsePlan& plan, double& distance) const
{
  const VertexState state = this->Analyze(v, work);
  if (state.Type == DecimationVertexType::Corner || state.Type == DecimationVertexType::Complex)
  {
    return false;
  }
  // Analyze left v's star in the workspace. Score the half-edges v → u it may collapse: by
  // their error (Quadric), length (§5.5) or area change under the deviation limit (§5.3).
  const bool quadric = this->Options.Measure == ImportanceMeasure::Quadric;
  const bool shortest = !quadric && this->Options.Choice == HalfEdgeChoice::ShortestEdge;
  const Vec3& p = this->Mesh.Point(v);
  work.Options.clear();
  ForEachTarget(state, work, [&](std::int32_t u) {
    if (this->IsHub(u))
    {
      return;
    }
    const double length = (this->Mesh.Point(u) - p).squaredNorm();
    if (quadric)
    {
      work.Options.push_back({ this->HalfEdgeError(v, u), length, u });
    }
    else if (shortest)
    {
      work.Options.push_back({ length, length, u });
    }
    else
    {
      const double change = this->AreaChange(u, work);
      if (change >= 0.0)
      {
        work.Options.push_back({ change, length, u });
      }
    }
  });
  std::sort(work.Options.begin(), work.Options.end(), [](const Workspace::Option& a, const Workspace::Option& b) {
    return a.Score != b.Score ? a.Score < b.Score : a.Length != b.Length ? a.Length < b.Length : a.Target < b.Target;
  });
  // The best that passes the engine's checks (and, for Quadric, the deviation limit).
  for (const Workspace::Option& option : work.Options)
  {
    if (quadric && this->AreaChange(option.Target, work) < 0.0)
    {
      continue;
    }
    plan.Vertices[0] = option.Target; // kept
    plan.Vertices[1] = v;
    plan.Vertices[2] = -1;
    plan.Count = 2;
    plan.Position = this->Mesh.Point(option.Target);
    plan.Weights[0] = 1.0;
    plan.Weights[1] = plan.Weights[2] = 0.0;
    if (!this->Mesh.IsLegal(plan, work.Scratch))
    {
      continue;
    }
    if (this->BoundLimit < 0.0)
    {
      return true;
    }
    // The survivor stays where it is: its own planes keep their distance, v's are new to it.
    distance = std::max(this->Bound.Error(option.Target), this->Bound.Distance(v, plan.Position));
    if (distance <= this->BoundLimit)
    {
      return true;
    }
  }
  return false;
}

double Decimator::GatherCandidates()
{
  // The vertices still in the mesh, compacted into Live, and of them the removable ones into
  // Order: counted per part, then written in order, concurrently. Returns the largest
  // importance among the candidates.
  const std::int64_t size = static_cast<std::int64_t>(this->Live.size());
  const std::int64_t parts = std::max<std::int64_t>(1, std::min<std::int64_t>(this->Context.Threads, size / 4096));
  std::vector<std::int64_t> liveAt(parts + 1, 0), candidateAt(parts + 1, 0);
  std::vector<double> largestOf(parts, 0.0);
  auto removable = [&](std::int32_t v) { return this->Importance[v] < Never && !this->Stuck[v]; };
  this->Context.For(parts, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t part = first; part < last; ++part)
    {
      std::int64_t lives = 0, candidates = 0;
      double largest = 0.0;
      for (std::int64_t i = size * part / parts, end = size * (part + 1) / parts; i < end; ++i)
      {
        const std::int32_t v = this->Live[i];
        lives += this->Gone[v] ? 0 : 1;
        if (!this->Gone[v] && removable(v))
        {
          ++candidates;
          largest = std::max(largest, this->Importance[v]);
        }
      }
      liveAt[part + 1] = lives;
      candidateAt[part + 1] = candidates;
      largestOf[part] = largest;
    }
  }, 4 * size);
  std::partial_sum(liveAt.begin(), liveAt.end(), liveAt.begin());
  std::partial_sum(candidateAt.begin(), candidateAt.end(), candidateAt.begin());
  this->NextLive.resize(static_cast<std::size_t>(liveAt[parts]));
  this->Order.resize(static_cast<std::size_t>(candidateAt[parts]));
  this->Context.For(parts, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t part = first; part < last; ++part)
    {
      std::int32_t* live = this->NextLive.data() + liveAt[part];
      std::int32_t* candidate = this->Order.data() + candidateAt[part];
      for (std::int64_t i = size * part / parts, end = size * (part + 1) / parts; i < end; ++i)
      {
        const std::int32_t v = this->Live[i];
        if (!this->Gone[v])
        {
          *live++ = v;
          if (removable(v))
          {
            *candidate++ = v;
          }
        }
      }
    }
  }, 4 * size);
  this->Live.swap(this->NextLive);
  return *std::max_element(largestOf.begin(), largestOf.end());
}

void Decimator::GatherRings(std::int64_t first, std::int64_t count)
{
  // The other two corners of each candidate's triangles, gathered concurrently a block at a
  // time, so the greedy pass (TakeFree), serial, reads flat lists instead of walking the mesh;
  // hubs as ~w. None for a candidate already near a vertex taken in an earlier block.
  const std::vector<std::int32_t>& sorted = this->Sorted;
  const std::uint8_t round = this->RoundStamp();
  this->RingStart.resize(static_cast<std::size_t>(count) + 1);
  this->RingStart[0] = 0;
  this->Context.For(count, [&](std::int64_t begin, std::int64_t last) {
    for (std::int64_t i = begin; i < last; ++i)
    {
      if (i + CollapseMesh::PrefetchDistance < last)
      {
        const std::int32_t ahead = sorted[first + i + CollapseMesh::PrefetchDistance];
        this->Mesh.PrefetchPlace(ahead); // the ring gathering below prefetches the spans
        Prefetch(this->Owner.data() + ahead);
      }
      const std::int32_t v = sorted[first + i];
      this->RingStart[i + 1] = this->Owner[v] == round ? 0 : 2 * this->Mesh.NumberOfTrianglesAround(v);
    }
  }, 5 * count);
  std::partial_sum(this->RingStart.begin(), this->RingStart.end(), this->RingStart.begin());
  this->Rings.resize(static_cast<std::size_t>(this->RingStart[count]));
  this->Context.For(count, [&](std::int64_t begin, std::int64_t last) {
    for (std::int64_t i = begin; i < last; ++i)
    {
      this->Mesh.PrefetchStars(sorted.data() + first, i, last);
      if (this->RingStart[i + 1] == this->RingStart[i])
      {
        continue;
      }
      std::int32_t* out = this->Rings.data() + this->RingStart[i];
      this->Mesh.ForEachCorner(sorted[first + i], [&](std::int32_t, std::int32_t next, std::int32_t previous) {
        *out++ = this->IsHub(next) ? ~next : next;
        *out++ = this->IsHub(previous) ? ~previous : previous;
      });
    }
  }, 20 * count);
}

void Decimator::TakeFree(std::int64_t first, std::int64_t count, std::int64_t need, std::int64_t& expected,
  std::vector<std::int32_t>& chosen)
{
  // A candidate is free when no vertex of its triangles is near a vertex taken before (a hub
  // may be, unless it is taken itself); then its triangles' vertices are marked as near it,
  // hubs as touched.
  const std::uint8_t round = this->RoundStamp();
  for (std::int64_t i = 0; i < count && expected < need; ++i)
  {
    const std::int32_t v = this->Sorted[first + i];
    const std::int32_t* ring = this->Rings.data() + this->RingStart[i];
    const std::int32_t* ringEnd = this->Rings.data() + this->RingStart[i + 1];
    bool free = this->Owner[v] != round && !(ringEnd - ring >= 2 * HubTriangles && this->Touched[v] == round);
    for (const std::int32_t* w = ring; free && w != ringEnd; ++w)
    {
      free = this->Owner[*w >= 0 ? *w : ~*w] != round;
    }
    if (!free)
    {
      continue;
    }
    chosen.push_back(v);
    this->Owner[v] = round;
    for (const std::int32_t* w = ring; w != ringEnd; ++w)
    {
      if (*w >= 0)
      {
        this->Owner[*w] = round;
      }
      else if (this->Touched[~*w] != round)
      {
        this->Touched[~*w] = round;
        this->SharedHubs.push_back(~*w);
      }
    }
    expected += this->TrianglesRemovedWith(v);
  }
}

bool Decimator::SelectRound(std::int64_t need, double fraction, std::vector<std::int32_t>& chosen)
{
  // §5.6: bucket the removable vertices by eq. (5.6) of their importance, in O(N) by counting;
  // then §5.5: take them greedily in that order while their neighbourhoods stay disjoint.
  const double largest = this->GatherCandidates();
  const std::int64_t candidates = static_cast<std::int64_t>(this->Order.size());
  const std::int64_t window =
    std::max<std::int64_t>(16, static_cast<std::int64_t>(std::ceil(fraction * static_cast<double>(candidates))));
  BucketOrder(this->Importance.data(), this->Order, largest, this->Options.BucketImportance,
    this->Options.BucketShare, this->Sorted, this->Buckets, static_cast<std::size_t>(window), this->Context);

  ++this->Round;
  chosen.clear();
  // Owner holds byte stamps (1–255), so that it stays in cache; cleared when they wrap.
  if (this->RoundStamp() == 1)
  {
    std::fill(this->Owner.begin(), this->Owner.end(), std::uint8_t(0));
    std::fill(this->Touched.begin(), this->Touched.end(), std::uint8_t(0));
  }
  this->SharedHubs.clear();
  std::int64_t expected = 0;
  const std::int64_t end = std::min<std::int64_t>(window, static_cast<std::int64_t>(this->Sorted.size()));
  for (std::int64_t first = 0; first < end && expected < need; first += RingBlock)
  {
    const std::int64_t count = std::min(RingBlock, end - first);
    this->GatherRings(first, count);
    this->TakeFree(first, count, need, expected, chosen);
  }
  return window >= candidates;
}

void Decimator::InitializeQuadric(std::int32_t v, const Workspace& work)
{
  // The planes of v's triangles weighted by area, and along a boundary edge the plane through
  // the edge perpendicular to its triangle, weighted by the squared edge length, so that
  // boundaries keep their place.
  Quadric& q = this->Quadrics[v];
  const Vec3& p = this->Mesh.Point(v);
  for (const StarTriangle& star : work.Star)
  {
    if (star.Length > 0.0)
    {
      const Vec3 normal = star.Cross / star.Length;
      q += Quadric::FromPlane(normal, -normal.dot(p), 0.5 * star.Length);
    }
  }
  for (const StarEdge& e : work.Edges)
  {
    if ((e.After < 0) == (e.Before < 0))
    {
      continue;
    }
    Quadric plane;
    if (Quadric::FromBorderEdge(p, this->Mesh.Point(e.W), work.Star[e.After >= 0 ? e.After : e.Before].Cross, plane))
    {
      q += plane;
    }
  }
}

std::int64_t Decimator::Prepare(const TriangleMeshView& input, ParallelDecimationResult& result)
{
  // The usable input, scaled by a power of two where its size is extreme (quadric errors grow
  // with the fourth power of lengths), in the engine with its locks and bound.
  PreparedMesh prepared = PrepareMesh(input, this->Options, Normalization::PowerOfTwo, this->Context);
  result.Report = prepared.Report();
  this->InputVertex = std::move(prepared.Mesh.InputVertex);
  this->InputTriangle = std::move(prepared.Mesh.InputTriangle);
  this->Normalised = prepared;
  this->Mesh.Load(prepared, this->Options.BoundaryCornerAngle, false, this->Context);
  this->Mesh.TrackMerges(); // for the output points' sources
  if (prepared.Bound >= 0.0)
  {
    this->Bound.Build(this->Mesh);
    this->BoundLimit = prepared.Bound;
  }
  const std::int32_t n = this->Mesh.NumberOfPoints();
  this->Importance.assign(n, Never);
  this->Types.assign(n, DecimationVertexType::Complex);
  this->Owner.assign(n, 0);
  this->Touched.assign(n, 0);
  this->Listed.assign(n, 0);
  this->Into.assign(n, -1);
  this->BestTarget.assign(n, -1);
  this->Updated.assign(n, 0);
  this->Stuck.assign(n, 0);
  this->Gone.assign(n, 0);
  this->Live.resize(n);
  std::iota(this->Live.begin(), this->Live.end(), 0);
  this->Accumulated.assign(n, 0.0);
  return prepared.TargetTriangles;
}

void Decimator::Measure(std::int32_t v, Workspace& work, bool starCollected)
{
  const VertexState state = this->Evaluate(v, work, starCollected);
  this->Types[v] = state.Type;
  this->Importance[v] = state.Importance;
  this->BestTarget[v] = state.Best;
  this->Stuck[v] = 0;
  this->Updated[v] = 0;
}

void Decimator::MeasureList(const std::int32_t* vertices, std::int64_t count)
{
  this->ForEachInParts(count, 500, [&](std::int64_t i, Workspace& work) {
    const std::int32_t v = vertices ? vertices[i] : static_cast<std::int32_t>(i);
    if (v >= 0) // -1: a repeat in the list
    {
      this->Measure(v, work, false);
    }
  });
}

void Decimator::MeasureAll()
{
  // Step 1–2 of §5.5: every vertex's type and importance, concurrently. Under Quadric each star
  // serves both the vertex's quadric (the only one its evaluation reads; the others' own errors
  // are still 0) and its evaluation.
  const std::int32_t n = this->Mesh.NumberOfPoints();
  const bool quadric = this->Options.Measure == ImportanceMeasure::Quadric;
  this->Quadrics.assign(quadric ? n : 0, Quadric());
  this->OwnError.assign(quadric ? n : 0, 0.0);
  this->ForEachInParts(n, 600, [&](std::int64_t i, Workspace& work) {
    const std::int32_t v = static_cast<std::int32_t>(i);
    if (quadric)
    {
      this->CollectStar(v, work);
      this->InitializeQuadric(v, work);
    }
    this->Measure(v, work, quadric);
  });
}

void Decimator::Reevaluate(const std::int32_t* vertices, std::int64_t count)
{
  // After a round, Quadric: a simple vertex whose least-error neighbour is still there and
  // absorbed nothing keeps that error as its least among its old neighbours (their errors can
  // only grow: Q_w and the points stay, a neighbour's own error grows when it absorbs); its one
  // new neighbour, the survivor, is the only new option. Other vertices are evaluated in full.
  this->ForEachInParts(count, 300, [&](std::int64_t i, Workspace& work) {
    this->PrefetchAhead(vertices, i, count);
    const std::int32_t w = vertices[i];
    if (w < 0)
    {
      return;
    }
    const std::int32_t into = this->Into[w], best = this->BestTarget[w];
    const bool absorbed = best >= 0 && this->Listed[best] == this->Round && this->Into[best] == best;
    if (this->Options.Measure == ImportanceMeasure::Quadric && into != w && best >= 0 &&
      this->Types[w] == DecimationVertexType::Simple && this->Importance[w] < Never && !this->Gone[best] &&
      !absorbed)
    {
      const double error = std::sqrt(this->HalfEdgeError(w, into));
      if (error < this->Importance[w])
      {
        this->Importance[w] = error;
        this->BestTarget[w] = into;
      }
      this->Stuck[w] = 0;
      this->Updated[w] = 1;
      return;
    }
    this->Measure(w, work, false);
  });
}

void Decimator::PlanRound()
{
  // Every chosen vertex's half-edge, concurrently; those without one are stuck until a change
  // nearby re-evaluates them. The others' plans go to Applied, in order.
  const std::int64_t count = static_cast<std::int64_t>(this->Chosen.size());
  this->Plans.resize(this->Chosen.size());
  this->Distances.resize(this->Chosen.size());
  this->Planned.assign(this->Chosen.size(), 0);
  this->ForEachInParts(count, 2000, [&](std::int64_t i, Workspace& work) {
    this->PrefetchAhead(this->Chosen.data(), i, count);
    this->Planned[i] = this->Plan(this->Chosen[i], work, this->Plans[i], this->Distances[i]) ? 1 : 0;
  });
  this->Applied.clear();
  this->Slices.assign(this->Chosen.size() + 1, 0);
  for (std::int64_t i = 0; i < count; ++i)
  {
    if (!this->Planned[i])
    {
      this->Stuck[this->Chosen[i]] = 1;
    }
    else
    {
      this->Applied.push_back(this->Plans[i]);
    }
    this->Slices[i + 1] =
      this->Slices[i] + (this->Planned[i] ? 2 * this->Mesh.NumberOfTrianglesAround(this->Chosen[i]) : 0);
  }
}

void Decimator::ListChanges()
{
  // The neighbours of each removed vertex are the vertices whose triangles change: listed per
  // removal in its own slice (two per triangle around it, each vertex once, the repeats -1),
  // concurrently, while the survivor inherits what the removed vertex measured. The stars of a
  // round's vertices share no vertex but hubs, so survivors are distinct and no other vertex is
  // listed in two slices; the hubs are listed after the slices, once each.
  const std::int64_t count = static_cast<std::int64_t>(this->Chosen.size());
  this->Neighbours.resize(static_cast<std::size_t>(this->Slices[count]));
  const std::uint8_t stamp = this->RoundStamp();
  this->Context.For(count, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t i = begin; i < end; ++i)
    {
      this->Mesh.PrefetchStars(this->Chosen.data(), i, end);
      if (!this->Planned[i])
      {
        continue;
      }
      const std::int32_t v = this->Chosen[i];
      const std::int32_t kept = this->Plans[i].Vertices[0];
      std::int32_t* out = this->Neighbours.data() + this->Slices[i];
      auto list = [&](std::int32_t w) {
        if (this->Touched[w] == stamp)
        {
          *out++ = -1;
          return;
        }
        *out++ = this->Listed[w] != this->Round ? w : -1;
        this->Listed[w] = this->Round;
        this->Into[w] = kept;
      };
      this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
        list(next);
        list(previous);
      });
      this->Inherit(v, i);
    }
  }, 40 * count);
  for (const std::int32_t hub : this->SharedHubs)
  {
    this->Neighbours.push_back(hub);
    this->Listed[hub] = this->Round;
    this->Into[hub] = hub; // evaluated in full
  }
}

void Decimator::Inherit(std::int32_t v, std::int64_t i)
{
  // The survivor of the round's removal i takes v's planes (Quadric) or importance
  // (AveragePlane with AccumulateError), and v's bound planes; v is gone.
  const std::int32_t kept = this->Plans[i].Vertices[0];
  if (this->Options.Measure == ImportanceMeasure::Quadric)
  {
    this->Quadrics[kept] += this->Quadrics[v];
    this->OwnError[kept] = this->Quadrics[kept].Evaluate(this->Mesh.Point(kept));
  }
  else if (this->Options.AccumulateError)
  {
    this->Accumulated[kept] += this->Importance[v];
  }
  if (this->BoundLimit >= 0.0)
  {
    this->Bound.Merge(this->Plans[i], this->Distances[i]); // the sets of a round are disjoint
  }
  this->Importance[v] = Never;
  this->Gone[v] = 1;
}

bool Decimator::Unstick(bool all, double& fraction, ParallelDecimationResult& result)
{
  // A round removed nothing: widen the window when it did not cover every candidate (every
  // vertex in it is stuck); try again when stuck vertices kept others out of the set (on a
  // small mesh one star can cover most of it); else relax the angles a step and start over.
  // False when nothing is left to try (at 180°, or under an error bound).
  if (!all)
  {
    fraction = std::min(1.0, 2.0 * fraction);
    return true;
  }
  if (this->Chosen.size() < this->Order.size())
  {
    return true;
  }
  if ((this->FeatureAngle >= 180.0 && this->DeviationAngle >= 180.0) || this->BoundLimit >= 0.0 || !this->MayRelax)
  {
    return false;
  }
  this->SetAngles(this->FeatureAngle + RelaxationStep, this->DeviationAngle + RelaxationStep);
  ++result.Relaxations;
  this->MeasureList(nullptr, this->Mesh.NumberOfPoints());
  return true;
}

bool Decimator::RemoveToTarget(std::int64_t target, ParallelDecimationResult& result)
{
  RoundScheduler scheduler{ *this, result, std::min(1.0, std::max(1e-3, this->Options.RoundFraction)) };
  this->LoopEnd = RunCollapseLoop(scheduler, target, { 0.05, 0.95 }, this->Context);
  return this->LoopEnd.Why != CollapseLoopEnd::Reason::Aborted;
}

bool Decimator::RemoveRound(std::int64_t target, double fraction, bool& coveredAll, ParallelDecimationResult& result)
{
  coveredAll = this->SelectRound(this->Mesh.NumberOfAliveTriangles() - target, fraction, this->Chosen);
  if (this->Options.RoundObserver)
  {
    this->Options.RoundObserver(this->Mesh, this->Chosen);
  }
  // Removed in vertex order, which follows space (MakeCompactMesh): nearby vertices share
  // cache lines where the importance order would jump across the mesh.
  this->Context.Sort(this->Chosen);
  this->PlanRound();
  this->ListChanges();
  ++result.Rounds;
  if (this->Applied.empty())
  {
    return false;
  }
  this->Mesh.ApplyIndependent(this->Applied, this->Context, this->SharedHubs);
  this->Reevaluate(this->Neighbours.data(), static_cast<std::int64_t>(this->Neighbours.size()));
  return true;
}

std::string Decimator::RefusalSummary() const
{
  // Why no vertex can be removed: the locked ones (non-manifold ones always are), and what
  // refuses every half-edge collapse of the others (measured once, where the rounds stop).
  std::array<std::int64_t, NumberOfLockReasons> lockedBy{};
  RefusalCounts refused;
  std::vector<std::int32_t> neighbours;
  CollapsePlan plan;
  plan.Count = 2;
  const std::int64_t left = this->Mesh.ForEachUnlockedLeft(lockedBy, [&](std::int32_t v) {
    this->Mesh.Neighbours(v, neighbours);
    for (const std::int32_t u : neighbours)
    {
      plan.Vertices[0] = u;
      plan.Vertices[1] = v;
      plan.Position = this->Mesh.Point(u);
      this->Mesh.CountRefusal(plan, this->Mesh.FirstFailedCheck(plan), refused);
    }
  });
  return DescribeLeft(left, "vertices", lockedBy, refused, "half-edge collapses",
    "are refused by the filter's own rules (a feature corner or edge above FeatureAngle, a normal turned by more "
    "than MaximumNormalDeviation)");
}

void Decimator::Judge(ParallelDecimationResult& result) const
{
  // Why the count is where it is: the reason first, then what was changed to get there.
  Outcome& report = result.Report;
  this->LoopEnd.Judge(report, this->BoundLimit >= 0.0, "no vertex is left that can be removed");
  if (result.Relaxations > 0)
  {
    report.Notes.push_back("FeatureAngle and MaximumNormalDeviation were raised by " +
      std::to_string(static_cast<std::int64_t>(RelaxationStep) * result.Relaxations) + " degrees to go on");
  }
}

bool Decimator::Run(const TriangleMeshView& input, ParallelDecimationResult& result)
{
  result = ParallelDecimationResult();
  const std::int64_t target = this->Prepare(input, result);
  this->MeasureAll();
  const bool removing = result.Report.Stop != StopReason::AllLocked;
  if (!this->Context.Report(0.05) || (removing && !this->RemoveToTarget(target, result)))
  {
    result.Report.Stop = StopReason::Aborted;
    return false;
  }
  // The survivors' importance and type in full where they were only updated.
  this->Neighbours.clear();
  for (const std::int32_t v : this->Live)
  {
    if (!this->Gone[v] && this->Updated[v])
    {
      this->Neighbours.push_back(v);
    }
  }
  this->MeasureList(this->Neighbours.data(), static_cast<std::int64_t>(this->Neighbours.size()));
  if (this->Options.MoveSurvivors && this->Options.Measure == ImportanceMeasure::Quadric)
  {
    result.MovedPoints = this->MoveSurvivors();
  }
  this->Output(input, result);
  this->Judge(result);
  return this->Context.Report(1.0);
}

std::int64_t Decimator::MoveSurvivors()
{
  // Every new point is found from the old points, so neither the order nor the thread count
  // matters: the survivor's quadric minimiser (along the directions the quadric determines, as
  // in vtkQuadricDecimation's placement) when it is within half the survivor's shortest edge,
  // else the point of least error within that distance (MinimizeQuadricWithin).
  const std::int32_t n = this->Mesh.NumberOfPoints();
  const std::int32_t m = this->Mesh.NumberOfTriangles();
  std::vector<Vec3> before(n);
  std::vector<Vec3> after(this->Live.size());
  std::vector<double> planeDistance(this->BoundLimit >= 0.0 ? this->Live.size() : 0);
  this->Moved.assign(n, 0);
  this->ForEachInParts(static_cast<std::int64_t>(this->Live.size()), 100, [&](std::int64_t i, Workspace&) {
    const std::int32_t v = this->Live[i];
    const Vec3& p = this->Mesh.Point(v);
    before[v] = p;
    const VertexClass c = this->Mesh.Class(v);
    if (this->Gone[v] || this->Mesh.IsLocked(v) || c == VertexClass::NonManifold || c == VertexClass::Corner ||
      c == VertexClass::Hinge)
    {
      return;
    }
    double shortest = Never; // squared
    this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
      shortest = std::min({ shortest, (this->Mesh.Point(next) - p).squaredNorm(),
        (this->Mesh.Point(previous) - p).squaredNorm() });
    });
    Vec3 x;
    MinimizeQuadricNear(this->Quadrics[v], p, x);
    const double reach = 0.5 * std::sqrt(shortest), distance = (x - p).norm();
    if (distance > 0.0 && reach < Never)
    {
      // Within the input's box: no survivor leaves a grid's border or rises above a peak.
      after[i] = this->Normalised.InBox(distance > reach ? MinimizeQuadricWithin(this->Quadrics[v], p, reach) : x);
      this->Moved[v] = 1;
    }
    if (this->Moved[v] && this->BoundLimit >= 0.0)
    {
      planeDistance[i] = this->Bound.Distance(v, after[i]); // v's planes are all it stands for
      this->Moved[v] = planeDistance[i] <= this->BoundLimit ? 1 : 0;
    }
  });
  for (std::size_t i = 0; i < this->Live.size(); ++i)
  {
    if (this->Moved[this->Live[i]])
    {
      this->Mesh.SetPoint(this->Live[i], after[i]);
    }
  }
  // A triangle that would turn by more than 60° (or degenerate) sends its moved corners back;
  // repeated until none does (a corner sent back can only undo turns).
  std::vector<std::uint8_t> turned(m);
  for (bool again = true; again;)
  {
    this->Context.For(m, [&](std::int64_t first, std::int64_t last) {
      for (std::int64_t t = first; t < last; ++t)
      {
        const std::int32_t* tri = this->Mesh.Triangle(static_cast<std::int32_t>(t));
        turned[t] = 0;
        if (!this->Mesh.IsAlive(static_cast<std::int32_t>(t)) ||
          !(this->Moved[tri[0]] || this->Moved[tri[1]] || this->Moved[tri[2]]))
        {
          continue;
        }
        const Vec3 a = (before[tri[1]] - before[tri[0]]).cross(before[tri[2]] - before[tri[0]]);
        const Vec3 b = (this->Mesh.Point(tri[1]) - this->Mesh.Point(tri[0]))
                         .cross(this->Mesh.Point(tri[2]) - this->Mesh.Point(tri[0]));
        turned[t] = a.dot(b) > 0.5 * a.norm() * b.norm() ? 0 : 1;
      }
    }, 20 * static_cast<std::int64_t>(m));
    again = false;
    for (std::int32_t t = 0; t < m; ++t)
    {
      const std::int32_t* tri = this->Mesh.Triangle(t);
      for (int k = 0; turned[t] && k < 3; ++k)
      {
        if (this->Moved[tri[k]])
        {
          this->Moved[tri[k]] = 0;
          this->Mesh.SetPoint(tri[k], before[tri[k]]);
          again = true;
        }
      }
    }
  }
  std::int64_t moved = 0;
  for (std::size_t i = 0; i < this->Live.size(); ++i)
  {
    const std::int32_t v = this->Live[i];
    moved += this->Moved[v];
    if (this->Moved[v] && this->BoundLimit >= 0.0)
    {
      this->Bound.SetError(v, planeDistance[i]);
    }
  }
  return moved;
}

void Decimator::Output(const TriangleMeshView& input, ParallelDecimationResult& result) const
{
  // The surviving triangles and their points (MoveSurvivors' moved ones through the scale), with
  // their importance and type.
  const std::vector<std::int32_t> used =
    WriteSurvivors(this->Mesh, this->Moved, this->Normalised, input, this->InputVertex, this->InputTriangle, result);
  // A distance (AveragePlane), or the square root of an area-weighted squared distance: divided
  // by Scale once or twice (Scale² underflows for the largest meshes).
  const bool squared = this->Options.Measure == ImportanceMeasure::Quadric;
  const bool bounded = this->BoundLimit >= 0.0;
  std::vector<double> importance(used.size()), types(used.size()), distance(bounded ? used.size() : 0);
  result.Report.MaximumError = bounded ? 0.0 : -1.0;
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    const std::int32_t v = used[i];
    const double scaled = this->Importance[v] / this->Normalised.Scale;
    importance[i] = this->Importance[v] < Never ? (squared ? scaled / this->Normalised.Scale : scaled) : -1.0;
    types[i] = static_cast<double>(this->Types[v]);
    if (bounded)
    {
      distance[i] = this->Bound.Error(v) / this->Normalised.Scale;
      result.Report.MaximumError = std::max(result.Report.MaximumError, distance[i]);
    }
  }
  result.AddPointArray("Importance", std::move(importance));
  result.AddPointArray("VertexType", std::move(types), NamedArray::Kind::Byte);
  if (bounded)
  {
    result.AddPointArray("PlaneDistance", std::move(distance));
  }
  AddSurvivorSources(used, this->InputVertex, result, this->Mesh.MergeTargets());
  result.FieldValues.emplace_back("Rounds", static_cast<double>(result.Rounds));
  result.FieldValues.emplace_back("MovedPoints", static_cast<double>(result.MovedPoints));
}

} // namespace

bool ParallelDecimation(const TriangleMeshView& input, const ParallelDecimationOptions& options,
  ParallelDecimationResult& result, const ExecutionContext& context)
{
  // The angles are raised only to reach the target. Where even 180 degrees misses it, raising
  // them removed features and reached nothing (the corpus's building lost the faces of its
  // ground plate), so the decimation is made again without raising them: its rounds are those
  // of the first run up to its first raise. Its progress stays at the end (abort still works).
  if (!Decimator(options, context, true).Run(input, result))
  {
    return false;
  }
  const std::int64_t target = result.Report.TargetTriangles, relaxed = result.NumberOfTriangles();
  if (result.Relaxations == 0 || relaxed - target <= options.Goal.Slack(target))
  {
    return true;
  }
  ExecutionContext atEnd = context;
  atEnd.Progress = [&context](double) { return context.Report(1.0); };
  if (!Decimator(options, atEnd, false).Run(input, result))
  {
    return false;
  }
  result.Report.Notes.push_back("FeatureAngle and MaximumNormalDeviation were left at their values: raising them "
    "up to 180 degrees removed features and reached only " + std::to_string(relaxed) +
    " triangles, where this output has " + std::to_string(result.NumberOfTriangles()));
  return true;
}

} // namespace meshsimp
