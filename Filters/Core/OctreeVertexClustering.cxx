// SPDX-License-Identifier: BSD-3-Clause
// Octree vertex clustering: Run, which calls the stages in order, and the public entry point.
// The stages are in OctreePreparation, OctreeClusters, OctreeRefinement, OctreeMending and
// OctreeOutput (.cxx); OctreeClusterer.h declares what they share and says what each holds.
#include "OctreeVertexClustering.h"

#include "OctreeClusterer.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace meshsimp
{
namespace octree
{
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
} // namespace octree

bool OctreeVertexClustering(const TriangleMeshView& mesh, const OctreeClusteringOptions& options,
  OctreeClusteringResult& result, const ExecutionContext& context)
{
  bool finished = octree::Clusterer(mesh, options, context).Run(result);
  if (finished && options.Goal.Bounded() && result.NumberOfTriangles() == 0 &&
    result.Report.UsableTriangles > 0)
  {
    // A bound so large that every cluster merges would leave no triangle: the coarsest mesh the
    // clustering makes instead (the nearest count to one triangle).
    OctreeClusteringOptions coarsest = options;
    coarsest.Goal.SetTriangleCount(1);
    finished = octree::Clusterer(mesh, coarsest, context).Run(result);
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
