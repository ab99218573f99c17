# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI (paraview --script=... --exit): load the plugin, simplify the cow with
each filter, and write the triangle counts ("octree volume parallel progressive-at-90 %
progressive-at-50 % builds", the progressive mesh's second level from its first build) - or the
error - to the file MESHSIMPLIFICATION_MARKER names, for Testing/GUI/TestParaViewGUI.cmake to
check."""
import os
import traceback

marker = os.environ["MESHSIMPLIFICATION_MARKER"]
try:
    from paraview.simple import *  # noqa: F401,F403

    LoadPlugin(os.environ["MESHSIMPLIFICATION_PLUGIN"], ns=globals())
    cow = OFFReader(FileName=os.environ["MESHSIMPLIFICATION_COW"])
    simplified = OctreeVertexClustering(Input=cow, TargetReduction=0.9)
    simplified.UpdatePipeline()
    Show(simplified)
    collapsed = VolumeTriangleCollapse(Input=cow, TargetReduction=0.9)
    collapsed.UpdatePipeline()
    Show(collapsed)
    decimated = ParallelDecimation(Input=cow, TargetReduction=0.9)
    decimated.UpdatePipeline()
    Show(decimated)
    levels = ProgressiveMesh(Input=cow, TargetReduction=0.9)
    Show(levels)
    Render()
    coarse = levels.GetDataInformation().GetNumberOfCells()
    levels.TargetReduction = 0.5  # as the slider does
    Render()
    fine = levels.GetDataInformation().GetNumberOfCells()
    levels.UpdatePropertyInformation()
    result = "%d %d %d %d %d %d\n" % (simplified.GetDataInformation().GetNumberOfCells(),
                                       collapsed.GetDataInformation().GetNumberOfCells(),
                                       decimated.GetDataInformation().GetNumberOfCells(),
                                       coarse, fine, levels.GetPropertyValue("NumberOfBuilds"))
except Exception:
    result = "error\n" + traceback.format_exc()
with open(marker, "w") as out:
    out.write(result)
