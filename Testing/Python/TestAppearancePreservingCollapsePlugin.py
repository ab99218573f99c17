# SPDX-License-Identifier: BSD-3-Clause
"""Appearance-Preserving Collapse through the ParaView plugin (pvpython).

Loads the built plugin, simplifies the cow by reduction and by triangle count, checks the
defaults, the Importance array, that the closed cow stays closed, that 1 and 2 threads agree,
that a colour array is carried and weighs in the order, and simplifies a multiblock input block
by block.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from paraview import servermanager

from plugintest import arguments, check, check_front_end, check_error_bound, check_unlocked_after_octree, finish

args = arguments()

LoadPlugin(args.plugin, ns=globals())

cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
collapsed = AppearancePreservingCollapse(Input=cow)
check(collapsed.TargetReduction == 0.9, "default TargetReduction is 0.9")
check(collapsed.Order == "Quadric" and collapsed.ExtremeAngle == 60 and collapsed.MaximumNormalDeviation == 45
      and collapsed.FlatEdgeAngle == 150 and collapsed.VertexMemory == 0 and collapsed.AttributeWeight == 0.1
      and collapsed.NormalWeight == 1 and collapsed.ColorWeight == 1 and collapsed.TextureCoordinateWeight == 1
      and collapsed.ScalarWeight == 1,
      "defaults")
collapsed.UpdatePipeline()
cells = collapsed.GetDataInformation().GetNumberOfCells()
check(abs(cells - 580) <= 0.01 * 580 + 1, "90 %% reduction gives 580 +- 1 %% triangles, got %d" % cells)
check("Importance" in collapsed.PointData.keys(), "the Importance array is present")
output = servermanager.Fetch(collapsed)
passes = output.GetFieldData().GetArray("Passes")
check(passes is not None and passes.GetValue(0) >= 1, "the number of passes in the field data")

# The closed cow stays a closed 2-manifold, in both orders and with the vertex memory.
for order, memory in (("Quadric", 0), ("Quadric", 1), ("Normal Spread", 0)):
    collapsed.Order = order
    collapsed.VertexMemory = memory
    edges = FeatureEdges(Input=collapsed, BoundaryEdges=1, NonManifoldEdges=1, FeatureEdges=0, ManifoldEdges=0)
    edges.UpdatePipeline()
    check(edges.GetDataInformation().GetNumberOfCells() == 0,
          "%s, memory %d: no boundary or non-manifold edge" % (order, memory))
collapsed.Order = "Quadric"
collapsed.VertexMemory = 0

# The same output with 1 and 2 threads.
one = AppearancePreservingCollapse(Input=cow, NumberOfThreads=1)
two = AppearancePreservingCollapse(Input=cow, NumberOfThreads=2)
a, b = servermanager.Fetch(one), servermanager.Fetch(two)
check(a.GetNumberOfPoints() == b.GetNumberOfPoints() and
      all(a.GetPoint(i) == b.GetPoint(i) for i in range(a.GetNumberOfPoints())),
      "1 and 2 threads give the same points")

# A colour array (the elevation through a colour map) is carried, and weighs in the order.
coloured = Calculator(Input=cow, ResultArrayName="Shade", ResultArrayType="Unsigned Char",
                      Function="iHat*(coordsY>0)*255 + jHat*(coordsY<=0)*255")
weighted = AppearancePreservingCollapse(Input=coloured, TargetReduction=0.95)
plain = AppearancePreservingCollapse(Input=coloured, TargetReduction=0.95, AttributeWeight=0)
w, p = servermanager.Fetch(weighted), servermanager.Fetch(plain)
check(w.GetPointData().GetArray("Shade") is not None, "the colour array is carried")
check(w.GetNumberOfPoints() != p.GetNumberOfPoints() or
      any(w.GetPoint(i) != p.GetPoint(i) for i in range(w.GetNumberOfPoints())),
      "the colours change the result")

collapsed.TargetMode = "Triangle Count"
collapsed.TargetTriangleCount = 1000
collapsed.UpdatePipeline()
cells = collapsed.GetDataInformation().GetNumberOfCells()
check(abs(cells - 1000) <= 11, "triangle count 1000 +- 1 %%, got %d" % cells)

# Maximum Error mode.
check_error_bound(collapsed, cow, 5804)

# No point is locked by default, also after the octree (whose ClusterError is active).
check_unlocked_after_octree(AppearancePreservingCollapse, OctreeVertexClustering, cow, 0.01)

# A multiblock input is simplified block by block; the terrain keeps its elevation values.
terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
group = GroupDatasets(Input=[cow, terrain])
blocks = AppearancePreservingCollapse(Input=group, TargetReduction=0.95)
blocks.UpdatePipeline()
expected = round(5804 * 0.05) + round(68742 * 0.05)
got = blocks.GetDataInformation().GetNumberOfCells()
check(abs(got - expected) <= 0.01 * expected + 2, "multiblock: %d cells for about %d" % (got, expected))
check("elevation" in blocks.PointData.keys(), "the terrain's elevation is carried")

check_front_end(AppearancePreservingCollapse, cow, 0.01)
finish()
