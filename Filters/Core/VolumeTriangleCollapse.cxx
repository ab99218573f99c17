// SPDX-License-Identifier: BSD-3-Clause
#include "VolumeTriangleCollapse.h"

#include "CollapseHeap.h"
#include "CollapseLoop.h"
#include "PlaneDistanceBound.h"
#include "Quadric.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;
constexpr double Pi = 3.14159265358979323846;
/// Added to the normal factor N of §3.2, which is 0 on a flat region: with no weight there, a
/// flat region's planes would not hold a vertex placed by eq. (5) on them.
constexpr double NormalFactorFloor = 0.01;
/// An edge of a triangle collapses instead of the triangle when its error is below this share
/// of the triangle's (measured: a half, the share per removed triangle, made more slivers).
constexpr double EdgeErrorShare = 0.25;
/// Corners with more triangles count in a triangle's normal factor only through the other
/// corners (ForEachAdjacent), and keep their sums (UpdateVertex) by differences.
constexpr std::int32_t FanLimit = 256;
/// A batch takes at most one collapse per this many input triangles: on a small mesh a batch of
/// BatchSize would relax the heap order over much of the surface (measured: a larger Hausdorff
/// distance than the strict order's; see VolumeTriangleCollapse.md), and gain little time.
constexpr std::int64_t BatchShare = 1000;
/// A collapse is flat when its error is below this fraction of Σ (plane weights) · (longest
/// edge)²: its point lies within about 3·10⁻⁴ edge lengths of the planes (RMS).
constexpr double FlatTolerance = 1e-7;

/// The heap key of a plan: its error per triangle it nominally removes (a triangle collapse
/// four, an edge collapse two).
double PriorityOf(double cost, int count)
{
  return cost / (count == 3 ? 4.0 : 2.0);
}

/// §3.5: the ω in [0, 1] for which ω p_i + (1 − ω) p_j minimises q.
double SegmentMinimum(const Quadric& q, const Vec3& pi, const Vec3& pj)
{
  const Vec3 d = pi - pj;
  const double a = d.dot(q.A() * d);
  const double b = d.dot(q.A() * pj + q.B());
  return a > 0.0 ? std::min(1.0, std::max(0.0, -b / a)) : 0.5;
}

class VolumeCollapser
{
public:
  VolumeCollapser(const VolumeCollapseOptions& options, const ExecutionContext& context)
    : Options(options)
    , Context(context)
  {
  }

  bool Run(const TriangleMeshView& input, VolumeCollapseResult& result);

private:
  struct Candidate
  {
    CollapsePlan Plan;
    Quadric Q; // the constriction matrix Q̄
    double Cost = 0.0;     // eq. (5) at the plan's position
    double Priority = 0.0; // the heap key: Cost per triangle the plan nominally removes
    bool Valid = false;
    bool FreePlacement = false; // placed by eq. (5)/(8), not by a boundary, lock or feature rule
  };

  /// Calls f(j) once for every triangle sharing a vertex with t, t included (Definition 2). A
  /// corner with more than FanLimit triangles (the centre of a triangulated polygon) adds only
  /// those the other corners' lists hold, unless it has the fewest: otherwise every update
  /// around a fan's centre would visit the whole fan.
  template <typename F>
  void ForEachAdjacent(std::int32_t t, F&& f) const
  {
    const std::int32_t* tri = this->Mesh.Triangle(t);
    std::int32_t fewest = 0;
    for (int k = 1; k < 3; ++k)
    {
      fewest = this->Mesh.NumberOfTrianglesAround(tri[k]) < this->Mesh.NumberOfTrianglesAround(tri[fewest]) ? k : fewest;
    }
    bool scanned[3] = { false, false, false };
    for (int k = 0; k < 3; ++k)
    {
      scanned[k] = k == fewest || this->Mesh.NumberOfTrianglesAround(tri[k]) <= FanLimit;
      if (!scanned[k])
      {
        continue;
      }
      // Once: a triangle holding an earlier scanned corner was visited there.
      this->Mesh.ForEachTriangle(tri[k], [&](std::int32_t j) {
        const std::int32_t* o = this->Mesh.Triangle(j);
        for (int i = 0; i < k; ++i)
        {
          if (scanned[i] && (o[0] == tri[i] || o[1] == tri[i] || o[2] == tri[i]))
          {
            return;
          }
        }
        f(j);
      });
    }
  }

