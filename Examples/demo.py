# SPDX-License-Identifier: BSD-3-Clause
"""The demo: simplify the bundled cow and Jacksboro terrain with the plugin (pvbatch).

Writes, for each model, the simplified mesh (.vtp) and a before/after picture (.png):
    pvbatch demo.py --plugin MeshSimplification.so --data Testing/Data --output out/
"""
import argparse
import os

from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--output", required=True)
args, _ = parser.parse_known_args()
LoadPlugin(args.plugin, ns=globals())
os.makedirs(args.output, exist_ok=True)


def side_by_side(before, after, color_array, title, png, camera):
    """Renders the input and the result next to each other and saves one picture."""
    layout = CreateLayout(title)
    views = []
    for source, label in ((before, "input"), (after, "simplified")):
        view = CreateRenderView()
        AssignViewToLayout(view=view, layout=layout, hint=0)
        view.OrientationAxesVisibility = 0
        display = Show(source, view)
        display.SetRepresentationType("Surface With Edges" if source is after else "Surface")
        if color_array and color_array in source.PointData.keys():
            ColorBy(display, ("POINTS", color_array))
        else:
            display.ColorArrayName = ["POINTS", ""]
        cells = source.GetDataInformation().GetNumberOfCells()
        text = Text(Text="%s: %d triangles" % (label, cells))
        Show(text, view)
        camera(view)
        views.append(view)
    layout.SetSize(1200, 500)
    SaveScreenshot(png, layout, ImageResolution=[1200, 500])
    print("wrote", png)


def cow_camera(view):
    view.CameraPosition = [2.0, 0.6, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()


def terrain_camera(view):
    view.CameraPosition = [170.0, -350.0, 500.0]
    view.CameraFocalPoint = [170.0, 200.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()


cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
cow_simplified = OctreeVertexClustering(Input=cow, TargetReduction=0.9)
SaveData(os.path.join(args.output, "cow_octree_90.vtp"), proxy=cow_simplified)
side_by_side(cow, cow_simplified, None, "cow", os.path.join(args.output, "cow_octree_90.png"), cow_camera)

terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
terrain_simplified = OctreeVertexClustering(Input=terrain, TargetReduction=0.95)
SaveData(os.path.join(args.output, "terrain_octree_95.vtp"), proxy=terrain_simplified)
side_by_side(terrain, terrain_simplified, "elevation", "terrain",
             os.path.join(args.output, "terrain_octree_95.png"), terrain_camera)

# The error-bound mode: every output point within 0.5 % of the diagonal; coloured by the
# ClusterError array the filter adds.
bounded = OctreeVertexClustering(Input=terrain, TargetMode="Maximum Error", MaximumError=0.005)
SaveData(os.path.join(args.output, "terrain_octree_error0.005.vtp"), proxy=bounded)
side_by_side(terrain, bounded, "ClusterError", "terrain-error",
             os.path.join(args.output, "terrain_octree_error0.005.png"), terrain_camera)

# The same bound with Volume Triangle Collapse: the same largest distance to the input planes
# with far fewer triangles.
volume_bounded = VolumeTriangleCollapse(Input=terrain, TargetMode="Maximum Error", MaximumError=0.005)
SaveData(os.path.join(args.output, "terrain_volume_error0.005.vtp"), proxy=volume_bounded)
side_by_side(terrain, volume_bounded, "elevation", "terrain-volume-error",
             os.path.join(args.output, "terrain_volume_error0.005.png"), terrain_camera)

# Volume Triangle Collapse: the closed cow stays closed; coloured by the squared volume error
# each output point absorbed.
cow_volume = VolumeTriangleCollapse(Input=cow, TargetReduction=0.9)
SaveData(os.path.join(args.output, "cow_volume_90.vtp"), proxy=cow_volume)
side_by_side(cow, cow_volume, "SquareVolumeError", "cow-volume",
             os.path.join(args.output, "cow_volume_90.png"), cow_camera)
terrain_volume = VolumeTriangleCollapse(Input=terrain, TargetReduction=0.95)
SaveData(os.path.join(args.output, "terrain_volume_95.vtp"), proxy=terrain_volume)
side_by_side(terrain, terrain_volume, "elevation", "terrain-volume",
             os.path.join(args.output, "terrain_volume_95.png"), terrain_camera)

# Parallel Decimation: vertices removed on all cores, survivors moved to their planes' best
# point; the cow coloured by each
# vertex's type (simple, boundary, crease, corner), the terrain by its elevation.
cow_parallel = ParallelDecimation(Input=cow, TargetReduction=0.9)
SaveData(os.path.join(args.output, "cow_parallel_90.vtp"), proxy=cow_parallel)
side_by_side(cow, cow_parallel, "VertexType", "cow-parallel",
             os.path.join(args.output, "cow_parallel_90.png"), cow_camera)
terrain_parallel = ParallelDecimation(Input=terrain, TargetReduction=0.95)
SaveData(os.path.join(args.output, "terrain_parallel_95.vtp"), proxy=terrain_parallel)
side_by_side(terrain, terrain_parallel, "elevation", "terrain-parallel",
             os.path.join(args.output, "terrain_parallel_95.png"), terrain_camera)

# Progressive Mesh: the sequence built once, three levels of the cow from it (coloured by the
# fraction of the sequence at which each point goes), and the whole sequence saved for later.
cow_levels = ProgressiveMesh(Input=cow)
for reduction in (0.5, 0.9, 0.98):
    cow_levels.TargetReduction = reduction
    name = "cow_progressive_%d" % round(100 * reduction)
    SaveData(os.path.join(args.output, name + ".vtp"), proxy=cow_levels)
    side_by_side(cow, cow_levels, "CollapseLevel", "cow-progressive-%d" % round(100 * reduction),
                 os.path.join(args.output, name + ".png"), cow_camera)
SaveData(os.path.join(args.output, "cow_progressive_sequence.vtp"), proxy=OutputPort(cow_levels, 1))
