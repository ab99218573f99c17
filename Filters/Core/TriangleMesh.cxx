// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleMesh.h"

#include <algorithm>
#include <tuple>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace meshsimp
{
namespace
{
/// The input's arrays with their element types fixed, so the loops below need no per-element
/// test of which arrays the view holds.
template <typename PointType, typename IdType>
struct TypedView
{
  const PointType* Points;
  const IdType* Ids;
  std::int64_t NumberOfPoints, NumberOfTriangles;
  Eigen::Vector3d Point(std::int64_t i) const
  {
    return { static_cast<double>(this->Points[3 * i]), static_cast<double>(this->Points[3 * i + 1]),
      static_cast<double>(this->Points[3 * i + 2]) };
  }
  std::int64_t Id(std::int64_t i) const { return static_cast<std::int64_t>(this->Ids[i]); }
};

/// Which triangles are usable: three distinct ids in range, three finite corners. Counts the
/// non-finite points into mesh.
template <typename View>
std::vector<std::uint8_t> MarkUsable(const View& input, CompactMesh& mesh, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  std::vector<std::uint8_t> finite(n);
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      finite[v] = input.Point(v).allFinite() ? 1 : 0;
    }
  });
  mesh.NonFinitePoints = std::count(finite.begin(), finite.end(), std::uint8_t(0));
  std::vector<std::uint8_t> usable(m);
  context.For(m, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t t = begin; t < end; ++t)
    {
      const std::int64_t tri[3] = { input.Id(3 * t), input.Id(3 * t + 1), input.Id(3 * t + 2) };
      bool ok = tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2];
      for (int k = 0; k < 3 && ok; ++k)
      {
        ok = tri[k] >= 0 && tri[k] < n && finite[tri[k]];
      }
      usable[t] = ok ? 1 : 0;
    }
  });
  return usable;
}

/// The Morton code (of a grid of 2^bits cells a side over the box) of each used vertex, -1 for
/// the others; any: whether a vertex is used at all.
template <typename View>
std::vector<std::int32_t> MortonCodes(const View& input, const std::vector<std::int32_t>& vertexOf,
  const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, bool any, int bits, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints;
  const std::int32_t side = 1 << bits;
  // A box wider than the largest double (coordinates near ±1.8e308) is gridded at half scale,
  // which is exact; any other at its own.
  const double shrink = any && !std::isfinite((hi - lo).maxCoeff()) ? 0.5 : 1.0;
  const double extent = any ? (shrink * hi - shrink * lo).maxCoeff() : 0.0;
  const double toCell = extent > 0.0 ? side / extent : 0.0;
  const Eigen::Vector3d corner = 0.5 * (shrink * lo + shrink * hi) - Eigen::Vector3d::Constant(0.5 * extent);
  std::vector<std::int32_t> code(n, -1);
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      if (vertexOf[v] < 0)
      {
        continue;
      }
      const Eigen::Vector3d cell = (shrink * input.Point(v) - corner) * toCell;
      std::int32_t morton = 0;
      for (int axis = 0; axis < 3; ++axis)
      {
        // Spread the (at most 7) bits of the cell index to every third bit.
        std::uint32_t i = static_cast<std::uint32_t>(
          std::min(std::max(static_cast<std::int32_t>(cell[axis]), 0), side - 1));
        i = (i | (i << 8)) & 0x0300F00Fu;
        i = (i | (i << 4)) & 0x030C30C3u;
        i = (i | (i << 2)) & 0x09249249u;
        morton |= static_cast<std::int32_t>(i << axis);
      }
      code[v] = morton;
    }
  });
  return code;
}

