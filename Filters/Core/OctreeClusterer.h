// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OctreeClusterer.h
 * @brief The octree vertex clustering's private parts, shared by its files (no public API: that
 * is OctreeVertexClustering.h).
 *
 * One class, Clusterer, carries a run from the input to the result; its member functions are
 * split by stage, one file each, all in namespace meshsimp::octree:
 *  - OctreeVertexClustering.cxx: Clusterer::Run, which calls the stages in order, and the
 *    public entry point OctreeVertexClustering (which runs again for a bound that would leave
 *    no triangle);
 *  - OctreePreparation.cxx: the prepared mesh, its normals and areas (PrepareGeometry), border
 *    and non-surface vertices (ClassifyVertices) and the vertex quadrics (PrepareQuadrics);
 *  - OctreeClusters.cxx: the clusters of a leaf and what they cost: the flood fill of a leaf's
 *    vertices into clusters (EvaluateLeaf), their quadrics, representatives and errors
 *    (ClusterQuadric, ClusterCentre, PlaceRepresentative, Represent, ClusterError, Folded,
 *    BoundaryPlane), the scan of a leaf's triangles (ScanLeaf), and leaves clustered
 *    concurrently (ClusterLeaves, MoveClusters). These run in refinement's inner loops, so they
 *    stay in one file, where they are inlined into each other;
 *  - OctreeRefinement.cxx: the octree and its heap: the top levels (PlantTree), splitting
 *    leaves (PartitionNode, SplitLeaves) and undoing splits, the batches and the refinement to
 *    a count or a bound (NextBatch, FitOvershoot, Refine), the leaves queued at triangles
 *    turned over (QueueFlippedLeaves) and RefineToTarget, which alternates refining with
 *    mending;
 *  - OctreeMending.cxx: tears mended: the surviving triangles, flaps that join their
 *    neighbours (JoinFlaps), labels split into pieces that merge without tearing (TornLabels,
 *    SplitIntoPieces with PieceGrowth, MendOnce, Settle) and the pieces committed as clusters
 *    (CommitPieces);
 *  - OctreeOutput.cxx: the output: collapses that finish a count target (FinishByCollapses),
 *    the output points, their representatives and the second error's iterations, the result
 *    written (Finalize, WriteResult, WriteInput) and the count judged (JudgeCount).
 * Small helpers called from more than one file in loops (TurnedOver), and the templates used by
 * two files (RingCentre, ProtrudingTip), are defined below the class.
 */
#ifndef MeshSimplification_OctreeClusterer_h
#define MeshSimplification_OctreeClusterer_h