  /// The corner angles of t, for the feature rule (only when it is on).
  void UpdateAngles(std::int32_t t);
  /// SurfaceErrorWeight's term of the heap key: the new point's weighted squared distance to
  /// the input planes merged into the plan's vertices.
  double SurfaceError(const CollapsePlan& plan) const;
  /// Adds the planes of t's open-border edges to their ends' InputPlanes.
  void AddBorderPlanes(std::int32_t t);
  /// The triangles across t's edges (edge k from corner k to the next): their summed quadrics
  /// and how many there are.
  struct EdgeNeighbours
  {
    Quadric Quadrics[3];
    int Count[3] = { 0, 0, 0 };
  };
  void ConstrictionMatrix(std::int32_t t, Quadric& q, EdgeNeighbours* across = nullptr) const;
  /// Makes the candidate the collapse of edge (kept, other) to position with quadric q.
  static void SetEdgePlan(std::int32_t kept, std::int32_t other, double keptWeight,
    const Vec3& position, const Quadric& q, double cost, Candidate& candidate);
  void CheaperEdge(std::int32_t t, const EdgeNeighbours& across, Candidate& candidate) const;
  /// The edge of t from corner k to the next: its quadric q (the triangles around its ends, own
  /// being t's) and point x; returns its error there.
  double PlaceEdge(std::int32_t t, int k, const Quadric& own, const EdgeNeighbours& across, Quadric& q, Vec3& x) const;
  /// Makes the candidate the collapse of edge (a, b) to x, the end nearer x kept.
  void SetEdgePlanAt(std::int32_t a, std::int32_t b, const Vec3& x, const Quadric& q, double cost, Candidate& candidate) const;
  /// The edge of t from corner k to the next.
  void CheaperBoundaryEdge(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const;
  void UpdateVertex(std::int32_t v);
  /// Adds (sign 1) or takes back (sign −1) what the triangles around the given vertices hold at
  /// their corners of more than FanLimit triangles (other than those vertices) to those corners'
  /// sums: a collapse next to a fan's centre changes a few of its triangles, and summing all of
  /// them again after every such collapse would cost the square of the fan's size.
  void UpdateFanSums(const std::int32_t* vertices, int count, double sign);
  void UpdateQuadric(std::int32_t t);
  Candidate Evaluate(std::int32_t t) const;
  /// Evaluate's plan for a triangle with one corner on the cut between pieces: the collapse of
  /// its edge from corner k to the next, off the cut.
  void OffTheCut(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const;
  /// Evaluate's last step: the surface term added to the key, and whether the plan is valid.
  Candidate Finish(Candidate& candidate) const;
  /// Evaluate's placements of a triangle's plan (v: its corners): onto corner k; along its
  /// boundary edge (returns the edge's first corner); the strong-feature corner (-1: none); the
  /// free placement of eq. (5)/(8).
  void OntoCorner(const std::int32_t* v, int k, CollapsePlan& plan) const;
  int OntoBoundaryEdge(const std::int32_t* v, const Quadric& q, CollapsePlan& plan) const;
  int StrongFeatureCorner(const std::int32_t* v) const;
  /// A triangle with a hinge corner: the corner it collapses onto (a hinge corner never moves,
  /// see CollapseMesh), or -1 when it has none; edge gets the corner starting its edge between
  /// two pinned corners when that is a hinge edge, else -1.
  int OntoHinge(const std::int32_t* v, const Quadric& q, int& edge) const;
  /// The hinge edge of t from corner k to the next alone, onto its cheaper pinned end, when that
  /// costs under EdgeErrorShare of the triangle's error.
  void CheaperHingeEdge(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const;
  void PlaceFreely(const std::int32_t* v, const Quadric& q, CollapsePlan& plan) const;
  /// Per thread: the checks' marks and the updates' ring.
  struct Scratch
  {
    CollapseMesh::CheckScratch Check;
    std::vector<std::uint32_t> Marks;
    std::uint32_t Stamp = 0;
    std::vector<std::int32_t> Ring;
  };
  bool OntoCheapestCorner(Candidate& candidate, Scratch& scratch) const;
  /// Whether the collapse leaves the surface where it was (see FlatTolerance).
  bool IsFlat(const Candidate& candidate) const;
  /// The smallest angle (degrees) of the triangles plan changes, at its position.
  double NewSmallestAngle(const CollapsePlan& plan) const;
  /// The heap key of a collapse refused by the angle guard alone: its priority times the square
  /// of how far below the guard its smallest new angle falls, (GuardAngle / angle)², so it waits
  /// until the collapses that make no sliver cost that much more.
  double SliverKey(const Candidate& candidate) const;
  /// What the engine's checks say of a popped triangle's plan.
  enum class Verdict : std::uint8_t
  {
    Invalid,  // no plan (locked, non-finite)
    Stale,    // its key grew past the next triangle's: queued again
    Legal,    // as evaluated
    Fallback, // illegal as evaluated; legal onto a corner, or as a flat collapse with slivers
    Sliver,   // illegal only by the angle guard
    Illegal
  };
  /// Evaluates t, queued with queuedKey, and checks its plan (the candidate becomes the
  /// fallback's where one is legal). Not checked, Stale, when its key grew past both queuedKey
  /// and nextKey, the highest key the next triangle to be popped can have.
  Verdict Examine(std::int32_t t, double queuedKey, double nextKey, Candidate& candidate,
    double& evaluatedPriority, Scratch& scratch) const;
  /// After a collapse: the geometry, quadrics and costs of the kept vertex's triangles and the
  /// sums of its ring (see the file's notes); writes each triangle around it and its heap key (< 0:
  /// not to be queued) in star order. Calls for collapses whose neighbourhoods are disjoint
  /// (ClaimNeighbourhood) may run concurrently: each writes only its own ring's data.
  void RefreshAround(std::int32_t kept, Scratch& scratch, std::int32_t* triangles, double* keys);
  /// RefreshAround for the kept vertex of each collapse in Applied, concurrently (their
  /// neighbourhoods are disjoint), then the keys of their triangles in order.
  void RefreshApplied();
  /// RefreshApplied for one collapse.
  void UpdateAround(std::int32_t kept);
  /// Marks every vertex of the triangles around t's corners with the stamp, unless one already
  /// has it: two collapses claimed in one batch then read and write disjoint data.
  bool ClaimNeighbourhood(std::int32_t t, std::uint32_t stamp);
  /// Pops the batch: up to limit of the cheapest alive triangles with disjoint neighbourhoods
  /// (one when limit is 1, or when it has a corner of more than FanLimit triangles); those passed
  /// over (Passed) go back with their keys after the batch.
  void SelectBatch(std::int64_t limit);
  /// Evaluates and checks the batch concurrently, then applies its collapses in key order under
  /// the heap's rule, listing their kept vertices in Applied; those passed over are queued again.
  void CollapseBatch(std::int64_t target, std::int64_t tolerance, VolumeCollapseResult& result);
  int CountRemoved(const CollapsePlan& plan) const;
  /// The prepared mesh in the engine with its locks, measured and queued; returns the count.
  std::int64_t Prepare(const TriangleMeshView& input, VolumeCollapseResult& result);
  void MeasureAll();
  void GatherInputPlanes();
  void QueueAll();
  /// Step 5–6 of §3.6 on the collapse loop (CollapseLoop.h), with the scheduler below; false
  /// when aborted.
  bool CollapseToTarget(std::int64_t target, VolumeCollapseResult& result);
  /// The loop's scheduler: batches of the cheapest triangles whose neighbourhoods are disjoint,
  /// evaluated and checked concurrently, collapsed in key order, updated concurrently.
  struct BatchScheduler
  {
    VolumeCollapser& Collapser;
    VolumeCollapseResult& Result;
    std::int64_t Tolerance; // below the target
    std::int64_t AliveTriangles() const { return this->Collapser.Mesh.NumberOfAliveTriangles(); }
    bool Step(std::int64_t target) { return this->Collapser.CollapseNextBatch(target, this->Tolerance, this->Result); }
    bool Unstick(std::int64_t target) { return this->Collapser.Unstick(target - this->Tolerance, this->Result); }
    std::string RefusalSummary() const { return this->Collapser.RefusalSummary(); }
  };
  /// One batch (SelectBatch, CollapseBatch, RefreshApplied); false when the heap is empty.
  bool CollapseNextBatch(std::int64_t target, std::int64_t tolerance, VolumeCollapseResult& result);
  /// When every collapse left is refused: the angle guard lowered a step, else the last resort
  /// (CollapseAnyEdges down to floor); false when neither is left (or under a bound).
  bool Unstick(std::int64_t floor, VolumeCollapseResult& result);
  /// Applies the plan (legal), with its eq. (5) cost; the updates around the kept vertex follow
  /// (UpdateAround, or RefreshAround for a batch).
  void Apply(const CollapsePlan& plan, double cost, VolumeCollapseResult& result);
  /// Apply, then UpdateAround.
  void Commit(const CollapsePlan& plan, double cost, VolumeCollapseResult& result);
  /// The last resort when no triangle's plan is legal: half-edge collapses of any edge, cheapest
  /// first, while at least floor triangles stay. Returns whether any was made.
  bool CollapseAnyEdges(std::int64_t floor, VolumeCollapseResult& result);
  /// ": of the N half-edge collapses left, x % would ..." from RefusedBy, or empty.
  std::string RefusalSummary() const;
  /// Frees what only the collapses need (quadrics, weights, normals, input planes, the heap)
  /// before the output is made, so that the two stages' memory does not add up.
  void ReleaseWorkspace();
  void Output(const TriangleMeshView& input, VolumeCollapseResult& result) const;
  /// The outcome: why it stopped where it did, and the angle guard's note.
  void Judge(VolumeCollapseResult& result) const;

  const VolumeCollapseOptions& Options;
  const ExecutionContext& Context;
  CollapseMesh Mesh;
  std::vector<std::int32_t> InputVertex, InputTriangle; // compact → input ids
  Frame Normalised;                                      // the centred box of diagonal 1
  double Diagonal = 1.0;                                 // 1 / Normalised.Scale
  /// A triangle's unit normal from its points (zero for a degenerate one): not kept (24 bytes a
  /// triangle), as the plane it orients is computed from the same points wherever it is read.
  Vec3 Normal(std::int32_t t) const
  {
    const std::int32_t* tri = this->Mesh.Triangle(t);
    const Vec3& p = this->Mesh.Point(tri[0]);
    const Vec3 cross = (this->Mesh.Point(tri[1]) - p).cross(this->Mesh.Point(tri[2]) - p);
    const double length = cross.norm();
    return length > 0.0 ? Vec3(cross / length) : Vec3::Zero();
  }
  /// The normal factor's normals (UseNormalFactor only, else empty): Normal in single
  /// precision, 12 bytes a triangle kept for the factor's reads of every neighbour, which
  /// computing them would cost; the factor is a weight, which needs no more. Refreshed with the
  /// triangle (RefreshAround). The planes are made from Normal itself.
  std::vector<Eigen::Vector3f> FactorNormals;
  void UpdateFactorNormal(std::int32_t t) { this->FactorNormals[t] = this->Normal(t).cast<float>(); }
  /// A triangle's area from its points, as Normal measures its normal: read only when a
  /// triangle or a vertex's sums are updated, it is not kept (8 bytes a triangle).
  double Area(std::int32_t t) const
  {
    const std::int32_t* tri = this->Mesh.Triangle(t);
    const Vec3& p = this->Mesh.Point(tri[0]);
    return 0.5 * (this->Mesh.Point(tri[1]) - p).cross(this->Mesh.Point(tri[2]) - p).norm();
  }
  /// Q_i of eq. (4) is the plane of triangle i (its normal through its first corner) with a
  /// weight: the weight is kept (8 bytes a triangle, not the quadric's 80) and the quadric
  /// made when read, from the triangle's points as they are then, which UpdateQuadric saw.
  std::vector<double> TriangleWeights;
  Quadric TriangleQuadric(std::int32_t t) const
  {
    const double weight = this->TriangleWeights[t];
    if (weight == 0.0)
    {
      return Quadric();
    }
    const Vec3 n = this->Normal(t);
    return Quadric::FromPlane(n, -n.dot(this->Mesh.Point(this->Mesh.Triangle(t)[0])), weight);
  }
  std::vector<Quadric> VertexQuadrics;   // the sum of Q_i around each vertex
  std::vector<Quadric> InputPlanes;      // input planes merged into each vertex (faces, borders)
  double SurfaceScale = 0.0;             // SurfaceErrorWeight · (mean input triangle area)²
  std::vector<double> VertexError;       // squared-volume error accumulated at each vertex
  // Only for the feature rule (FeatureCurvature > 0), else empty: nothing else reads them.
  bool TracksCurvature = false;
  std::vector<double> Angles;            // the corner angles of each triangle
  std::vector<double> Deficit;           // angle deficit of each vertex (eq. 6)
  std::vector<double> VertexArea;        // area of its adjacent triangles, A_v
  std::vector<std::uint8_t> Moved;       // a collapse gave the vertex a new position
  bool HasFans = false;                  // a vertex has more than FanLimit triangles
  double TotalArea = 0.0;
  double GuardAngle = 0.0; // the angle guard in force (lowered when it refuses every collapse)
  CollapseHeap Heap;
  PlaneDistanceBound Bound;
  double BoundLimit = -1.0; // MaximumError in normalised units; < 0: no bound
  CollapseLoopEnd LoopEnd; // how the collapses ended
  // The last resort's last pass, when it found no legal edge: what refused each edge collapse
  // (by CollapseCheck), for the report.
  RefusalCounts RefusedBy{};
  std::int64_t BatchLimit = 1;            // Options.BatchSize, at most BatchShare of the mesh
  std::vector<std::uint32_t> VertexMarks; // ClaimNeighbourhood's stamps
  std::uint32_t Stamp = 0;
  std::vector<Scratch> Scratches; // one per thread
  struct BatchItem
  {
    std::int32_t Triangle = -1;
    double QueuedKey = 0.0;
    double EvaluatedPriority = 0.0; // before a fallback
    Verdict Check = Verdict::Invalid;
    Candidate Chosen;
  };
  std::vector<BatchItem> Batch;
  struct Entry
  {
    std::int32_t Triangle;
    double Key;
  };
  std::vector<Entry> Passed; // popped for a batch but not taken: queued again after it
  std::vector<std::int32_t> Applied;         // the kept vertices of a batch's collapses
  std::vector<std::int64_t> RefreshOffsets;  // their stars' places in the two lists below
  std::vector<std::int32_t> RefreshTriangles;
  std::vector<double> RefreshKeys;
};

void VolumeCollapser::UpdateAngles(std::int32_t t)
{
  const std::int32_t* tri = this->Mesh.Triangle(t);
  const Vec3* p[3] = { &this->Mesh.Point(tri[0]), &this->Mesh.Point(tri[1]), &this->Mesh.Point(tri[2]) };
  const double length = (*p[1] - *p[0]).cross(*p[2] - *p[0]).norm();
  // Two corner angles measured, the third from their sum: atan2 of |e1 × e2| = 2S and e1 · e2.
  double* angles = this->Angles.data() + 3 * static_cast<std::size_t>(t);
  angles[0] = std::atan2(length, (*p[1] - *p[0]).dot(*p[2] - *p[0]));
  angles[1] = std::atan2(length, (*p[2] - *p[1]).dot(*p[0] - *p[1]));
  angles[2] = std::max(0.0, Pi - angles[0] - angles[1]);
}

double VolumeCollapser::SurfaceError(const CollapsePlan& plan) const
{
  if (this->InputPlanes.empty())
  {
    return 0.0;
  }
  Quadric q = this->InputPlanes[plan.Vertices[0]];
  for (int i = 1; i < plan.Count; ++i)
  {
    q += this->InputPlanes[plan.Vertices[i]];
  }
  return this->SurfaceScale * q.Evaluate(plan.Position);
}

void VolumeCollapser::UpdateVertex(std::int32_t v)
{
  // Also the sum of the quadrics around v, from which constriction matrices are assembled.
  double angles = 0.0, area = 0.0;
  Quadric sum;
  this->Mesh.ForEachTriangle(v, [&](std::int32_t t) {
    if (this->TracksCurvature)
    {
      const std::int32_t* tri = this->Mesh.Triangle(t);
      angles += this->Angles[3 * t + (tri[0] == v ? 0 : tri[1] == v ? 1 : 2)];
    }
    area += this->Area(t);
    sum += this->TriangleQuadric(t);
  });
  this->VertexQuadrics[v] = sum;
  if (this->TracksCurvature)
  {
    // Eq. (6): 2π minus the angles around an interior vertex, π around a boundary one.
    this->Deficit[v] = (this->Mesh.OnBoundary(v) ? Pi : 2.0 * Pi) - angles;
  }
  this->VertexArea[v] = area;
}

void VolumeCollapser::UpdateFanSums(const std::int32_t* vertices, int count, double sign)
{
  if (!this->HasFans)
  {
    return;
  }
  for (int i = 0; i < count; ++i)
  {
    this->Mesh.ForEachTriangle(vertices[i], [&](std::int32_t t) {
      const std::int32_t* tri = this->Mesh.Triangle(t);
      for (int j = 0; j < i; ++j)
      {
        if (tri[0] == vertices[j] || tri[1] == vertices[j] || tri[2] == vertices[j])
        {
          return; // visited around an earlier vertex
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        const std::int32_t c = tri[k];
        if (this->Mesh.NumberOfTrianglesAround(c) <= FanLimit ||
          std::find(vertices, vertices + count, c) != vertices + count)
        {
          continue;
        }
        if (sign > 0.0)
        {
          this->VertexQuadrics[c] += this->TriangleQuadric(t);
        }
        else
        {
          this->VertexQuadrics[c] -= this->TriangleQuadric(t);
        }
        if (this->TracksCurvature)
        {
          this->Deficit[c] -= sign * this->Angles[3 * t + k];
        }
        this->VertexArea[c] += sign * this->Area(t);
      }
    });
  }
}

void VolumeCollapser::UpdateQuadric(std::int32_t t)
{
  const double area = this->Area(t);
  const Vec3 n = this->Normal(t);
  if (!(area > 0.0) || n == Vec3::Zero())
  {
    this->TriangleWeights[t] = 0.0;
    return;
  }
  const std::int32_t* tri = this->Mesh.Triangle(t);
  double weight = area * area / 9.0; // eq. (3)
  if (this->Options.UseShapeFactor)
  {
    // §3.2: W = 2 (1 − cos min α) · S.
    const double smallest = SmallestAngleCosine(
      this->Mesh.Point(tri[0]), this->Mesh.Point(tri[1]), this->Mesh.Point(tri[2]));
    weight *= 2.0 * (1.0 - smallest) * area;
  }
  if (this->Options.UseNormalFactor)
  {
    // §3.2: N = mean over the adjacent triangles of (1 − |n · n_j|) / 2.
    double sum = 0.0;
    int count = 0;
    this->ForEachAdjacent(t, [&](std::int32_t j) {
      if (j != t)
      {
        sum += 0.5 * (1.0 - std::abs(n.dot(this->FactorNormals[j].cast<double>())));
        ++count;
      }
    });
    weight *= (count > 0 ? std::max(0.0, sum / count) : 0.0) + NormalFactorFloor;
  }
  if (this->Options.UseVolumeWeights)
  {
    // §3.1's constraint weight φ, relative to the triangle's own squared volume scale S³.
    const double accumulated =
      (this->VertexError[tri[0]] + this->VertexError[tri[1]] + this->VertexError[tri[2]]) / 3.0;
    weight *= 1.0 + accumulated / (area * area * area);
  }
  this->TriangleWeights[t] = weight;
}

void VolumeCollapser::ConstrictionMatrix(std::int32_t t, Quadric& q, EdgeNeighbours* across) const
{
  // Σ Q_j over the triangles sharing a vertex with t (Definition 2), from the vertex sums:
  // a triangle across an edge of t is in two of them, t itself in three.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  q = this->VertexQuadrics[tri[0]];
  q += this->VertexQuadrics[tri[1]];
  q += this->VertexQuadrics[tri[2]];
  const Quadric own = this->TriangleQuadric(t);
  q -= own;
  q -= own;
  for (int k = 0; k < 3; ++k)
  {
    this->Mesh.ForEachTriangleOnEdge(tri[k], tri[(k + 1) % 3], [&](std::int32_t j) {
      if (j != t)
      {
        const Quadric neighbour = this->TriangleQuadric(j);
        q -= neighbour;
        if (across)
        {
          across->Quadrics[k] += neighbour;
          ++across->Count[k];
        }
      }
    });
  }
}

void VolumeCollapser::OntoCorner(const std::int32_t* v, int k, CollapsePlan& plan) const
{
  // The kept corner goes first in the plan; weights follow the plan's vertex order.
  plan.Vertices[0] = v[k];
  plan.Vertices[1] = v[(k + 1) % 3];
  plan.Vertices[2] = v[(k + 2) % 3];
  plan.Position = this->Mesh.Point(v[k]);
  plan.Weights[0] = 1.0;
  plan.Weights[1] = plan.Weights[2] = 0.0;
}

int VolumeCollapser::OntoBoundaryEdge(const std::int32_t* v, const Quadric& q, CollapsePlan& plan) const
{
  // §3.5: an edge-boundary triangle collapses to ω v_i + (1 − ω) v_j minimising eq. (1).
  // Returns i, the corner its boundary edge starts from.
  const int interior = !this->Mesh.OnBoundary(v[0]) ? 0 : !this->Mesh.OnBoundary(v[1]) ? 1 : 2;
  const int i = (interior + 1) % 3, j = (interior + 2) % 3;
  const Vec3& pi = this->Mesh.Point(v[i]);
  const Vec3& pj = this->Mesh.Point(v[j]);
  const double omega = SegmentMinimum(q, pi, pj);
  const int kept = omega >= 0.5 ? i : j;
  this->OntoCorner(v, kept, plan);
  plan.Position = pj + omega * (pi - pj);
  plan.Weights[0] = kept == i ? omega : 1.0 - omega;
  // The plan lists (kept, next, next-next); the other boundary vertex takes the rest.
  const int other = kept == i ? j : i;
  const int slot = v[(kept + 1) % 3] == v[other] ? 1 : 2;
  plan.Weights[slot] = 1.0 - plan.Weights[0];
  plan.Weights[3 - slot] = 0.0;
  return i;
}

int VolumeCollapser::StrongFeatureCorner(const std::int32_t* v) const
{
  // Eq. (6)–(7): the corner of largest |K_v| when the triangle is a strong feature, else -1.
  if (!(this->Options.FeatureCurvature > 0.0))
  {
    return -1;
  }
  const double areas = this->VertexArea[v[0]] + this->VertexArea[v[1]] + this->VertexArea[v[2]];
  const double deficits = std::abs(this->Deficit[v[0]]) + std::abs(this->Deficit[v[1]]) + std::abs(this->Deficit[v[2]]);
  const double meanArea = this->TotalArea / static_cast<double>(this->Mesh.NumberOfAliveTriangles());
  if (!(areas > 0.0 && deficits / areas * meanArea > this->Options.FeatureCurvature))
  {
    return -1;
  }
  int strongest = 0;
  double best = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const double curvature = this->VertexArea[v[k]] > 0.0 ? std::abs(this->Deficit[v[k]]) / this->VertexArea[v[k]] : 0.0;
    if (curvature > best)
    {
      best = curvature;
      strongest = k;
    }
  }
  return strongest;
}

MESHSIMP_RARE_PATH int VolumeCollapser::OntoHinge(const std::int32_t* v, const Quadric& q, int& edge) const
{
  // Pinned corners (hinge or locked) stay where they are: one is the kept corner; two must be
  // the ends of a hinge edge, the hinge corner merged into the other end (a locked one, or the
  // cheaper); three cannot collapse.
  edge = -1;
  int pinned[3], count = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (this->Mesh.OnHinge(v[k]) || this->Mesh.IsLocked(v[k]))
    {
      pinned[count++] = k;
    }
  }
  if (count == 1)
  {
    return pinned[0];
  }
  if (count != 2)
  {
    return -1;
  }
  const int a = pinned[0], b = pinned[1];
  if (this->Mesh.TrianglesOnEdge(v[a], v[b]) < 3)
  {
    return -1; // two pinned corners across a sheet
  }
  edge = b == a + 1 ? a : b; // corners (0, 1) start edge 0, (1, 2) edge 1, (0, 2) edge 2
  if (this->Mesh.IsLocked(v[a]) || this->Mesh.IsLocked(v[b]))
  {
    return this->Mesh.IsLocked(v[a]) ? a : b;
  }
  return q.Evaluate(this->Mesh.Point(v[b])) < q.Evaluate(this->Mesh.Point(v[a])) ? b : a;
}

MESHSIMP_RARE_PATH void VolumeCollapser::CheaperHingeEdge(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const
{
  // A straight run of a hinge loses a vertex without error this way; the triangle never does.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  const std::int32_t ends[2] = { tri[k], tri[(k + 1) % 3] };
  Quadric q = this->VertexQuadrics[ends[0]];
  q += this->VertexQuadrics[ends[1]];
  q -= this->TriangleQuadric(t);
  q -= across.Quadrics[k];
  double best = EdgeErrorShare * candidate.Cost;
  int kept = -1;
  for (int i = 0; i < 2; ++i)
  {
    const double cost = q.Evaluate(this->Mesh.Point(ends[i]));
    if (!this->Mesh.IsLocked(ends[1 - i]) && cost < best)
    {
      best = cost;
      kept = i;
    }
  }
  if (kept >= 0)
  {
    SetEdgePlan(ends[kept], ends[1 - kept], 1.0, this->Mesh.Point(ends[kept]), q, best, candidate);
  }
}

void VolumeCollapser::PlaceFreely(const std::int32_t* v, const Quadric& q, CollapsePlan& plan) const
{
  // Eq. (8): the blend weighted by the corners' adjacent areas; eq. (5)'s minimiser where Q̄ is
  // well conditioned, and along its well-conditioned directions only where it is not (a flat
  // region keeps the blend, a crease keeps the blend's place along it).
  Vec3 x;
  const Vec3& p0 = this->Mesh.Point(v[0]);
  const Vec3& p1 = this->Mesh.Point(v[1]);
  const Vec3& p2 = this->Mesh.Point(v[2]);
  const double longest = std::max({ (p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm() });
  const Vec3 centroid = (p0 + p1 + p2) / 3.0;
  const double sum = this->VertexArea[v[0]] + this->VertexArea[v[1]] + this->VertexArea[v[2]];
  const Vec3 blend = sum > 0.0
    ? Vec3((this->VertexArea[v[0]] * p0 + this->VertexArea[v[1]] * p1 + this->VertexArea[v[2]] * p2) / sum)
    : centroid;
  MinimizeQuadricNear(q, blend, x);
  if ((x - centroid).norm() > 2.0 * longest)
  {
    x = blend; // a far minimiser of a barely conditioned Q̄ would make a spike
  }
  if (this->Normalised.InBox(x) != x)
  {
    x = blend; // no point beyond the input's box (a terrain's peak, its border): the blend is inside
  }
  // Attribute weights: barycentric coordinates of x projected onto the triangle, clamped.
  const Vec3 n = (p1 - p0).cross(p2 - p0);
  const double n2 = n.squaredNorm();
  double w[3] = { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };
  if (n2 > 0.0)
  {
    w[0] = std::max(0.0, n.dot((p1 - x).cross(p2 - x)) / n2);
    w[1] = std::max(0.0, n.dot((p2 - x).cross(p0 - x)) / n2);
    w[2] = std::max(0.0, n.dot((p0 - x).cross(p1 - x)) / n2);
    const double total = w[0] + w[1] + w[2];
    for (double& wk : w)
    {
      wk = total > 0.0 ? wk / total : 1.0 / 3.0;
    }
  }
  const int kept = w[0] >= w[1] && w[0] >= w[2] ? 0 : w[1] >= w[2] ? 1 : 2;
  this->OntoCorner(v, kept, plan);
  plan.Position = x;
  for (int i = 0; i < 3; ++i)
  {
    plan.Weights[i] = w[(kept + i) % 3];
  }
}

VolumeCollapser::Candidate VolumeCollapser::Evaluate(std::int32_t t) const
{
  // The plan of triangle t by the paper's rules, in order: onto its one locked corner, onto its
  // one boundary corner, along its boundary edge, onto its strongest feature corner, else the
  // free placement; then a cheaper edge instead where one is (EdgeCollapses).
  Candidate candidate;
  const std::int32_t* v = this->Mesh.Triangle(t);
  int boundaryCount = 0, lockedCount = 0, locked = -1;
  for (int k = 0; k < 3; ++k)
  {
    boundaryCount += this->Mesh.OnBoundary(v[k]) ? 1 : 0;
    if (this->Mesh.IsLocked(v[k]))
    {
      ++lockedCount;
      locked = k;
    }
  }
  const bool onHinge =
    this->Mesh.HasHinges() && (this->Mesh.OnHinge(v[0]) || this->Mesh.OnHinge(v[1]) || this->Mesh.OnHinge(v[2]));
  if (lockedCount >= 2 || boundaryCount == 3 ||
    (lockedCount == 1 && boundaryCount > 0 && !this->Mesh.OnBoundary(v[locked])) || (onHinge && boundaryCount > 0))
  {
    return candidate;
  }
  // A corner on the cut between the pieces of a distributed mesh (locked as shared with another
  // piece) is on no border of the surface: §3.5's rule would draw the interior onto the cut.
  const bool onCut =
    lockedCount == 1 && boundaryCount == 1 && this->Mesh.WhyLocked(v[locked]) == LockReason::SharedPoint;
  Quadric q;
  EdgeNeighbours across;
  this->ConstrictionMatrix(t, q, this->Options.EdgeCollapses || onCut ? &across : nullptr);
  CollapsePlan& plan = candidate.Plan;
  plan.Count = 3;
  int boundaryEdge = -1; // an edge-boundary triangle's edge between its boundary corners
  int hingeEdge = -1;    // the same along a hinge
  const int feature = lockedCount == 0 && boundaryCount == 0 && !onHinge ? this->StrongFeatureCorner(v) : -1;
  if (onCut)
  {
    this->OffTheCut(t, (locked + 1) % 3, across, candidate);
    return this->Finish(candidate);
  }
  if (onHinge)
  {
    const int kept = this->OntoHinge(v, q, hingeEdge);
    if (kept < 0)
    {
      return candidate;
    }
    this->OntoCorner(v, kept, plan);
  }
  else if (lockedCount == 1)
  {
    this->OntoCorner(v, locked, plan);
  }
  else if (boundaryCount == 1)
  {
    // §3.5: a vertex-boundary triangle collapses onto its boundary vertex.
    this->OntoCorner(v, this->Mesh.OnBoundary(v[0]) ? 0 : this->Mesh.OnBoundary(v[1]) ? 1 : 2, plan);
  }
  else if (boundaryCount == 2)
  {
    boundaryEdge = this->OntoBoundaryEdge(v, q, plan);
  }
  else if (feature >= 0)
  {
    this->OntoCorner(v, feature, plan);
  }
  else
  {
    this->PlaceFreely(v, q, plan);
    candidate.FreePlacement = true;
  }
  candidate.Q = q;
  candidate.Cost = q.Evaluate(plan.Position); // eq. (5)
  candidate.Priority = PriorityOf(candidate.Cost, 3);
  // An edge can only be cheaper than a triangle of positive error: Quadric::Evaluate is never
  // negative (a flat region's triangles skip the search).
  const bool edgeMayBeCheaper = this->Options.EdgeCollapses && EdgeErrorShare * candidate.Cost > 0.0;
  if (candidate.FreePlacement && edgeMayBeCheaper)
  {
    this->CheaperEdge(t, across, candidate);
  }
  else if (boundaryEdge >= 0 && edgeMayBeCheaper)
  {
    this->CheaperBoundaryEdge(t, boundaryEdge, across, candidate);
  }
  else if (hingeEdge >= 0 && edgeMayBeCheaper)
  {
    this->CheaperHingeEdge(t, hingeEdge, across, candidate);
  }
  return this->Finish(candidate);
}

void VolumeCollapser::OffTheCut(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const
{
  // The edge off the cut collapses, placed as a free edge is, or onto one of its ends when that
  // point is refused (Examine's fallback for a free placement).
  Quadric edge;
  Vec3 x;
  const double cost = this->PlaceEdge(t, k, this->TriangleQuadric(t), across, edge, x);
  const std::int32_t* v = this->Mesh.Triangle(t);
  this->SetEdgePlanAt(v[k], v[(k + 1) % 3], x, edge, cost, candidate);
  candidate.FreePlacement = true;
}

VolumeCollapser::Candidate VolumeCollapser::Finish(Candidate& candidate) const
{
  candidate.Priority += this->SurfaceError(candidate.Plan);
  // Quadric::Evaluate clamps at zero, which would make a non-finite quadric look free.
  const Quadric& chosen = candidate.Q;
  candidate.Valid = std::isfinite(candidate.Cost) && std::isfinite(chosen.A00 + chosen.A11 + chosen.A22 + chosen.C);
  return candidate;
}

bool VolumeCollapser::IsFlat(const Candidate& candidate) const
{
  const CollapsePlan& plan = candidate.Plan;
  double longest2 = 0.0;
  for (int i = 0; i < plan.Count; ++i)
  {
    for (int j = i + 1; j < plan.Count; ++j)
    {
      longest2 = std::max(
        longest2, (this->Mesh.Point(plan.Vertices[i]) - this->Mesh.Point(plan.Vertices[j])).squaredNorm());
    }
  }
  const Quadric& q = candidate.Q;
  return candidate.Cost <= FlatTolerance * (q.A00 + q.A11 + q.A22) * longest2;
}

void VolumeCollapser::SetEdgePlan(std::int32_t kept, std::int32_t other, double keptWeight,
  const Vec3& position, const Quadric& q, double cost, Candidate& candidate)
{
  CollapsePlan& plan = candidate.Plan;
  plan.Count = 2;
  plan.Vertices[0] = kept;
  plan.Vertices[1] = other;
  plan.Vertices[2] = -1;
  plan.Weights[0] = keptWeight;
  plan.Weights[1] = 1.0 - keptWeight;
  plan.Weights[2] = 0.0;
  plan.Position = position;
  candidate.Q = q;
  candidate.Cost = cost;
  candidate.Priority = PriorityOf(cost, 2);
}

void VolumeCollapser::CheaperEdge(std::int32_t t, const EdgeNeighbours& across, Candidate& candidate) const
{
  // The edge of t of least error collapses instead when that error is below EdgeErrorShare of
  // the triangle's: on a cylinder an edge along a ruling line merges without error, a triangle
  // never does.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  int best = -1;
  double bestCost = EdgeErrorShare * candidate.Cost;
  Quadric bestQ;
  Vec3 bestX;
  const Quadric own = this->TriangleQuadric(t);
  for (int k = 0; k < 3; ++k)
  {
    Quadric q;
    Vec3 x;
    const double cost = this->PlaceEdge(t, k, own, across, q, x);
    if (cost < bestCost)
    {
      best = k;
      bestCost = cost;
      bestQ = q;
      bestX = x;
    }
  }
  if (best >= 0)
  {
    this->SetEdgePlanAt(tri[best], tri[(best + 1) % 3], bestX, bestQ, bestCost, candidate);
  }
}

double VolumeCollapser::PlaceEdge(
  std::int32_t t, int k, const Quadric& own, const EdgeNeighbours& across, Quadric& q, Vec3& x) const
{
  // An edge's quadric sums the triangles around its two ends (t and the one across, which hold
  // both, once); its point minimises it as in §3.4.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  q = this->VertexQuadrics[tri[k]];
  q += this->VertexQuadrics[tri[(k + 1) % 3]];
  q -= own;
  q -= across.Quadrics[k];
  const Vec3& pa = this->Mesh.Point(tri[k]);
  const Vec3& pb = this->Mesh.Point(tri[(k + 1) % 3]);
  const Vec3 middle = 0.5 * (pa + pb);
  MinimizeQuadricNear(q, middle, x);
  if ((x - middle).squaredNorm() > 4.0 * (pb - pa).squaredNorm())
  {
    x = middle; // as for triangles: no spike from a barely conditioned quadric
  }
  if (this->Normalised.InBox(x) != x)
  {
    x = middle; // inside the input's box, as the edge is
  }
  return q.Evaluate(x);
}

void VolumeCollapser::SetEdgePlanAt(
  std::int32_t a, std::int32_t b, const Vec3& x, const Quadric& q, double cost, Candidate& candidate) const
{
  // Attribute weights from the point's projection onto the edge; the nearer end is kept.
  const Vec3 d = this->Mesh.Point(b) - this->Mesh.Point(a);
  const double length2 = d.squaredNorm();
  const double s = length2 > 0.0 ? std::min(1.0, std::max(0.0, (x - this->Mesh.Point(a)).dot(d) / length2)) : 0.5;
  if (s <= 0.5)
  {
    SetEdgePlan(a, b, 1.0 - s, x, q, cost, candidate);
  }
  else
  {
    SetEdgePlan(b, a, s, x, q, cost, candidate);
  }
}

void VolumeCollapser::CheaperBoundaryEdge(std::int32_t t, int k, const EdgeNeighbours& across, Candidate& candidate) const
{
  // An edge-boundary triangle (§3.5) collapses its boundary edge alone instead, at the point of
  // least error on it, when that costs under EdgeErrorShare of the triangle's error. Without it
  // a fan around one interior vertex (a triangulated polygon) cannot be simplified: every
  // triangle is edge-boundary and merging the centre into the rim leaves a rim vertex with two
  // neighbours.
  if (across.Count[k] != 0)
  {
    return; // not a boundary edge: two boundary vertices joined across the interior
  }
  const std::int32_t* tri = this->Mesh.Triangle(t);
  const std::int32_t a = tri[k], b = tri[(k + 1) % 3];
  Quadric q = this->VertexQuadrics[a];
  q += this->VertexQuadrics[b];
  q -= this->TriangleQuadric(t);
  const double omega = SegmentMinimum(q, this->Mesh.Point(a), this->Mesh.Point(b));
  const Vec3 x = this->Mesh.Point(b) + omega * (this->Mesh.Point(a) - this->Mesh.Point(b));
  const double cost = q.Evaluate(x);
  if (!(cost < EdgeErrorShare * candidate.Cost))
  {
    return;
  }
  if (omega >= 0.5)
  {
    SetEdgePlan(a, b, omega, x, q, cost, candidate);
  }
  else
  {
    SetEdgePlan(b, a, 1.0 - omega, x, q, cost, candidate);
  }
}

bool VolumeCollapser::OntoCheapestCorner(Candidate& candidate, Scratch& scratch) const
{
  // When the free placement folds or degenerates the mesh, the triangle (or edge) may still
  // collapse onto one of its corners: the legal one of least error (the first of equal ones),
  // so the corners are checked cheapest first (Quadric::Evaluate gives no NaN: it clamps at 0).
  const CollapsePlan original = candidate.Plan;
  const int count = original.Count;
  std::array<std::pair<double, int>, 3> corners;
  corners.fill({ std::numeric_limits<double>::infinity(), 3 }); // past count: sorted last
  for (int k = 0; k < count; ++k)
  {
    corners[k] = { candidate.Q.Evaluate(this->Mesh.Point(original.Vertices[k])), k };
  }
  std::sort(corners.begin(), corners.end());
  for (int c = 0; c < count; ++c)
  {
    const int k = corners[c].second;
    CollapsePlan plan;
    plan.Count = count;
    for (int i = 0; i < count; ++i)
    {
      plan.Vertices[i] = original.Vertices[(k + i) % count];
    }
    plan.Position = this->Mesh.Point(plan.Vertices[0]);
    if (this->Mesh.IsLegal(plan, scratch.Check))
    {
      candidate.Plan = plan;
      candidate.Cost = corners[c].first;
      candidate.Priority = PriorityOf(candidate.Cost, count) + this->SurfaceError(candidate.Plan);
      return true;
    }
  }
  return false;
}

double VolumeCollapser::NewSmallestAngle(const CollapsePlan& plan) const
{
  return std::acos(std::min(1.0, this->Mesh.SmallestNewAngleCosine(plan))) * 180.0 / Pi;
}

double VolumeCollapser::SliverKey(const Candidate& candidate) const
{
  const double angle = std::max(NewSmallestAngle(candidate.Plan), 0.01 * this->GuardAngle);
  const double below = std::max(1.0, this->GuardAngle / angle);
  return candidate.Priority * below * below;
}

VolumeCollapser::Verdict VolumeCollapser::Examine(std::int32_t t, double queuedKey, double nextKey,
  Candidate& candidate, double& evaluatedPriority, Scratch& scratch) const
{
  candidate = this->Evaluate(t);
  evaluatedPriority = candidate.Priority;
  if (!candidate.Valid)
  {
    return Verdict::Invalid;
  }
  if (candidate.Priority > queuedKey && candidate.Priority > nextKey)
  {
    return Verdict::Stale;
  }
  const CollapseCheck failed = this->Mesh.FirstFailedCheck(candidate.Plan, scratch.Check);
  if (failed == CollapseCheck::Passed)
  {
    return Verdict::Legal;
  }
  // A free placement that fails may still collapse onto a corner; a flat collapse that fails
  // only the angle guard may make its slivers (a plane or a crease line loses nothing, and CAD
  // meshes need slivers along their creases: see VolumeTriangleCollapse.md).
  const Candidate original = candidate;
  if (candidate.FreePlacement && this->OntoCheapestCorner(candidate, scratch))
  {
    return Verdict::Fallback;
  }
  candidate = original;
  if (failed != CollapseCheck::AngleGuard)
  {
    return Verdict::Illegal;
  }
  candidate.Plan.GuardAngles = false; // legal so: the guard is the last check
  return this->IsFlat(candidate) ? Verdict::Fallback : Verdict::Sliver;
}

void VolumeCollapser::RefreshAround(
  std::int32_t kept, Scratch& scratch, std::int32_t* triangles, double* keys)
{
  // The new vertex's triangles changed shape, and the angle sums of their corners changed: their
  // geometry, quadrics and costs are updated at once. The costs of triangles further out (their
  // constriction matrices hold some of these quadrics) are refreshed when they reach the top of
  // the heap; the normal factors of triangles further out when a collapse next moves them.
  if (scratch.Marks.size() < static_cast<std::size_t>(this->Mesh.NumberOfPoints()) ||
    scratch.Stamp == std::numeric_limits<std::uint32_t>::max())
  {
    scratch.Marks.assign(static_cast<std::size_t>(this->Mesh.NumberOfPoints()), 0u);
    scratch.Stamp = 0;
  }
  const std::uint32_t mark = ++scratch.Stamp;
  scratch.Ring.clear();
  this->Mesh.ForEachTriangle(kept, [&](std::int32_t t) {
    if (this->TracksCurvature)
    {
      this->UpdateAngles(t);
    }
    if (this->Options.UseNormalFactor)
    {
      this->UpdateFactorNormal(t);
    }
    const std::int32_t* tri = this->Mesh.Triangle(t);
    for (int k = 0; k < 3; ++k)
    {
      if (scratch.Marks[tri[k]] != mark)
      {
        scratch.Marks[tri[k]] = mark;
        scratch.Ring.push_back(tri[k]);
      }
    }
  });
  this->Mesh.ForEachTriangle(kept, [&](std::int32_t t) { this->UpdateQuadric(t); });
  for (const std::int32_t v : scratch.Ring)
  {
    if (v == kept || this->Mesh.NumberOfTrianglesAround(v) <= FanLimit)
    {
      this->UpdateVertex(v);
    }
  }
  this->UpdateFanSums(&kept, 1, 1.0); // Apply took back what they held before
  std::int32_t i = 0;
  this->Mesh.ForEachTriangle(kept, [&](std::int32_t t) {
    const Candidate candidate = this->Evaluate(t);
    triangles[i] = t;
    keys[i] = candidate.Valid ? candidate.Priority : -1.0;
    ++i;
  });
}

void VolumeCollapser::UpdateAround(std::int32_t kept)
{
  this->Applied.assign(1, kept);
  this->RefreshApplied();
}

void VolumeCollapser::RefreshApplied()
{
  const std::int64_t applied = static_cast<std::int64_t>(this->Applied.size());
  this->RefreshOffsets.assign(static_cast<std::size_t>(applied) + 1, 0);
  for (std::int64_t i = 0; i < applied; ++i)
  {
    this->RefreshOffsets[i + 1] =
      this->RefreshOffsets[i] + this->Mesh.NumberOfTrianglesAround(this->Applied[i]);
  }
  this->RefreshTriangles.resize(static_cast<std::size_t>(this->RefreshOffsets[applied]));
  this->RefreshKeys.resize(this->RefreshTriangles.size());
  this->Context.ForEachWithScratch(this->Scratches, applied, 10000, [&](std::int64_t i, Scratch& scratch) {
    this->RefreshAround(this->Applied[i], scratch, this->RefreshTriangles.data() + this->RefreshOffsets[i],
      this->RefreshKeys.data() + this->RefreshOffsets[i]);
  });
  for (const std::int32_t kept : this->Applied)
  {
    this->HasFans = this->HasFans || this->Mesh.NumberOfTrianglesAround(kept) > FanLimit;
  }
  for (std::size_t i = 0; i < this->RefreshTriangles.size(); ++i)
  {
    if (this->RefreshKeys[i] >= 0.0)
    {
      this->Heap.Set(this->RefreshTriangles[i], this->RefreshKeys[i]);
    }
    else
    {
      this->Heap.Remove(this->RefreshTriangles[i]);
    }
  }
}

bool VolumeCollapser::ClaimNeighbourhood(std::int32_t t, std::uint32_t stamp)
{
  const std::int32_t* tri = this->Mesh.Triangle(t);
  bool taken = false;
  for (int k = 0; k < 3 && !taken; ++k)
  {
    this->Mesh.ForEachTriangle(tri[k], [&](std::int32_t j) {
      const std::int32_t* o = this->Mesh.Triangle(j);
      taken = taken || this->VertexMarks[o[0]] == stamp || this->VertexMarks[o[1]] == stamp ||
        this->VertexMarks[o[2]] == stamp;
    });
  }
  if (taken)
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Mesh.ForEachTriangle(tri[k], [&](std::int32_t j) {
      const std::int32_t* o = this->Mesh.Triangle(j);
      this->VertexMarks[o[0]] = this->VertexMarks[o[1]] = this->VertexMarks[o[2]] = stamp;
    });
  }
  return true;
}

void VolumeCollapser::SelectBatch(std::int64_t limit)
{
  this->Batch.clear();
  if (++this->Stamp == 0)
  {
    std::fill(this->VertexMarks.begin(), this->VertexMarks.end(), 0u);
    this->Stamp = 1;
  }
  this->Passed.clear();
  for (std::int64_t pops = 0; static_cast<std::int64_t>(this->Batch.size()) < limit && !this->Heap.Empty() &&
       pops < 4 * limit;
       ++pops)
  {
    const double key = this->Heap.TopCost();
    const std::int32_t t = this->Heap.Pop();
    if (!this->Mesh.IsAlive(t))
    {
      continue;
    }
    const std::int32_t* tri = this->Mesh.Triangle(t);
    const bool hub = std::any_of(
      tri, tri + 3, [&](std::int32_t v) { return this->Mesh.NumberOfTrianglesAround(v) > FanLimit; });
    if (limit > 1 && (hub ? !this->Batch.empty() : !this->ClaimNeighbourhood(t, this->Stamp)))
    {
      this->Passed.push_back({ t, key });
      if (hub)
      {
        break; // next batch, alone
      }
      continue;
    }
    BatchItem item;
    item.Triangle = t;
    item.QueuedKey = key;
    this->Batch.push_back(item);
    if (hub)
    {
      break; // a fan's centre: a batch of one, without walking its triangles
    }
  }
}

int VolumeCollapser::CountRemoved(const CollapsePlan& plan) const
{
  int removed = 0;
  for (int i = 0; i < plan.Count; ++i)
  {
    this->Mesh.ForEachTriangle(plan.Vertices[i], [&](std::int32_t t) {
      const std::int32_t* tri = this->Mesh.Triangle(t);
      int inside = 0, first = -1;
      for (int j = 0; j < plan.Count; ++j)
      {
        if (tri[0] == plan.Vertices[j] || tri[1] == plan.Vertices[j] || tri[2] == plan.Vertices[j])
        {
          ++inside;
          first = first < 0 ? j : first;
        }
      }
      removed += inside > 1 && first == i ? 1 : 0;
    });
  }
  return removed;
}

std::int64_t VolumeCollapser::Prepare(const TriangleMeshView& input, VolumeCollapseResult& result)
{
  // The usable input in normalised coordinates (box centred at the origin, diagonal 1, which
  // keeps the sixth and eighth powers of lengths in the costs within range), in the engine with
  // its locks; then its geometry, quadrics and first costs.
  PreparedMesh prepared = PrepareMesh(input, this->Options, Normalization::CentreAndDiagonal, this->Context);
  result.Report = prepared.Report();
  this->InputVertex = std::move(prepared.Mesh.InputVertex);
  this->InputTriangle = std::move(prepared.Mesh.InputTriangle);
  this->Normalised = prepared;
  this->Diagonal = prepared.Diagonal > 0.0 ? prepared.Diagonal : 1.0;
  // No triangle's smallest angle exceeds 60°: a larger guard (or an infinite one, which
  // halving never lowers) would only refuse every collapse.
  this->GuardAngle = std::min(60.0, std::max(0.0, this->Options.MinimumAngle));
  result.FinalMinimumAngle = this->GuardAngle;
  this->Mesh.SetMinimumAngle(this->GuardAngle);
  this->Mesh.Load(prepared, this->Options.BoundaryCornerAngle, true, this->Context);
  if (prepared.Bound >= 0.0)
  {
    this->Bound.Build(this->Mesh);
    this->BoundLimit = prepared.Bound;
  }
  this->MeasureAll();
  this->QueueAll();
  // At most a record per vertex removed, and a mesh of T triangles keeps about T / 2 vertices:
  // reserved so that the list never doubles (which held 1.5 times its size at once).
  this->Mesh.ReserveRecords(this->Mesh.NumberOfPoints() - prepared.TargetTriangles / 2);
  return prepared.TargetTriangles;
}

void VolumeCollapser::MeasureAll()
{
  // Every triangle's geometry and quadric, every vertex's sums, and the input planes of the
  // surface term: concurrently, with work estimates in nanoseconds (ExecutionContext), measured.
  const std::int32_t n = this->Mesh.NumberOfPoints();
  const std::int32_t m = this->Mesh.NumberOfTriangles();
  this->TracksCurvature = this->Options.FeatureCurvature > 0.0;
  this->Angles.resize(this->TracksCurvature ? 3 * static_cast<std::size_t>(m) : 0);
  this->TriangleWeights.resize(m);
  this->VertexQuadrics.resize(n);
  this->VertexError.assign(n, 0.0);
  this->Moved.assign(n, 0);
  this->Deficit.resize(this->TracksCurvature ? n : 0);
  this->VertexArea.resize(n);
  this->VertexMarks.assign(n, 0);
  this->BatchLimit =
    std::max<std::int64_t>(1, std::min<std::int64_t>(this->Options.BatchSize, m / BatchShare));
  this->FactorNormals.resize(this->Options.UseNormalFactor ? m : 0);
  if (this->TracksCurvature || this->Options.UseNormalFactor)
  {
    this->Context.For(m, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t t = b; t < e; ++t)
      {
        if (this->TracksCurvature)
        {
          this->UpdateAngles(static_cast<std::int32_t>(t));
        }
        if (this->Options.UseNormalFactor)
        {
          this->UpdateFactorNormal(static_cast<std::int32_t>(t));
        }
      }
    }, 150 * static_cast<std::int64_t>(m));
  }
  this->Context.For(m, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t t = b; t < e; ++t)
    {
      this->UpdateQuadric(static_cast<std::int32_t>(t));
    }
  }, 300 * static_cast<std::int64_t>(m));
  this->Context.For(n, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t v = b; v < e; ++v)
    {
      this->UpdateVertex(static_cast<std::int32_t>(v));
    }
  }, 100 * static_cast<std::int64_t>(n));
  for (std::int32_t v = 0; v < n && !this->HasFans; ++v)
  {
    this->HasFans = this->Mesh.NumberOfTrianglesAround(v) > FanLimit;
  }
  for (std::int32_t t = 0; t < m; ++t)
  {
    this->TotalArea += this->Area(t);
  }
  if (this->Options.SurfaceErrorWeight > 0.0)
  {
    this->GatherInputPlanes();
  }
}