/// The used vertices in the Morton order of a coarse grid over their bounding cube (input order
/// within a cell): mesh's InputVertex, Points and box; vertexOf maps input points to them (-1:
/// unused). Returns where each cell's vertices end (cell c holds [end of c − 1, end of c)).
template <typename View>
std::vector<std::int32_t> OrderVertices(const View& input, const std::vector<std::uint8_t>& usable,
  CompactMesh& mesh, std::vector<std::int32_t>& vertexOf, const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  vertexOf.assign(n, -1); // used vertices are marked 0 first
  for (std::int64_t t = 0; t < m; ++t)
  {
    for (int k = 0; k < 3 && usable[t]; ++k)
    {
      vertexOf[input.Id(3 * t + k)] = 0;
    }
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  std::int64_t used = 0;
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (vertexOf[v] == 0)
    {
      lo = lo.cwiseMin(input.Point(v));
      hi = hi.cwiseMax(input.Point(v));
      ++used;
    }
  }
  if (used > 0)
  {
    mesh.Lower = lo;
    mesh.Upper = hi;
  }
  // Morton code of each used vertex's cell in a grid of about one cell per vertex, then a
  // counting sort by code that keeps input order inside a cell.
  int bits = 1;
  while (bits < 7 && (std::int64_t(1) << (3 * (bits + 1))) <= used)
  {
    ++bits;
  }
  const std::vector<std::int32_t> code = MortonCodes(input, vertexOf, lo, hi, used > 0, bits, context);
  std::vector<std::int32_t> start((std::size_t(1) << (3 * bits)) + 1, 0);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (code[v] >= 0)
    {
      ++start[code[v] + 1];
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  mesh.InputVertex.resize(used);
  for (std::int64_t v = 0; v < n; ++v)
  {
    if (code[v] >= 0)
    {
      vertexOf[v] = start[code[v]]++;
      mesh.InputVertex[vertexOf[v]] = static_cast<std::int32_t>(v);
    }
  }
  mesh.Points.resize(used);
  context.For(used, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t v = begin; v < end; ++v)
    {
      mesh.Points[v] = input.Point(mesh.InputVertex[v]);
    }
  });
  start.pop_back(); // the counting moved each cell's start to its end
  return start;
}

/// Triangles by their lowest vertex (counting sort, input order among equals), corners kept,
/// and each vertex's corners (counting sort by vertex) in the same two passes, over parts of
/// the triangles concurrently: each part counts its own, then writes from cursors that start
/// after the earlier parts' entries, so the result is the same for any number of parts.
template <typename View>
void OrderTriangles(const View& input, const std::vector<std::uint8_t>& usable,
  const std::vector<std::int32_t>& vertexOf, CompactMesh& mesh, const ExecutionContext& context)
{
  const std::int64_t m = input.NumberOfTriangles;
  const std::int64_t used = static_cast<std::int64_t>(mesh.Points.size());
  const std::int64_t parts = std::max<std::int64_t>(1, std::min<std::int64_t>(context.Threads, m / 65536));
  std::vector<std::vector<std::int32_t>> nextTriangle(parts), nextCorner(parts);
  auto forEachUsable = [&](std::int64_t part, auto&& f) {
    for (std::int64_t t = m * part / parts, end = m * (part + 1) / parts; t < end; ++t)
    {
      if (usable[t])
      {
        f(t, vertexOf[input.Id(3 * t)], vertexOf[input.Id(3 * t + 1)], vertexOf[input.Id(3 * t + 2)]);
      }
    }
  };
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::vector<std::int32_t>& triangles = nextTriangle[part];
      std::vector<std::int32_t>& corners = nextCorner[part];
      triangles.assign(used, 0);
      corners.assign(used, 0);
      forEachUsable(part, [&](std::int64_t, std::int32_t a, std::int32_t b, std::int32_t c) {
        ++triangles[std::min({ a, b, c })];
        ++corners[a];
        ++corners[b];
        ++corners[c];
      });
    }
  }, 10 * m);
  // Counts become cursors: per vertex, the parts in order.
  VertexTriangleAdjacency& adjacency = mesh.Adjacency;
  adjacency.Offsets.resize(used + 1);
  std::int32_t triangleCount = 0, cornerCount = 0;
  for (std::int64_t v = 0; v < used; ++v)
  {
    adjacency.Offsets[v] = cornerCount;
    for (std::int64_t part = 0; part < parts; ++part)
    {
      const std::int32_t triangles = nextTriangle[part][v], corners = nextCorner[part][v];
      nextTriangle[part][v] = triangleCount;
      nextCorner[part][v] = cornerCount;
      triangleCount += triangles;
      cornerCount += corners;
    }
  }
  adjacency.Offsets[used] = cornerCount;
  mesh.InputTriangle.resize(triangleCount);
  mesh.Triangles.resize(3 * static_cast<std::size_t>(triangleCount));
  adjacency.Corners.resize(cornerCount);
  context.For(parts, [&](std::int64_t begin, std::int64_t end) {
    for (std::int64_t part = begin; part < end; ++part)
    {
      std::vector<std::int32_t>& triangles = nextTriangle[part];
      std::vector<std::int32_t>& corners = nextCorner[part];
      forEachUsable(part, [&](std::int64_t t, std::int32_t a, std::int32_t b, std::int32_t c) {
        const std::int32_t slot = triangles[std::min({ a, b, c })]++;
        mesh.InputTriangle[slot] = static_cast<std::int32_t>(t);
        mesh.Triangles[3 * static_cast<std::size_t>(slot)] = a;
        mesh.Triangles[3 * static_cast<std::size_t>(slot) + 1] = b;
        mesh.Triangles[3 * static_cast<std::size_t>(slot) + 2] = c;
        adjacency.Corners[corners[a]++] = { slot, b, c };
        adjacency.Corners[corners[b]++] = { slot, c, a };
        adjacency.Corners[corners[c]++] = { slot, a, b };
      });
    }
  }, 30 * m);
}

