// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering: tears mended, by flaps that join and labels split into pieces (see OctreeClusterer.h).
#include "OctreeClusterer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <iterator>
#include <map>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace meshsimp
{
namespace octree
{
namespace
{
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
} // namespace

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

} // namespace octree
} // namespace meshsimp
