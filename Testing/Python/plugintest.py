# SPDX-License-Identifier: BSD-3-Clause
"""What the plugin tests share: their command line, a check that records failures, and the
exit status."""
import argparse
import sys

failures = []


def arguments(*extra):
    """--plugin and --data, plus the named optional arguments."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    for name in extra:
        parser.add_argument(name)
    args, _ = parser.parse_known_args()
    return args


def check(condition, message):
    if not condition:
        failures.append(message)
        print("check failed:", message, file=sys.stderr)


def check_error_bound(simplifier, source, input_triangles):
    """Maximum Error mode of a collapse filter: as far as the bound (1 % of the diagonal) lets;
    the field data holds the largest distance reached in the bound's units (a fraction of the
    diagonal), the point array PlaneDistance each point's in input units; a tighter bound keeps
    more triangles."""
    from paraview import servermanager
    simplifier.TargetMode = "Maximum Error"
    simplifier.MaximumError = 0.01
    output = servermanager.Fetch(simplifier)
    bounds = source.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    reached = output.GetFieldData().GetArray("MaximumError")
    check(reached is not None and 0.005 < reached.GetValue(0) <= 0.01,
          "largest plane distance within the bound, in its units")
    distances = output.GetPointData().GetArray("PlaneDistance")
    check(distances is not None and distances.GetNumberOfTuples() == output.GetNumberOfPoints() and
          abs(distances.GetRange()[1] / diagonal - reached.GetValue(0)) < 1e-9,
          "PlaneDistance per point in input units, its largest in the field data")
    simplifier.MaximumError = 0.002
    loose, tight = output.GetNumberOfPolys(), servermanager.Fetch(simplifier).GetNumberOfPolys()
    check(loose < tight < input_triangles,
          "bounds 0.01 and 0.002 give %d and %d triangles" % (loose, tight))


def check_unlocked_after_octree(simplifier_class, octree_class, source, tolerance):
    """No point is locked by default, also after a filter whose output has active point scalars
    (the octree's ClusterError, nonzero nearly everywhere, which ParaView would pick): the
    octree's output is reduced by 90 % within tolerance. The classes are the plugin's proxies."""
    clustered = octree_class(Input=source, TargetReduction=0.5)
    clustered.UpdatePipeline()  # as in the GUI, where the octree is applied first
    chained = simplifier_class(Input=clustered)
    locks = list(chained.LockedPoints)
    check(locks == ["POINTS", "None"], "no locked points by default after the octree, got %s" % locks)
    chained.UpdatePipeline()
    target = 0.1 * clustered.GetDataInformation().GetNumberOfCells()
    got = chained.GetDataInformation().GetNumberOfCells()
    check(abs(got - target) <= tolerance * target + 1,
          "after the octree: %d triangles for 90 %% reduction (%d)" % (got, round(target)))


def largest_distance(source, simplified):
    """The largest distance from a point of source to the surface of simplified (a cell
    locator), measured here independently of the filters."""
    import math
    from paraview import servermanager
    from vtkmodules.vtkCommonDataModel import vtkCellLocator, vtkGenericCell
    from vtkmodules.vtkCommonCore import mutable
    surface = servermanager.Fetch(simplified)
    points = servermanager.Fetch(source)
    locator = vtkCellLocator()
    locator.SetDataSet(surface)
    locator.BuildLocator()
    closest, cell, cell_id, sub_id, d2 = [0.0, 0.0, 0.0], vtkGenericCell(), mutable(0), mutable(0), mutable(0.0)
    largest = 0.0
    for i in range(points.GetNumberOfPoints()):
        locator.FindClosestPoint(points.GetPoint(i), closest, cell, cell_id, sub_id, d2)
        largest = max(largest, math.sqrt(float(d2)))
    return largest


def check_front_end(simplifier_class, source, tolerance):
    """What every filter's proxy shares (MeshSimplificationFilter.xml), on the cow: Deviation on
    by default, two-sided (its maximum at least the largest distance of
    an input point to the output), the attribute-border properties, the original ids on request; a reduction of 5 clamped to 1 (an empty
    output); an unstructured grid of triangles (after Merge Blocks) simplified like the cow;
    ParaView's default Sphere (96 triangles, 10 asked for) not emptied; a triangle count shared
    out over the blocks of a multiblock."""
    from paraview.simple import GroupDatasets, MergeBlocks, Sphere
    simplified = simplifier_class(Input=source)
    simplified.UpdatePipeline()
    check(simplified.ComputeDeviation == 1 and "Deviation" in simplified.PointData.keys(),
          "the Deviation array by default")
    largest = simplified.FieldData["DeviationMaximum"].GetRange()[1] if "DeviationMaximum" in simplified.FieldData.keys() else -1
    check(largest >= largest_distance(source, simplified) - 1e-9,
          "DeviationMaximum %g covers the input's points (two-sided)" % largest)
    check(simplified.PreserveAttributeBorders == 0 and list(simplified.AttributeBorders) == ["POINTS", "None"],
          "attribute borders off, no array by default")
    check(simplified.CloseCracks == 1, "cracks closed by default")
    # ParaView's data information lists no array named vtkOriginal...: the data is fetched.
    from paraview import servermanager
    plain = servermanager.Fetch(simplified)
    check(simplified.GenerateOriginalIds == 0 and not plain.GetPointData().GetArray("vtkOriginalPointIds"),
          "no original ids by default")
    simplified.GenerateOriginalIds = 1
    output = servermanager.Fetch(simplified)
    ids = output.GetPointData().GetArray("vtkOriginalPointIds")
    cells = output.GetCellData().GetArray("vtkOriginalCellIds")
    ids, cells = (ids.GetRange() if ids else (-1, -1)), (cells.GetRange() if cells else (-1, -1))
    points_in = source.GetDataInformation().GetNumberOfPoints()
    cells_in = source.GetDataInformation().GetNumberOfCells()
    check(0 <= ids[0] <= ids[1] < points_in and 0 <= cells[0] <= cells[1] < cells_in,
          "GenerateOriginalIds: input point ids %s of %d, cell ids %s of %d" % (ids, points_in, cells, cells_in))
    clamped = simplifier_class(Input=source, TargetReduction=5)
    clamped.UpdatePipeline()
    check(clamped.GetDataInformation().GetNumberOfCells() == 0, "TargetReduction 5 gives an empty output")
    merged = MergeBlocks(Input=GroupDatasets(Input=[source]))
    grid = simplifier_class(Input=merged)
    grid.UpdatePipeline()
    got = grid.GetDataInformation().GetNumberOfCells()
    check(merged.GetDataInformation().GetDataClassName() == "vtkUnstructuredGrid" and
          abs(got - 580) <= tolerance * 580 + 1, "after Merge Blocks: %d triangles" % got)
    sphere = simplifier_class(Input=Sphere())
    sphere.UpdatePipeline()
    check(sphere.GetDataInformation().GetNumberOfCells() > 0, "the default Sphere is not emptied")
    fine = Sphere(ThetaResolution=64, PhiResolution=64)
    group = GroupDatasets(Input=[source, fine])
    shared = simplifier_class(Input=group, TargetMode="Triangle Count", TargetTriangleCount=1000)
    shared.UpdatePipeline()
    got = shared.GetDataInformation().GetNumberOfCells()
    check(abs(got - 1000) <= 2 * tolerance * 1000 + 2, "a count of 1000 over two blocks gives %d" % got)


def render_textured(bake, path):
    """Texture Baking's first output drawn with its second as its texture (a Texture proxy,
    scalar colouring off), seen along +y with z up, 300 x 300, saved to path and read back as
    vtkImageData."""
    from paraview import servermanager
    from paraview.simple import ColorBy, CreateRenderView, Delete, OutputPort, Render, SaveScreenshot, Show
    from vtkmodules.vtkIOImage import vtkPNGReader
    view = CreateRenderView()
    view.ViewSize = [300, 300]
    view.OrientationAxesVisibility = 0
    display = Show(OutputPort(bake, 0), view)
    ColorBy(display, None)
    texture = servermanager.rendering.Texture()
    texture.Input = OutputPort(bake, 1)
    display.Texture = texture
    view.CameraPosition = [0, -3, 0]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[300, 300])
    Delete(view)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def finish():
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    sys.exit(1 if failures else 0)
