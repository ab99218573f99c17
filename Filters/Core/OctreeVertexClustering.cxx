// SPDX-License-Identifier: BSD-3-Clause
#include "OctreeVertexClustering.h"

#include "CollapseMesh.h"
#include "ProgressiveMesh.h"
#include "Quadric.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>
#include <map>
#include <queue>
#include <tuple>
#include <unordered_map>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;

/// Heap keys above every error: leaves that must be split whatever the target.
constexpr double ForcedSplitKey = std::numeric_limits<double>::infinity();
/// Under an error bound, leaves whose clustering flips a related triangle (§2.4): always split.
constexpr double FlipSplitKey = std::numeric_limits<double>::max();
/// Leaves smaller than this (in units of the bounding-box diagonal) hold coincident points.
constexpr double MinimumCellHalfSize = 1e-9;
constexpr int MaximumDepth = 40;
/// Leaves split together, and clustered concurrently, while a target is far (see Refine). The
/// result depends on it, never on the thread count.
constexpr std::size_t MaximumBatch = 32;
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

/// Whether one of the edges in thirds has a single third: it borders one triangle.
bool SingleThird(const Thirds& thirds)
{
  for (std::size_t k = 0; k < thirds.size(); ++k)
  {
    const bool alone = (k == 0 || thirds[k - 1].first != thirds[k].first) &&
      (k + 1 == thirds.size() || thirds[k + 1].first != thirds[k].first);
    if (alone)
    {
      return true;
    }
  }
  return false;
}

/**
 * Pieces of a label's vertices grown by merges that keep the surface a surface (see
 * Clusterer::SplitIntoPieces). The members (sorted) start as single points, labelled −2 − v (no
 * other label is negative); a piece grows from some vertices by merging its members' neighbours
 * among the members while the merge passes the link condition on the mesh as it stands (every
 * other vertex at its label's point): the labels that both the vertex and the piece neighbour
 * are exactly the third corners of their shared triangles, one or two; for two, not both on an
 * open border (which would pinch it) and no tetrahedron closed. A label without triangles
 * (shown false: a cap, which will join) is no neighbour that counts. Merges that pass keep a
 * surface a surface (Dey, Edelsbrunner, Guha and Nekhayev, "Topology preserving edge
 * contraction"), so the pieces tear nothing.
 */
class PieceGrowth
{
public:
  PieceGrowth(const VertexTriangleAdjacency& adjacency, const std::vector<std::int32_t>& members,
    const std::vector<std::uint8_t>& shown, std::vector<std::int32_t>& labels)
    : Adjacency(adjacency)
    , Members(members)
    , Shown(shown)
    , Labels(labels)
  {
    for (const std::int32_t v : members)
    {
      labels[v] = -2 - v;
    }
  }

  /// Whether v is a member in no piece yet.
  bool Single(std::int32_t v) const { return this->Labels[v] == -2 - v; }

  /// Grows the piece of the given label from [begin, end): candidates by the number of their
  /// triangles the piece holds, most first (compact pieces leave few hidden cycles); a vertex
  /// that fails is tried again when that number grows.
  void Grow(std::int32_t label, const std::int32_t* begin, const std::int32_t* end)
  {
    this->Label = label;
    this->Near.clear();
    this->Piece.clear();
    this->TrackingThirds = false;
    std::priority_queue<std::pair<std::int32_t, std::int32_t>> candidates;
    const auto add = [&](std::int32_t w) {
      this->Merge(w);
      for (const Corner* c = this->Adjacency.Begin(w); c != this->Adjacency.End(w); ++c)
      {
        for (const std::int32_t u : { c->Next, c->Previous })
        {
          if (this->Single(u)) // only members are single: other labels are not negative
          {
            candidates.emplace(this->Held(u), -u);
          }
        }
      }
    };
    std::for_each(begin, end, add);
    for (; !candidates.empty(); candidates.pop())
    {
      const std::int32_t w = -candidates.top().second;
      if (this->Single(w) && candidates.top().first == this->Held(w) && this->Mergeable(w))
      {
        add(w);
      }
    }
  }

private:
  /// Whether a label keeps triangles. Labels past Shown are pieces made by earlier splits in the
  /// same pass: like caps, they count as neighbours from the next pass on, when Shown has them
  /// (reading past Shown was a heap overflow, found by AddressSanitizer).
  bool IsShown(std::int32_t label) const
  {
    return static_cast<std::size_t>(label) < this->Shown.size() && this->Shown[label] != 0;
  }

  /// How many of w's triangles the piece holds.
  std::int32_t Held(std::int32_t w) const
  {
    std::int32_t count = 0;
    for (const Corner* c = this->Adjacency.Begin(w); c != this->Adjacency.End(w); ++c)
    {
      count += this->Labels[c->Next] == this->Label || this->Labels[c->Previous] == this->Label ? 1 : 0;
    }
    return count;
  }

  /// The triangle (a, b, c) of labels, as the piece sees it: its other labels counted sign times,
  /// and, once tracked (TrackThirds), each of them as the third of the piece's edge to the other.
  void Tally(std::int32_t a, std::int32_t b, std::int32_t c, std::int32_t sign)
  {
    if ((a == this->Label || b == this->Label || c == this->Label) && a != b && b != c && a != c)
    {
      std::array<std::int32_t, 2> others;
      int n = 0;
      for (const std::int32_t x : { a, b, c })
      {
        this->Near[x] += x != this->Label ? sign : 0;
        if (x != this->Label)
        {
          others[n++] = x;
        }
      }
      if (this->TrackingThirds)
      {
        this->CountThird(others[0], others[1], sign);
        this->CountThird(others[1], others[0], sign);
      }
    }
  }

  /// Labels are negative for single members: their bits, unsigned, make the key.
  static std::uint64_t PairKey(std::int32_t x, std::int32_t y)
  {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32 |
      static_cast<std::uint32_t>(y);
  }

  /// The piece's edges and their thirds, from the first time Mergeable asks for them (most
  /// pieces never need them) and then kept up by Tally as the piece grows: what EdgeThirds gives
  /// over all its vertices, with triangle counts, without rescanning them at each ask.
  void TrackThirds()
  {
    this->PieceThirds.clear();
    this->ThirdsPerEdge.clear();
    this->SingleThirdEdges = 0;
    for (const std::int32_t u : this->Piece)
    {
      for (const Corner* c = this->Adjacency.Begin(u); c != this->Adjacency.End(u); ++c)
      {
        const std::int32_t x = this->Labels[c->Next], y = this->Labels[c->Previous];
        if (x != y && x != this->Label && y != this->Label)
        {
          this->CountThird(x, y, 1);
          this->CountThird(y, x, 1);
        }
      }
    }
    this->TrackingThirds = true;
  }

  /// The piece's edge to x gains (sign 1) or loses (−1) a triangle whose third is y: the pairs
  /// with a positive count, and how many of its edges have a single third.
  void CountThird(std::int32_t x, std::int32_t y, std::int32_t sign)
  {
    std::int32_t& count = this->PieceThirds[PairKey(x, y)];
    const bool had = count > 0;
    count += sign;
    if (had == (count > 0))
    {
      return;
    }
    std::int32_t& thirds = this->ThirdsPerEdge[x];
    this->SingleThirdEdges -= thirds == 1 ? 1 : 0;
    thirds += had ? -1 : 1;
    this->SingleThirdEdges += thirds == 1 ? 1 : 0;
  }

  /// Whether the piece's edge to pair.first has the third pair.second: a triangle holds the
  /// piece and both.
  bool PieceHasThirds(const std::pair<std::int32_t, std::int32_t>& pair) const
  {
    const auto found = this->PieceThirds.find(PairKey(pair.first, pair.second));
    return found != this->PieceThirds.end() && found->second > 0;
  }

  void Merge(std::int32_t w)
  {
    for (const Corner* c = this->Adjacency.Begin(w); c != this->Adjacency.End(w); ++c)
    {
      if (this->Labels[w] != this->Label)
      {
        this->Tally(this->Labels[w], this->Labels[c->Next], this->Labels[c->Previous], -1);
      }
      this->Tally(this->Label, this->Labels[c->Next], this->Labels[c->Previous], 1);
    }
    this->Labels[w] = this->Label;
    this->Piece.push_back(w);
  }

  bool Mergeable(std::int32_t w)
  {
    this->EdgeThirds(w, this->Ends);
    const Thirds& ends = this->Ends;
    const auto first = std::lower_bound(ends.begin(), ends.end(),
      std::make_pair(this->Label, std::numeric_limits<std::int32_t>::min()));
    auto last = first;
    while (last != ends.end() && last->first == this->Label)
    {
      ++last;
    }
    for (const auto& end : ends)
    {
      const auto found = this->Near.find(end.first);
      if (end.first != this->Label && found != this->Near.end() && found->second > 0 &&
        (end.first < 0 || this->IsShown(end.first)) &&
        std::none_of(first, last, [&end](const auto& e) { return e.second == end.first; }))
      {
        return false; // a common neighbour beyond the shared triangles
      }
    }
    if (last - first != 2)
    {
      return last - first == 1;
    }
    const std::pair<std::int32_t, std::int32_t> opposite(first->second, (first + 1)->second);
    const bool closesTetrahedron = std::binary_search(ends.begin(), ends.end(), opposite);
    if (!closesTetrahedron && !SingleThird(ends))
    {
      return true;
    }
    if (!this->TrackingThirds)
    {
      this->TrackThirds();
    }
    return !(SingleThird(ends) && this->SingleThirdEdges > 0) &&
      !(closesTetrahedron && this->PieceHasThirds(opposite));
  }

  /// The edges at u's point with their thirds: each triangle of u's that keeps three labels
  /// gives its two edges there its third corners. Sorted, unique.
  void EdgeThirds(std::int32_t u, Thirds& thirds) const
  {
    thirds.clear();
    for (const Corner* c = this->Adjacency.Begin(u); c != this->Adjacency.End(u); ++c)
    {
      const std::int32_t x = this->Labels[c->Next], y = this->Labels[c->Previous];
      if (x != y && x != this->Labels[u] && y != this->Labels[u])
      {
        thirds.emplace_back(x, y);
        thirds.emplace_back(y, x);
      }
    }
    std::sort(thirds.begin(), thirds.end());
    thirds.erase(std::unique(thirds.begin(), thirds.end()), thirds.end());
  }

