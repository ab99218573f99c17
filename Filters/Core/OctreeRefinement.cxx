// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering: the octree refined to a count or a bound (see OctreeClusterer.h).
#include "OctreeClusterer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace meshsimp
{
namespace octree
{
/// Leaves split together, and clustered concurrently, while a target is far (see Refine). The
/// result depends on it, never on the thread count.
constexpr std::size_t MaximumBatch = 32;

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

} // namespace octree
} // namespace meshsimp
