// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering: the output points, their representatives and the result (see OctreeClusterer.h).
#include "OctreeClusterer.h"

#include "ProgressiveMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace meshsimp
{
namespace octree
{
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

} // namespace octree
} // namespace meshsimp