  const VertexTriangleAdjacency& Adjacency;
  const std::vector<std::int32_t>& Members;
  const std::vector<std::uint8_t>& Shown;
  std::vector<std::int32_t>& Labels;
  std::int32_t Label = 0;                              // the growing piece's
  std::vector<std::int32_t> Piece;                     // its vertices
  std::unordered_map<std::int32_t, std::int32_t> Near; // its neighbours: their triangles with it
  Thirds Ends; // Mergeable's: the candidate's edges and their thirds
  // The piece's edges and their thirds (TrackThirds), kept up by CountThird: the triangles of
  // each (neighbour, third) pair, the thirds of each neighbour, and how many neighbours have one.
  std::unordered_map<std::uint64_t, std::int32_t> PieceThirds;
  std::unordered_map<std::int32_t, std::int32_t> ThirdsPerEdge;
  std::int32_t SingleThirdEdges = 0;
  bool TrackingThirds = false;
};

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

void Clusterer::SetKey(HeapEntry& entry, bool counting) const
{
  // The leaf's error, or the error of clusters it would lose. A leaf that flips a neighbouring
  // triangle (§2.4) is always split under an error bound; under a count target, where every
  // split spends triangles, it goes as if its error were 10 % larger.
  if (entry.Key == ForcedSplitKey)
  {
    return;
  }
  const double base = std::max(entry.Error, entry.Vanishing);
  entry.Key = !entry.Flipped ? base : counting ? 1.1 * base + MinimumCellHalfSize : FlipSplitKey;
}