void VolumeCollapser::GatherInputPlanes()
{
  // Garland–Heckbert quadrics: each vertex starts with the planes of its input triangles,
  // weighted by area, and those of its border edges. The mean area squared gives the term the
  // volume error's units (length⁸).
  const std::int32_t m = this->Mesh.NumberOfTriangles();
  const double meanArea = this->TotalArea / static_cast<double>(std::max<std::int32_t>(1, m));
  this->SurfaceScale = this->Options.SurfaceErrorWeight * meanArea * meanArea;
  this->InputPlanes.assign(this->Mesh.NumberOfPoints(), Quadric());
  for (std::int32_t t = 0; t < m; ++t)
  {
    const double area = this->Area(t);
    if (area > 0.0)
    {
      const Vec3 normal = this->Normal(t);
      const std::int32_t* tri = this->Mesh.Triangle(t);
      const Quadric plane = Quadric::FromPlane(normal, -normal.dot(this->Mesh.Point(tri[0])), area);
      for (int k = 0; k < 3; ++k)
      {
        this->InputPlanes[tri[k]] += plane;
      }
      this->AddBorderPlanes(t);
    }
  }
}

void VolumeCollapser::AddBorderPlanes(std::int32_t t)
{
  // Along an open border, the plane through each border edge perpendicular to its triangle,
  // weighted by the squared edge length: in-plane moves of the border (a hole's rim cut by a
  // chord) sweep no volume, and the face planes do not see them either.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  for (int k = 0; k < 3; ++k)
  {
    const std::int32_t a = tri[k], b = tri[(k + 1) % 3];
    if (!this->Mesh.OnBoundary(a) || !this->Mesh.OnBoundary(b))
    {
      continue;
    }
    int sharing = 0;
    this->Mesh.ForEachTriangleOnEdge(a, b, [&sharing](std::int32_t) { ++sharing; });
    Quadric border;
    if (sharing == 1 && Quadric::FromBorderEdge(this->Mesh.Point(a), this->Mesh.Point(b), this->Normal(t), border))
    {
      this->InputPlanes[a] += border;
      this->InputPlanes[b] += border;
    }
  }
}

