// SPDX-License-Identifier: BSD-3-Clause
#include "SharedBorders.h"

#include "SurfaceSearch.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace meshsimp
{
namespace
{
constexpr double Infinite = std::numeric_limits<double>::infinity();

BorderPlace PlaceAt(const std::vector<double>& values, std::size_t i)
{
  return { values[i], values[i + 1], values[i + 2], values[i + 3] };
}

std::pair<std::int32_t, std::int32_t> Ordered(std::int32_t a, std::int32_t b)
{
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}
}

// ---------------------------------------------------------------------------------------------
// The curves

void SharedCurves::Build(const std::vector<double>& places, const std::vector<double>& edges)
{
  // Points: each distinct place, with the number of pieces that hold it.
  std::vector<BorderPlace> listed;
  for (std::size_t i = 0; i + 4 <= places.size(); i += 4)
  {
    listed.push_back(PlaceAt(places, i));
  }
  std::sort(listed.begin(), listed.end());
  std::vector<int> holders;
  for (std::size_t i = 0; i < listed.size(); ++i)
  {
    if (i == 0 || listed[i] != listed[i - 1])
    {
      this->Places.push_back(listed[i]);
      holders.push_back(0);
    }
    ++holders.back();
  }
  // Edges: each distinct pair, with the number of pieces that have it.
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  for (std::size_t i = 0; i + 8 <= edges.size(); i += 8)
  {
    const std::int32_t a = this->Find(PlaceAt(edges, i)), b = this->Find(PlaceAt(edges, i + 4));
    if (a >= 0 && b >= 0 && a != b)
    {
      pairs.push_back(Ordered(a, b));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  const std::size_t n = this->Places.size();
  std::vector<std::vector<std::int32_t>> around(n);
  std::vector<std::uint8_t> singleEdge(n, 0); // has an edge not held by exactly two pieces
  for (std::size_t i = 0; i < pairs.size();)
  {
    std::size_t j = i;
    while (j < pairs.size() && pairs[j] == pairs[i])
    {
      ++j;
    }
    const auto [a, b] = pairs[i];
    around[a].push_back(b);
    around[b].push_back(a);
    if (j - i != 2)
    {
      singleEdge[a] = singleEdge[b] = 1;
    }
    this->Edges.insert(pairs[i]);
    i = j;
  }
  // Removable: two pieces hold the point and both of its two edges.
  this->Neighbours.assign(n, { -1, -1 });
  this->Alive.assign(n, 0);
  for (std::size_t g = 0; g < n; ++g)
  {
    if (holders[g] == 2 && around[g].size() == 2 && !singleEdge[g])
    {
      this->Neighbours[g] = { around[g][0], around[g][1] };
      this->Alive[g] = 1;
      this->Candidates.push_back(static_cast<std::int32_t>(g));
    }
  }
}

std::int32_t SharedCurves::Find(const BorderPlace& place) const
{
  const auto found = std::lower_bound(this->Places.begin(), this->Places.end(), place);
  return found != this->Places.end() && *found == place ? static_cast<std::int32_t>(found - this->Places.begin()) : -1;
}

std::vector<std::int32_t> SharedCurves::Choose(const std::vector<double>& costs, std::int64_t count) const
{
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < this->Candidates.size(); ++k)
  {
    if (costs[k] < Infinite)
    {
      order.push_back(k);
    }
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return costs[a] != costs[b] ? costs[a] < costs[b] : this->Candidates[a] < this->Candidates[b];
  });
  // A chosen point's neighbours are taken with it: no two chosen points are adjacent or share
  // a neighbour. One whose neighbours are adjacent already would double their edge.
  std::vector<std::uint8_t> taken(this->Places.size(), 0);
  std::vector<std::int32_t> chosen;
  for (const std::size_t k : order)
  {
    if (static_cast<std::int64_t>(chosen.size()) >= count)
    {
      break;
    }
    const std::int32_t x = this->Candidates[k];
    const auto [p, n] = this->Neighbours[x];
    if (taken[x] || taken[p] || taken[n] || this->Edges.count(Ordered(p, n)))
    {
      continue;
    }
    taken[x] = taken[p] = taken[n] = 1;
    chosen.push_back(x);
  }
  return chosen;
}

void SharedCurves::Remove(const std::vector<std::int32_t>& points)
{
  for (const std::int32_t x : points)
  {
    const auto [p, n] = this->Neighbours[x];
    for (const auto& [end, other] : { std::make_pair(p, n), std::make_pair(n, p) })
    {
      if (this->Alive[end])
      {
        std::array<std::int32_t, 2>& ends = this->Neighbours[end];
        ends[ends[0] == x ? 0 : 1] = other;
      }
    }
    this->Edges.erase(Ordered(p, x));
    this->Edges.erase(Ordered(x, n));
    this->Edges.insert(Ordered(p, n));
    this->Alive[x] = 0;
  }
  this->Candidates.erase(std::remove_if(this->Candidates.begin(), this->Candidates.end(),
                           [this](std::int32_t g) { return !this->Alive[g]; }),
    this->Candidates.end());
}

// ---------------------------------------------------------------------------------------------
// One piece

PieceBorders::PieceBorders(SimplifiedMesh& mesh, const TriangleMeshView& input, const std::uint8_t* locks,
  const std::int32_t* regions, double key)
  : Mesh(mesh)
{
  const TriangleMeshView result{ mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(),
    mesh.NumberOfTriangles() };
  CompactMesh compact = MakeCompactMesh(result);
  this->OutputPoint = compact.InputVertex;
  this->Vertex.assign(static_cast<std::size_t>(mesh.NumberOfPoints()), -1);
  for (std::size_t v = 0; v < this->OutputPoint.size(); ++v)
  {
    this->Vertex[this->OutputPoint[v]] = static_cast<std::int32_t>(v);
  }
  this->TriangleOf.assign(static_cast<std::size_t>(mesh.NumberOfTriangles()), -1);
  for (std::size_t t = 0; t < compact.InputTriangle.size(); ++t)
  {
    this->TriangleOf[compact.InputTriangle[t]] = static_cast<std::int32_t>(t);
  }
  // The shared vertices and their places, from the input points they stand for (locked, so
  // never moved nor merged into another).
  const std::size_t n = this->OutputPoint.size();
  this->Shared.assign(n, 0);
  this->SharedPlace.resize(n);
  std::vector<std::int32_t> vertexRegions(regions ? n : 0);
  for (std::size_t v = 0; v < n; ++v)
  {
    const std::int32_t source = mesh.Representative(this->OutputPoint[v]);
    if (locks && locks[source] == SharedPointLock)
    {
      const Eigen::Vector3d x = input.Point(source);
      this->Shared[v] = 1;
      this->SharedPlace[v] = { key, x.x(), x.y(), x.z() };
    }
    if (regions)
    {
      vertexRegions[v] = regions[source];
    }
  }
  this->Edited.Build(std::move(compact));
  this->Edited.SetRegions(std::move(vertexRegions));
  this->Edited.TrackMerges();
}

void PieceBorders::Describe(std::vector<double>& places, std::vector<double>& edges) const
{
  std::vector<std::int32_t> ring;
  for (std::int32_t v = 0; v < this->Edited.NumberOfPoints(); ++v)
  {
    if (!this->Shared[v])
    {
      continue;
    }
    places.insert(places.end(), this->SharedPlace[v].begin(), this->SharedPlace[v].end());
    this->Edited.Neighbours(v, ring);
    for (const std::int32_t w : ring)
    {
      if (w > v && this->Shared[w] && this->Edited.TrianglesOnEdge(v, w) == 1)
      {
        edges.insert(edges.end(), this->SharedPlace[v].begin(), this->SharedPlace[v].end());
        edges.insert(edges.end(), this->SharedPlace[w].begin(), this->SharedPlace[w].end());
      }
    }
  }
}

void PieceBorders::Bind(const SharedCurves& curves)
{
  this->CurveVertex.assign(static_cast<std::size_t>(curves.NumberOfPoints()), -1);
  for (std::int32_t v = 0; v < this->Edited.NumberOfPoints(); ++v)
  {
    const std::int32_t g = this->Shared[v] ? curves.Find(this->SharedPlace[v]) : -1;
    if (g >= 0)
    {
      this->CurveVertex[g] = v;
    }
  }
}

bool PieceBorders::KeepsSharedEdges(std::int32_t removed, std::int32_t kept, std::int32_t otherEnd) const
{
  // The removed vertex's shared neighbours become the kept one's: only its curve neighbours may
  // be new to it (another piece could join the same two shared points by an edge of its own).
  std::vector<std::int32_t> ring, keptRing;
  this->Edited.Neighbours(removed, ring);
  this->Edited.Neighbours(kept, keptRing);
  return std::all_of(ring.begin(), ring.end(), [&](std::int32_t q) {
    return !this->Shared[q] || q == kept || q == otherEnd ||
      std::find(keptRing.begin(), keptRing.end(), q) != keptRing.end();
  });
}

bool PieceBorders::BestRemoval(const SharedCurves& curves, std::int32_t point, CollapsePlan& plan, double& cost) const
{
  const std::int32_t x = this->CurveVertex[point];
  const std::array<std::int32_t, 2>& ends = curves.Ends(point);
  const Eigen::Vector3d& at = this->Edited.Point(x);
  cost = Infinite;
  for (int k = 0; k < 2; ++k)
  {
    const std::int32_t y = this->CurveVertex[ends[k]], other = this->CurveVertex[ends[1 - k]];
    if (y < 0 || other < 0 || this->Edited.TrianglesOnEdge(x, y) != 1)
    {
      continue;
    }
    CollapsePlan candidate;
    candidate.Vertices[0] = y;
    candidate.Vertices[1] = x;
    candidate.Count = 2;
    candidate.Position = this->Edited.Point(y);
    if (this->Edited.FirstFailedCheck(candidate) != CollapseCheck::Passed || !this->KeepsSharedEdges(x, y, other))
    {
      continue;
    }
    // How far x is from the triangles that replace its own (from the new curve edge where none
    // is left).
    const Eigen::Vector3d& y0 = this->Edited.Point(y);
    double distance = PointTriangleDistance(at, this->Edited.Point(other), y0, y0);
    this->Edited.ForEachCorner(x, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
      if (next != y && previous != y)
      {
        distance = std::min(distance, PointTriangleDistance(at, y0, this->Edited.Point(next), this->Edited.Point(previous)));
      }
    });
    if (distance < cost)
    {
      cost = distance;
      plan = candidate;
    }
  }
  return cost < Infinite;
}