HeapEntry Clusterer::MakeEntry(
  std::int32_t node, double error, const LeafScan& scan, bool counting) const
{
  HeapEntry entry{ error, this->Nodes[node].Half, node, this->Nodes[node].Serial, error, 0.0,
    false };
  if (error != ForcedSplitKey)
  {
    entry.Vanishing = scan.Vanishing;
    entry.Flipped = scan.Flipped;
    this->SetKey(entry, counting);
  }
  return entry;
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

std::int32_t Clusterer::PartitionNode(std::int32_t node)
{
  // Distribute the node's vertices to its octants, keeping their order (stable counting sort),
  // and append the non-empty children to Nodes. Returns the id of the first child.
  const OctreeNode cell = this->Nodes[node];
  const std::int32_t begin = cell.Begin, end = cell.End;
  auto octant = [&](std::int32_t v) {
    const Vec3& p = this->P[v];
    return (p.x() > cell.Center.x() ? 1 : 0) | (p.y() > cell.Center.y() ? 2 : 0) |
      (p.z() > cell.Center.z() ? 4 : 0);
  };
  std::array<std::int32_t, 9> start{};
  for (std::int32_t i = begin; i < end; ++i)
  {
    this->Octants[i] = static_cast<std::uint8_t>(octant(this->Order[i]));
    ++start[this->Octants[i] + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::array<std::int32_t, 8> fill;
  std::copy(start.begin(), start.begin() + 8, fill.begin());
  for (std::int32_t i = begin; i < end; ++i)
  {
    this->Reordered[begin + fill[this->Octants[i]]++] = this->Order[i];
  }
  for (std::int32_t i = begin; i < end; ++i)
  {
    this->Order[i] = this->Reordered[i];
    this->Position[this->Order[i]] = i;
  }
  const std::int32_t first = static_cast<std::int32_t>(this->Nodes.size());
  const double half = 0.5 * cell.Half;
  for (int o = 0; o < 8; ++o)
  {
    if (start[o + 1] == start[o])
    {
      continue;
    }
    OctreeNode child;
    child.Center = cell.Center +
      half * Vec3((o & 1) ? 1.0 : -1.0, (o & 2) ? 1.0 : -1.0, (o & 4) ? 1.0 : -1.0);
    child.Half = half;
    child.Begin = begin + start[o];
    child.End = begin + start[o + 1];
    child.Depth = cell.Depth + 1;
    child.FirstCluster = child.ClusterCount = 0;
    this->AddNode(child);
  }
  return first;
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

void Clusterer::SplitLeaves(const std::vector<HeapEntry>& leaves, std::vector<HeapEntry>& children)
{
  // The leaves are split as if one after the other, in their order: the same nodes, cluster
  // ids, split log and triangle count. A child's gain counts the triangles with two or more
  // corners in its split leaf: they were degenerate before, the others keep their status, so
  // the gains of all children add up.
  std::vector<NewLeaf> made;
  std::vector<std::size_t> firstChild(leaves.size());
  const std::size_t firstRecord = this->Splits.size();
  const std::int32_t batchBase = static_cast<std::int32_t>(this->ClusterPositions.size());
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    const std::int32_t node = leaves[l].Node;
    const OctreeNode cell = this->Nodes[node];
    this->Splits.push_back({ leaves[l], this->Nodes.size(), 0, this->SavedClusters.size(), 0,
      cell.FirstCluster, cell.ClusterCount });
    for (std::int32_t i = cell.Begin; i < cell.End; ++i)
    {
      this->SavedClusters.emplace_back(this->Order[i], this->VertexCluster[this->Order[i]]);
    }
    this->Nodes[node].ClusterCount = 0; // no longer a leaf
    const std::int32_t first = this->PartitionNode(node);
    const std::int32_t last = static_cast<std::int32_t>(this->Nodes.size());
    const std::int32_t base = static_cast<std::int32_t>(this->ClusterPositions.size());
    this->ClusterPositions.resize(base + (cell.End - cell.Begin));
    this->ClusterNodes.resize(base + (cell.End - cell.Begin));
    firstChild[l] = made.size();
    for (std::int32_t child = first; child < last; ++child)
    {
      NewLeaf leaf;
      leaf.Node = child;
      leaf.FirstCluster = base + (this->Nodes[child].Begin - cell.Begin);
      leaf.CountBegin = cell.Begin;
      leaf.CountEnd = cell.End;
      made.push_back(leaf);
    }
  }
  this->ClusterLeaves(made, batchBase);

  children.clear();
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    SplitRecord& record = this->Splits[firstRecord + l];
    record.Clusters = this->Nodes[made[firstChild[l]].Node].FirstCluster;
    record.SurvivingCount = this->SurvivingCount;
    const std::size_t end = l + 1 < leaves.size() ? firstChild[l + 1] : made.size();
    for (std::size_t k = firstChild[l]; k < end; ++k)
    {
      this->SurvivingCount += made[k].Scan.Surviving;
      if (made[k].Splittable)
      {
        children.push_back(this->MakeEntry(
          made[k].Node, made[k].Key, made[k].Scan, this->Counting()));
      }
    }
  }
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

void Clusterer::UndoLastSplit()
{
  // The nodes and clusters made after the split are exactly those past its marks, since
  // splits are undone last-first; their heap entries become stale (IsLeaf).
  const SplitRecord record = this->Splits.back();
  this->Splits.pop_back();
  for (std::size_t k = record.Saved; k < this->SavedClusters.size(); ++k)
  {
    this->VertexCluster[this->SavedClusters[k].first] = this->SavedClusters[k].second;
  }
  this->SavedClusters.resize(record.Saved);
  this->Nodes.resize(record.Nodes);
  this->ClusterPositions.resize(record.Clusters);
  this->ClusterNodes.resize(record.Clusters);
  this->SurvivingCount = record.SurvivingCount;
  this->Nodes[record.Leaf.Node].FirstCluster = record.FirstCluster;
  this->Nodes[record.Leaf.Node].ClusterCount = record.ClusterCount;
}

double Clusterer::BatchSize(std::int64_t target, std::int64_t splits, std::int64_t startCount) const
{
  // Several leaves are split together, their children clustered concurrently, when that hardly
  // changes which leaves get split: the batch is a small share of the leaves waiting (1/16) and,
  // with a count target, of the room left below 80 % of it (a quarter, judged by the mean gain
  // of the splits so far). Near a count target leaves go one at a time, so that single splits
  // can be undone and traded.
  double wanted = std::min(static_cast<double>(MaximumBatch), this->Heap.size() / 16.0);
  if (target >= 0)
  {
    const double meanGain =
      splits > 0 ? static_cast<double>(this->SurvivingCount - startCount) / splits : 0.0;
    const double room = 0.8 * static_cast<double>(target) - static_cast<double>(this->SurvivingCount);
    wanted = meanGain > 0.0 ? std::min(wanted, 0.25 * room / meanGain) : 1.0;
  }
  return std::max(wanted, 1.0);
}

std::vector<HeapEntry>& Clusterer::NextBatch(std::int64_t target, double bound, double wanted)
{
  // The next leaves to split, best first: forced splits always; others while the count is
  // below the target, or while their error is above the bound.
  std::vector<HeapEntry>& batch = this->Batch;
  batch.clear();
  const bool counting = target >= 0;
  while (static_cast<double>(batch.size()) < std::floor(wanted) && !this->Heap.empty())
  {
    const HeapEntry top = this->Heap.top();
    const bool forced = top.Key == ForcedSplitKey;
    if (!forced && counting && this->SurvivingCount >= target)
    {
      break;
    }
    if (!forced && !counting && top.Key <= bound)
    {
      break; // every leaf left is within the bound and flips nothing
    }
    this->Heap.pop();
    if (!this->IsLeaf(top) ||
      std::any_of(batch.begin(), batch.end(), [&](const HeapEntry& e) { return e.Node == top.Node; }))
    {
      continue; // its node was undone, or it is already taken
    }
    if (!forced && top.Vanishing > top.Error)
    {
      // Neighbours split since the leaf was queued may have brought its clusters back.
      HeapEntry entry = top;
      Scratch scratch;
      entry.Vanishing = this->ScanLeaf(top.Node, true, 0, 0, scratch).Vanishing;
      this->SetKey(entry, counting);
      if (entry.Key < top.Key)
      {
        this->Heap.push(entry);
        continue;
      }
    }
    batch.push_back(top);
  }
  return batch;
}

Clusterer::Fit Clusterer::FitOvershoot(const std::vector<HeapEntry>& batch, std::int64_t ceiling,
  std::vector<HeapEntry>& children, int& rejections)
{
  // A single split beyond the count's ceiling (the target's tolerance) is undone; then the
  // latest splits of far smaller error (a third or less) are undone, last first, until it fits,
  // and it is split again; failing that, smaller leaves are tried instead. A split of a
  // clustering without triangles stays: no count is nearer the target than the first.
  const HeapEntry& top = batch.back();
  if (this->Splits.back().SurvivingCount == 0)
  {
    return Fit::Kept;
  }
  const std::int64_t gain = this->SurvivingCount - this->Splits.back().SurvivingCount;
  this->UndoLastSplit();
  if (++rejections > 64)
  {
    return Fit::GiveUp;
  }
  const OctreeNode& cell = this->Nodes[top.Node];
  std::size_t undo = this->Splits.size();
  std::int64_t count = this->SurvivingCount;
  while (undo > 0 && count + gain > ceiling)
  {
    const SplitRecord& record = this->Splits[undo - 1];
    const OctreeNode& other = this->Nodes[record.Leaf.Node];
    const bool ancestor = other.Begin <= cell.Begin && cell.End <= other.End;
    if (ancestor || record.Leaf.Key == ForcedSplitKey || record.Leaf.Key * 3.0 > top.Key)
    {
      break;
    }
    count = record.SurvivingCount;
    --undo;
  }
  if (count + gain > ceiling)
  {
    return Fit::Skipped; // the leaf stays as it is
  }
  while (this->Splits.size() > undo)
  {
    const HeapEntry undone = this->Splits.back().Leaf;
    this->UndoLastSplit();
    this->Heap.push(undone);
  }
  this->SplitLeaves(batch, children);
  if (this->SurvivingCount > ceiling)
  {
    this->UndoLastSplit();
    return Fit::Skipped;
  }
  return Fit::Kept;
}

bool Clusterer::Refine(std::int64_t target, double bound)
{
  // Leaves are split in decreasing order of their key until the count reaches the target
  // (target >= 0) or every leaf is within the bound.
  std::vector<HeapEntry> children;
  int rejections = 0;
  std::int64_t splits = 0, reported = 0;
  const std::int64_t startCount = this->SurvivingCount;
  const double firstKey = this->Heap.empty() ? 0.0 : this->Heap.top().Key;
  const std::int64_t ceiling = target + this->Options.Goal.Slack(target);
  while (!this->Heap.empty())
  {
    const std::vector<HeapEntry>& batch = this->NextBatch(target, bound, this->BatchSize(target, splits, startCount));
    if (batch.empty())
    {
      break;
    }
    const HeapEntry top = batch.back();
    this->SplitLeaves(batch, children);
    if (batch.size() == 1 && target >= 0 && top.Key != ForcedSplitKey && this->SurvivingCount > ceiling)
    {
      const Fit fit = this->FitOvershoot(batch, ceiling, children, rejections);
      if (fit == Fit::GiveUp)
      {
        break;
      }
      if (fit == Fit::Skipped)
      {
        continue;
      }
    }
    for (const HeapEntry& child : children)
    {
      this->Heap.push(child);
    }
    splits += static_cast<std::int64_t>(batch.size());
    if (splits - reported < 256)
    {
      continue;
    }
    reported = splits;
    double done = 0.0;
    if (target > 0)
    {
      done = static_cast<double>(this->SurvivingCount) / target;
    }
    else if (target < 0 && top.Key < FlipSplitKey && firstKey < FlipSplitKey && top.Key > bound &&
      firstKey > bound)
    {
      done = std::log(firstKey / top.Key) / std::log(firstKey / bound);
    }
    if (!this->Report(0.15 + 0.7 * std::min(std::max(done, 0.0), 1.0)))
    {
      return false;
    }
  }
  return true;
}

bool Clusterer::QueueSplit(std::int32_t node)
{
  const OctreeNode& cell = this->Nodes[node];
  if (!CanSplit(cell, cell.ClusterCount))
  {
    return false;
  }
  // Its error is not known here: the key alone makes it split, under a bound (SetKey), and past
  // a count target (NextBatch).
  this->Heap.push({ this->Counting() ? ForcedSplitKey : FlipSplitKey, cell.Half, node, cell.Serial, 0.0, 0.0, true });
  return true;
}

bool Clusterer::QueueLargestSplit(const std::array<std::int32_t, 3>& clusters)
{
  // The largest of their leaves that can split (the first of equal ones).
  std::int32_t largest = -1;
  for (const std::int32_t cluster : clusters)
  {
    const std::int32_t node = this->ClusterNodes[cluster];
    const OctreeNode& cell = this->Nodes[node];
    if (CanSplit(cell, cell.ClusterCount) && (largest < 0 || cell.Half > this->Nodes[largest].Half))
    {
      largest = node;
    }
  }
  return largest >= 0 && this->QueueSplit(largest);
}

bool Clusterer::QueueFlippedLeaves()
{
  // §2.4: a leaf that turns a triangle over is split (SetKey), but a leaf's flag is set when
  // the leaf is made and tests only triangles with one corner in it. A neighbour split later,
  // or one that cannot be split (a lone vertex, kept where it is), can still leave a triangle
  // turned over: the largest of its corners' leaves is queued to be split (one is enough to
  // move a corner; splitting all three spends more triangles, see OctreeVertexClustering.md).
  // Each triangle of three clusters is read at its lowest corner.
  // With a count target these splits pass the target, and quadric collapses take the clustered
  // mesh back to it (FinishByCollapses, multiphase simplification): so not where the input is no
  // surface at a corner (collapses are refused there, the splits would only add triangles), and
  // not with cell limits (Settle: nothing finishes then).
  const bool counting = this->Counting();
  bool queued = false;
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(this->P.size()); ++v)
  {
    const std::int32_t c0 = this->VertexCluster[v];
    for (const Corner* corner = this->Adjacency.Begin(v); corner != this->Adjacency.End(v); ++corner)
    {
      const std::int32_t c1 = this->VertexCluster[corner->Next], c2 = this->VertexCluster[corner->Previous];
      if (v > corner->Next || v > corner->Previous || c0 == c1 || c1 == c2 || c0 == c2 ||
        (counting && (this->Irregular[v] || this->Irregular[corner->Next] || this->Irregular[corner->Previous])) ||
        !this->TurnedOver({ corner->Triangle, { v, corner->Next, corner->Previous } }, this->VertexCluster,
          this->ClusterPositions))
      {
        continue;
      }
      queued = this->QueueLargestSplit({ c0, c1, c2 }) || queued;
    }
  }
  return queued;
}

std::vector<Clusterer::Survivor> Clusterer::SurvivingTriangles(const std::vector<std::int32_t>& labels) const
{
  // Triangles with three distinct labels, minus duplicates (the same three labels in either
  // orientation): the lowest input triangle of each set survives. In input triangle order. The
  // triangle list itself is gone by now: each triangle is read at its lowest corner.
  struct Key
  {
    std::array<std::int32_t, 3> Clusters;
    std::int32_t InputTriangle;
    Survivor Triangle;
    bool operator<(const Key& o) const
    {
      // One pass over the fields: std::array's != goes through memcmp (libstdc++).
      return std::tie(this->Clusters[0], this->Clusters[1], this->Clusters[2], this->InputTriangle) <
        std::tie(o.Clusters[0], o.Clusters[1], o.Clusters[2], o.InputTriangle);
    }
  };
  // Gathered per chunk of vertices (in parallel), then joined in chunk order.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  constexpr std::int64_t ChunkSize = 4096;
  std::vector<std::vector<Key>> chunks((n + ChunkSize - 1) / ChunkSize);
  this->Context.For(static_cast<std::int64_t>(chunks.size()), [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t chunk = b; chunk < e; ++chunk)
    {
      const std::int32_t last = static_cast<std::int32_t>(std::min(n, (chunk + 1) * ChunkSize));
      for (std::int32_t v = static_cast<std::int32_t>(chunk * ChunkSize); v < last; ++v)
      {
        const std::int32_t c0 = labels[v];
        for (const Corner* corner = this->Adjacency.Begin(v); corner != this->Adjacency.End(v); ++corner)
        {
          // Tested without branches (& rather than &&): the tests are unpredictable, the rare
          // survivors are not.
          std::array<std::int32_t, 3> c = { c0, labels[corner->Next], labels[corner->Previous] };
          const bool lowest = (v < corner->Next) & (v < corner->Previous);
          if (lowest & (c[0] != c[1]) & (c[1] != c[2]) & (c[0] != c[2]))
          {
            std::sort(c.begin(), c.end());
            chunks[chunk].push_back({ c, this->Prepared.Mesh.InputTriangle[corner->Triangle],
              { corner->Triangle, { v, corner->Next, corner->Previous } } });
          }
        }
      }
    }
  }, 8 * static_cast<std::int64_t>(this->Adjacency.Corners.size()));
  std::vector<Key> keys;
  for (const std::vector<Key>& chunk : chunks)
  {
    keys.insert(keys.end(), chunk.begin(), chunk.end());
  }
  std::sort(keys.begin(), keys.end());
  std::vector<Survivor> survivors;
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    if (i == 0 || keys[i].Clusters != keys[i - 1].Clusters)
    {
      survivors.push_back(keys[i].Triangle);
    }
  }
  std::sort(survivors.begin(), survivors.end(), [this](const Survivor& a, const Survivor& b) {
    return this->Prepared.Mesh.InputTriangle[a.Triangle] < this->Prepared.Mesh.InputTriangle[b.Triangle];
  });
  return survivors;
}

std::vector<std::uint8_t> Clusterer::LabelKinds(const std::vector<std::int32_t>& labels, std::size_t count) const
{
  std::vector<std::uint8_t> kinds(count, 0);
  for (std::size_t v = 0; v < this->P.size(); ++v)
  {
    if (static_cast<std::size_t>(labels[v]) < count)
    {
      kinds[labels[v]] |= (this->BoundaryVertices[v] ? OnBorder : 0) | (this->Irregular[v] ? NotSurface : 0);
    }
  }
  return kinds;
}