void VolumeCollapser::QueueAll()
{
  // Costs in parallel, queued in triangle order (the heap's tie rule makes that order count).
  const std::int32_t m = this->Mesh.NumberOfTriangles();
  std::vector<double> priority(m);
  this->Context.For(m, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t t = b; t < e; ++t)
    {
      const std::int32_t id = static_cast<std::int32_t>(t);
      const Candidate candidate = this->Mesh.IsAlive(id) ? this->Evaluate(id) : Candidate();
      priority[t] = candidate.Valid ? candidate.Priority : -1.0;
    }
  }, 1000 * static_cast<std::int64_t>(m));
  this->Heap.Reset(m);
  for (std::int32_t t = 0; t < m; ++t)
  {
    if (priority[t] >= 0.0)
    {
      this->Heap.Set(t, priority[t]);
    }
  }
}

void VolumeCollapser::Commit(const CollapsePlan& plan, double cost, VolumeCollapseResult& result)
{
  this->Apply(plan, cost, result);
  this->UpdateAround(plan.Vertices[0]);
}

void VolumeCollapser::Apply(const CollapsePlan& plan, double cost, VolumeCollapseResult& result)
{
  const std::int32_t kept = plan.Vertices[0];
  double error = cost;
  for (int i = 0; i < plan.Count; ++i)
  {
    error += this->VertexError[plan.Vertices[i]];
  }
  this->Moved[kept] |= plan.Position != this->Mesh.Point(kept) ? 1 : 0;
  for (int i = 1; i < plan.Count && !this->InputPlanes.empty(); ++i)
  {
    this->InputPlanes[kept] += this->InputPlanes[plan.Vertices[i]];
  }
  this->UpdateFanSums(plan.Vertices, plan.Count, -1.0);
  this->Mesh.Apply(plan, false);
  this->VertexError[kept] = error;
  result.SquareVolumeError += cost;
}