void PieceBorders::Price(const SharedCurves& curves, std::vector<double>& costs) const
{
  const std::vector<std::int32_t>& removable = curves.Removable();
  for (std::size_t k = 0; k < removable.size(); ++k)
  {
    const std::int32_t x = this->CurveVertex[removable[k]];
    const std::array<std::int32_t, 2>& ends = curves.Ends(removable[k]);
    const std::int32_t p = this->CurveVertex[ends[0]], n = this->CurveVertex[ends[1]];
    double cost = -Infinite;
    if (x >= 0)
    {
      CollapsePlan plan;
      this->BestRemoval(curves, removable[k], plan, cost);
    }
    else if (p >= 0 && n >= 0 && this->Edited.TrianglesOnEdge(p, n) > 0)
    {
      cost = Infinite; // the curve's new edge p-n would be this piece's too
    }
    costs[k] = std::max(costs[k], cost);
  }
}

void PieceBorders::Claim(const SharedCurves& curves, const std::vector<std::int32_t>& chosen, std::vector<double>& accepted)
{
  for (std::size_t k = 0; k < chosen.size(); ++k)
  {
    if (accepted[k] == 0.0 || this->CurveVertex[chosen[k]] < 0)
    {
      continue;
    }
    CollapsePlan plan;
    double cost = Infinite;
    if (!this->BestRemoval(curves, chosen[k], plan, cost))
    {
      accepted[k] = 0.0;
      continue;
    }
    this->Edited.Apply(plan, true);
    this->Tentative.push_back(k);
  }
}

