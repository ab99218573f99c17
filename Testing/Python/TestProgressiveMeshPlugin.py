# SPDX-License-Identifier: BSD-3-Clause
"""Progressive Mesh through the ParaView plugin (pvpython).

Loads the built plugin, moves the Target Reduction slider 20 times on the cow and checks that
the sequence was built once (NumberOfBuilds) and that each level equals a fresh build at that
level; a build property builds again; the second output (the sequence) written as .vtp and read
back gives the same levels without a build; the target is animateable; a multiblock input is
simplified block by block, its second output a multiblock of the sequences; the properties every
filter shares behave as in the other filters.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from paraview import servermanager

from plugintest import arguments, check, check_front_end, finish

args = arguments("--temp")

LoadPlugin(args.plugin, ns=globals())


def mesh(data):
    """Points and triangles of a fetched level, in order."""
    points = [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    cells = []
    for c in range(data.GetNumberOfCells()):
        data.GetCellPoints(c, ids)
        cells.append(tuple(ids.GetId(k) for k in range(ids.GetNumberOfIds())))
    return points, cells


def builds(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetPropertyValue("NumberOfBuilds")


cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
slider = ProgressiveMesh(Input=cow)
check(slider.TargetReduction == 0.9 and slider.QuadricWeight == 1 and slider.LengthWeight == 0, "defaults")
check(slider.GetProperty("TargetReduction").GetAnimateable() == 1, "the target is animateable")
slider.UpdatePipeline()
check(builds(slider) == 1, "one build at the first update")
for step in range(20):
    reduction = 0.05 * step if step % 2 == 0 else 0.97 - 0.04 * step
    slider.TargetReduction = reduction
    level = servermanager.Fetch(slider)
    check(abs(level.GetNumberOfCells() - round(5804 * (1 - reduction))) <= 1,
          "reduction %.2f: %d triangles" % (reduction, level.GetNumberOfCells()))
    fresh = ProgressiveMesh(Input=cow, TargetReduction=reduction)
    check(mesh(servermanager.Fetch(fresh)) == mesh(level), "reduction %.2f equals a fresh build" % reduction)
    Delete(fresh)
check(builds(slider) == 1, "20 slider moves, still one build (got %d)" % builds(slider))
check("CollapseLevel" in slider.PointData.keys(), "the CollapseLevel array")
slider.CurvatureWeight = 2
slider.UpdatePipeline()
check(builds(slider) == 2, "a build property builds again")

# The sequence (output port 1) saved and read back: any level without a build.
path = os.path.join(args.temp, "progressive_plugin_cow.vtp")
SaveData(path, proxy=OutputPort(slider, 1))
stored = XMLPolyDataReader(FileName=[path])
replay = ProgressiveMesh(Input=stored, TargetReduction=0.8)
slider.TargetReduction = 0.8
check(mesh(servermanager.Fetch(replay)) == mesh(servermanager.Fetch(slider)),
      "the stored sequence gives the same level, point for point and triangle for triangle")
check(builds(replay) == 0, "no build from a stored sequence")

# An unstructured grid of triangles (after Merge Blocks) is built once too: ParaView's shallow
# copies of the input do not count as changes.
grid = MergeBlocks(Input=cow)
merged = ProgressiveMesh(Input=grid)
for reduction in (0.9, 0.5, 0.8):
    merged.TargetReduction = reduction
    merged.UpdatePipeline()
check(builds(merged) == 1, "an unstructured grid input: one build for three targets (got %d)" % builds(merged))

# A multiblock input: each block gets its own sequence, and the reduction applies to each.
terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
group = GroupDatasets(Input=[cow, terrain])
blocks = ProgressiveMesh(Input=group, TargetReduction=0.95)
blocks.UpdatePipeline()
expected = round(5804 * 0.05) + round(68742 * 0.05)
got = blocks.GetDataInformation().GetNumberOfCells()
check(abs(got - expected) <= 2, "multiblock: %d cells for %d" % (got, expected))
check("elevation" in blocks.PointData.keys(), "the terrain's elevation is carried")
# Its second port holds every block's whole sequence, in a multiblock of the same structure.
sequences = blocks.GetDataInformation(1)
check(sequences.GetDataSetTypeAsString() == "vtkMultiBlockDataSet" and
      sequences.GetNumberOfCells() == 5804 + 68742,
      "multiblock: port 1 has both sequences (%s, %d cells)" % (sequences.GetDataSetTypeAsString(),
                                                             sequences.GetNumberOfCells()))

check_front_end(ProgressiveMesh, cow, 0.01)
finish()
