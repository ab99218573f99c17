# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's LoD Interpolation (pvpython): the cow morphed towards its simplification at 95 %.
Its defaults; t = 0 gives the cow's triangles; ten frames of an animated Interpolation build the
correspondence once; at t = 1 the points stand on the coarse surface; the paper's nearest
vertices at t = 1 leave about the coarse surface's triangles; the time drives the frame; Exact
ends on the recorded coarse triangles, also from Progressive Mesh's sequence alone."""
import os

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)

from plugintest import arguments, check, finish

args = arguments()

LoadPlugin(args.plugin, ns=globals())

cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
coarse = AppearancePreservingCollapse(Input=cow, TargetReduction=0.95)
morph = LoDInterpolation(Detailed=cow, Coarse=coarse)
check(morph.Interpolation == 0 and morph.Correspondence == "Nearest Surface Point" and morph.MergeDistance == 0.001,
      "defaults")
morph.UpdatePipeline()
check(morph.GetDataInformation().GetNumberOfCells() == 5804, "t = 0 gives the cow's 5804 triangles")
for frame in range(1, 11):
    morph.Interpolation = frame / 10.0
    morph.UpdatePipeline()
output = servermanager.Fetch(morph)
builds = output.GetFieldData().GetArray("CorrespondenceBuilds")
check(builds is not None and builds.GetValue(0) == 1, "ten frames, one correspondence")
check(output.GetPointData().GetArray("Displacement") is not None, "the Displacement array")
coarse_cells = coarse.GetDataInformation().GetNumberOfCells()
morph.Correspondence = "Nearest Vertex"
morph.UpdatePipeline()
cells = morph.GetDataInformation().GetNumberOfCells()
check(cells <= 1.1 * coarse_cells, "nearest vertices at t = 1: %d triangles for the coarse %d" % (cells, coarse_cells))

# The Play button: with Interpolation From Time the filter has 21 times in [0, 1], and the time
# 0.5 gives the frame Interpolation 0.5 gives.
morph.Correspondence = "Nearest Surface Point"
morph.Interpolation = 0.5
by_value = servermanager.Fetch(morph).GetPointData().GetArray("Displacement").GetRange()
morph.InterpolationFromTime = 1
morph.UpdatePipelineInformation()
check(len(morph.TimestepValues) == 21 and morph.TimestepValues[-1] == 1.0, "21 times in [0, 1]")
morph.UpdatePipeline(0.5)
by_time = servermanager.Fetch(morph).GetPointData().GetArray("Displacement").GetRange()
check(by_time == by_value, "time 0.5 is Interpolation 0.5")

# Exact, the geomorph: the coarse surface records what each cow point became (Generate Original
# Ids), and at t = 1 the cow's triangles end as the coarse ones.
recorded = ProgressiveMesh(Input=cow, TargetReduction=0.95, GenerateOriginalIds=1)
geomorph = LoDInterpolation(Detailed=cow, Coarse=recorded, Correspondence="Exact", Interpolation=1.0)
geomorph.UpdatePipeline()
check(geomorph.GetDataInformation().GetNumberOfCells() == recorded.GetDataInformation().GetNumberOfCells(),
      "Exact at t = 1: the coarse triangles")
# Progressive Mesh's sequence alone: its levels at 0 and 95 % are the two surfaces.
levels = LoDInterpolation(Detailed=OutputPort(recorded, 1), CoarseReduction=0.95, Correspondence="Exact",
                          Interpolation=1.0)
levels.UpdatePipeline()
check(levels.GetDataInformation().GetNumberOfCells() == recorded.GetDataInformation().GetNumberOfCells(),
      "a sequence alone, Exact at t = 1: the 95 % level's triangles")

finish()
