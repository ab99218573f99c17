# SPDX-License-Identifier: BSD-3-Clause
"""The filters under MPI (mpiexec -n 2 pvbatch): simplified pieces still fit together.

Every process reads the closed cow and keeps its share of the triangles (split at the median of
the triangles' x), so the pieces meet along a cut that merges back into a closed surface. The
simplified pieces are written in parallel, read back here and merged: with the cut's points
locked on both sides (LockSharedPoints) the collapse filters' pieces (Volume Triangle
Collapse, Parallel Decimation, Progressive Mesh) close up, with no boundary or non-manifold
edge (unlocked: 48 and 23 open edges), and no open edge of the octree's lies along the cut
(vertex clustering leaves some elsewhere, 38 on the whole cow in one process; unlocked: 126 in
all).

The cow is then dealt out in seven oblique stripes, alternately to the processes, so that each
piece is several strips whose two borders a collapse could join: the collapse filters join no two
shared points by a new edge (the other piece could make the same one), so the merged pieces have
no edge of four triangles (3 without that rule, from the volume filter) and no open edge. With a
layer of ghost cells added to each piece the result is the same (ghost cells are not simplified).
Composite inputs close up too: a multiblock of two striped cows, and the stripes as a
vtkPartitionedDataSet of 8 and 6 partitions on the two processes (54 and 26 open or shared edges
when blocks went one by one through the executive without the exchange).
"""
import os
import re

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPPolyDataReader

from plugintest import arguments, check, failures, finish

args = arguments("--temp")
LoadPlugin(args.plugin, ns=globals())


def cow_pieces(split, partitions=None):
    """The cow's triangles of this process's piece, chosen by the expression split (of the
    triangle f, its centroid's x(f) and y(f), the piece number and the count of pieces); with
    partitions (an expression of f too), a vtkPartitionedDataSet of them, one partition per
    value in order."""
    source = ProgrammableSource(OutputDataSetType="vtkPartitionedDataSet" if partitions else "vtkPolyData")
    source.Script = SCRIPT % (os.path.join(args.data, "cow.off"), split, partitions or "0")
    source.ScriptRequestInformation = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetExecutive().GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""
    return source


SCRIPT = """
import builtins
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
info = self.GetOutputInformation(0)
piece, count = info.Get(pipeline.UPDATE_PIECE_NUMBER()), info.Get(pipeline.UPDATE_NUMBER_OF_PIECES())
lines = [l for l in open(%r).read().split("\\n") if l.strip()]
nv, nf = map(int, lines[1].split()[:2])
V = [tuple(map(float, l.split()[:3])) for l in lines[2:2 + nv]]
F = [tuple(map(int, l.split()[1:4])) for l in lines[2 + nv:2 + nv + nf]]
x = lambda f: builtins.sum(V[i][0] for i in f) / 3
y = lambda f: builtins.sum(V[i][1] for i in f) / 3
xs = sorted(x(f) for f in F)
cuts = [xs[len(xs) * k // count] for k in range(count)] + [float("inf")]
mine = [f for f in F if %s]
def polydata(faces):
    used = sorted(set(i for f in faces for i in f))
    local = {v: k for k, v in enumerate(used)}
    points = vtkPoints()
    for v in used:
        points.InsertNextPoint(V[v])
    cells = vtkCellArray()
    for f in faces:
        cells.InsertNextCell(3)
        for i in f:
            cells.InsertCellPoint(local[i])
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(cells)
    return data
partition = lambda f: %s
out = self.GetOutputDataObject(0)
if out.IsA("vtkPolyData"):
    out.ShallowCopy(polydata(mine))
else:
    for k, value in enumerate(sorted(set(partition(f) for f in mine))):
        out.SetPartition(k, polydata([f for f in mine if partition(f) == value]))
"""
pieces = cow_pieces("cuts[piece] <= x(f) < cuts[piece + 1]")


def piece_points(name, k):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(args.temp, "PieceBorders_%s" % name, "PieceBorders_%s_%d.vtp" % (name, k)))
    reader.Update()
    data = reader.GetOutput()
    return set(data.GetPoint(i) for i in range(data.GetNumberOfPoints()))


def merged(name, proxy):
    """Writes the pieces, reads them back; the merged triangle count and its open edges (each a
    tuple of its end points)."""
    path = os.path.join(args.temp, "PieceBorders_%s.pvtp" % name)
    SaveData(path, proxy=proxy, DataMode="Ascii")
    with open(path) as f:
        written = f.read().count("<Piece ")
    reader = vtkXMLPPolyDataReader()
    reader.SetFileName(path)
    clean = vtkCleanPolyData()
    clean.SetInputConnection(reader.GetOutputPort())
    edges = vtkFeatureEdges()
    edges.SetInputConnection(clean.GetOutputPort())
    edges.BoundaryEdgesOn()
    edges.NonManifoldEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.Update()
    lines = edges.GetOutput()
    ends = [tuple(lines.GetPoint(lines.GetCell(i).GetPointId(k)) for k in range(2))
            for i in range(lines.GetNumberOfCells())]
    return written, reader.GetOutput().GetNumberOfCells(), ends


written, cells, open_edges = merged("input", pieces)
check(written == 2, "two pieces written (run under mpiexec -n 2), got %d" % written)
check(cells == 5804 and not open_edges, "the input pieces make the closed cow (%d, %d)" % (cells, len(open_edges)))
cut = piece_points("input", 0) & piece_points("input", 1)
check(len(cut) > 50, "the pieces share a cut, %d points" % len(cut))
# Every registered filter (Filters/MeshSimplificationFilterList.h), by its CLI method; all but the
# octree's clustering collapse edges, and their pieces close up everywhere.
with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Filters",
                       "MeshSimplificationFilterList.h")) as registration:
    FILTERS = tuple((method, globals()[name])
                    for name, method in re.findall(r"\n  X\(([A-Za-z]+), ([a-z]+), [A-Za-z]+,", registration.read()))