std::int32_t Clusterer::FlapTarget(const std::array<std::int32_t, 3>& corners, int k) const
{
  // Joined, the flap's vertices go to the target's point: one farther from its own point than
  // half its cell's edge would cost more than the cell's error, so the flap is split as a tear.
  const Vec3& from = this->ClusterPositions[this->VertexCluster[corners[k]]];
  const double reach = this->Nodes[this->ClusterNodes[this->VertexCluster[corners[k]]]].Half;
  std::int32_t target = -1;
  for (const int j : { (k + 1) % 3, (k + 2) % 3 })
  {
    const std::int32_t o = this->VertexCluster[corners[j]];
    const bool sameRegion = this->Regions.empty() || this->Regions[corners[j]] == this->Regions[corners[k]];
    const bool nearer = target < 0 ||
      (this->ClusterPositions[o] - from).squaredNorm() < (this->ClusterPositions[target] - from).squaredNorm();
    const bool within = (this->ClusterPositions[o] - from).norm() <= reach;
    target = !this->Locked[corners[j]] && sameRegion && nearer && within ? o : target;
  }
  return target;
}

std::vector<std::int32_t> Clusterer::JoinFlaps(const std::vector<Survivor>& survivors) const
{
  // A cluster that keeps a single triangle (c, x, y) is a flap: its two edges have that
  // triangle alone, and the edge (x, y) one more than the surface has there (an island of a
  // coarse cell poking into another, a sliver between two clusters, the end of a thin part) -
  // unless the input is no surface there, or both edges stand for open borders (a corner, not
  // an island: a triangle that all three of its clusters keep alone is no corner). With
  // a count target it joins x or y, whichever point is nearer its own (not a locked point, nor
  // one of another region): its triangle goes, and (x, y) keeps the others. Only that triangle
  // changes, so x and y are looked at again (the lowest cluster first), unless they took a flap
  // (a thin part is not eaten from its end); one that loses its last triangle is left without
  // (a stranded cap, see JoinStrandedCaps). Under an error bound or cell limits nothing joins:
  // a joined point's error is not bounded, nor its extent.
  std::vector<std::int32_t> labels = this->VertexCluster;
  if (!this->Counting() || this->CellLimits())
  {
    return labels; // a joined flap would cross its cell's limits
  }
  const std::int32_t count = static_cast<std::int32_t>(this->ClusterPositions.size());
  std::vector<std::int32_t> offsets(count + 1, 0);
  for (const Survivor& survivor : survivors)
  {
    for (const std::int32_t v : survivor.Corners)
    {
      ++offsets[labels[v] + 1];
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<std::int32_t> incident(offsets.back()), fill(offsets.begin(), offsets.end() - 1), triangles(count), joined(count);
  for (std::size_t t = 0; t < survivors.size(); ++t)
  {
    for (const std::int32_t v : survivors[t].Corners)
    {
      incident[fill[labels[v]]++] = static_cast<std::int32_t>(t);
    }
  }
  for (std::int32_t c = 0; c < count; ++c)
  {
    triangles[c] = offsets[c + 1] - offsets[c];
    joined[c] = c;
  }
  const std::vector<std::uint8_t> kinds = this->LabelKinds(labels, count);
  const Thirds borders = this->BorderPairs(labels);
  const auto border = [&borders](std::int32_t a, std::int32_t b) {
    return std::binary_search(borders.begin(), borders.end(), std::make_pair(std::min(a, b), std::max(a, b)));
  };
  std::vector<std::uint8_t> alive(survivors.size(), 1), took(count, 0);
  const auto isFlap = [&](std::int32_t c) {
    return joined[c] == c && triangles[c] == 1 && !(kinds[c] & NotSurface) && !took[c];
  };
  std::priority_queue<std::int32_t, std::vector<std::int32_t>, std::greater<std::int32_t>> flaps;
  for (std::int32_t c = 0; c < count; ++c)
  {
    if (isFlap(c))
    {
      flaps.push(c);
    }
  }
  for (; !flaps.empty(); flaps.pop())
  {
    const std::int32_t c = flaps.top();
    const std::int32_t* t = incident.data() + offsets[c];
    while (isFlap(c) && !alive[*t])
    {
      ++t; // a flap keeps one
    }
    // The triangle's corners: c's (k), then the candidates'.
    const std::array<std::int32_t, 3>& corners = survivors[*t].Corners;
    const int k = labels[corners[0]] == c ? 0 : labels[corners[1]] == c ? 1 : 2;
    const std::int32_t x = labels[corners[(k + 1) % 3]], y = labels[corners[(k + 2) % 3]];
    const bool island = triangles[x] == 1 && triangles[y] == 1; // a piece of border cut off
    if (!isFlap(c) || this->Locked[corners[k]] || (border(c, x) && border(c, y) && !island))
    {
      continue;
    }
    const std::int32_t target = this->FlapTarget(corners, k);
    if (target >= 0)
    {
      joined[c] = target;
      took[target] = 1;
      alive[*t] = 0;
      for (const std::int32_t o : { x, y })
      {
        if (--triangles[o] == 1 && isFlap(o))
        {
          flaps.push(o);
        }
      }
    }
  }
  for (std::int32_t& l : labels)
  {
    while (joined[l] != l)
    {
      l = joined[l];
    }
  }
  return labels;
}

Thirds Clusterer::BorderPairs(const std::vector<std::int32_t>& labels) const
{
  Thirds borders;
  for (std::size_t v = 0; v < this->P.size(); ++v)
  {
    const std::uint8_t* flags = this->BoundaryCorners.data() + this->Adjacency.Offsets[v];
    for (const Corner* c = this->Adjacency.Begin(v); this->BoundaryVertices[v] && c != this->Adjacency.End(v); ++c, ++flags)
    {
      const std::int32_t a = labels[v], b = labels[c->Next];
      if ((*flags & OutgoingBoundaryEdge) && a != b)
      {
        borders.emplace_back(std::min(a, b), std::max(a, b));
      }
    }
  }
  std::sort(borders.begin(), borders.end());
  borders.erase(std::unique(borders.begin(), borders.end()), borders.end());
  return borders;
}

std::vector<std::int32_t> Clusterer::TornLabels(const std::vector<Survivor>& survivors,
  const std::vector<std::int32_t>& labels, const std::vector<std::uint8_t>& tried,
  std::vector<std::int32_t>& explode) const
{
  const std::size_t count = tried.size();
  // Each output edge (a, b) carries one triangle per distinct third label. Where the input is a
  // surface (neither a nor b holds a vertex where it is not), it must keep two, or one where an
  // input border edge joins a and b (it stands for an open border): else the output gets an
  // open or a non-manifold edge that the input did not have. Of such an edge's labels, the one
  // of most vertices is split (a single vertex cannot be): a, b, or else one of the thirds.
  const Thirds borders = this->BorderPairs(labels);
  std::vector<std::int32_t> sizes(count, 0);
  for (std::size_t v = 0; v < this->P.size(); ++v)
  {
    ++sizes[labels[v]];
  }
  // (a < b, third), sorted: (a, b) packed in one key, which sorts as the pair does.
  struct Edge
  {
    std::uint64_t Ends;
    std::int32_t Third;
    std::int32_t A() const { return static_cast<std::int32_t>(this->Ends >> 32); }
    std::int32_t B() const { return static_cast<std::int32_t>(this->Ends & 0xffffffffu); }
    bool operator<(const Edge& o) const { return std::tie(this->Ends, this->Third) < std::tie(o.Ends, o.Third); }
  };
  std::vector<Edge> edges;
  edges.reserve(3 * survivors.size());
  for (const Survivor& survivor : survivors)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::int32_t a = labels[survivor.Corners[k]], b = labels[survivor.Corners[(k + 1) % 3]];
      edges.push_back({ static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint32_t>(std::max(a, b)),
        labels[survivor.Corners[(k + 2) % 3]] });
    }
  }
  std::sort(edges.begin(), edges.end());
  const std::vector<std::uint8_t> kinds = this->LabelKinds(labels, count);
  const std::vector<std::uint8_t> none(count, 0);
  const auto smaller = [&sizes](std::int32_t a, std::int32_t b, const std::vector<std::uint8_t>& skip) {
    return sizes[a] > 1 && !skip[a] && (b < 0 || sizes[a] < sizes[b] || (sizes[a] == sizes[b] && a < b)) ? a : b;
  };
  std::vector<std::int32_t> torn;
  explode.clear();
  for (std::size_t k = 0, end = 0; k < edges.size(); k = end)
  {
    const std::int32_t a = edges[k].A(), b = edges[k].B();
    for (end = k; end < edges.size() && edges[end].Ends == edges[k].Ends; ++end)
    {
    }
    const bool border = std::binary_search(borders.begin(), borders.end(), std::make_pair(a, b));
    if (((kinds[a] | kinds[b]) & NotSurface) || end - k == 2 || (end - k == 1 && border))
    {
      continue;
    }
    std::int32_t split = smaller(a, smaller(b, -1, tried), tried);
    for (std::size_t j = k; j < end && split < 0; ++j)
    {
      split = smaller(edges[j].Third, split, tried);
    }
    if (split >= 0)
    {
      torn.push_back(split);
      continue;
    }
    // Every label there re-formed whole: the smallest goes to single points.
    split = smaller(a, smaller(b, -1, none), none);
    for (std::size_t j = k; j < end; ++j)
    {
      split = smaller(edges[j].Third, split, none);
    }
    if (split >= 0)
    {
      explode.push_back(split);
    }
  }
  for (std::vector<std::int32_t>* list : { &torn, &explode })
  {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  return torn;
}

std::size_t Clusterer::SplitIntoPieces(const std::vector<std::int32_t>& members, const std::vector<std::int32_t>& joined,
  const std::vector<std::uint8_t>& shown, std::vector<std::int32_t>& labels, std::int32_t& next) const
{
  // Pieces grow (PieceGrowth) from the flaps the label took, which keep it, then from the
  // members left in member order; without flaps the piece of most members keeps the label.
  // The others take next, next + 1, ...
  const std::int32_t label = labels[members[0]];
  PieceGrowth growth(this->Adjacency, members, shown, labels);
  if (!joined.empty())
  {
    growth.Grow(label, joined.data(), joined.data() + joined.size());
  }
  for (const std::int32_t& seed : members)
  {
    if (growth.Single(seed))
    {
      growth.Grow(labels[seed], &seed, &seed + 1);
    }
  }
  std::map<std::int32_t, std::int32_t> sizes;
  for (const std::int32_t v : members)
  {
    ++sizes[labels[v]];
  }
  std::int32_t largest = labels[members[0]];
  for (const std::int32_t v : members)
  {
    largest = sizes[labels[v]] > sizes[largest] ? labels[v] : largest;
  }
  std::map<std::int32_t, std::int32_t> renamed = { { joined.empty() ? largest : label, label } };
  for (const std::int32_t v : members)
  {
    const auto found = renamed.emplace(labels[v], next);
    next += found.second ? 1 : 0;
    labels[v] = found.first->second;
  }
  return sizes.size();
}

bool Clusterer::Settle(std::int64_t target, std::vector<Survivor>& survivors, Mending& mending)
{
  // Refined to the target (and further while a triangle is turned over: see
  // QueueFlippedLeaves), flaps join their neighbours (JoinFlaps), and what still tears is
  // split into pieces (MendOnce), again while a split leaves a tear; so is a locked vertex
  // without a triangle (BareLocks). Mending only splits, so the count may pass the target: the
  // caller refines further or finishes by collapses (see RefineToTarget).
  if (!this->Refine(target, this->Bound()))
  {
    return false;
  }
  const bool finishable = !this->Counting() || !this->CellLimits(); // see QueueFlippedLeaves
  for (std::size_t nodes = 0; finishable && this->Options.PreventFlips && nodes != this->Nodes.size() &&
       this->QueueFlippedLeaves();)
  {
    nodes = this->Nodes.size(); // a bound above every key splits nothing: the loop ends
    if (!this->Report(this->Reported) || !this->Refine(target, this->Bound()))
    {
      return false;
    }
  }
  mending.Cluster = this->VertexCluster;
  mending.Label = this->JoinFlaps(this->SurvivingTriangles(this->VertexCluster));
  mending.PieceNodes.clear();
  const std::int32_t clusters = static_cast<std::int32_t>(this->ClusterPositions.size());
  std::vector<std::uint8_t> tried;
  std::vector<std::int32_t> torn, explode;
  for (;;)
  {
    survivors = this->SurvivingTriangles(mending.Label);
    const std::vector<std::int32_t> detach = this->BareLocks(survivors, mending.Label);
    tried.resize(clusters + mending.PieceNodes.size(), 0);
    explode.clear();
    torn = this->TornLabels(survivors, mending.Label, tried, explode);
    if (torn.empty() && explode.empty() && detach.empty())
    {
      return true;
    }
    this->MendOnce(survivors, torn, explode, detach, tried, mending);
  }
}

std::vector<std::int32_t> Clusterer::BareLocks(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& labels) const
{
  // A locked vertex v stays an output point used by the output's triangles, as in the collapse
  // filters. It is a label of its own, so it has none left only where each triangle (v, a, b)
  // at it has a and b in one label. Its nearest such ring neighbour a is detached (a piece of
  // its own): the triangles (v, a, b) then keep three labels, and a detach takes no triangle
  // from a locked vertex. Tears it may make are mended like any other.
  std::vector<std::uint8_t> used(this->P.size(), 0);
  for (const Survivor& survivor : survivors)
  {
    for (const std::int32_t v : survivor.Corners)
    {
      used[v] = 1;
    }
  }
  std::vector<std::int32_t> detach;
  for (std::size_t v = 0; v < this->P.size(); ++v)
  {
    std::int32_t nearest = -1;
    double best = std::numeric_limits<double>::infinity();
    for (const Corner* c = this->Adjacency.Begin(v); this->Locked[v] && !used[v] && c != this->Adjacency.End(v); ++c)
    {
      for (const std::int32_t u : { c->Next, c->Previous })
      {
        const double d = (this->P[u] - this->P[v]).squaredNorm();
        if (labels[c->Next] == labels[c->Previous] && (d < best || (d == best && u < nearest)))
        {
          best = d;
          nearest = u;
        }
      }
    }
    if (nearest >= 0)
    {
      detach.push_back(nearest);
    }
  }
  std::sort(detach.begin(), detach.end());
  detach.erase(std::unique(detach.begin(), detach.end()), detach.end());
  return detach;
}

void Clusterer::MendOnce(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& torn,
  const std::vector<std::int32_t>& explode, const std::vector<std::int32_t>& detach,
  std::vector<std::uint8_t>& tried, Mending& mending) const
{
  // Each torn label is split into pieces that merge without tearing (SplitIntoPieces), the
  // flaps it took seeding the piece that keeps it. A label that tears although every label at
  // its torn edge re-formed whole when split goes to single points: around single points the
  // output is the input, so mending ends without a tear. A piece is part of one cluster, in
  // its cell.
  const std::int32_t clusters = static_cast<std::int32_t>(this->ClusterPositions.size());
  std::vector<std::int32_t>& labels = mending.Label;
  std::int32_t next = clusters + static_cast<std::int32_t>(mending.PieceNodes.size());
  std::vector<std::uint8_t> shown(next, 0); // labels that keep triangles
  for (const Survivor& survivor : survivors)
  {
    for (const std::int32_t v : survivor.Corners)
    {
      shown[labels[v]] = 1;
    }
  }
  // Per label to split, its own cluster's vertices and those of the flaps it took.
  std::map<std::int32_t, std::array<std::vector<std::int32_t>, 2>> members;
  for (std::size_t v = 0; v < labels.size(); ++v)
  {
    const std::int32_t l = labels[v];
    if (std::binary_search(torn.begin(), torn.end(), l) || std::binary_search(explode.begin(), explode.end(), l))
    {
      members[l][mending.Cluster[v] == l ? 0 : 1].push_back(static_cast<std::int32_t>(v));
    }
  }
  for (auto& label : members)
  {
    const std::int32_t node = label.first < clusters ? this->ClusterNodes[label.first]
                                                       : mending.PieceNodes[label.first - clusters];
    if (std::binary_search(explode.begin(), explode.end(), label.first))
    {
      for (const std::int32_t v : label.second[1])
      {
        labels[v] = mending.Cluster[v]; // the flaps it took go back
      }
      for (std::size_t i = 1; i < label.second[0].size(); ++i)
      {
        labels[label.second[0][i]] = next++;
      }
    }
    else
    {
      this->KeepLargestGroup(label.second[1], mending.Cluster, labels);
      tried[label.first] = this->SplitIntoPieces(label.second[0], label.second[1], shown, labels, next) == 1;
    }
    mending.PieceNodes.resize(next - clusters, node);
    for (const std::int32_t v : label.second[0])
    {
      mending.Cluster[v] = labels[v];
    }
  }
  for (const std::int32_t v : detach)
  {
    const std::int32_t from = mending.Cluster[v];
    mending.PieceNodes.push_back(from < clusters ? this->ClusterNodes[from] : mending.PieceNodes[from - clusters]);
    labels[v] = mending.Cluster[v] = next++;
  }
}

void Clusterer::KeepLargestGroup(std::vector<std::int32_t>& vertices, const std::vector<std::int32_t>& clusters,
  std::vector<std::int32_t>& labels) const
{
  std::vector<std::int32_t> group(vertices.size(), -1), stack, sizes;
  const auto at = [&vertices](std::int32_t v) {
    const auto found = std::lower_bound(vertices.begin(), vertices.end(), v);
    return found != vertices.end() && *found == v ? found - vertices.begin() : -1;
  };
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    if (group[i] >= 0)
    {
      continue;
    }
    const std::int32_t g = static_cast<std::int32_t>(sizes.size());
    sizes.push_back(0);
    group[i] = g;
    for (stack.assign(1, vertices[i]); !stack.empty();)
    {
      const std::int32_t u = stack.back();
      stack.pop_back();
      ++sizes[g];
      for (const Corner* c = this->Adjacency.Begin(u); c != this->Adjacency.End(u); ++c)
      {
        const std::ptrdiff_t k = at(c->Next);
        if (k >= 0 && group[k] < 0)
        {
          group[k] = g;
          stack.push_back(c->Next);
        }
      }
    }
  }
  const std::int32_t kept = sizes.empty() ? 0 : static_cast<std::int32_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  std::size_t left = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    if (group[i] == kept)
    {
      vertices[left++] = vertices[i];
    }
    else
    {
      labels[vertices[i]] = clusters[vertices[i]];
    }
  }
  vertices.resize(left);
}

