# SPDX-License-Identifier: BSD-3-Clause
"""The collapse filters under MPI (mpiexec -n 2 pvbatch): pieces stay crack-free.

Every process reads the closed cow and keeps its share of the triangles (split at the median of
the triangles' x), so the pieces meet along a cut that merges back into a closed surface. The
simplified pieces are written in parallel, read back here and merged: with the cut's points
locked on both sides (LockPieceBorders) they still close up, with no boundary or non-manifold
edge; unlocked, both filters left 23–48 open edges.
"""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges
from vtkmodules.vtkIOXML import vtkXMLPPolyDataReader

from plugintest import arguments, check, failures, finish

args = arguments("--temp")
LoadPlugin(args.plugin, ns=globals())

pieces = ProgrammableSource(OutputDataSetType="vtkPolyData")
pieces.Script = """
import builtins
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as pipeline
info = self.GetOutputInformation(0)
piece, count = info.Get(pipeline.UPDATE_PIECE_NUMBER()), info.Get(pipeline.UPDATE_NUMBER_OF_PIECES())
lines = [l for l in open(%r).read().split("\\n") if l.strip()]
nv, nf = map(int, lines[1].split()[:2])
V = [tuple(map(float, l.split()[:3])) for l in lines[2:2 + nv]]
F = [tuple(map(int, l.split()[1:4])) for l in lines[2 + nv:2 + nv + nf]]
x = lambda f: builtins.sum(V[i][0] for i in f) / 3
xs = sorted(x(f) for f in F)
cuts = [xs[len(xs) * k // count] for k in range(count)] + [float("inf")]
mine = [f for f in F if cuts[piece] <= x(f) < cuts[piece + 1]]
used = sorted(set(i for f in mine for i in f))
local = {v: k for k, v in enumerate(used)}
points = vtkPoints()
for v in used:
    points.InsertNextPoint(V[v])
cells = vtkCellArray()
for f in mine:
    cells.InsertNextCell(3)
    for i in f:
        cells.InsertCellPoint(local[i])
out = self.GetPolyDataOutput()
out.SetPoints(points)
out.SetPolys(cells)
""" % os.path.join(args.data, "cow.off")
pieces.ScriptRequestInformation = """
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetExecutive().GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""


def merged(name, proxy):
    """Writes the pieces, reads them back; the merged triangle count and its open edges."""
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
    return written, reader.GetOutput().GetNumberOfCells(), edges.GetOutput().GetNumberOfCells()


written, cells, open_edges = merged("input", pieces)
check(written == 2, "two pieces written (run under mpiexec -n 2), got %d" % written)
check(cells == 5804 and open_edges == 0, "the input pieces make the closed cow (%d, %d)" % (cells, open_edges))
for name, F in (("volume", VolumeTriangleCollapse), ("parallel", ParallelDecimation)):
    written, cells, open_edges = merged(name, F(Input=pieces))
    check(written == 2 and abs(cells - 580) <= 12, "%s: 2 pieces, 580 +- 2 %% triangles, got %d" % (name, cells))
    check(open_edges == 0, "%s: the simplified pieces fit together, %d open edges" % (name, open_edges))
# pvbatch ends MPI when the script returns; exiting from one process aborts the others, which
# is only right for a failure.
if failures:
    finish()
print("1 passed, 0 failed")