bool VolumeCollapser::CollapseAnyEdges(std::int64_t floor, VolumeCollapseResult& result)
{
  // Every legal half-edge collapse, cheapest first by the quadric sums of its two ends (ties in
  // triangle and corner order), each checked again before it is made.
  struct Option
  {
    double Cost;
    std::int32_t Kept, Other;
  };
  std::vector<Option> options;
  for (std::int32_t t = 0; t < this->Mesh.NumberOfTriangles(); ++t)
  {
    if (!this->Mesh.IsAlive(t))
    {
      continue;
    }
    const std::int32_t* tri = this->Mesh.Triangle(t);
    for (int k = 0; k < 6; ++k)
    {
      // Corner k % 3 kept, its next (k < 3) or previous corner merged: both ways of each edge.
      const std::int32_t kept = tri[k % 3], other = tri[(k % 3 + (k < 3 ? 1 : 2)) % 3];
      Quadric q = this->VertexQuadrics[kept];
      q += this->VertexQuadrics[other];
      options.push_back({ q.Evaluate(this->Mesh.Point(kept)), kept, other });
    }
  }
  std::stable_sort(options.begin(), options.end(), [](const Option& a, const Option& b) { return a.Cost < b.Cost; });
  bool any = false;
  this->RefusedBy = RefusalCounts();
  // Until a collapse is made, what refused each option: the report of a pass that makes none.
  std::vector<std::tuple<std::int32_t, std::int32_t, CollapseCheck>> verdicts;
  for (const Option& option : options)
  {
    CollapsePlan plan;
    plan.Count = 2;
    plan.Vertices[0] = option.Kept;
    plan.Vertices[1] = option.Other;
    plan.Position = this->Mesh.Point(option.Kept);
    if (this->Mesh.NumberOfAliveTriangles() <= floor)
    {
      break;
    }
    if (this->Mesh.NumberOfTrianglesAround(option.Kept) == 0 || this->Mesh.NumberOfTrianglesAround(option.Other) == 0)
    {
      continue;
    }
    const CollapseCheck failed = this->Mesh.FirstFailedCheck(plan);
    if (failed == CollapseCheck::Passed && this->Mesh.NumberOfAliveTriangles() - this->CountRemoved(plan) >= floor)
    {
      this->Commit(plan, option.Cost, result);
      any = true;
    }
    else if (!any)
    {
      verdicts.emplace_back(option.Kept, option.Other, failed);
    }
  }
  if (!any)
  {
    // Nothing changed during the pass: each half-edge (listed from both its triangles) once.
    std::sort(verdicts.begin(), verdicts.end());
    verdicts.erase(std::unique(verdicts.begin(), verdicts.end()), verdicts.end());
    CollapsePlan plan;
    plan.Count = 2;
    for (const auto& verdict : verdicts)
    {
      plan.Vertices[0] = std::get<0>(verdict);
      plan.Vertices[1] = std::get<1>(verdict);
      plan.Position = this->Mesh.Point(plan.Vertices[0]);
      this->Mesh.CountRefusal(plan, std::get<2>(verdict), this->RefusedBy);
    }
  }
  return any;
}