bool Clusterer::CommitPieces(const Mending& mending, const std::vector<Survivor>& survivors,
  std::vector<std::int32_t>& owner)
{
  // Each piece becomes a cluster of its leaf; the pieces and what is left of the clusters they
  // came from are placed again, each at the better (smaller cluster error) of its own point and
  // its original cluster's. A cluster goes to its label's point when the label keeps
  // triangles. What is left of a cluster may fold where the whole did not (Folded), and so be
  // farther than the bound from both points: then, if its leaf can still be split, the commit
  // is undone and the leaf queued, to be refined and mended again. (Triangles that mending turns
  // over are left: they are very few, and mending again for them costs far more instructions;
  // see OctreeVertexClustering.md.)
  const std::int32_t clusters = static_cast<std::int32_t>(this->ClusterPositions.size());
  const std::int32_t count = clusters + static_cast<std::int32_t>(mending.PieceNodes.size());
  this->ClusterPositions.resize(count, Vec3::Zero());
  this->ClusterNodes.resize(count);
  std::copy(mending.PieceNodes.begin(), mending.PieceNodes.end(), this->ClusterNodes.begin() + clusters);
  std::vector<Vec3> before(this->ClusterPositions);
  std::vector<std::uint8_t> changed(count, 0), shown(count, 0);
  std::vector<std::pair<std::int32_t, std::int32_t>> moved; // (vertex, its cluster before)
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(this->P.size()); ++v)
  {
    const std::int32_t from = this->VertexCluster[v], to = mending.Cluster[v];
    if (from != to)
    {
      changed[from] = changed[to] = 1;
      before[to] = this->ClusterPositions[from];
      moved.emplace_back(v, from);
    }
    this->VertexCluster[v] = to;
  }
  for (const Survivor& survivor : survivors)
  {
    for (const std::int32_t v : survivor.Corners)
    {
      shown[mending.Label[v]] = 1;
    }
  }
  owner.assign(count, -1);
  std::map<std::int32_t, std::vector<std::int32_t>> members; // of the clusters placed again
  for (std::size_t v = 0; v < this->P.size(); ++v)
  {
    const std::int32_t c = this->VertexCluster[v];
    owner[c] = shown[mending.Label[v]] ? mending.Label[v] : -1;
    if (changed[c])
    {
      members[c].push_back(static_cast<std::int32_t>(v));
    }
  }
  bool queued = false;
  for (const auto& cluster : members)
  {
    const std::int32_t c = cluster.first, size = static_cast<std::int32_t>(cluster.second.size());
    const std::int32_t* set = cluster.second.data();
    Vec3 x = this->P[set[0]];
    const double error = size == 1 ? 0.0
      : this->Represent(c, this->ClusterQuadric(set, size), this->Region(this->Nodes[this->ClusterNodes[c]]), set, size, x);
    const double kept = this->ClusterError(before[c], set, size, this->Folded(set, size), nullptr);
    const Vec3 previous = this->ClusterPositions[c];
    this->ClusterPositions[c] = error <= kept ? x : before[c];
    before[c] = previous; // for the undo
    queued = (!this->Counting() && std::min(error, kept) > this->Bound() &&
               this->QueueSplit(this->ClusterNodes[c])) || queued;
  }
  if (!queued)
  {
    return true;
  }
  for (const auto& cluster : members)
  {
    this->ClusterPositions[cluster.first] = before[cluster.first];
  }
  for (const auto& vertex : moved)
  {
    this->VertexCluster[vertex.first] = vertex.second;
  }
  this->ClusterPositions.resize(clusters);
  this->ClusterNodes.resize(clusters);
  return false;
}

