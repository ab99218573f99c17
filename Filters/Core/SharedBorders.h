// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SharedBorders.h
 * @brief The border round of a surface simplified in pieces (MPI ranks, composite blocks): the
 * curves along which the pieces meet, kept whole by every piece's own simplification, are
 * simplified afterwards on every piece at once, so that the pieces still fit together and the
 * whole meets its count.
 *
 * Each piece's simplification locks the points it shares with another piece (LockSharedPoints
 * in the VTK layer), so its border keeps the input's resolution, and the pieces together would
 * end far above their count at a strong reduction. The border round removes shared points by
 * half-edge collapses along the curve: a point x between its curve neighbours p and n goes into
 * p or n (each piece picks the legal one whose new triangles stay nearest x), which makes the
 * curve's edge p–n on every side, so the sides still match edge for edge and no point moves.
 *
 * The round is the same on every process (only its exchanges are collective, through
 * BorderExchange):
 *  1. every piece lists its shared points and the border edges between them (Describe); the
 *     gathered lists make the curves (SharedCurves), the same everywhere. A point is removable
 *     when exactly two pieces hold it and its two curve edges: junctions of three pieces, ends
 *     at an open border, and points where a piece only touches stay;
 *  2. each round, every piece prices the removable points it holds (the distance from x to its
 *     new triangles; infinite where no collapse passes the engine's checks, the piece's regions
 *     and the shared-edge rule, or where a piece that holds both of x's neighbours already joins
 *     them by an edge), the largest price over the pieces counts; the cheapest points, no two
 *     adjacent on a curve, are chosen up to the count still to remove;
 *  3. each piece makes the chosen removals in that order, each one checked on the mesh the ones
 *     before it left, and refuses those that fail; a point goes where every piece that holds it
 *     made it. A piece that made a removal another refused undoes its removals, and every piece
 *     tries again without the refused ones, until the pieces agree (the first chosen point always
 *     passes, so each round removes at least one);
 *  4. rounds go on until the count is removed or no point is agreed.
 * The output points' sources grow by the removed points' (weight 0): they are represented by the
 * point they went into.
 */
#ifndef MeshSimplification_SharedBorders_h
#define MeshSimplification_SharedBorders_h

#include "CollapseMesh.h"
#include "Simplification.h"