bool PieceBorders::Agrees(const std::vector<double>& accepted) const
{
  return std::all_of(this->Tentative.begin(), this->Tentative.end(), [&](std::size_t k) { return accepted[k] != 0.0; });
}

void PieceBorders::Revert()
{
  for (std::size_t i = 0; i < this->Tentative.size(); ++i)
  {
    this->Edited.Undo();
  }
  this->Tentative.clear();
}

void PieceBorders::Commit(const std::vector<std::int32_t>& chosen)
{
  for (const std::size_t k : this->Tentative)
  {
    this->CurveVertex[chosen[k]] = -1;
    this->Changed = true;
  }
  this->Tentative.clear();
}

std::vector<std::int32_t> PieceBorders::Destinations() const
{
  const std::vector<std::int32_t>& into = this->Edited.MergeTargets();
  std::vector<std::int32_t> goesTo(static_cast<std::size_t>(this->Mesh.NumberOfPoints()));
  for (std::size_t p = 0; p < goesTo.size(); ++p)
  {
    std::int32_t v = this->Vertex[p];
    while (v >= 0 && into[v] >= 0)
    {
      v = into[v];
    }
    goesTo[p] = v >= 0 ? this->OutputPoint[v] : static_cast<std::int32_t>(p);
  }
  return goesTo;
}