bool Clusterer::FinishByCollapses(std::int64_t target, std::vector<Survivor>& survivors,
  std::vector<std::int32_t>& owner) const
{
  // Clustering that mends every tear can overshoot a count target on steep or thin input: there
  // a coarser tree tears more, and mending gives the triangles back. The clustered mesh (one
  // point per surviving label at its cluster's position) is then taken down to the target by
  // quadric half-edge collapses (ProgressiveMesh's core, whose link condition keeps the surface
  // manifold), as multiphase simplification does after clustering (Garland and Shaffer): a
  // collapse x -> y joins x's clusters to y's point, which Finalize places for the joined set.
  // Locked labels are regions of their own, so nothing joins them.
  std::vector<std::int32_t> pointOf(owner.size(), -1), labelOf;
  std::vector<double> points;
  std::vector<std::int32_t> triangles, regions;
  std::vector<std::uint8_t> locked;
  for (const Survivor& survivor : survivors)
  {
    for (const std::int32_t v : survivor.Corners)
    {
      const std::int32_t label = owner[this->VertexCluster[v]];
      if (pointOf[label] < 0)
      {
        pointOf[label] = static_cast<std::int32_t>(labelOf.size());
        labelOf.push_back(label);
        points.insert(points.end(), this->ClusterPositions[label].data(), this->ClusterPositions[label].data() + 3);
        locked.push_back(this->Locked[v]);
        regions.push_back(this->Locked[v] ? -1 - label : this->Regions.empty() ? 0 : this->Regions[v]);
      }
      triangles.push_back(pointOf[label]);
    }
  }
  const TriangleMeshView clustered{ points.data(), static_cast<std::int64_t>(labelOf.size()), triangles.data(),
    static_cast<std::int64_t>(survivors.size()) };
  ProgressiveMeshOptions options;
  options.LockedPoints = locked.data();
  options.Regions = regions.data();
  options.StopTriangles = target;
  options.CloseCracks = false; // clusters at one position stay apart, as their triangles have them
  // With the caller's threads and abort, its progress going on from where clustering left it.
  ExecutionContext collapses = this->Context;
  collapses.Progress = [this](double progress) { return this->Context.Report(0.85 + 0.1 * progress); };
  ProgressiveMesh sequence;
  if (!BuildProgressiveMesh(clustered, options, sequence, collapses))
  {
    return false;
  }
  Outcome outcome;
  Target goal;
  goal.SetTriangleCount(target);
  const std::int64_t level = LevelFor(sequence, goal, outcome);
  // Each point joins its first ancestor in the level.
  const std::vector<std::int32_t> ancestor = LevelAncestors(sequence, level);
  const std::int64_t kept = sequence.NumberOfPoints() - static_cast<std::int64_t>(ancestor.size());
  std::vector<std::int32_t> joinedTo(labelOf); // a point the build did not use stays as it is
  for (std::int64_t i = 0; i < sequence.NumberOfPoints(); ++i)
  {
    const std::int64_t survivor = i < kept ? i : ancestor[i - kept];
    joinedTo[sequence.InputPoint[i]] = labelOf[sequence.InputPoint[survivor]];
  }
  for (std::int32_t& label : owner)
  {
    label = label >= 0 && pointOf[label] >= 0 ? joinedTo[pointOf[label]] : label;
  }
  // The survivors the level's collapses removed go; the others stay, in their order.
  std::vector<std::uint8_t> removed(survivors.size(), 0);
  for (std::size_t t = static_cast<std::size_t>(sequence.TrianglesAt(level)); t < sequence.InputTriangle.size(); ++t)
  {
    removed[sequence.InputTriangle[t]] = 1;
  }
  std::size_t left = 0;
  for (std::size_t t = 0; t < survivors.size(); ++t)
  {
    survivors[left] = survivors[t];
    left += removed[t] ? 0 : 1;
  }
  survivors.resize(left);
  return true;
}

std::vector<std::int32_t> Clusterer::JoinStrandedCaps(std::vector<std::int32_t> owner) const
{
  // The surviving cluster each cluster's vertices go to: owner's (its own when it keeps a
  // triangle, or the one a flap joined). With a count target, a cluster that lost every
  // triangle and touches a single surviving cluster
  // (a cap on a thin part: a trunk's or a finger's end) has its vertices represented by that
  // cluster's point, so they join it: its point then accounts for them, and the protruding-tip
  // rule can put it at the part's end instead of leaving the part cut off. Repeated, so chains
  // of such caps join too. (Under an error bound every such cap is within ε of its neighbours
  // already, and a joined point's error is not bounded.) Locked vertices neither join nor are
  // joined, and a cap joins no cluster of another region.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  const std::size_t clusters = this->ClusterPositions.size();
  constexpr std::int32_t Several = -2;
  std::vector<std::int32_t> candidate(clusters, -1);
  std::vector<std::int32_t> stranded; // the vertices of clusters without an owner yet
  for (std::int64_t v = 0; v < n && this->Counting(); ++v)
  {
    if (owner[this->VertexCluster[v]] < 0)
    {
      stranded.push_back(static_cast<std::int32_t>(v));
    }
  }
  const auto sameRegion = [this](std::int32_t v, std::int32_t w) {
    return this->Regions.empty() || this->Regions[v] == this->Regions[w];
  };
  for (bool joined = true; joined && !stranded.empty();)
  {
    for (const std::int32_t v : stranded)
    {
      candidate[this->VertexCluster[v]] = -1;
    }
    for (const std::int32_t v : stranded)
    {
      const std::int32_t c = this->VertexCluster[v];
      for (const Corner* k = this->Adjacency.Begin(v); k != this->Adjacency.End(v) && !this->Locked[v]; ++k)
      {
        for (const std::int32_t w : { k->Next, k->Previous })
        {
          const std::int32_t o = owner[this->VertexCluster[w]];
          if (o >= 0 && !this->Locked[w] && sameRegion(v, w) && candidate[c] != o)
          {
            candidate[c] = candidate[c] == -1 ? o : Several;
          }
        }
      }
    }
    joined = false;
    for (const std::int32_t v : stranded)
    {
      const std::int32_t c = this->VertexCluster[v];
      if (candidate[c] >= 0)
      {
        owner[c] = candidate[c];
        joined = true;
      }
    }
    stranded.erase(std::remove_if(stranded.begin(), stranded.end(),
                     [&](std::int32_t v) { return owner[this->VertexCluster[v]] >= 0; }),
      stranded.end());
  }
  return owner;
}

Clusterer::OutputPoints Clusterer::NumberPoints(const std::vector<std::int32_t>& owner) const
{
  // Output points: owning clusters, in the order of their first vertex; their vertices by a
  // counting sort.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  OutputPoints points;
  std::vector<std::int32_t> pointOfCluster(owner.size(), -1);
  points.PointOf.assign(n, -1);
  for (std::int64_t v = 0; v < n; ++v)
  {
    const std::int32_t c = owner[this->VertexCluster[v]];
    if (c < 0)
    {
      continue;
    }
    if (pointOfCluster[c] < 0)
    {
      pointOfCluster[c] = static_cast<std::int32_t>(points.ClusterOf.size());
      points.ClusterOf.push_back(c);
    }
    points.PointOf[v] = pointOfCluster[c];
  }
  points.Offsets.assign(points.ClusterOf.size() + 1, 0);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (points.PointOf[v] >= 0)
    {
      ++points.Offsets[points.PointOf[v] + 1];
    }
  }
  std::partial_sum(points.Offsets.begin(), points.Offsets.end(), points.Offsets.begin());
  points.Members.resize(points.Offsets.back());
  std::vector<std::int32_t> fill(points.Offsets.begin(), points.Offsets.end() - 1);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (points.PointOf[v] >= 0)
    {
      points.Members[fill[points.PointOf[v]]++] = static_cast<std::int32_t>(v);
    }
  }
  return points;
}

