// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TriangleMesh.h
 * @brief Triangle-mesh views and adjacency in flat arrays, shared by all filters.
 *
 * Indices are 32-bit: the core serves meshes of up to 2^31 − 1 points and MaximumTriangles
 * triangles (the adjacency counts three corners per triangle in 32 bits). Algorithms
 * take an input view, make a compact, spatially ordered copy of its usable part and walk its
 * vertex→triangle adjacency: a CSR of corners (offsets + one {triangle, next, previous} per
 * incident triangle) built by counting, so it costs two flat arrays and no per-vertex
 * allocation.
 */
#ifndef MeshSimplification_TriangleMesh_h
#define MeshSimplification_TriangleMesh_h

#include "Execution.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace meshsimp
{

/// The most triangles an input may have (usable or not): their corners, three each, are
/// counted in 32 bits. Callers check it; the VTK filters refuse larger inputs with an error.
constexpr std::int64_t MaximumTriangles = std::numeric_limits<std::int32_t>::max() / 3;

/// The value of a point's flag in the algorithms' LockedPoints that marks it as shared with
/// another piece of a distributed mesh: locked, and (collapse filters) never joined to another
/// shared point by a new edge, which the other piece could make too. Other nonzero values lock.
constexpr std::uint8_t SharedPointLock = 2;

/// A read-only view of an indexed triangle mesh: 3 coordinates per point, 3 ids per triangle.
/// Input meshes may give single-precision points (FloatPoints instead of Points) and 64-bit ids
/// (Triangles64 instead of Triangles), so that callers need not copy them; algorithms read an
/// input through MakeCompactMesh, which accepts either.
struct TriangleMeshView
{
  const double* Points = nullptr;
  std::int64_t NumberOfPoints = 0;
  const std::int32_t* Triangles = nullptr;
  std::int64_t NumberOfTriangles = 0;
  const float* FloatPoints = nullptr;
  const long long* Triangles64 = nullptr; // the type of VTK's 64-bit ids

  Eigen::Vector3d Point(std::int64_t i) const
  {
    if (this->Points)
    {
      return { this->Points[3 * i], this->Points[3 * i + 1], this->Points[3 * i + 2] };
    }
    return { this->FloatPoints[3 * i], this->FloatPoints[3 * i + 1], this->FloatPoints[3 * i + 2] };
  }
  /// Id number i of the flat triangle list (corner i % 3 of triangle i / 3).
  std::int64_t Id(std::int64_t i) const
  {
    return this->Triangles ? this->Triangles[i] : static_cast<std::int64_t>(this->Triangles64[i]);
  }
};

/// Whether triangle t of a view can be used: three distinct point ids in range, three finite
/// corners.
inline bool UsableTriangle(const TriangleMeshView& mesh, std::int64_t t)
{
  const std::int64_t ids[3] = { mesh.Id(3 * t), mesh.Id(3 * t + 1), mesh.Id(3 * t + 2) };
  for (int k = 0; k < 3; ++k)
  {
    if (ids[k] < 0 || ids[k] >= mesh.NumberOfPoints || ids[k] == ids[(k + 1) % 3] || !mesh.Point(ids[k]).allFinite())
    {
      return false;
    }
  }
  return true;
}

/// One triangle around a vertex v: its id and its other corners, so that the triangle reads
/// (v, Next, Previous) in its own orientation.
struct Corner
{
  std::int32_t Triangle, Next, Previous;
};

/**
 * Positions by vertex id in the list of ids around one vertex (a fan's next or previous
 * corners, read through idAt(position)): a scan while the list is short, a binary search in its
 * (id, position) pairs sorted once when it is long, so that a fan of thousands of triangles
 * around one vertex costs n log n rather than n². Reuse one lookup per thread: it keeps its
 * memory.
 */
class FanLookup
{
public:
  /// Lists up to this long are scanned.
  static constexpr std::int32_t ScanLimit = 32;

  /// Indexes idAt(0), ..., idAt(count − 1).
  template <typename IdAt>
  void Reset(std::int32_t count, const IdAt& idAt)
  {
    this->Size = count;
    this->Sorted.clear();
    if (count > ScanLimit)
    {
      for (std::int32_t i = 0; i < count; ++i)
      {
        this->Sorted.emplace_back(idAt(i), i);
      }
      std::sort(this->Sorted.begin(), this->Sorted.end());
    }
  }

  /// The first position holding w (−1 when none), with the same idAt as Reset; count, when
  /// given, receives how many hold it, counted up to two.
  template <typename IdAt>
  std::int32_t Find(std::int32_t w, const IdAt& idAt, int* count = nullptr) const
  {
    std::int32_t first = -1;
    int found = 0;
    if (this->Size > ScanLimit)
    {
      for (auto it = std::lower_bound(this->Sorted.begin(), this->Sorted.end(), std::make_pair(w, std::int32_t(0)));
           it != this->Sorted.end() && it->first == w && found < 2; ++it, ++found)
      {
        first = first < 0 ? it->second : first;
      }
    }
    else
    {
      for (std::int32_t i = 0; i < this->Size && found < 2 && (count || found == 0); ++i)
      {
        if (idAt(i) == w)
        {
          first = first < 0 ? i : first;
          ++found;
        }
      }
    }
    if (count)
    {
      *count = found;
    }
    return first;
  }

  /// Whether an id appears twice, with the same idAt as Reset: pairs compared while the list is
  /// short, neighbours in the sorted list when it is long.
  template <typename IdAt>
  bool HasRepeat(const IdAt& idAt) const
  {
    if (this->Size > ScanLimit)
    {
      return std::adjacent_find(this->Sorted.begin(), this->Sorted.end(),
               [](const auto& a, const auto& b) { return a.first == b.first; }) != this->Sorted.end();
    }
    bool repeat = false;
    for (std::int32_t i = 1; i < this->Size; ++i)
    {
      const std::int32_t w = idAt(i);
      for (std::int32_t j = 0; j < i; ++j)
      {
        repeat |= idAt(j) == w;
      }
    }
    return repeat;
  }

private:
  std::int32_t Size = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> Sorted;
};

/// Vertex → incident triangles with their other corners, as CSR arrays, so that walks around a
/// vertex never go back to the triangle list. MakeCompactMesh builds it.
struct VertexTriangleAdjacency
{
  std::vector<std::int32_t> Offsets; // NumberOfPoints + 1
  std::vector<Corner> Corners;       // per vertex, in the order its triangles were added
  const Corner* Begin(std::int64_t v) const { return this->Corners.data() + this->Offsets[v]; }
  const Corner* End(std::int64_t v) const { return this->Corners.data() + this->Offsets[v + 1]; }
};

/**
 * The usable part of an input mesh, renumbered for memory locality. A triangle is usable when
 * its three indices are distinct and in range and its corners are finite; every algorithm skips
 * the others (they count as dropped input). Vertices used by a usable triangle are ordered by
 * the Morton code of a coarse grid over their bounding cube (input order within a grid cell), and
 * triangles by their lowest vertex, so walks over the adjacency of one region of space touch
 * nearby memory: on a badly ordered scan this halves the run time of the octree clustering.
 * Each octree cell of the grid's depth or less holds a contiguous range of vertices. The
 * vertex → triangle adjacency is built in the same passes (corners in input triangle order).
 */
struct CompactMesh
{
  std::vector<Eigen::Vector3d> Points;     // input coordinates
  Eigen::Vector3d Lower = Eigen::Vector3d::Zero(), Upper = Eigen::Vector3d::Zero(); // their box
  std::vector<std::int32_t> Triangles;     // 3 per triangle
  std::vector<std::int32_t> InputVertex;   // vertex → input point
  std::vector<std::int32_t> InputTriangle; // triangle → input triangle
  std::int64_t NonFinitePoints = 0;        // input points with a NaN or infinite coordinate
  std::int64_t JoinedPoints = 0;           // input points joined to another to close a crack
  VertexTriangleAdjacency Adjacency;

  /// The box's diagonal, also where its square would over- or underflow (coordinates beyond
  /// about 1e150 or below 1e-150, whose normalisation would otherwise divide by inf or 0). A
  /// diagonal beyond the largest double (coordinates near ±1.8e308) is given as that largest
  /// double: normalised by it, such a box has a diagonal of at most √3·2 rather than 1.
  double Diagonal() const
  {
    const double diagonal = (this->Upper - this->Lower).norm();
    if (diagonal > 1e-150 && diagonal < 1e150)
    {
      return diagonal;
    }
    return std::min(2.0 * (0.5 * this->Upper - 0.5 * this->Lower).stableNorm(),
      std::numeric_limits<double>::max());
  }
  /// The box's centre, also where Lower + Upper would overflow.
  Eigen::Vector3d Centre() const { return 0.5 * this->Lower + 0.5 * this->Upper; }
};

/// Whether two input points (by id) may become one vertex.
using PointMergeTest = std::function<bool(std::int64_t, std::int64_t)>;

/// The compact mesh of an input. With mayMerge, zero-width cracks are closed first: where two
/// open border edges, and no third, join the same two positions and run in opposite directions,
/// or alike (one side turned over) with their triangles more than 60 degrees apart around the
/// edge (split-off copies of points, patches stored with their own copies of a shared border,
/// soups, also with turned triangles), their coincident ends become one vertex, as if the input
/// had shared them, when mayMerge allows both pairs (it is taken as transitive). No join makes an
/// edge of more than two triangles or a vertex of two fans, and joins of turned sides are made
/// only where the result can be oriented (a Moebius strip's seam stays open). Points that only
/// touch, two copies of one sheet, creases sharper than 60 degrees between turned sides and
/// T-junctions stay apart. Coincident points are found with a hash table per Morton cell, the
/// crack's sides by sorting border edges.
CompactMesh MakeCompactMesh(
  const TriangleMeshView& input, const ExecutionContext& context = {}, const PointMergeTest& mayMerge = {});

/// The cosine of a triangle's smallest angle (the largest of its three cosines; 1 when
/// degenerate): a shape measure without trigonometry.
inline double SmallestAngleCosine(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  // The edges leaving a, b and c; the angle at a is between ab and -ca, and so on (negating a
  // vector changes no rounding, so each length and dot product is measured once).
  const Eigen::Vector3d edge[3] = { b - a, c - b, a - c };
  const double length[3] = { edge[0].norm(), edge[1].norm(), edge[2].norm() };
  double largest = -1.0;
  for (int k = 0; k < 3; ++k)
  {
    const int before = (k + 2) % 3; // the edge that arrives at corner k
    const double lengths = length[k] * length[before];
    largest = std::max(largest, lengths > 0.0 ? -edge[k].dot(edge[before]) / lengths : 1.0);
  }
  return largest;
}

/// Boundary flags of a corner slot: the triangle's edge (v, Next), resp. (Previous, v), belongs
/// to no other triangle.
enum BoundaryCorner : std::uint8_t
{
  OutgoingBoundaryEdge = 1,
  IncomingBoundaryEdge = 2
};

/**
 * Writes the BoundaryCorner flags of every corner slot around v to flags[0 .. degree(v)) and
 * returns whether any is set. An edge shared by three or more triangles, or by two of opposite
 * orientations, is not a boundary. Works one vertex at a time, so callers fuse it into their
 * own vertex loops and vertices can be processed concurrently. A fan of more than a few dozen
 * triangles is matched through FanLookup (n log n instead of n²).
 */
inline bool MarkBoundaryCorners(
  const VertexTriangleAdjacency& adjacency, std::int64_t v, std::uint8_t* flags)
{
  const Corner* first = adjacency.Begin(v);
  const Corner* last = adjacency.End(v);
  const std::size_t degree = static_cast<std::size_t>(last - first);
  std::fill(flags, flags + degree, static_cast<std::uint8_t>(OutgoingBoundaryEdge | IncomingBoundaryEdge));
  const auto nextAt = [first](std::int32_t i) { return first[i].Next; };
  const auto previousAt = [first](std::int32_t i) { return first[i].Previous; };
  FanLookup byNext, byPrevious;
  const bool large = degree > static_cast<std::size_t>(FanLookup::ScanLimit);
  if (large)
  {
    byNext.Reset(static_cast<std::int32_t>(degree), nextAt);
    byPrevious.Reset(static_cast<std::int32_t>(degree), previousAt);
  }
  // A consistently oriented neighbour o shares c's edge (v, Next) as its (Previous, v): both
  // flags are cleared at once. What is left takes the general test: another triangle around v
  // with the edge's far end as any corner.
  for (std::size_t i = 0; i < degree; ++i)
  {
    // The first match, found without an early exit (its position is unpredictable).
    std::size_t match = degree;
    if (large)
    {
      const std::int32_t found = byPrevious.Find(first[i].Next, previousAt);
      match = found >= 0 ? static_cast<std::size_t>(found) : degree;
    }
    for (std::size_t j = large ? 0 : degree; j-- > 0;)
    {
      match = first[j].Previous == first[i].Next ? j : match;
    }
    if (match < degree)
    {
      flags[i] &= static_cast<std::uint8_t>(~OutgoingBoundaryEdge);
      flags[match] &= static_cast<std::uint8_t>(~IncomingBoundaryEdge);
    }
  }
  if (std::all_of(flags, flags + degree, [](std::uint8_t f) { return f == 0; }))
  {
    return false; // every edge paired: a closed fan
  }
  bool any = false;
  for (std::size_t i = 0; i < degree; ++i)
  {
    if (large && flags[i])
    {
      // The far end as a previous corner anywhere, or as another triangle's next corner (two
      // holders, i being one); likewise for the edge into v.
      int holders = 0;
      if ((flags[i] & OutgoingBoundaryEdge) &&
        (byPrevious.Find(first[i].Next, previousAt) >= 0 ||
          (byNext.Find(first[i].Next, nextAt, &holders), holders > 1)))
      {
        flags[i] &= static_cast<std::uint8_t>(~OutgoingBoundaryEdge);
      }
      if ((flags[i] & IncomingBoundaryEdge) &&
        (byNext.Find(first[i].Previous, nextAt) >= 0 ||
          (byPrevious.Find(first[i].Previous, previousAt, &holders), holders > 1)))
      {
        flags[i] &= static_cast<std::uint8_t>(~IncomingBoundaryEdge);
      }
    }
    for (std::size_t j = 0; j < degree && flags[i] && !large; ++j)
    {
      const Corner& o = first[j];
      if ((flags[i] & OutgoingBoundaryEdge) &&
        (o.Previous == first[i].Next || (j != i && o.Next == first[i].Next)))
      {
        flags[i] &= static_cast<std::uint8_t>(~OutgoingBoundaryEdge);
      }
      if ((flags[i] & IncomingBoundaryEdge) &&
        (o.Next == first[i].Previous || (j != i && o.Previous == first[i].Previous)))
      {
        flags[i] &= static_cast<std::uint8_t>(~IncomingBoundaryEdge);
      }
    }
    any = any || flags[i] != 0;
  }
  return any;
}

} // namespace meshsimp

#endif