/// Marks every triangle whose three vertices an earlier one (in input order) already has, in
/// either orientation, unusable; returns whether any was. Such triangles share their lowest
/// vertex, whose run of triangles (OrderTriangles: contiguous, in input order) is sorted by the
/// other two corners, so a fan of any size costs d log d.
bool DropDuplicateTriangles(const CompactMesh& mesh, std::vector<std::uint8_t>& usable)
{
  bool any = false;
  struct Entry
  {
    std::int32_t Low, High, Triangle; // the other two corners, sorted; the position in the run
  };
  std::vector<Entry> run;
  const std::size_t m = mesh.InputTriangle.size();
  for (std::size_t first = 0, last = 0; first < m; first = last)
  {
    const std::int32_t* tri = mesh.Triangles.data() + 3 * first;
    const std::int32_t lowest = std::min({ tri[0], tri[1], tri[2] });
    run.clear();
    for (last = first; last < m; ++last)
    {
      const std::int32_t* t = mesh.Triangles.data() + 3 * last;
      if (std::min({ t[0], t[1], t[2] }) != lowest)
      {
        break;
      }
      const std::int32_t highest = std::max({ t[0], t[1], t[2] });
      const auto middle = static_cast<std::int32_t>(
        static_cast<std::int64_t>(t[0]) + t[1] + t[2] - lowest - highest);
      run.push_back({ middle, highest, static_cast<std::int32_t>(last) });
    }
    std::sort(run.begin(), run.end(), [](const Entry& a, const Entry& b) {
      return std::tie(a.Low, a.High, a.Triangle) < std::tie(b.Low, b.High, b.Triangle);
    });
    for (std::size_t k = 1; k < run.size(); ++k)
    {
      if (run[k].Low == run[k - 1].Low && run[k].High == run[k - 1].High)
      {
        usable[mesh.InputTriangle[run[k].Triangle]] = 0;
        any = true;
      }
    }
  }
  return any;
}

/// Whether some edge is used twice in one direction (two triangles both go from v to w): the
/// triangles around it face against each other.
bool HasMisorientedEdge(const VertexTriangleAdjacency& adjacency, const ExecutionContext& context)
{
  const std::int64_t n = static_cast<std::int64_t>(adjacency.Offsets.size()) - 1;
  std::vector<std::uint8_t> found(
    static_cast<std::size_t>(std::max<std::int64_t>(1, context.Threads)), 0);
  context.ForEachWithScratch(found, n, 20, [&](std::int64_t v, std::uint8_t& any) {
    if (any)
    {
      return;
    }
    FanLookup byNext;
    const Corner* first = adjacency.Begin(v);
    const auto nextAt = [first](std::int32_t i) { return first[i].Next; };
    const std::int32_t degree = static_cast<std::int32_t>(adjacency.End(v) - first);
    byNext.Reset(degree, nextAt);
    any = byNext.HasRepeat(nextAt);
  });
  return std::find(found.begin(), found.end(), 1) != found.end();
}