void Clusterer::PlaceRepresentatives(OutputPoints& points) const
{
  // Protruding clusters take their tip again (the clusters around them may have changed
  // since); the others start from their refinement point. A point with joined caps takes
  // whichever of its own cluster's point and the whole set's point represents the whole set
  // better (the cluster error with the members' distances, see ClusterError).
  const std::int64_t count = points.Size();
  points.Position.resize(count);
  points.Centre.resize(count);
  points.Ring.resize(count);
  points.FaceQuadric.resize(count);
  points.Folded.assign(count, 0);
  points.Protruding.assign(count, 0);
  points.Regions.resize(count);
  this->Context.For(count, [&](std::int64_t b, std::int64_t e) {
    std::vector<std::int32_t> own;
    for (std::int64_t p = b; p < e; ++p)
    {
      const std::int32_t cluster = points.ClusterOf[p];
      const std::int32_t* members = points.MembersOf(p);
      const std::int32_t size = points.Count(p);
      points.Centre[p] = this->ClusterCentre(members, size);
      points.FaceQuadric[p] = this->ClusterQuadric(members, size);
      points.Regions[p] = this->Region(this->Nodes[this->ClusterNodes[cluster]]);
      for (std::int32_t i = 0; i < size; ++i)
      {
        const std::int32_t joined = this->VertexCluster[members[i]];
        if (joined != cluster)
        {
          points.Regions[p] = points.Regions[p].Joined(this->Region(this->Nodes[this->ClusterNodes[joined]]));
        }
      }
      points.Folded[p] = this->Folded(members, size) ? 1 : 0;
      // The point of the given members: their tip when they protrude, else the cluster's.
      const auto place = [&](const std::int32_t* set, std::int32_t setSize, bool isFolded,
                           const auto& member, Vec3& x, Vec3& setRing) {
        std::int32_t tip;
        x = this->ClusterPositions[cluster];
        if (isFolded && this->ProtrudingTip(member, set, setSize, tip, setRing))
        {
          x = this->P[tip];
          return true;
        }
        return false;
      };
      const auto inPoint = [&points, p](std::int32_t v) { return points.PointOf[v] == p; };
      points.Protruding[p] =
        place(members, size, points.Folded[p], inPoint, points.Position[p], points.Ring[p]) ? 1 : 0;
      const auto inCluster = [&](std::int32_t v) { return this->VertexCluster[v] == cluster; };
      own.clear();
      std::copy_if(members, members + size, std::back_inserter(own), inCluster);
      if (static_cast<std::int32_t>(own.size()) == size)
      {
        continue; // nothing joined
      }
      Vec3 x, ownRing;
      const std::int32_t ownSize = static_cast<std::int32_t>(own.size());
      const bool ownTip = place(own.data(), ownSize, this->Folded(own.data(), ownSize), inCluster, x, ownRing);
      if (this->ClusterError(x, members, size, true, ownTip ? &ownRing : nullptr) <
        this->ClusterError(points.Position[p], members, size, true, points.Protruding[p] ? &points.Ring[p] : nullptr))
      {
        points.Position[p] = x;
        points.Protruding[p] = ownTip ? 1 : 0;
        points.Ring[p] = ownRing;
      }
    }
  }, 64 * static_cast<std::int64_t>(points.Members.size()));
}

void Clusterer::IterateSecondError(const std::vector<Survivor>& survivors, OutputPoints& points) const
{
  // e2 by the paper's iteration (eq. 8–11): with the representatives of the previous iterate,
  // the squared distance of a cluster vertex a to a new triangle (v0, b', c') is the squared
  // distance of v0 to the plane through (a, b', c') scaled by (area(a,b',c') / area(v0,b',c'))².
  const std::int64_t count = points.Size();
  const bool bounded = !this->Counting();
  const double bound = this->Bound();
  std::vector<Quadric> quadric(count);
  std::vector<Vec3> next(count);
  for (int iteration = 0; iteration < this->Options.ErrorIterations; ++iteration)
  {
    quadric = points.FaceQuadric;
    for (const Survivor& survivor : survivors)
    {
      const std::array<std::int32_t, 3>& tri = survivor.Corners;
      for (int k = 0; k < 3; ++k)
      {
        const std::int32_t a = tri[k];
        const std::int32_t pa = points.PointOf[a];
        if (points.Count(pa) == 1)
        {
          continue; // a lone vertex is its own representative
        }
        const Vec3& xb = points.Position[points.PointOf[tri[(k + 1) % 3]]];
        const Vec3& xc = points.Position[points.PointOf[tri[(k + 2) % 3]]];
        const Vec3 through = (xb - this->P[a]).cross(xc - this->P[a]);
        const double areaThrough = through.norm();
        const double areaNew = (xb - points.Position[pa]).cross(xc - points.Position[pa]).norm();
        if (areaThrough <= 0.0)
        {
          continue;
        }
        // Capped, so that a nearly degenerate new triangle does not outweigh all the others.
        const double ratio = areaNew > 0.0 ? std::min(areaThrough / areaNew, 2.0) : 2.0;
        const Vec3 normal = through / areaThrough;
        quadric[pa] += Quadric::FromPlane(normal, -normal.dot(this->P[a]), 0.5 * areaThrough * ratio * ratio);
      }
    }
    this->Context.For(count, [&](std::int64_t b, std::int64_t e) {
      for (std::int64_t p = b; p < e; ++p)
      {
        next[p] = points.Position[p];
        if (points.Count(p) == 1 || points.Protruding[p])
        {
          continue;
        }
        const Vec3 x = this->PlaceRepresentative(
          quadric[p], points.Centre[p], points.Regions[p], points.MembersOf(p), points.Count(p));
        if (!bounded || this->ClusterError(x, points.MembersOf(p), points.Count(p), points.Folded[p], nullptr) <= bound)
        {
          next[p] = x;
        }
      }
    }, 64 * static_cast<std::int64_t>(points.Members.size()));
    if (this->Options.PreventFlips)
    {
      this->UndoTurningMoves(survivors, points, next);
    }
    points.Position.swap(next);
  }
}

bool Clusterer::TurnedOver(const Survivor& survivor, const std::vector<std::int32_t>& pointOf,
  const std::vector<Vec3>& position) const
{
  const Vec3& normal = this->TriangleNormals[survivor.Triangle];
  const Vec3& a = position[pointOf[survivor.Corners[0]]];
  const Vec3& b = position[pointOf[survivor.Corners[1]]];
  const Vec3& c = position[pointOf[survivor.Corners[2]]];
  return normal != Vec3::Zero() && (b - a).cross(c - a).dot(normal) <= 0.0;
}

void Clusterer::UndoTurningMoves(
  const std::vector<Survivor>& survivors, const OutputPoints& points, std::vector<Vec3>& next) const
{
  // §2.4 for the iteration: the moves of a triangle's corners are undone where the moved points
  // turn it against its input triangle and the points before did not, until no triangle is
  // turned over anew (undoing only puts points back, so this ends).
  for (bool undone = true; undone;)
  {
    undone = false;
    for (const Survivor& survivor : survivors)
    {
      if (!this->TurnedOver(survivor, points.PointOf, next) ||
        this->TurnedOver(survivor, points.PointOf, points.Position))
      {
        continue;
      }
      for (const std::int32_t v : survivor.Corners)
      {
        const std::int32_t p = points.PointOf[v];
        undone = undone || next[p] != points.Position[p];
        next[p] = points.Position[p];
      }
    }
  }
}

void Clusterer::WriteResult(const std::vector<Survivor>& survivors, const OutputPoints& points,
  OctreeClusteringResult& result) const
{
  // Points in input coordinates (locked ones exactly as they were) and their cells, their
  // cluster errors, and their sources: the cluster's input points by area weight, the heaviest
  // first.
  const std::int64_t count = points.Size();
  const std::vector<std::int32_t>& inputVertex = this->Prepared.Mesh.InputVertex;
  result.Points.resize(3 * count);
  result.PointCells.resize(6 * count);
  result.SourceOffsets = points.Offsets;
  result.SourcePoints.resize(points.Members.size());
  result.SourceWeights.resize(points.Members.size());
  std::vector<double> clusterSize(count), clusterError(count);
  this->Context.For(count, [&](std::int64_t b, std::int64_t e) {
    for (std::int64_t p = b; p < e; ++p)
    {
      const std::int32_t* members = points.MembersOf(p);
      const std::int32_t size = points.Count(p);
      // Within the box: the way back to input units may round a point on its face out of it.
      const auto toInput = [this](const Vec3& y) { return this->Prepared.ToInput(y); };
      const Vec3 x =
        this->Locked[members[0]] ? this->Input.Point(inputVertex[members[0]]) : toInput(points.Position[p]);
      const Vec3 lower = toInput(points.Regions[p].Lower), upper = toInput(points.Regions[p].Upper);
      for (int k = 0; k < 3; ++k)
      {
        result.Points[3 * p + k] = x[k];
        result.PointCells[6 * p + k] = lower[k];
        result.PointCells[6 * p + 3 + k] = upper[k];
      }
      clusterSize[p] = size;
      clusterError[p] = this->ClusterError(points.Position[p], members, size, points.Folded[p],
                          points.Protruding[p] ? &points.Ring[p] : nullptr) / this->Prepared.Scale;
      double total = 0.0;
      std::int32_t heaviest = 0;
      for (std::int32_t i = 0; i < size; ++i)
      {
        total += this->VertexWeights[members[i]];
        heaviest = this->VertexWeights[members[i]] > this->VertexWeights[members[heaviest]] ? i : heaviest;
      }
      for (std::int32_t i = 0; i < size; ++i)
      {
        const std::int32_t slot = i == 0 ? heaviest : i == heaviest ? 0 : i;
        result.SourcePoints[points.Offsets[p] + i] = inputVertex[members[slot]];
        result.SourceWeights[points.Offsets[p] + i] =
          total > 0.0 ? this->VertexWeights[members[slot]] / total : 1.0 / size;
      }
    }
  }, 64 * static_cast<std::int64_t>(points.Members.size()));
  result.Report.MaximumError = clusterError.empty() ? 0.0 : *std::max_element(clusterError.begin(), clusterError.end());
  result.FieldValues.emplace_back("MaximumClusterError", result.Report.MaximumError);
  result.AddPointArray("ClusterSize", std::move(clusterSize), NamedArray::Kind::Integer);
  result.AddPointArray("ClusterError", std::move(clusterError));

  result.Triangles.resize(3 * survivors.size());
  result.TriangleSource.resize(survivors.size());
  for (std::size_t i = 0; i < survivors.size(); ++i)
  {
    result.TriangleSource[i] = this->Prepared.Mesh.InputTriangle[survivors[i].Triangle];
    for (int k = 0; k < 3; ++k)
    {
      result.Triangles[3 * i + k] = points.PointOf[survivors[i].Corners[k]];
    }
  }
  result.VertexToPoint.assign(this->Input.NumberOfPoints, -1);
  for (std::size_t v = 0; v < inputVertex.size(); ++v)
  {
    result.VertexToPoint[inputVertex[v]] = points.PointOf[v];
  }
}