#include "OctreeVertexClustering.h"
#include "Quadric.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace meshsimp
{
namespace octree
{
using Vec3 = Eigen::Vector3d;

/// Heap keys above every error: leaves that must be split whatever the target.
constexpr double ForcedSplitKey = std::numeric_limits<double>::infinity();
/// Under an error bound, leaves whose clustering flips a related triangle (§2.4): always split.
constexpr double FlipSplitKey = std::numeric_limits<double>::max();
/// Leaves smaller than this (in units of the bounding-box diagonal) hold coincident points.
constexpr double MinimumCellHalfSize = 1e-9;
constexpr int MaximumDepth = 40;

struct Plane
{
  Vec3 Normal = Vec3::Zero(); // unit, or zero for a zero-area triangle
  double Offset = 0.0;
  double Distance(const Vec3& x) const { return std::abs(this->Normal.dot(x) + this->Offset); }
};

/// An axis-aligned box of the normalised space: where a representative may lie.
struct Box
{
  Vec3 Lower, Upper;
  bool Contains(const Vec3& x) const
  {
    return (x.array() >= this->Lower.array()).all() && (x.array() <= this->Upper.array()).all();
  }
  Vec3 Clamp(const Vec3& x) const { return x.cwiseMax(this->Lower).cwiseMin(this->Upper); }
  Box Joined(const Box& other) const
  {
    return { this->Lower.cwiseMin(other.Lower), this->Upper.cwiseMax(other.Upper) };
  }
};

struct OctreeNode
{
  Vec3 Center;
  double Half;
  std::int32_t Begin, End; // range of Clusterer::Order
  std::int32_t Depth;
  std::int32_t FirstCluster, ClusterCount; // its clusters while it is a leaf
  std::int32_t Serial;                     // unique, so heap entries of undone nodes are seen
};

struct HeapEntry
{
  double Key;  // leaf error, or one of the split keys above
  double Half; // ties: larger cells first
  std::int32_t Node;
  std::int32_t Serial;
  double Error;       // the leaf's cluster error
  double Vanishing;   // error of its clusters that lose every triangle (see ScanLeaf)
  bool Flipped;       // clustering the leaf turns a neighbouring triangle over (§2.4)
  bool operator<(const HeapEntry& o) const
  {
    if (this->Key != o.Key)
    {
      return this->Key < o.Key;
    }
    if (this->Half != o.Half)
    {
      return this->Half < o.Half;
    }
    return this->Node > o.Node; // older nodes first: the order never depends on threads
  }
};

/// What one pass over the corners of a leaf's vertices finds (see Clusterer::ScanLeaf).
struct LeafScan
{
  double Vanishing = 0.0;       // error of its clusters that lose every triangle
  bool Flipped = false;         // clustering it turns a neighbouring triangle over (§2.4)
  std::int64_t Surviving = 0;   // triangles with three distinct clusters in the count range
};

/// (neighbour, third) label pairs, sorted and unique: the edges at a point and the third
/// corners of their triangles; also label pairs (a < b) as such.
using Thirds = std::vector<std::pair<std::int32_t, std::int32_t>>;

class Clusterer
{
public:
  Clusterer(const TriangleMeshView& input, const OctreeClusteringOptions& options,
    const ExecutionContext& context)
    : Input(input)
    , Options(options)
    , Context(context)
  {
  }

  bool Run(OctreeClusteringResult& result);

private:
  /// Per-thread scratch of EvaluateLeaf, indexed by position in the leaf: the flood fill of
  /// its components and the members of each cluster (CSR); and of ScanLeaf.
  struct Scratch
  {
    std::vector<std::int32_t> Stack, Root;
    std::vector<std::int32_t> Offsets, Fill, Members;
    std::vector<std::uint8_t> Survives;    // per cluster of the leaf
    std::vector<std::int64_t> Neighbours; // cluster << 32 | neighbouring cluster
  };

  /// ε in the normalised coordinates (under an error bound).
  double Bound() const { return this->Prepared.Bound; }
  /// Under a count target (the octree's own convention: a negative target is a bound).
  bool Counting() const { return !this->Options.Goal.Bounded(); }
  /// Whether §2.4 rules (a) or (b) limit the cells: then no cluster joins another.
  bool CellLimits() const
  {
    return (this->Options.MaximumCellSize > 0 && this->Options.MaximumCellSize < 1) ||
      this->Options.MaximumVerticesPerCell > 0;
  }
  void PrepareGeometry();
  void ClassifyVertices();
  void PrepareQuadrics();
  Plane BoundaryPlane(std::int32_t a, std::int32_t b, std::int32_t triangle, double& weight) const;
  bool InRange(std::int32_t v, std::int32_t begin, std::int32_t end) const
  {
    const std::int32_t p = this->Position[v];
    return p >= begin && p < end;
  }
  /// Whether vertex v belongs to cluster. Reads only the cluster's own leaf, so leaves that are
  /// clustered concurrently never read each other's vertices.
  bool InCluster(std::int32_t v, std::int32_t cluster) const
  {
    const OctreeNode& cell = this->Nodes[this->ClusterNodes[cluster]];
    return this->InRange(v, cell.Begin, cell.End) && this->VertexCluster[v] == cluster;
  }
  std::int32_t EvaluateLeaf(std::int32_t node, std::int32_t firstCluster, Scratch& scratch,
    double& key, bool& canSplit);
  /// One pass over the corners of a leaf's vertices. With forEntry, the vanishing error and the
  /// flip test of its heap entry; always, the triangles with three distinct clusters that have
  /// another corner in [countBegin, countEnd), each counted from its first corner there.
  LeafScan ScanLeaf(std::int32_t node, bool forEntry, std::int32_t countBegin,
    std::int32_t countEnd, Scratch& scratch) const;
  HeapEntry MakeEntry(std::int32_t node, double error, const LeafScan& scan, bool counting) const;
  void SetKey(HeapEntry& entry, bool counting) const;
  Quadric ClusterQuadric(const std::int32_t* members, std::int32_t count) const;
  Vec3 ClusterCentre(const std::int32_t* members, std::int32_t count) const;
  /// Where a cluster of the cell's may have its point: the cell within the input's box.
  Box Region(const OctreeNode& cell) const
  {
    const Vec3 half = Vec3::Constant(cell.Half);
    return { (cell.Center - half).cwiseMax(this->Bounds.Lower), (cell.Center + half).cwiseMin(this->Bounds.Upper) };
  }
  Vec3 PlaceRepresentative(const Quadric& q, const Vec3& centre, const Box& region,
    const std::int32_t* members, std::int32_t count) const;
  double ClusterError(const Vec3& x, const std::int32_t* members, std::int32_t count,
    bool folded, const Vec3* ring) const;
  bool Folded(const std::int32_t* members, std::int32_t count) const;
  /// Member(v) says whether vertex v belongs to the cluster of members.
  template <typename Member>
  bool RingCentre(const Member& member, const std::int32_t* members, std::int32_t count,
    Vec3& centre, double& radius) const;
  template <typename Member>
  bool ProtrudingTip(const Member& member, const std::int32_t* members, std::int32_t count,
    std::int32_t& tip, Vec3& ring) const;
  double Represent(std::int32_t cluster, const Quadric& q, const Box& region,
    const std::int32_t* members, std::int32_t count, Vec3& x) const;
  std::int32_t PartitionNode(std::int32_t node);
  /// A leaf just made, to be clustered and scanned by ClusterLeaves.
  struct NewLeaf
  {
    std::int32_t Node;
    std::int32_t FirstCluster;         // for now: one id per vertex of its range, reserved
    std::int32_t CountBegin, CountEnd; // ScanLeaf's count range
    double Key = 0.0;
    bool Splittable = false;
    LeafScan Scan;
  };
  std::int32_t ClusterLeaves(std::vector<NewLeaf>& leaves, std::int32_t first);
  void SplitLeaves(const std::vector<HeapEntry>& leaves, std::vector<HeapEntry>& children);
  std::int32_t MoveClusters(std::int32_t node, std::int32_t first);
  void UndoLastSplit();
  std::int32_t AddNode(OctreeNode node)
  {
    node.Serial = this->NextSerial++;
    this->Nodes.push_back(node);
    return static_cast<std::int32_t>(this->Nodes.size() - 1);
  }
  /// Whether a leaf of count clusters can be split into smaller ones.
  static bool CanSplit(const OctreeNode& cell, std::int32_t count)
  {
    return cell.End - cell.Begin >= 2 && count < cell.End - cell.Begin &&
      cell.Half > MinimumCellHalfSize && cell.Depth < MaximumDepth;
  }
  bool IsLeaf(const HeapEntry& entry) const
  {
    return entry.Node < static_cast<std::int32_t>(this->Nodes.size()) &&
      this->Nodes[entry.Node].Serial == entry.Serial && this->Nodes[entry.Node].ClusterCount > 0;
  }
  /// A triangle of the output: its id and its corners, in its orientation.
  struct Survivor
  {
    std::int32_t Triangle;
    std::array<std::int32_t, 3> Corners;
  };
  /// The output triangles when each vertex goes to the point of its label (a cluster, or what
  /// it joined or split into; see Settle).
  std::vector<Survivor> SurvivingTriangles(const std::vector<std::int32_t>& labels) const;
  /// Kinds of vertices a label holds (LabelKinds).
  enum LabelKind : std::uint8_t
  {
    OnBorder = 1,  // an open-border vertex
    NotSurface = 2 // a vertex where the input is not a surface (Irregular)
  };
  /// Per label below count, the LabelKind flags of its vertices.
  std::vector<std::uint8_t> LabelKinds(const std::vector<std::int32_t>& labels, std::size_t count) const;
  /// Each vertex's label once flaps joined their neighbours (see the body): its cluster, or the
  /// one its cluster joined.
  std::vector<std::int32_t> JoinFlaps(const std::vector<Survivor>& survivors) const;
  /// The cluster a flap joins, of its triangle's other corners (its own is corners[k]): the
  /// nearer point of a cluster that may take it (see JoinFlaps); −1 for none.
  std::int32_t FlapTarget(const std::array<std::int32_t, 3>& corners, int k) const;
  /// The label pairs (a < b) that an input border edge joins.
  Thirds BorderPairs(const std::vector<std::int32_t>& labels) const;
  /// The labels (below count) to split into pieces: one at each output edge that tears the
  /// surface (see the body).
  std::vector<std::int32_t> TornLabels(const std::vector<Survivor>& survivors,
    const std::vector<std::int32_t>& labels, const std::vector<std::uint8_t>& tried,
    std::vector<std::int32_t>& explode) const;
  /// Vertices to make pieces of their own so that no locked vertex is left without a triangle
  /// (see the body), sorted.
  std::vector<std::int32_t> BareLocks(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& labels) const;
  /// Splits the vertices of one label (members) into pieces that each merge without tearing the
  /// surface (see the body); new pieces take labels next, next + 1, ...
  std::size_t SplitIntoPieces(const std::vector<std::int32_t>& members, const std::vector<std::int32_t>& joined,
    const std::vector<std::uint8_t>& shown, std::vector<std::int32_t>& labels, std::int32_t& next) const;
  /// What Settle makes of the clustering: each vertex's cluster (its leaf cluster, or a piece
  /// split off one: ids from the number of clusters on, PieceNodes giving their leaves) and its
  /// label (the cluster whose point it goes to: its own, or the one a flap joined).
  struct Mending
  {
    std::vector<std::int32_t> Cluster, Label, PieceNodes;
  };
  /// Refines to the target, then joins flaps and splits what still tears into pieces (see the
  /// body); survivors are the output triangles. Returns false when aborted.
  bool Settle(std::int64_t target, std::vector<Survivor>& survivors, Mending& mending);
  /// One mending step: splits the torn labels into pieces, the exploded ones into single points,
  /// then makes each detached vertex a piece of its own.
  void MendOnce(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& torn,
    const std::vector<std::int32_t>& explode, const std::vector<std::int32_t>& detach,
    std::vector<std::uint8_t>& tried, Mending& mending) const;
  /// Keeps the largest connected group of the vertices (sorted) in their label; the others go
  /// back to their clusters' labels (each is a flap that joined, and may join again).
  void KeepLargestGroup(std::vector<std::int32_t>& vertices, const std::vector<std::int32_t>& clusters,
    std::vector<std::int32_t>& labels) const;
  /// Makes the pieces clusters of their own in their leaves, placed; owner: the cluster each
  /// cluster's vertices go to (−1 for those without a triangle). Under an error bound, where a
  /// cluster mending changed is left above it and its leaf can still be split, nothing is
  /// committed and the leaf is queued (false; see the body).
  bool CommitPieces(const Mending& mending, const std::vector<Survivor>& survivors,
    std::vector<std::int32_t>& owner);
  /// With a count target that clustering without tears overshoots, joins whole output points
  /// by half-edge collapses of the clustered mesh down to the target (see the body); owner and
  /// survivors as CommitPieces and SurvivingTriangles give them.
  /// Returns false when aborted (the context's progress, from 0.85 to 0.95 of the whole).
  bool FinishByCollapses(std::int64_t target, std::vector<Survivor>& survivors, std::vector<std::int32_t>& owner) const;
  /// The leaves to split next, best first (see Refine); empty when refinement is done.
  std::vector<HeapEntry>& NextBatch(std::int64_t target, double bound, double wanted);
  /// How many leaves to split together now (see Refine).
  double BatchSize(std::int64_t target, std::int64_t splits, std::int64_t startCount) const;
  enum class Fit : std::uint8_t
  {
    Kept,    // the split stays
    Skipped, // it was undone: the leaf stays as it is
    GiveUp   // too many splits were undone: refinement ends
  };
  Fit FitOvershoot(const std::vector<HeapEntry>& batch, std::int64_t ceiling,
    std::vector<HeapEntry>& children, int& rejections);
  bool Refine(std::int64_t target, double bound);
  /// Queues a splittable leaf at the corners of each triangle turned over now (see the body);
  /// false when there are none.
  bool QueueFlippedLeaves();
  /// Queues the leaf to be split whatever its error (and past a count target), if it can be
  /// split.
  bool QueueSplit(std::int32_t node);
  /// Queues the largest of the clusters' leaves that can be split (see QueueFlippedLeaves).
  bool QueueLargestSplit(const std::array<std::int32_t, 3>& clusters);
  /// The root and the top levels of the tree (see PlantTree's body), clustered and queued.
  void PlantTree(std::int64_t target);
  /// Refines to the target and returns the surviving triangles and the mended clustering (see
  /// Settle), or false when aborted.
  bool RefineToTarget(std::int64_t target, std::vector<Survivor>& survivors, Mending& mending);
  /// The output points being made (Finalize): each one's cluster, its vertices (CSR), the
  /// state of its representative and where it may lie (the box of its clusters' regions).
  struct OutputPoints
  {
    std::vector<std::int32_t> PointOf;   // vertex → output point, −1 for none
    std::vector<std::int32_t> ClusterOf; // output point → its cluster
    std::vector<std::int32_t> Offsets, Members;
    std::vector<Vec3> Position, Centre, Ring; // Ring: where a protruding one meets the rest
    std::vector<Box> Regions;
    std::vector<Quadric> FaceQuadric;
    std::vector<std::uint8_t> Folded, Protruding; // see Folded; Protruding keeps its tip
    std::int64_t Size() const { return static_cast<std::int64_t>(this->ClusterOf.size()); }
    const std::int32_t* MembersOf(std::int64_t p) const { return this->Members.data() + this->Offsets[p]; }
    std::int32_t Count(std::int64_t p) const { return this->Offsets[p + 1] - this->Offsets[p]; }
  };
  std::vector<std::int32_t> JoinStrandedCaps(std::vector<std::int32_t> owner) const;
  OutputPoints NumberPoints(const std::vector<std::int32_t>& owner) const;
  void PlaceRepresentatives(OutputPoints& points) const;
  void IterateSecondError(const std::vector<Survivor>& survivors, OutputPoints& points) const;
  /// Whether the survivor, its corners at these points, faces against its input triangle (§2.4).
  bool TurnedOver(const Survivor& survivor, const std::vector<std::int32_t>& pointOf,
    const std::vector<Vec3>& position) const;
  /// Puts back the points of an iteration's step that turn a triangle over (see the body).
  void UndoTurningMoves(const std::vector<Survivor>& survivors, const OutputPoints& points,
    std::vector<Vec3>& next) const;
  /// The usable input as it is, for a count target that keeps every triangle (a reduction of
  /// 0): each point its own cluster at its input coordinates, no error, as the collapse
  /// filters give it back.
  void WriteInput(OctreeClusteringResult& result) const;
  void WriteResult(const std::vector<Survivor>& survivors, const OutputPoints& points,
    OctreeClusteringResult& result) const;
  void Finalize(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& owner,
    OctreeClusteringResult& result);
  /// The outcome of the count: why it is where it is when it misses the target.
  void JudgeCount(OctreeClusteringResult& result) const;

  const TriangleMeshView& Input;
  const OctreeClusteringOptions& Options;
  const ExecutionContext& Context;
  /// Reports progress, never below what was reported before (refinement runs again when a
  /// split leaf turns a triangle over, or mending leaves a cluster above the bound).
  bool Report(double progress)
  {
    this->Reported = std::max(this->Reported, progress);
    return this->Context.Report(this->Reported);
  }
  double Reported = 0.0;
  /// The usable input, renumbered (every id below is one of its ids) and normalised so that
  /// the bounding-box diagonal is 1 and tolerances are relative.
  PreparedMesh Prepared;
  Outcome Start; // the prepared mesh's report
  bool KeepsEverything = false; // a count target of every usable triangle: the input as it is
  std::vector<Vec3> P;
  Box Bounds; // of P
  std::vector<HeapEntry> Batch; // NextBatch's
  VertexTriangleAdjacency Adjacency;
  // Unit normal of each triangle, zero for a zero-area one; its plane passes through each of its
  // corners, so walks around a vertex v measure distances to it from P[v].
  std::vector<Vec3> TriangleNormals;
  std::vector<double> TriangleAreas; // until the vertex quadrics are made
  std::vector<Quadric> VertexQuadrics;
  std::vector<double> VertexWeights; // a third of the incident area
  std::vector<Vec3> VertexAreaNormals; // a third of the incident area-weighted normals
  std::vector<Eigen::Vector3f> Facing; // per vertex: the unit mean of its normals (zero where they cancel)
  std::vector<std::uint8_t> BoundaryCorners; // per adjacency slot (BoundaryCorner flags)
  std::vector<std::uint8_t> BoundaryVertices; // per vertex: one of its slots has a flag
  std::vector<std::uint8_t> Irregular; // per vertex: the input is no surface there (SurfaceVertex)
  std::vector<std::uint8_t> Locked; // per vertex: a cluster of its own (locks of the options)
  std::vector<std::int32_t> Regions; // per vertex: clusters never join two (empty: one region)

  // Octree: every node owns a contiguous range of Order (the compact mesh's vertices, in its
  // spatial order within a leaf); Position is the inverse permutation.
  std::vector<std::int32_t> Order, Position;
  std::vector<OctreeNode> Nodes;
  std::priority_queue<HeapEntry> Heap;
  std::int64_t SurvivingCount = 0;

  // Clusters: ids grow as leaves split; VertexCluster holds the current one of each vertex.
  std::vector<std::int32_t> VertexCluster;
  std::vector<Vec3> ClusterPositions;
  std::vector<std::int32_t> ClusterNodes;

  // PartitionNode's scratch, indexed by Order position.
  std::vector<std::int32_t> Reordered;
  std::vector<std::uint8_t> Octants;

  // Every split, so that splits can be undone last-first: an overshooting one, or cheap late
  // ones that make room for a leaf of much larger error (see Refine).
  struct SplitRecord
  {
    HeapEntry Leaf; // as it was popped
    std::size_t Nodes, Clusters, Saved;
    std::int64_t SurvivingCount;
    std::int32_t FirstCluster, ClusterCount; // of the split leaf
  };
  std::vector<SplitRecord> Splits;
  std::vector<std::pair<std::int32_t, std::int32_t>> SavedClusters; // vertex, previous cluster
  std::int32_t NextSerial = 0;
};

// Templates that both OctreeClusters.cxx and OctreeOutput.cxx instantiate.

template <typename Member>
bool Clusterer::RingCentre(const Member& member, const std::int32_t* members, std::int32_t count,
  Vec3& centre, double& radius) const
{
  // Mean of the members with a neighbour in another cluster: where the cluster meets the rest.
  Vec3 sum = Vec3::Zero();
  std::int32_t ring = 0;
  for (std::int32_t i = 0; i < count; ++i)
  {
    const std::int32_t v = members[i];
    bool touches = false;
    for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v) && !touches; ++c)
    {
      touches = !member(c->Next) || !member(c->Previous);
    }
    if (touches)
    {
      sum += this->P[v];
      ++ring;
    }
  }
  if (ring == 0)
  {
    return false;
  }
  centre = sum / ring;
  radius = 0.0;
  for (std::int32_t i = 0; i < count; ++i)
  {
    const std::int32_t v = members[i];
    for (const Corner* c = this->Adjacency.Begin(v); c != this->Adjacency.End(v); ++c)
    {
      if (!member(c->Next) || !member(c->Previous))
      {
        radius = std::max(radius, (this->P[v] - centre).norm());
        break;
      }
    }
  }
  return true;
}

