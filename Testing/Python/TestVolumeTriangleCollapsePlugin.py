# SPDX-License-Identifier: BSD-3-Clause
"""Volume Triangle Collapse through the ParaView plugin (pvpython).

Loads the built plugin, simplifies the cow by reduction and by triangle count, checks the error
arrays and that the closed cow stays closed, and simplifies a multiblock input block by block.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from paraview import servermanager

from plugintest import arguments, check, check_front_end, check_error_bound, check_unlocked_after_octree, finish

args = arguments()

LoadPlugin(args.plugin, ns=globals())

cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
simplified = VolumeTriangleCollapse(Input=cow)
check(simplified.TargetReduction == 0.9, "default TargetReduction is 0.9")
check(simplified.UseShapeFactor == 0 and simplified.UseNormalFactor == 1, "factor defaults")
check(simplified.EdgeCollapses == 1 and simplified.MinimumAngle == 10, "edge collapses and guard defaults")
simplified.UpdatePipeline()
cells = simplified.GetDataInformation().GetNumberOfCells()
check(abs(cells - 580) <= 0.01 * 580, "90 %% reduction gives 580 +- 1 %% triangles, got %d" % cells)
check("SquareVolumeError" in simplified.PointData.keys(), "the error array is present")

output = servermanager.Fetch(simplified)
total = output.GetFieldData().GetArray("SquareVolumeError")
reduction = output.GetFieldData().GetArray("AchievedReduction")
check(total is not None and total.GetValue(0) > 0, "total squared volume error in the field data")
check(reduction is not None and abs(reduction.GetValue(0) - (1 - cells / 5804.0)) < 1e-12,
      "achieved reduction in the field data")

# With the paper's triangle collapses only, the same count is met by another mesh.
trianglesOnly = VolumeTriangleCollapse(Input=cow, EdgeCollapses=0)
trianglesOnly.UpdatePipeline()
check(abs(trianglesOnly.GetDataInformation().GetNumberOfCells() - 580) <= 6,
      "triangle collapses only: 580 +- 1 %% triangles")
other = servermanager.Fetch(trianglesOnly)
points = lambda mesh: set(mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints()))
check(points(other) != points(output), "EdgeCollapses changes the result")

# The surface term is on by default; 0 gives the paper's order, another mesh meeting the target.
check(simplified.SurfaceErrorWeight == 3000, "SurfaceErrorWeight default")
volumeOnly = VolumeTriangleCollapse(Input=cow, SurfaceErrorWeight=0)
volumeOnly.UpdatePipeline()
check(abs(volumeOnly.GetDataInformation().GetNumberOfCells() - 580) <= 0.01 * 580,
      "580 +- 1 %% triangles without the surface term")
check(points(servermanager.Fetch(volumeOnly)) != points(output), "SurfaceErrorWeight changes the result")

# Collapses go in batches (BatchSize, default 64, at most one per 1000 input triangles: 5 on the
# cow): the output depends on the batch size, never on the thread count.
check(simplified.BatchSize == 64, "BatchSize default")
pointList = lambda mesh: [mesh.GetPoint(i) for i in range(mesh.GetNumberOfPoints())]
byThreads = [pointList(servermanager.Fetch(VolumeTriangleCollapse(Input=cow, NumberOfThreads=n))) for n in (1, 2)]
check(byThreads[0] == byThreads[1] == pointList(output), "the same output with 1 and 2 threads")
strict = VolumeTriangleCollapse(Input=cow, BatchSize=1)
strict.UpdatePipeline()
check(abs(strict.GetDataInformation().GetNumberOfCells() - 580) <= 0.01 * 580, "BatchSize 1: 580 +- 1 %% triangles")
check(points(servermanager.Fetch(strict)) != points(output), "BatchSize changes the result")

# The closed cow stays a closed 2-manifold.
edges = FeatureEdges(Input=simplified, BoundaryEdges=1, NonManifoldEdges=1, FeatureEdges=0,
                     ManifoldEdges=0)
edges.UpdatePipeline()
check(edges.GetDataInformation().GetNumberOfCells() == 0, "no boundary or non-manifold edge")

# Locked points: none by default; with a point array selected, its nonzero points stay.
check(list(simplified.LockedPoints) == ["POINTS", "None"], "no locked points by default")
# Also after the octree (whose ClusterError is active).
check_unlocked_after_octree(VolumeTriangleCollapse, OctreeVertexClustering, cow, 0.01)
marks = Calculator(Input=cow, ResultArrayName="Locked", Function="coordsY > 0.25")
locked = VolumeTriangleCollapse(Input=marks, LockedPoints=["POINTS", "Locked"])
before, after = servermanager.Fetch(marks), servermanager.Fetch(locked)
kept = set(after.GetPoint(i) for i in range(after.GetNumberOfPoints()))
marked = [before.GetPoint(i) for i in range(before.GetNumberOfPoints())
          if before.GetPointData().GetArray("Locked").GetValue(i) != 0]
check(len(marked) > 0 and all(p in kept for p in marked), "every locked point is kept")

simplified.TargetMode = "Triangle Count"
simplified.TargetTriangleCount = 1000
simplified.UpdatePipeline()
cells = simplified.GetDataInformation().GetNumberOfCells()
check(abs(cells - 1000) <= 10, "triangle count 1000 +- 1 %%, got %d" % cells)

# Maximum Error mode.
check_error_bound(simplified, cow, 5804)

# A multiblock input is simplified block by block.
terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
group = GroupDatasets(Input=[cow, terrain])
blocks = VolumeTriangleCollapse(Input=group, TargetReduction=0.95)
blocks.UpdatePipeline()
expected = round(5804 * 0.05) + round(68742 * 0.05)
got = blocks.GetDataInformation().GetNumberOfCells()
check(abs(got - expected) <= 0.01 * expected, "multiblock: %d cells for about %d" % (got, expected))
check("elevation" in blocks.PointData.keys(), "the terrain's elevation is carried")

check_front_end(VolumeTriangleCollapse, cow, 0.01)
finish()