void Clusterer::WriteInput(OctreeClusteringResult& result) const
{
  const CompactMesh& mesh = this->Prepared.Mesh;
  const std::int64_t n = static_cast<std::int64_t>(mesh.InputVertex.size());
  result.Points.resize(3 * n);
  result.PointCells.resize(6 * n);
  result.SourceOffsets.resize(n + 1);
  result.SourcePoints = mesh.InputVertex;
  result.SourceWeights.assign(n, 1.0);
  result.VertexToPoint.assign(this->Input.NumberOfPoints, -1);
  for (std::int64_t v = 0; v < n; ++v)
  {
    const Vec3 x = this->Input.Point(mesh.InputVertex[v]);
    for (int k = 0; k < 3; ++k)
    {
      result.Points[3 * v + k] = result.PointCells[6 * v + k] = result.PointCells[6 * v + 3 + k] = x[k];
    }
    result.SourceOffsets[v] = static_cast<std::int32_t>(v);
    result.VertexToPoint[mesh.InputVertex[v]] = static_cast<std::int32_t>(v);
  }
  result.SourceOffsets[n] = static_cast<std::int32_t>(n);
  result.Triangles = mesh.Triangles;
  result.TriangleSource = mesh.InputTriangle;
  result.Report.MaximumError = 0.0;
  result.FieldValues.emplace_back("MaximumClusterError", 0.0);
  result.AddPointArray("ClusterSize", std::vector<double>(n, 1.0), NamedArray::Kind::Integer);
  result.AddPointArray("ClusterError", std::vector<double>(n, 0.0));
}

void Clusterer::Finalize(const std::vector<Survivor>& survivors, const std::vector<std::int32_t>& owner,
  OctreeClusteringResult& result)
{
  OutputPoints points = this->NumberPoints(this->JoinStrandedCaps(owner));
  this->PlaceRepresentatives(points);
  this->IterateSecondError(survivors, points);
  this->WriteResult(survivors, points, result);
}

void Clusterer::JudgeCount(OctreeClusteringResult& result) const
{
  Outcome& report = result.Report;
  const std::int64_t count = result.NumberOfTriangles(), target = report.TargetTriangles;
  if (!this->Counting() || std::abs(count - target) <= this->Options.Goal.Slack(target) ||
    report.Stop == StopReason::AllLocked)
  {
    return;
  }
  report.Stop = StopReason::NearestCount;
  if (count > target && this->Options.MaximumCellSize > 0.0 && this->Options.MaximumCellSize < 1.0)
  {
    report.Reason = "MaximumCellSize (" + std::to_string(this->Options.MaximumCellSize) + ") splits larger cells";
  }
  else if (count > target && report.LockedPoints > 0)
  {
    report.Reason = "locked points are clusters of their own";
  }
  else
  {
    report.Reason = "the nearest count vertex clustering gives on this input";
  }
}

void Clusterer::PlantTree(std::int64_t target)
{
  // Every vertex of the compact mesh is used; its order is already spatial.
  const std::int64_t n = static_cast<std::int64_t>(this->P.size());
  this->Order.resize(n);
  std::iota(this->Order.begin(), this->Order.end(), 0);
  this->Position = this->Order;
  this->VertexCluster.assign(n, -1);
  this->Reordered.resize(n);
  this->Octants.resize(n);

  OctreeNode root;
  // The bounding cube of the normalised points (a margin covers their rounding).
  const CompactMesh& mesh = this->Prepared.Mesh;
  root.Center = Vec3::Zero();
  root.Half = (0.5 * mesh.Upper - 0.5 * mesh.Lower).maxCoeff() * this->Prepared.Scale * (1.0 + 1e-9) + 1e-12;
  root.Begin = 0;
  root.End = static_cast<std::int32_t>(n);
  root.Depth = 0;
  root.FirstCluster = root.ClusterCount = 0;
  this->AddNode(root);

  // With a count target, the top levels are split without evaluating them while they hold
  // far fewer cells than the target needs clusters (about target / 2): the error-ordered
  // refinement would split each of them anyway, so only their leaves are evaluated.
  std::vector<std::int32_t> frontier = { 0 };
  while (target >= 0)
  {
    const std::size_t mark = this->Nodes.size();
    std::vector<std::int32_t> next;
    for (const std::int32_t node : frontier)
    {
      if (this->Nodes[node].End - this->Nodes[node].Begin < 2)
      {
        next.push_back(node);
        continue;
      }
      const std::int32_t first = this->PartitionNode(node);
      for (std::int32_t child = first; child < static_cast<std::int32_t>(this->Nodes.size()); ++child)
      {
        next.push_back(child);
      }
    }
    if (static_cast<std::int64_t>(next.size()) * 4 > target || next.size() == frontier.size())
    {
      this->Nodes.resize(mark);
      break;
    }
    frontier.swap(next);
  }
  // The frontier's leaves, in range order, each reserving the cluster ids of its range for now:
  // ids, and the whole result, do not depend on the thread count. Each triangle is counted once,
  // from its first corner.
  std::sort(frontier.begin(), frontier.end(),
    [this](std::int32_t a, std::int32_t b) { return this->Nodes[a].Begin < this->Nodes[b].Begin; });
  const std::int32_t all = static_cast<std::int32_t>(n);
  this->ClusterPositions.resize(all);
  this->ClusterNodes.resize(all);
  std::vector<NewLeaf> leaves(frontier.size());
  for (std::size_t i = 0; i < frontier.size(); ++i)
  {
    leaves[i].Node = frontier[i];
    leaves[i].FirstCluster = this->Nodes[frontier[i]].Begin;
    leaves[i].CountBegin = 0;
    leaves[i].CountEnd = all;
  }
  this->ClusterLeaves(leaves, 0);
  this->ClusterPositions.shrink_to_fit(); // the room of one id per vertex serves later arrays
  this->ClusterNodes.shrink_to_fit();
  for (const NewLeaf& leaf : leaves)
  {
    this->SurvivingCount += leaf.Scan.Surviving;
    if (leaf.Splittable)
    {
      this->Heap.push(this->MakeEntry(leaf.Node, leaf.Key, leaf.Scan, target >= 0));
    }
  }
}

bool Clusterer::RefineToTarget(std::int64_t target, std::vector<Survivor>& survivors, Mending& mending)
{
  // A count target is approached on the estimate (triangles with three distinct clusters).
  // Duplicates removed at the end, flaps that join and pieces split so that nothing tears
  // (Settle) make the real count differ. Above the target, collapses finish (FinishByCollapses):
  // coarsening the tree instead tears more on steep or thin input, and mending gives the
  // triangles back, so that the count jumps around the target from one try to the next. More
  // than 2 % below it, the estimate's target is scaled by the ratio of estimate to real count
  // and refinement resumes (at most 6 rounds).
  std::int64_t internalTarget = target;
  for (int round = 0;; ++round)
  {
    if (!this->Settle(internalTarget, survivors, mending))
    {
      return false;
    }
    const std::int64_t count = static_cast<std::int64_t>(survivors.size());
    if (target < 0 || round == 5 || count >= target - target / 50 || this->Heap.empty())
    {
      return true;
    }
    internalTarget = std::max<std::int64_t>(internalTarget + 1,
      std::llround(static_cast<double>(this->SurvivingCount) * target / std::max<std::int64_t>(1, count)));
  }
}

bool Clusterer::Run(OctreeClusteringResult& result)
{
  result = OctreeClusteringResult();
  this->PrepareGeometry();
  if (!this->Report(0.05))
  {
    return false;
  }
  if (this->KeepsEverything && !this->P.empty())
  {
    result.Report = this->Start;
    this->WriteInput(result);
    return this->Report(1.0);
  }
  this->ClassifyVertices();
  this->PrepareQuadrics();
  if (!this->Report(0.15))
  {
    return false;
  }
  const std::int64_t target = this->Counting() ? this->Prepared.TargetTriangles : -1;
  result.Report = this->Start;
  if (this->P.empty())
  {
    // No usable triangle: an empty result, its maps still well formed.
    result.VertexToPoint.assign(this->Input.NumberOfPoints, -1);
    return this->Report(1.0);
  }

  this->PlantTree(target);
  std::vector<Survivor> survivors;
  Mending mending;
  if (!this->RefineToTarget(target, survivors, mending) || !this->Report(0.85))
  {
    return false;
  }
  std::vector<std::int32_t> owner;
  while (!this->CommitPieces(mending, survivors, owner))
  {
    if (!this->RefineToTarget(target, survivors, mending))
    {
      return false;
    }
  }
  if (target >= 0 && !this->CellLimits() && static_cast<std::int64_t>(survivors.size()) > target + this->Options.Goal.Slack(target))
  {
    if (!this->FinishByCollapses(target, survivors, owner))
    {
      return false;
    }
  }
  this->Finalize(survivors, owner, result);
  this->JudgeCount(result);
  std::vector<std::uint8_t> isLeaf(this->Nodes.size(), 0);
  for (const std::int32_t v : this->Order)
  {
    isLeaf[this->ClusterNodes[this->VertexCluster[v]]] = 1;
  }
  for (std::size_t i = 0; i < this->Nodes.size(); ++i)
  {
    if (isLeaf[i])
    {
      ++result.NumberOfLeaves;
      result.Depth = std::max(result.Depth, this->Nodes[i].Depth);
    }
  }
  return this->Report(1.0);
}

} // namespace

bool OctreeVertexClustering(const TriangleMeshView& mesh, const OctreeClusteringOptions& options,
  OctreeClusteringResult& result, const ExecutionContext& context)
{
  bool finished = Clusterer(mesh, options, context).Run(result);
  if (finished && options.Goal.Bounded() && result.NumberOfTriangles() == 0 &&
    result.Report.UsableTriangles > 0)
  {
    // A bound so large that every cluster merges would leave no triangle: the coarsest mesh the
    // clustering makes instead (the nearest count to one triangle).
    OctreeClusteringOptions coarsest = options;
    coarsest.Goal.SetTriangleCount(1);
    finished = Clusterer(mesh, coarsest, context).Run(result);
    result.Report.TargetTriangles = 0;
    result.Report.Stop = StopReason::NearestCount;
    result.Report.Reason = "the bound would leave no triangle";
    result.Report.Notes.push_back("the bound would leave no triangle: the coarsest mesh vertex clustering makes, of " +
      std::to_string(result.NumberOfTriangles()) + " triangles, is given");
  }
  if (!finished)
  {
    result.Report.Stop = StopReason::Aborted;
  }
  return finished;
}

} // namespace meshsimp
