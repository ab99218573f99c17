# SPDX-License-Identifier: BSD-3-Clause
"""Each filter's count and distance under MPI: a closed iso-surface cut between 1, 2 and 4 processes.

  python3 mpi_count.py --metro KIT_BUILD/metro [--ranks 1 2 4] [--extent 20] [--count 318]
      [--plugin build/lib/paraview-5.11/plugins/MeshSimplification/MeshSimplification.so]

The surface is ParaView's Wavelet (extent -EXTENT..EXTENT, 20 by default) contoured at 200 and
triangulated: 15 884 triangles in one closed surface at extent 20; each process contours its own
piece. Each filter is asked for
COUNT triangles (98 % by default); its pieces are written in parallel (.pvtp), merged here
(vtkCleanPolyData, exact coordinates), and compared with the whole input by the kit's metro
(two-sided RMS). Per run: the triangles, their distance from the count, the open or shared edges
of the merged pieces (0: they fit together), and the RMS as a multiple of the one-process run's.
"""
import argparse
import json
import os
import re
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
# Every registered filter, as Filters/FilterList.cmake reads them.
with open(os.path.join(HERE, "..", "..", "Filters", "MeshSimplificationFilterList.h")) as registration:
    FILTERS = tuple(re.findall(r"\n  X\(([A-Za-z]+), [a-z]+, [A-Za-z]+,", registration.read()))
RUN = """
import os, sys
from paraview.simple import *
from vtkmodules.vtkParallelCore import vtkMultiProcessController
LoadPlugin(sys.argv[1], ns=globals())
out, count, extent = sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
iso = Triangulate(Input=Contour(Input=Wavelet(WholeExtent=[-extent, extent] * 3),
                                ContourBy=["POINTS", "RTData"], Isosurfaces=[200.0], ComputeScalars=0))
SaveData(os.path.join(out, "input_%d.pvtp" % ranks), proxy=ExtractSurface(Input=iso))
for name in FILTERS_HERE:
    f = globals()[name](Input=iso, TargetMode="Triangle Count", TargetTriangleCount=count, ComputeDeviation=0)
    SaveData(os.path.join(out, "%s_%d.pvtp" % (name, ranks)), proxy=ExtractSurface(Input=MergeBlocks(Input=f)))
""".replace("FILTERS_HERE", repr(FILTERS))
MERGE = """
import sys
from vtkmodules.vtkIOXML import vtkXMLPPolyDataReader
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkFeatureEdges
from vtkmodules.vtkIOPLY import vtkPLYWriter
reader = vtkXMLPPolyDataReader()
reader.SetFileName(sys.argv[1])
clean = vtkCleanPolyData()
clean.SetInputConnection(reader.GetOutputPort())
clean.SetTolerance(0.0)
edges = vtkFeatureEdges()
edges.SetInputConnection(clean.GetOutputPort())
edges.BoundaryEdgesOn(); edges.NonManifoldEdgesOn(); edges.FeatureEdgesOff(); edges.ManifoldEdgesOff()
edges.Update()
writer = vtkPLYWriter()
writer.SetInputConnection(clean.GetOutputPort())
writer.SetFileName(sys.argv[2])
writer.Write()
print(clean.GetOutput().GetNumberOfCells(), edges.GetOutput().GetNumberOfCells())
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--metro", required=True)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--extent", type=int, default=20)
    parser.add_argument("--count", type=int, default=318)
    parser.add_argument("--plugin", default=os.path.join(HERE, "..", "..", "build", "lib", "paraview-5.11", "plugins",
                                                         "MeshSimplification", "MeshSimplification.so"))
    args = parser.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    with tempfile.TemporaryDirectory() as out:
        run, merge = os.path.join(out, "run.py"), os.path.join(out, "merge.py")
        open(run, "w").write(RUN)
        open(merge, "w").write(MERGE)

        def merged(name):
            path = os.path.join(out, name)
            text = subprocess.run(["pvpython", merge, path + ".pvtp", path + ".ply"], capture_output=True,
                                  text=True, check=True).stdout.split()
            return int(text[-2]), int(text[-1]), path + ".ply"

        serial = {}
        print("| processes | filter | triangles | from the count | open edges | RMS | RMS / one process's |")
        print("|---|---|---|---|---|---|---|")
        for ranks in args.ranks:
            subprocess.run(["mpiexec", "-n", str(ranks), "pvbatch", "--force-offscreen-rendering", run,
                            os.path.abspath(args.plugin), out, str(args.count), str(args.extent)],
                           env=env, check=True, capture_output=True)
            reference = merged("input_1")[2] if os.path.exists(os.path.join(out, "input_1.pvtp")) else None
            for name in FILTERS:
                cells, opened, ply = merged("%s_%d" % (name, ranks))
                rms = json.loads(subprocess.run([args.metro, reference, ply], capture_output=True, text=True,
                                                check=True).stdout)["symmetric"]["rms"] if reference else float("nan")
                serial.setdefault(name, rms)
                print("| %d | %s | %d | %+.1f %% | %d | %.3g | %.2f |" % (
                    ranks, name, cells, 100.0 * (cells - args.count) / args.count, opened, rms, rms / serial[name]))


if __name__ == "__main__":
    main()