void PieceBorders::Finish()
{
  if (!this->Changed)
  {
    return;
  }
  // Each output point's point after the round (itself, or the one it went into), and the
  // points left numbered in order.
  SimplifiedMesh& mesh = this->Mesh;
  const std::vector<std::int32_t> goesTo = this->Destinations();
  const std::int64_t points = mesh.NumberOfPoints();
  std::vector<std::int32_t> newId(static_cast<std::size_t>(points), -1);
  std::int32_t kept = 0;
  for (std::int64_t p = 0; p < points; ++p)
  {
    newId[p] = goesTo[p] == p ? kept++ : -1;
  }
  SimplifiedMesh edited;
  // Triangles: those the round removed go, the others' corners follow their points.
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    if (this->TriangleOf[t] < 0 || this->Edited.IsAlive(this->TriangleOf[t]))
    {
      for (int k = 0; k < 3; ++k)
      {
        edited.Triangles.push_back(newId[goesTo[mesh.Triangles[3 * t + k]]]);
      }
      edited.TriangleSource.push_back(mesh.TriangleSource[t]);
    }
  }
  // Points and their sources: a removed point's sources join its point's, weight 0.
  std::vector<std::vector<std::int32_t>> joined(static_cast<std::size_t>(points));
  for (std::int64_t p = 0; p < points; ++p)
  {
    if (goesTo[p] != p)
    {
      joined[goesTo[p]].push_back(static_cast<std::int32_t>(p));
    }
  }
  const auto addSources = [&](std::int64_t p, bool weighted) {
    for (std::int32_t s = mesh.SourceOffsets[p]; s < mesh.SourceOffsets[p + 1]; ++s)
    {
      edited.SourcePoints.push_back(mesh.SourcePoints[s]);
      edited.SourceWeights.push_back(weighted ? mesh.SourceWeights[s] : 0.0);
    }
  };
  for (std::int64_t p = 0; p < points; ++p)
  {
    if (newId[p] >= 0)
    {
      edited.Points.insert(edited.Points.end(), mesh.Points.begin() + 3 * p, mesh.Points.begin() + 3 * p + 3);
      addSources(p, true);
      for (const std::int32_t q : joined[p])
      {
        addSources(q, false);
      }
      edited.SourceOffsets.push_back(static_cast<std::int32_t>(edited.SourcePoints.size()));
    }
  }
  // The algorithm's per-point figures of the points left.
  for (NamedArray& array : mesh.PointArrays)
  {
    const std::size_t components = points > 0 ? array.Values.size() / static_cast<std::size_t>(points) : 1;
    std::vector<double> values;
    for (std::int64_t p = 0; p < points; ++p)
    {
      if (newId[p] >= 0)
      {
        values.insert(values.end(), array.Values.begin() + p * components, array.Values.begin() + (p + 1) * components);
      }
    }
    array.Values = std::move(values);
  }
  edited.PointArrays = std::move(mesh.PointArrays);
  edited.FieldValues = std::move(mesh.FieldValues);
  edited.Report = std::move(mesh.Report);
  mesh = std::move(edited);
  this->Changed = false;
}