void VolumeCollapser::CollapseBatch(std::int64_t target, std::int64_t tolerance, VolumeCollapseResult& result)
{
  const std::int64_t size = static_cast<std::int64_t>(this->Batch.size());
  // The next key a batch's triangle is compared with below is at most the next one's key in
  // the batch, or the heap's top now for the last: the heap only gains keys until the batch is
  // collapsed, so its top can only fall.
  const double unbounded = std::numeric_limits<double>::infinity();
  const double lastNextKey = this->Heap.Empty() ? unbounded : this->Heap.TopCost();
  this->Context.ForEachWithScratch(this->Scratches, size, 1500, [&](std::int64_t i, Scratch& scratch) {
    BatchItem& item = this->Batch[i];
    const double nextKey = i + 1 < size ? this->Batch[i + 1].QueuedKey : lastNextKey;
    item.Check =
      this->Examine(item.Triangle, item.QueuedKey, nextKey, item.Chosen, item.EvaluatedPriority, scratch);
  });
  this->Applied.clear();
  for (std::int64_t i = 0; i < size; ++i)
  {
    BatchItem& item = this->Batch[i];
    const std::int32_t t = item.Triangle;
    if (item.Check == Verdict::Invalid)
    {
      continue; // until a collapse nearby requeues it
    }
    // The key the next triangle would be popped with.
    const bool hasNext = i + 1 < size || !this->Heap.Empty();
    double nextKey = i + 1 < size ? this->Batch[i + 1].QueuedKey : 0.0;
    if (!this->Heap.Empty())
    {
      nextKey = i + 1 < size ? std::min(nextKey, this->Heap.TopCost()) : this->Heap.TopCost();
    }
    if (item.Check == Verdict::Stale ||
      (item.EvaluatedPriority > item.QueuedKey && hasNext && item.EvaluatedPriority > nextKey))
    {
      this->Heap.Set(t, item.EvaluatedPriority); // its neighbourhood changed since it was queued
      continue;
    }
    const double sliverKey = item.Check == Verdict::Sliver ? this->SliverKey(item.Chosen) : 0.0;
    if (item.Check == Verdict::Sliver && item.QueuedKey < sliverKey)
    {
      this->Heap.Set(t, sliverKey);
      continue;
    }
    if (item.Check == Verdict::Illegal)
    {
      continue; // until a collapse nearby requeues it
    }
    Candidate& candidate = item.Chosen;
    if (item.Check == Verdict::Fallback && hasNext && candidate.Priority > nextKey)
    {
      this->Heap.Set(t, candidate.Priority);
      continue;
    }
    CollapsePlan& plan = candidate.Plan;
    // A collapse removes at most four triangles, but for one along a hinge of k pages (k + 2).
    const std::int64_t alive = this->Mesh.NumberOfAliveTriangles();
    const bool mayPassTarget = alive - 4 < target - tolerance || this->Mesh.HasHinges();
    if (mayPassTarget && alive - this->CountRemoved(plan) < target - tolerance)
    {
      // Near the target: collapse only the edge to the corner of larger weight instead.
      const int other = plan.Weights[1] >= plan.Weights[2] ? 1 : 2;
      CollapsePlan edge = plan;
      edge.Count = 2;
      edge.Vertices[1] = plan.Vertices[other];
      edge.Vertices[2] = -1;
      const double sum = plan.Weights[0] + plan.Weights[other];
      edge.Weights[0] = sum > 0.0 ? plan.Weights[0] / sum : 0.5;
      edge.Weights[1] = 1.0 - edge.Weights[0];
      edge.Weights[2] = 0.0;
      if (!this->Mesh.IsLegal(edge) || alive - this->CountRemoved(edge) < target - tolerance)
      {
        continue;
      }
      plan = edge;
    }
    if (this->BoundLimit >= 0.0)
    {
      const double distance = this->Bound.Distance(plan);
      if (distance > this->BoundLimit)
      {
        continue; // until a collapse nearby requeues it
      }
      this->Bound.Merge(plan, distance);
    }
    if (item.Check == Verdict::Sliver)
    {
      result.FinalMinimumAngle = std::min(result.FinalMinimumAngle, this->NewSmallestAngle(plan));
    }
    this->Apply(plan, candidate.Cost, result);
    this->Applied.push_back(plan.Vertices[0]);
  }
  // The triangles passed over go back, with their keys: the next batch starts with them.
  for (const Entry& entry : this->Passed)
  {
    this->Heap.Set(entry.Triangle, entry.Key);
  }
}

