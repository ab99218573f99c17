# SPDX-License-Identifier: BSD-3-Clause
"""Octree Vertex Clustering through the ParaView plugin (pvpython or pvbatch).

Loads the built plugin, reads the cow with the plugin's OFF reader, simplifies it by reduction
and by error bound, simplifies a multiblock input block by block, and (with --baseline)
compares a screenshot with the committed baseline image.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from paraview import servermanager

from plugintest import arguments, check, check_front_end, finish

args = arguments("--baseline", "--temp")

LoadPlugin(args.plugin, ns=globals())

cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
cow.UpdatePipeline()
check(cow.GetDataInformation().GetNumberOfCells() == 5804, "the OFF reader reads 5804 cells")

simplified = OctreeVertexClustering(Input=cow)
check(simplified.TargetReduction == 0.9, "default TargetReduction is 0.9")
simplified.TargetReduction = 0.9
simplified.UpdatePipeline()
cells = simplified.GetDataInformation().GetNumberOfCells()
check(abs(cells - 580) <= 0.03 * 580, "90 %% reduction gives 580 +- 3 %% triangles, got %d" % cells)
names = simplified.PointData.keys()
check("ClusterSize" in names and "ClusterError" in names, "error arrays present: %s" % names)

# Error-bound mode: every ClusterError is at most the bound (relative to the diagonal).
simplified.TargetMode = "Maximum Error"
simplified.MaximumError = 0.01
simplified.UpdatePipeline()
output = servermanager.Fetch(simplified)
bounds = cow.GetDataInformation().GetBounds()
diagonal = ((bounds[1] - bounds[0]) ** 2 + (bounds[3] - bounds[2]) ** 2 + (bounds[5] - bounds[4]) ** 2) ** 0.5
errors = output.GetPointData().GetArray("ClusterError")
check(errors is not None and errors.GetRange()[1] <= 0.01 * diagonal * (1 + 1e-9),
      "ClusterError within the bound")
check(0 < output.GetNumberOfPolys() < 5804, "error mode simplifies")

# A multiblock input is simplified block by block.
terrain = XMLPolyDataReader(FileName=[os.path.join(args.data, "jacksboro_dem_half.vtp")])
group = GroupDatasets(Input=[cow, terrain])
blocks = OctreeVertexClustering(Input=group, TargetReduction=0.95)
blocks.UpdatePipeline()
expected = round(5804 * 0.05) + round(68742 * 0.05)
got = blocks.GetDataInformation().GetNumberOfCells()
check(abs(got - expected) <= 0.03 * expected, "multiblock: %d cells for about %d" % (got, expected))
check("elevation" in blocks.PointData.keys(), "the terrain's elevation is carried")

if args.baseline:
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference

    simplified.TargetMode = "Reduction"
    view = CreateRenderView()
    view.ViewSize = [400, 300]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    display = Show(simplified, view)
    ColorBy(display, ("POINTS", "ClusterError"))
    display.SetRepresentationType("Surface With Edges")
    view.ResetCamera()
    view.CameraPosition = [2.0, 0.6, 2.2]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    Render(view)
    shot = os.path.join(args.temp or ".", os.path.basename(args.baseline))
    SaveScreenshot(shot, view, ImageResolution=[400, 300])
    if not os.path.exists(args.baseline):
        check(False, "no baseline %s; the new image is %s" % (args.baseline, shot))
    else:
        readers = []
        for path in (shot, args.baseline):
            reader = vtkPNGReader()
            reader.SetFileName(path)
            reader.Update()
            readers.append(reader)
        difference = vtkImageDifference()
        difference.SetInputConnection(readers[0].GetOutputPort())
        difference.SetImageConnection(readers[1].GetOutputPort())
        difference.Update()
        error = difference.GetThresholdedError()
        print("image difference:", error)
        check(error <= 15.0, "screenshot matches the baseline (thresholded error %g)" % error)
    # Release the view's OpenGL context before the interpreter exits: left to the exit handlers,
    # Mesa under Xvfb reports GLXBadContext and Xlib ends the process with status 1.
    Delete(view)
    del view

check_front_end(OctreeVertexClustering, cow, 0.03)
finish()