// ---------------------------------------------------------------------------------------------
// The round

namespace
{
/// One round's agreement (see SharedBorders.h, step 3): the chosen points every piece that holds
/// them removed, which all pieces keep.
std::vector<std::int32_t> Agree(std::vector<PieceBorders*>& pieces, const SharedCurves& curves,
  const std::vector<std::int32_t>& chosen, const BorderExchange& exchange)
{
  std::vector<double> accepted(chosen.size(), 1.0);
  for (bool agreed = false; !agreed;)
  {
    for (PieceBorders* piece : pieces)
    {
      piece->Claim(curves, chosen, accepted);
    }
    exchange.Minimum(accepted);
    std::vector<double> agreement{ 1.0 };
    for (const PieceBorders* piece : pieces)
    {
      agreement[0] = piece->Agrees(accepted) ? agreement[0] : 0.0;
    }
    exchange.Minimum(agreement);
    agreed = agreement[0] > 0.0;
    for (PieceBorders* piece : pieces)
    {
      if (!agreed)
      {
        piece->Revert(); // and try again without the refused points
      }
      else
      {
        piece->Commit(chosen);
      }
    }
  }
  std::vector<std::int32_t> removed;
  for (std::size_t k = 0; k < chosen.size(); ++k)
  {
    if (accepted[k] > 0.0)
    {
      removed.push_back(chosen[k]);
    }
  }
  return removed;
}
}

std::int64_t SimplifySharedBorders(std::vector<PieceBorders*>& pieces, std::int64_t count, const BorderExchange& exchange)
{
  std::vector<double> places, edges;
  for (const PieceBorders* piece : pieces)
  {
    piece->Describe(places, edges);
  }
  SharedCurves curves;
  curves.Build(exchange.Gather(places), exchange.Gather(edges));
  for (PieceBorders* piece : pieces)
  {
    piece->Bind(curves);
  }
  // Each removal takes one triangle from each of its two pieces.
  std::int64_t removed = 0;
  while (count - removed >= 2 && !curves.Removable().empty())
  {
    std::vector<double> costs(curves.Removable().size(), -Infinite);
    for (const PieceBorders* piece : pieces)
    {
      piece->Price(curves, costs);
    }
    exchange.Maximum(costs);
    for (double& cost : costs)
    {
      cost = cost == -Infinite ? Infinite : cost; // held by no piece any more
    }
    const std::vector<std::int32_t> chosen = curves.Choose(costs, (count - removed) / 2);
    const std::vector<std::int32_t> agreed = chosen.empty() ? chosen : Agree(pieces, curves, chosen, exchange);
    if (agreed.empty())
    {
      break;
    }
    curves.Remove(agreed);
    removed += 2 * static_cast<std::int64_t>(agreed.size());
  }
  for (PieceBorders* piece : pieces)
  {
    piece->Finish();
  }
  return removed;
}

} // namespace meshsimp