/// Across each edge k of each triangle t, at 3 t + k: the one other triangle sharing it (-1 when
/// the edge is open or has more), and whether that one runs along it in the same direction (so
/// faces against t). The edges are sorted by their ends, so a fan of any size costs d log d.
void ManifoldNeighbours(const CompactMesh& mesh, std::vector<std::int32_t>& across,
  std::vector<std::uint8_t>& same)
{
  struct Edge
  {
    std::int32_t Low, High, Slot; // Slot = 3 t + k
    bool Upward;                  // runs from Low to High
  };
  const std::size_t slots = mesh.Triangles.size();
  std::vector<Edge> edges(slots);
  for (std::size_t slot = 0; slot < slots; ++slot)
  {
    const std::int32_t a = mesh.Triangles[slot];
    const std::int32_t b = mesh.Triangles[slot - slot % 3 + (slot % 3 + 1) % 3];
    edges[slot] = { std::min(a, b), std::max(a, b), static_cast<std::int32_t>(slot), a < b };
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return std::tie(x.Low, x.High, x.Slot) < std::tie(y.Low, y.High, y.Slot);
  });
  across.assign(slots, -1);
  same.assign(slots, 0);
  for (std::size_t first = 0, last = 0; first < slots; first = last)
  {
    for (last = first + 1; last < slots && edges[last].Low == edges[first].Low &&
         edges[last].High == edges[first].High;
         ++last)
    {
    }
    if (last - first == 2)
    {
      const Edge& x = edges[first];
      const Edge& y = edges[first + 1];
      across[x.Slot] = y.Slot / 3;
      across[y.Slot] = x.Slot / 3;
      same[x.Slot] = same[y.Slot] = x.Upward == y.Upward ? 1 : 0;
    }
  }
}

/// Turns triangle t over: its corners b and c swap, in the list and in its corners' slots.
void Flip(CompactMesh& mesh, std::int32_t t)
{
  std::int32_t* tri = mesh.Triangles.data() + 3 * static_cast<std::size_t>(t);
  std::swap(tri[1], tri[2]);
  for (int k = 0; k < 3; ++k)
  {
    for (Corner* c = mesh.Adjacency.Corners.data() + mesh.Adjacency.Offsets[tri[k]];
         c != mesh.Adjacency.Corners.data() + mesh.Adjacency.Offsets[tri[k] + 1]; ++c)
    {
      if (c->Triangle == t)
      {
        std::swap(c->Next, c->Previous);
      }
    }
  }
}

/// Makes the orientation consistent across manifold edges where some edge is used twice in one
/// direction: each connected part is walked from its first triangle, a triangle facing against
/// a visited neighbour being marked to turn over; then the part keeps the orientation most of
/// its triangles have, and the others turn. On a non-orientable part (a Moebius strip) the walk
/// leaves the edges it cannot mend as they were.
void OrientConsistently(CompactMesh& mesh, const ExecutionContext& context)
{
  if (!HasMisorientedEdge(mesh.Adjacency, context))
  {
    return;
  }
  const std::int32_t m = static_cast<std::int32_t>(mesh.InputTriangle.size());
  std::vector<std::int32_t> across;
  std::vector<std::uint8_t> same;
  ManifoldNeighbours(mesh, across, same); // parts are independent: one part's flips change none
  std::vector<std::int8_t> flip(static_cast<std::size_t>(m), -1); // -1: not reached yet
  std::vector<std::int32_t> part;
  for (std::int32_t seed = 0; seed < m; ++seed)
  {
    if (flip[seed] >= 0)
    {
      continue;
    }
    flip[seed] = 0;
    part.assign(1, seed);
    for (std::size_t next = 0; next < part.size(); ++next)
    {
      const std::int32_t t = part[next];
      for (std::size_t slot = 3 * static_cast<std::size_t>(t); slot < 3 * static_cast<std::size_t>(t) + 3; ++slot)
      {
        const std::int32_t s = across[slot];
        if (s >= 0 && flip[s] < 0)
        {
          flip[s] = static_cast<std::int8_t>(flip[t] ^ same[slot]);
          part.push_back(s);
        }
      }
    }
    const std::size_t flipped = static_cast<std::size_t>(
      std::count_if(part.begin(), part.end(), [&](std::int32_t t) { return flip[t] == 1; }));
    const std::int8_t turn = 2 * flipped > part.size() ? 0 : 1; // the minority turns over
    for (const std::int32_t t : part)
    {
      if (flip[t] == turn)
      {
        Flip(mesh, t);
      }
    }
  }
}