COLLAPSE_FILTERS = tuple(entry for entry in FILTERS if entry[0] != "octree")
for name, F in FILTERS:
    written, cells, open_edges = merged(name, F(Input=pieces))
    check(written == 2 and abs(cells - 580) <= 12, "%s: 2 pieces, 580 +- 2 %% triangles, got %d" % (name, cells))
    on_cut = [e for e in open_edges if e[0] in cut and e[1] in cut]
    check(not on_cut, "%s: the simplified pieces meet along the cut, %d open edges there" % (name, len(on_cut)))
    if name != "octree":
        check(not open_edges, "%s: the simplified pieces close up, %d open edges" % (name, len(open_edges)))
# The OFF writer gathers the pieces to write them: each brings its own copy of the cut's points
# (issue 45: 1 016 points where one process writes 784), written once on request.
for merge in (0, 1):
    path = os.path.join(args.temp, "PieceBorders_volume_%d.off" % merge)
    SaveData(path, proxy=VolumeTriangleCollapse(Input=pieces), MergeCoincidentPoints=merge)
    with open(path) as f:
        lines = [line.split() for line in f if line.strip()]
    count = int(lines[1][0])
    distinct = len(set(tuple(words) for words in lines[2:2 + count]))
    check(count == distinct if merge else count > distinct,
          "OFF of the gathered pieces, merge %d: %d points, %d distinct" % (merge, count, distinct))
stripes = cow_pieces("int((x(f) * 0.738 + y(f)) * 7) % count == piece")
# With a layer of ghost cells (the neighbour's triangles, flagged in vtkGhostType) the filters
# simplify each piece's own triangles only: the same closed result.
ghosted = GhostCellsGenerator(Input=stripes, MinimumNumberOfGhosts=1, BuildIfRequired=0)
for name, F in COLLAPSE_FILTERS:
    written, cells, open_edges = merged("stripes_" + name, F(Input=stripes))
    check(written == 2 and 0 < cells < 5804, "%s on stripes: 2 pieces, simplified, got %d" % (name, cells))
    check(not open_edges, "%s on stripes: the simplified pieces close up, %d open or shared edges" % (name, len(open_edges)))
    ghost_written, ghost_cells, ghost_open = merged("ghosts_" + name, F(Input=ghosted))
    check(ghost_cells == cells and not ghost_open,
          "%s on stripes with ghost cells: %d triangles (%d without), %d open or shared edges" % (name, ghost_cells, cells, len(ghost_open)))
# A multiblock input (the striped cow and a copy moved aside, each block split over the
# processes): one exchange serves every block, matched by block, so the blocks' pieces close up
# as the single cow's do; before, blocks went one by one without it.
moved = Transform(Input=stripes)
moved.Transform.Translate = [10.0, 0.0, 0.0]
group = GroupDatasets(Input=[stripes, moved])
for name, F in COLLAPSE_FILTERS:
    one_cow = merged("stripes_" + name, F(Input=stripes))[1]
    surface = ExtractSurface(Input=MergeBlocks(Input=F(Input=group)))
    written, cells, open_edges = merged("blocks_" + name, surface)
    check(abs(cells - 2 * one_cow) <= 0.02 * 2 * one_cow and not open_edges,
          "%s on a multiblock of two striped cows: %d triangles (2 x %d), %d open or shared edges"
          % (name, cells, one_cow, len(open_edges)))
# A vtkPartitionedDataSet: each process holds its stripes, each cut in two partitions at x = 0,
# so the processes hold different numbers of partitions (8 and 6) and partitions of one process
# meet too. One exchange locks the points every partition shares with another, here or on the
# other process, and the pieces close up as before.
partitioned = cow_pieces("int((x(f) * 0.738 + y(f)) * 7) % count == piece", "(int((x(f) * 0.738 + y(f)) * 7), x(f) < 0)")
for name, F in COLLAPSE_FILTERS:
    surface = ExtractSurface(Input=MergeBlocks(Input=F(Input=partitioned)))
    written, cells, open_edges = merged("partitions_" + name, surface)
    check(0 < cells < 5804 and not open_edges,
          "%s on partitioned stripes: %d triangles, %d open or shared edges" % (name, cells, len(open_edges)))
# The count under MPI (issue 46): a closed iso-surface cut between the processes, 318 triangles
# asked for (98 %). With the cut's points locked through each piece's simplification the pieces
# kept it whole: 556 to 788 triangles. The border round thins the cut on both sides at once and
# takes each piece to its share again: every filter within 5 % of the count, still closed.
wavelet = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
iso = Triangulate(Input=Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0], ComputeScalars=0))
for name, F in FILTERS:
    written, cells, open_edges = merged("iso_" + name, ExtractSurface(Input=MergeBlocks(
        Input=F(Input=iso, TargetMode="Triangle Count", TargetTriangleCount=318, ComputeDeviation=0))))
    check(abs(cells - 318) <= 16 and not open_edges,
          "%s on a cut iso-surface: 318 +- 5 %% triangles, closed; got %d, %d open edges" % (name, cells, len(open_edges)))
# pvbatch ends MPI when the script returns; exiting from one process aborts the others, which
# is only right for a failure.
if failures:
    finish()
print("1 passed, 0 failed")