template <typename Member>
bool Clusterer::ProtrudingTip(const Member& member, const std::int32_t* members,
  std::int32_t count, std::int32_t& tip, Vec3& ring) const
{
  // A folded cluster (see Folded; the caller has checked) sticks out when its member farthest
  // from where it meets its neighbours (the ring) lies farther than the ring is wide: a leg, a
  // finger.
  double radius = 0.0;
  if (!this->RingCentre(member, members, count, ring, radius))
  {
    return false;
  }
  tip = members[0];
  for (std::int32_t i = 1; i < count; ++i)
  {
    if ((this->P[members[i]] - ring).squaredNorm() > (this->P[tip] - ring).squaredNorm())
    {
      tip = members[i];
    }
  }
  return (this->P[tip] - ring).norm() > radius;
}

// Called per corner by QueueFlippedLeaves (refinement) and UndoTurningMoves (output).
inline bool Clusterer::TurnedOver(const Survivor& survivor, const std::vector<std::int32_t>& pointOf,
  const std::vector<Vec3>& position) const
{
  const Vec3& normal = this->TriangleNormals[survivor.Triangle];
  const Vec3& a = position[pointOf[survivor.Corners[0]]];
  const Vec3& b = position[pointOf[survivor.Corners[1]]];
  const Vec3& c = position[pointOf[survivor.Corners[2]]];
  return normal != Vec3::Zero() && (b - a).cross(c - a).dot(normal) <= 0.0;
}

} // namespace octree
} // namespace meshsimp

#endif