bool VolumeCollapser::CollapseToTarget(std::int64_t target, VolumeCollapseResult& result)
{
  // A closed mesh has an even count: one triangle of slack at least.
  BatchScheduler scheduler{ *this, result, std::max<std::int64_t>(1, this->Options.Goal.Slack(target)) };
  this->LoopEnd = RunCollapseLoop(scheduler, target, { 0.1, 0.95 }, this->Context);
  return this->LoopEnd.Why != CollapseLoopEnd::Reason::Aborted;
}

bool VolumeCollapser::CollapseNextBatch(std::int64_t target, std::int64_t tolerance, VolumeCollapseResult& result)
{
  // A batch of the cheapest triangles whose neighbourhoods are disjoint: evaluated and checked
  // concurrently, then collapsed in key order, then updated concurrently. A collapse removes at
  // most four triangles (the link condition leaves one across each edge; more along a hinge,
  // which CollapseBatch counts), so near the target the batch shrinks to one: the strict heap
  // order, with the exact count below.
  if (this->Heap.Empty())
  {
    return false;
  }
  const std::int64_t room = (this->Mesh.NumberOfAliveTriangles() - target) / 4;
  const std::int64_t limit = std::max<std::int64_t>(1, std::min<std::int64_t>(this->BatchLimit, room));
  this->SelectBatch(limit);
  this->CollapseBatch(target, tolerance, result);
  this->RefreshApplied();
  return true;
}