/// Each vertex's position: the first vertex (in mesh order) at exactly its place, itself when it
/// is alone there; empty when every vertex is alone. Coincident vertices share a Morton cell
/// (OrderVertices), so each cell's vertices are looked up in a hash table of their own.
std::vector<std::int32_t> CoincidentVertices(
  const CompactMesh& mesh, const std::vector<std::int32_t>& cellEnds, const ExecutionContext& context)
{
  struct Scratch
  {
    std::vector<std::int32_t> Table; // open addressing, -1: empty
    bool Any = false;
  };
  const auto hash = [](const Eigen::Vector3d& p) {
    std::uint64_t h = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double c = p[axis] + 0.0; // -0 as +0
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits ^ (bits >> 32)) * 0x9E3779B97F4A7C15ull;
    }
    return (h ^ (h >> 32)) * 0xBF58476D1CE4E5B9ull >> 32; // every bit of the input stirs the high bits
  };
  std::vector<std::int32_t> positionOf(mesh.Points.size());
  std::iota(positionOf.begin(), positionOf.end(), 0);
  std::vector<Scratch> scratches;
  const auto cells = static_cast<std::int64_t>(cellEnds.size());
  context.ForEachWithScratch(scratches, cells, 20, [&](std::int64_t c, Scratch& scratch) {
    const std::int32_t begin = c > 0 ? cellEnds[c - 1] : 0, end = cellEnds[c];
    if (end - begin < 2)
    {
      return;
    }
    std::size_t size = 4;
    while (size < 2 * static_cast<std::size_t>(end - begin))
    {
      size *= 2;
    }
    scratch.Table.assign(size, -1);
    for (std::int32_t v = begin; v < end; ++v)
    {
      std::size_t slot = hash(mesh.Points[v]) & (size - 1);
      while (scratch.Table[slot] >= 0 && mesh.Points[scratch.Table[slot]] != mesh.Points[v])
      {
        slot = (slot + 1) & (size - 1);
      }
      if (scratch.Table[slot] >= 0)
      {
        positionOf[v] = scratch.Table[slot];
        scratch.Any = true;
      }
      else
      {
        scratch.Table[slot] = v;
      }
    }
  });
  const bool any = std::any_of(scratches.begin(), scratches.end(), [](const Scratch& s) { return s.Any; });
  return any ? positionOf : std::vector<std::int32_t>();
}

/// An open border edge with an end at a shared position, keyed by the positions of its ends.
struct CrackEdge
{
  std::int32_t Low, High; // the positions (see CoincidentVertices) of its ends, Low < High
  std::int32_t From, To;  // its vertices, in its triangle's direction
  std::int32_t Opposite;  // its triangle's third vertex
  bool operator<(const CrackEdge& other) const
  {
    return std::tie(this->Low, this->High, this->From, this->To) <
      std::tie(other.Low, other.High, other.From, other.To);
  }
  bool SamePositions(const CrackEdge& other) const { return this->Low == other.Low && this->High == other.High; }
};