#include <array>
#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace meshsimp
{

/// A shared point's place: the key of the surface its piece belongs to, then its coordinates.
using BorderPlace = std::array<double, 4>;

/// The curves where pieces meet, built alike on every process from every piece's Describe.
class SharedCurves
{
public:
  /// places: 4 values per shared point of each piece (a point held by two pieces is listed
  /// twice); edges: 8 per border edge between shared points of each piece.
  void Build(const std::vector<double>& places, const std::vector<double>& edges);

  std::int32_t NumberOfPoints() const { return static_cast<std::int32_t>(this->Places.size()); }
  /// The point's id, or -1.
  std::int32_t Find(const BorderPlace& place) const;
  /// A removable point's two curve neighbours.
  const std::array<std::int32_t, 2>& Ends(std::int32_t point) const { return this->Neighbours[point]; }
  /// The removable points still on the curves, in id order.
  const std::vector<std::int32_t>& Removable() const { return this->Candidates; }

  /// The cheapest removable points (costs follow Removable), no two adjacent on a curve and none
  /// of infinite cost, at most count of them, in the order chosen.
  std::vector<std::int32_t> Choose(const std::vector<double>& costs, std::int64_t count) const;
  /// Takes the points off the curves: their neighbours become adjacent.
  void Remove(const std::vector<std::int32_t>& points);

private:
  std::vector<BorderPlace> Places;
  std::vector<std::array<std::int32_t, 2>> Neighbours; // of removable points
  std::vector<std::uint8_t> Alive;                     // removable and not removed yet
  std::vector<std::int32_t> Candidates;                // the alive points, in id order
  std::set<std::pair<std::int32_t, std::int32_t>> Edges; // the curves' edges, (lower, higher)
};

/// One piece's side of the border round: its result, edited in place.
class PieceBorders
{
public:
  /**
   * mesh: the piece's simplified result; input: the triangles it was made from; locks: per input
   * point, SharedPointLock on the points shared with another piece that the round may remove
   * (not those the user locked too); regions: per input point, or null; key: the surface the
   * piece belongs to.
   */
  PieceBorders(SimplifiedMesh& mesh, const TriangleMeshView& input, const std::uint8_t* locks,
    const std::int32_t* regions, double key);

  /// Appends the piece's shared points and border edges between them (see SharedCurves::Build).
  void Describe(std::vector<double>& places, std::vector<double>& edges) const;
  /// Finds the curves' points in the piece.
  void Bind(const SharedCurves& curves);
  /// For each removable point the piece holds, costs[k] becomes the larger of it and the
  /// piece's price (infinite where the piece cannot remove it).
  void Price(const SharedCurves& curves, std::vector<double>& costs) const;
  /// Removes, in order, the chosen points the piece holds and no piece refused yet (accepted[k]
  /// nonzero), each checked on the mesh the ones before left; sets accepted[k] to 0 for those
  /// that fail. The removals stay tentative until Commit or Revert.
  void Claim(const SharedCurves& curves, const std::vector<std::int32_t>& chosen, std::vector<double>& accepted);
  /// Whether every tentative removal is one the pieces accepted.
  bool Agrees(const std::vector<double>& accepted) const;
  /// Undoes the tentative removals.
  void Revert();
  /// Keeps the tentative removals.
  void Commit(const std::vector<std::int32_t>& chosen);
  /// Writes the edited mesh back into the result (nothing when no point was removed).
  void Finish();

private:
  /// The legal removal of the piece's vertex of curve point x nearest the surface it leaves, as a
  /// plan; false when none passes.
  bool BestRemoval(const SharedCurves& curves, std::int32_t point, CollapsePlan& plan, double& cost) const;
  bool KeepsSharedEdges(std::int32_t removed, std::int32_t kept, std::int32_t otherEnd) const;
  /// Per output point, the output point it went into (itself where it stays).
  std::vector<std::int32_t> Destinations() const;

  SimplifiedMesh& Mesh;
  CollapseMesh Edited;
  std::vector<std::int32_t> OutputPoint;  // per vertex of Edited
  std::vector<std::int32_t> Vertex;       // per output point (-1: in no usable triangle)
  std::vector<std::int32_t> TriangleOf;   // per output triangle, Edited's (-1: none)
  std::vector<std::uint8_t> Shared;       // per vertex of Edited
  std::vector<BorderPlace> SharedPlace;   // per vertex of Edited (meaningful where Shared)
  std::vector<std::int32_t> CurveVertex;  // per curve point, the piece's vertex or -1
  std::vector<std::size_t> Tentative;     // the chosen points (their places in the list) removed
  bool Changed = false;
};

/// The collective steps of the border round (identity for a single process).
struct BorderExchange
{
  /// Every process's values, in process order.
  std::function<std::vector<double>(const std::vector<double>&)> Gather = [](const std::vector<double>& v) { return v; };
  /// Element-wise maximum and minimum over the processes, in place.
  std::function<void(std::vector<double>&)> Maximum = [](std::vector<double>&) {};
  std::function<void(std::vector<double>&)> Minimum = [](std::vector<double>&) {};
};

/**
 * The border round over this process's pieces (collective: every process calls it, with the
 * same count). count: the triangles to remove over all pieces of all processes (two a point).
 * Returns the triangles removed.
 */
std::int64_t SimplifySharedBorders(std::vector<PieceBorders*>& pieces, std::int64_t count, const BorderExchange& exchange);

} // namespace meshsimp

#endif