bool VolumeCollapser::Unstick(std::int64_t floor, VolumeCollapseResult& result)
{
  if (this->BoundLimit >= 0.0)
  {
    return false; // with a bound, simply the end
  }
  if (this->GuardAngle > 0.0)
  {
    // Every collapse left is refused: lower the angle guard a step (halving; 0 below 2°),
    // requeue every triangle and go on, rather than stop short of the target.
    this->GuardAngle = this->GuardAngle >= 2.0 ? 0.5 * this->GuardAngle : 0.0;
    this->Mesh.SetMinimumAngle(this->GuardAngle);
    result.FinalMinimumAngle = std::min(result.FinalMinimumAngle, this->GuardAngle);
    this->QueueAll();
    return true;
  }
  // The guard is down and no triangle's plan is legal: the last resort (their neighbourhoods
  // are queued again).
  return this->Options.EdgeCollapses && this->CollapseAnyEdges(floor, result);
}

void VolumeCollapser::Output(const TriangleMeshView& input, VolumeCollapseResult& result) const
{
  // The surviving triangles and their points, with their errors and their sources (from the
  // collapse records).
  const std::vector<std::int32_t> used =
    WriteSurvivors(this->Mesh, this->Moved, this->Normalised, input, this->InputVertex, this->InputTriangle, result);
  // Error units: length⁸ (eq. 4–5). Beyond about 1e38 that power overflows; a zero error stays
  // zero rather than becoming 0 · inf.
  const double scale8 = std::pow(this->Diagonal, 8);
  const auto inInputUnits = [scale8](double error) { return error != 0.0 ? error * scale8 : 0.0; };
  std::vector<double> pointError(used.size());
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    pointError[i] = inInputUnits(this->VertexError[used[i]]);
  }
  result.AddPointArray("SquareVolumeError", std::move(pointError));
  if (this->BoundLimit >= 0.0)
  {
    AddPlaneDistances(this->Bound, used, this->Diagonal, result);
  }
  AddCollapseSources(this->Mesh.Records(), used, this->InputVertex, result);
  result.SquareVolumeError = inInputUnits(result.SquareVolumeError);
  result.FieldValues.emplace_back("SquareVolumeError", result.SquareVolumeError);
}

std::string VolumeCollapser::RefusalSummary() const
{
  // What refused the half-edge collapses left: on a mesh stuck at its non-manifold edges the
  // user reads that locks stop it, not that something is wrong.
  const std::int64_t tried = this->RefusedBy.Total();
  return tried == 0 ? std::string()
                    : ": of the " + std::to_string(tried) + " half-edge collapses left, " +
      DescribeRefusals(this->RefusedBy, "would take the count below the target");
}

void VolumeCollapser::Judge(VolumeCollapseResult& result) const
{
  // Why the count is where it is: the reason first, then what was changed to get there.
  Outcome& report = result.Report;
  this->LoopEnd.Judge(report, this->BoundLimit >= 0.0, "no collapse is left that keeps the mesh valid");
  if (this->GuardAngle < std::min(60.0, this->Options.MinimumAngle))
  {
    // Lowered all the way and still short of the target, the guard is not what binds.
    std::ostringstream note;
    if (report.Stop == StopReason::NothingRemovable)
    {
      note << "the angle guard was also lowered from " << this->Options.MinimumAngle << " to "
           << this->GuardAngle << " degrees, which did not reach it either";
    }
    else
    {
      note << "the angle guard refused every collapse left before the target: lowered from "
           << this->Options.MinimumAngle << " to " << this->GuardAngle << " degrees";
    }
    report.Notes.push_back(note.str());
  }
}

bool VolumeCollapser::Run(const TriangleMeshView& input, VolumeCollapseResult& result)
{
  result = VolumeCollapseResult();
  const std::int64_t target = this->Prepare(input, result);
  const bool collapsing = result.Report.Stop != StopReason::AllLocked;
  if (!this->Context.Report(0.1) || (collapsing && !this->CollapseToTarget(target, result)))
  {
    result.Report.Stop = StopReason::Aborted;
    return false;
  }
  this->ReleaseWorkspace();
  this->Output(input, result);
  this->Judge(result);
  return this->Context.Report(1.0);
}

void VolumeCollapser::ReleaseWorkspace()
{
  const auto release = [](auto& list) { std::decay_t<decltype(list)>().swap(list); };
  release(this->TriangleWeights);
  release(this->FactorNormals);
  release(this->VertexQuadrics);
  release(this->InputPlanes);
  release(this->Angles);
  release(this->Deficit);
  release(this->VertexArea);
  release(this->VertexMarks);
  release(this->Scratches);
  release(this->Batch);
  release(this->Passed);
  release(this->RefreshTriangles);
  release(this->RefreshKeys);
  this->Heap.Reset(0);
}

} // namespace

bool VolumeTriangleCollapse(const TriangleMeshView& input, const VolumeCollapseOptions& options,
  VolumeCollapseResult& result, const ExecutionContext& context)
{
  return VolumeCollapser(options, context).Run(input, result);
}

} // namespace meshsimp