/// The open border edges that touch a vertex sharing its position with another, each once,
/// sorted by the positions of their ends: the two sides of a crack are then neighbours. Edges
/// of a triangle with two corners at one position (a needle) are no crack's side.
std::vector<CrackEdge> CrackEdges(const CompactMesh& mesh, const std::vector<std::int32_t>& positionOf)
{
  const std::int32_t n = static_cast<std::int32_t>(positionOf.size());
  std::vector<std::uint8_t> shared(static_cast<std::size_t>(n), 0);
  for (std::int32_t v = 0; v < n; ++v)
  {
    shared[v] |= positionOf[v] != v ? 1 : 0;
    shared[positionOf[v]] |= positionOf[v] != v ? 1 : 0;
  }
  std::vector<CrackEdge> edges;
  const auto add = [&](std::int32_t from, std::int32_t to, std::int32_t opposite) {
    const std::int32_t a = positionOf[from], b = positionOf[to], c = positionOf[opposite];
    if (a != b && c != a && c != b)
    {
      edges.push_back({ std::min(a, b), std::max(a, b), from, to, opposite });
    }
  };
  std::vector<std::uint8_t> flags;
  for (std::int32_t v = 0; v < n; ++v)
  {
    if (!shared[v])
    {
      continue;
    }
    const Corner* corner = mesh.Adjacency.Begin(v);
    flags.resize(static_cast<std::size_t>(mesh.Adjacency.End(v) - corner));
    MarkBoundaryCorners(mesh.Adjacency, v, flags.data());
    for (std::size_t i = 0; i < flags.size(); ++i)
    {
      if (flags[i] & OutgoingBoundaryEdge)
      {
        add(v, corner[i].Next, corner[i].Previous);
      }
      if ((flags[i] & IncomingBoundaryEdge) && !shared[corner[i].Previous]) // else listed there
      {
        add(corner[i].Previous, v, corner[i].Next);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

/// Vertex sets joined by a union-find forest (each set stands for its lowest vertex).
struct JoinedSets
{
  std::vector<std::int32_t> Root;
  bool Turned = false; // a join of sides that run alike (one turned over) was made
  explicit JoinedSets(std::size_t n) : Root(n) { std::iota(this->Root.begin(), this->Root.end(), 0); }
  std::int32_t Find(std::int32_t v)
  {
    while (this->Root[v] != v)
    {
      v = this->Root[v] = this->Root[this->Root[v]];
    }
    return v;
  }
  void Unite(std::int32_t p, std::int32_t q)
  {
    const std::int32_t a = this->Find(p), b = this->Find(q);
    this->Root[std::max(a, b)] = std::min(a, b);
  }
};

/// Whether the triangles of two border edges along one segment lie apart around it: their third
/// vertices more than 60 degrees apart seen along the edge, as a crack's two sides are however
/// each is turned, well clear of rounding at any crease of 90 degrees or blunter; two copies of
/// one sheet lie on top of each other (0 degrees). Each vector is scaled by its largest component
/// first, so no product over- or underflows.
bool LieApart(const CompactMesh& mesh, const CrackEdge& a, const CrackEdge& b)
{
  const Eigen::Vector3d start = mesh.Points[a.From];
  const Eigen::Vector3d along = (mesh.Points[a.To] - start).stableNormalized();
  const auto across = [&](std::int32_t opposite) {
    const Eigen::Vector3d d = mesh.Points[opposite] - start;
    const Eigen::Vector3d side = d - d.dot(along) * along;
    const double largest = side.cwiseAbs().maxCoeff();
    return largest > 0.0 ? Eigen::Vector3d(side / largest) : Eigen::Vector3d::Zero();
  };
  const Eigen::Vector3d sideA = across(a.Opposite), sideB = across(b.Opposite);
  return sideA.dot(sideB) < 0.5 * sideA.norm() * sideB.norm();
}

/**
 * Joins the two sides of each crack that may close: two border edges between the same two
 * positions, and no third, that run in opposite directions (as the sides of a cut through a
 * consistently oriented surface do) or, with allowTurned, where the triangles' orientations
 * disagree, alike with the triangles apart around the edge (LieApart; two copies of one sheet
 * run alike on top of each other, and stay apart); and whose ends' two vertices are one already
 * or may become one (mayMerge, and neither refused). A pair joins only along a side that
 * closes, so a joined vertex's fan stays one fan (no bow-tie where the crack's neighbours stay
 * apart); turned triangles are turned to agree afterwards (OrientConsistently). False when
 * nothing joins.
 */
bool JoinCrackSides(const CompactMesh& mesh, const std::vector<CrackEdge>& edges, const PointMergeTest& mayMerge,
  const std::vector<std::uint8_t>& refused, bool allowTurned, JoinedSets& sets)
{
  const auto mergeable = [&](std::int32_t p, std::int32_t q) {
    return p == q || (!refused[p] && !refused[q] && mayMerge(mesh.InputVertex[p], mesh.InputVertex[q]));
  };
  bool any = false;
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j)
  {
    while (j < edges.size() && edges[j].SamePositions(edges[i]))
    {
      ++j;
    }
    if (j - i != 2)
    {
      continue;
    }
    const CrackEdge& a = edges[i];
    const CrackEdge& b = edges[i + 1];
    const bool opposite = mesh.Points[a.From] == mesh.Points[b.To]; // a runs from where b ends
    const std::int32_t atFrom = opposite ? b.To : b.From, atTo = opposite ? b.From : b.To;
    if ((opposite || (allowTurned && LieApart(mesh, a, b))) && mergeable(a.From, atFrom) && mergeable(a.To, atTo))
    {
      sets.Unite(a.From, atFrom);
      sets.Unite(a.To, atTo);
      sets.Turned = sets.Turned || !opposite;
      any = true;
    }
  }
  return any;
}

/// The vertices of edges that the joins would make of several, with more than two triangles (a
/// hinge made of cracks that meet, two sheets' rim triangles folded onto each other): joining
/// them would make the surface non-manifold where the input was not. Empty when none.
std::vector<std::int32_t> OverfullJoinedEdges(const CompactMesh& mesh, JoinedSets& sets)
{
  struct JoinedEdge
  {
    std::int32_t Low, High, From, To; // the roots of its ends, Low < High; its vertices
  };
  const std::int32_t n = static_cast<std::int32_t>(sets.Root.size());
  std::vector<std::uint8_t> joined(static_cast<std::size_t>(n), 0);
  for (std::int32_t v = 0; v < n; ++v)
  {
    joined[v] |= sets.Find(v) != v ? 1 : 0;
    joined[sets.Find(v)] |= sets.Find(v) != v ? 1 : 0;
  }
  std::vector<JoinedEdge> edges;
  std::vector<std::uint8_t> seen(mesh.Triangles.size() / 3, 0);
  for (std::int32_t v = 0; v < n; ++v)
  {
    for (const Corner* c = mesh.Adjacency.Begin(v); joined[v] && c != mesh.Adjacency.End(v); ++c)
    {
      if (seen[c->Triangle]++)
      {
        continue;
      }
      const std::int32_t* tri = mesh.Triangles.data() + 3 * c->Triangle;
      const std::int32_t r[3] = { sets.Find(tri[0]), sets.Find(tri[1]), sets.Find(tri[2]) };
      for (int k = 0; k < 3 && r[0] != r[1] && r[1] != r[2] && r[2] != r[0]; ++k)
      {
        const std::int32_t a = r[k], b = r[(k + 1) % 3];
        edges.push_back({ std::min(a, b), std::max(a, b), tri[k], tri[(k + 1) % 3] });
      }
    }
  }
  std::sort(edges.begin(), edges.end(), [](const JoinedEdge& x, const JoinedEdge& y) {
    return std::tie(x.Low, x.High, x.From, x.To) < std::tie(y.Low, y.High, y.From, y.To);
  });
  std::vector<std::int32_t> overfull;
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j)
  {
    while (j < edges.size() && edges[j].Low == edges[i].Low && edges[j].High == edges[i].High)
    {
      ++j;
    }
    // Only where the joins made one edge of several (an input's own hinge is kept, as without
    // joins; two triangles in one direction are turned to agree by OrientConsistently).
    const auto original = [](const JoinedEdge& e) { return std::minmax(e.From, e.To); };
    bool made = false;
    for (std::size_t k = i + 1; k < j; ++k)
    {
      made = made || original(edges[k]) != original(edges[i]);
    }
    if (made && j - i > 2)
    {
      for (std::size_t k = i; k < j; ++k)
      {
        overfull.insert(overfull.end(), { edges[k].From, edges[k].To });
      }
    }
  }
  return overfull;
}

/**
 * Closes zero-width cracks (JoinCrackSides), refusing the vertices of any edge the joins would
 * make non-manifold and joining again without them, until the joins keep every edge manifold.
 * mayMerge is taken as transitive: a set of coincident vertices joins as one when each join
 * along the cracks is allowed. Returns each input point's replacement (-1: kept), empty when
 * none joins. Time: n log n in the border edges at shared positions, per round of refusals.
 */
std::vector<std::int32_t> CrackJoins(const CompactMesh& mesh, std::int64_t inputPoints,
  const std::vector<CrackEdge>& edges, const PointMergeTest& mayMerge, bool allowTurned, bool& turned)
{
  std::vector<std::uint8_t> refused(mesh.Points.size(), 0);
  for (;;)
  {
    JoinedSets sets(mesh.Points.size());
    if (!JoinCrackSides(mesh, edges, mayMerge, refused, allowTurned, sets))
    {
      return {};
    }
    const std::vector<std::int32_t> overfull = OverfullJoinedEdges(mesh, sets);
    if (overfull.empty())
    {
      turned = sets.Turned;
      std::vector<std::int32_t> replacement(static_cast<std::size_t>(inputPoints), -1);
      for (std::int32_t v = 0; v < static_cast<std::int32_t>(sets.Root.size()); ++v)
      {
        replacement[mesh.InputVertex[v]] = sets.Find(v) != v ? mesh.InputVertex[sets.Find(v)] : -1;
      }
      return replacement;
    }
    for (const std::int32_t v : overfull)
    {
      refused[v] = 1;
    }
  }
}

template <typename PointType, typename IdType>
CompactMesh BuildCompactMesh(
  const TypedView<PointType, IdType>& input, const PointMergeTest& mayMerge, const ExecutionContext& context);

/// The compact mesh made anew from the input with the joined points replaced in its triangles
/// (those that spanned a crack become degenerate and are dropped), oriented.
template <typename PointType, typename IdType>
CompactMesh RebuildJoined(const TypedView<PointType, IdType>& input, const std::vector<std::int32_t>& replacement,
  const ExecutionContext& context)
{
  const std::int64_t n = input.NumberOfPoints;
  std::vector<IdType> ids(3 * static_cast<std::size_t>(input.NumberOfTriangles));
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    const std::int64_t id = input.Id(static_cast<std::int64_t>(k));
    ids[k] = id >= 0 && id < n && replacement[id] >= 0 ? static_cast<IdType>(replacement[id]) : input.Ids[k];
  }
  CompactMesh joined = BuildCompactMesh(
    TypedView<PointType, IdType>{ input.Points, ids.data(), n, input.NumberOfTriangles }, {}, context);
  joined.JoinedPoints = std::count_if(replacement.begin(), replacement.end(), [](std::int32_t r) { return r >= 0; });
  return joined;
}

template <typename PointType, typename IdType>
CompactMesh BuildCompactMesh(
  const TypedView<PointType, IdType>& input, const PointMergeTest& mayMerge, const ExecutionContext& context)
{
  CompactMesh mesh;
  std::vector<std::uint8_t> usable = MarkUsable(input, mesh, context);
  std::vector<std::int32_t> vertexOf;
  const std::vector<std::int32_t> cellEnds = OrderVertices(input, usable, mesh, vertexOf, context);
  OrderTriangles(input, usable, vertexOf, mesh, context);
  if (DropDuplicateTriangles(mesh, usable))
  {
    OrderTriangles(input, usable, vertexOf, mesh, context);
  }
  const std::vector<std::int32_t> positionOf =
    mayMerge ? CoincidentVertices(mesh, cellEnds, context) : std::vector<std::int32_t>();
  const std::vector<CrackEdge> edges = positionOf.empty() ? std::vector<CrackEdge>() : CrackEdges(mesh, positionOf);
  // Joins of turned sides are kept only where the surface they make can be oriented (a Möbius
  // strip's seam stays open); else the cracks are closed again without them.
  for (const bool allowTurned : { true, false })
  {
    bool turned = false;
    const std::vector<std::int32_t> replacement = edges.empty()
      ? std::vector<std::int32_t>()
      : CrackJoins(mesh, input.NumberOfPoints, edges, mayMerge, allowTurned, turned);
    if (replacement.empty())
    {
      break;
    }
    CompactMesh joined = RebuildJoined(input, replacement, context);
    if (!turned || !HasMisorientedEdge(joined.Adjacency, context))
    {
      return joined;
    }
  }
  OrientConsistently(mesh, context);
  return mesh;
}
} // namespace

CompactMesh MakeCompactMesh(
  const TriangleMeshView& input, const ExecutionContext& context, const PointMergeTest& mayMerge)
{
  const std::int64_t n = input.NumberOfPoints, m = input.NumberOfTriangles;
  if (input.Points)
  {
    return input.Triangles
      ? BuildCompactMesh(TypedView<double, std::int32_t>{ input.Points, input.Triangles, n, m }, mayMerge, context)
      : BuildCompactMesh(TypedView<double, long long>{ input.Points, input.Triangles64, n, m }, mayMerge, context);
  }
  return input.Triangles
    ? BuildCompactMesh(TypedView<float, std::int32_t>{ input.FloatPoints, input.Triangles, n, m }, mayMerge, context)
    : BuildCompactMesh(TypedView<float, long long>{ input.FloatPoints, input.Triangles64, n, m }, mayMerge, context);
}

} // namespace meshsimp
