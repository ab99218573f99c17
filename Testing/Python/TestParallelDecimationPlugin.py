# SPDX-License-Identifier: BSD-3-Clause
"""Parallel Decimation through the ParaView plugin (pvpython).

Loads the built plugin, decimates the cow by reduction and by triangle count with both
importance measures, checks that the output points are input points, the Importance and
VertexType arrays, that the closed cow stays closed, that 1 and 2 threads agree, and decimates
a multiblock input block by block.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from paraview import servermanager

from plugintest import arguments, check, check_front_end, check_error_bound, check_unlocked_after_octree, finish

args = arguments()

LoadPlugin(args.plugin, ns=globals())

cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
decimated = ParallelDecimation(Input=cow)
check(decimated.TargetReduction == 0.9, "default TargetReduction is 0.9")
check(decimated.ImportanceMeasure == "Quadric" and decimated.FeatureAngle == 75, "defaults")
decimated.UpdatePipeline()
cells = decimated.GetDataInformation().GetNumberOfCells()
check(abs(cells - 580) <= 0.02 * 580, "90 %% reduction gives 580 +- 2 %% triangles, got %d" % cells)
check("Importance" in decimated.PointData.keys() and "VertexType" in decimated.PointData.keys(),
      "the Importance and VertexType arrays are present")

# Survivors move to their quadrics' minimisers by default (MovedPoints in the field data); with
# MoveSurvivors off every output point is an input point, and the triangles are the same.
check(decimated.MoveSurvivors == 1, "MoveSurvivors is on by default")
source, output = servermanager.Fetch(cow), servermanager.Fetch(decimated)
inputs = set(source.GetPoint(i) for i in range(source.GetNumberOfPoints()))
rounds = output.GetFieldData().GetArray("Rounds")
check(rounds is not None and rounds.GetValue(0) > 0, "the number of rounds in the field data")
moved = output.GetFieldData().GetArray("MovedPoints")
check(moved is not None and 0 < moved.GetValue(0) <= output.GetNumberOfPoints(),
      "the number of moved points in the field data")
check(sum(output.GetPoint(i) not in inputs for i in range(output.GetNumberOfPoints())) == moved.GetValue(0),
      "exactly the moved points are new")
decimated.MoveSurvivors = 0
kept = servermanager.Fetch(decimated)
check(all(kept.GetPoint(i) in inputs for i in range(kept.GetNumberOfPoints())),
      "MoveSurvivors off: every output point is an input point")
check(kept.GetNumberOfCells() == output.GetNumberOfCells() and kept.GetNumberOfPoints() == output.GetNumberOfPoints(),
      "MoveSurvivors changes no triangle count")
decimated.MoveSurvivors = 1

# The closed cow stays a closed 2-manifold, with either measure.
for measure in ("Quadric", "Average Plane"):
    decimated.ImportanceMeasure = measure
    edges = FeatureEdges(Input=decimated, BoundaryEdges=1, NonManifoldEdges=1, FeatureEdges=0,
                         ManifoldEdges=0)
    edges.UpdatePipeline()
    check(edges.GetDataInformation().GetNumberOfCells() == 0,
          "%s: no boundary or non-manifold edge" % measure)
decimated.ImportanceMeasure = "Quadric"

# The same output with 1 and 2 threads.
one = ParallelDecimation(Input=cow, NumberOfThreads=1)
two = ParallelDecimation(Input=cow, NumberOfThreads=2)
a, b = servermanager.Fetch(one), servermanager.Fetch(two)
check(a.GetNumberOfPoints() == b.GetNumberOfPoints() and
      all(a.GetPoint(i) == b.GetPoint(i) for i in range(a.GetNumberOfPoints())),
      "1 and 2 threads give the same points")

decimated.TargetMode = "Triangle Count"
decimated.TargetTriangleCount = 1000
decimated.UpdatePipeline()
cells = decimated.GetDataInformation().GetNumberOfCells()
check(abs(cells - 1000) <= 20, "triangle count 1000 +- 2 %%, got %d" % cells)

# Maximum Error mode.
check_error_bound(decimated, cow, 5804)

# No point is locked by default, also after the octree (whose ClusterError is active).
check_unlocked_after_octree(ParallelDecimation, OctreeVertexClustering, cow, 0.02)

# A multiblock input is decimated block by block; the terrain keeps its elevation values.
terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
group = GroupDatasets(Input=[cow, terrain])
blocks = ParallelDecimation(Input=group, TargetReduction=0.95)
blocks.UpdatePipeline()
expected = round(5804 * 0.05) + round(68742 * 0.05)
got = blocks.GetDataInformation().GetNumberOfCells()
check(abs(got - expected) <= 0.02 * expected, "multiblock: %d cells for about %d" % (got, expected))
check("elevation" in blocks.PointData.keys(), "the terrain's elevation is carried")

check_front_end(ParallelDecimation, cow, 0.02)
finish()
