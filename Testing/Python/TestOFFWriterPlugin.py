# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's OFF writer (pvpython): SaveData of a simplified cow to .off gives a file the
plugin's OFF reader reads back with the same points and cells; a multiblock dataset gives one
file per block."""
import os

from paraview.simple import *  # noqa: F401,F403 (the pvpython idiom)

from plugintest import arguments, check, finish

args = arguments("--temp")

LoadPlugin(args.plugin, ns=globals())


def read_back(path):
    """The file's point and cell counts and bounds, through the plugin's OFF reader."""
    check(os.path.exists(path), "%s was written" % path)
    reader = OFFReader(FileName=path)
    reader.UpdatePipeline()
    info = reader.GetDataInformation()
    counts = (info.GetNumberOfPoints(), info.GetNumberOfCells(), info.GetBounds())
    Delete(reader)
    return counts


def remove(*paths):
    for path in paths:
        if os.path.exists(path):
            os.remove(path)


cow = OFFReader(FileName=os.path.join(args.data, "cow.off"))
simplified = VolumeTriangleCollapse(Input=cow, TargetReduction=0.9)
simplified.UpdatePipeline()
written = simplified.GetDataInformation()
path = os.path.join(args.temp, "plugin_cow_volume.off")
remove(path)
SaveData(path, proxy=simplified)
points, cells, bounds = read_back(path)
check(points == written.GetNumberOfPoints() and cells == written.GetNumberOfCells(),
      "read back %d points and %d cells for %d and %d" %
      (points, cells, written.GetNumberOfPoints(), written.GetNumberOfCells()))
check(all(abs(a - b) <= 1e-12 for a, b in zip(bounds, written.GetBounds())), "the same bounds")

# A multiblock dataset: ParaView's serial writer writes each block to its own file.
group = GroupDatasets(Input=[simplified, cow])
base = os.path.join(args.temp, "plugin_group")
remove(base + "0.off", base + "1.off")
SaveData(base + ".off", proxy=group)
check(read_back(base + "0.off")[1] == written.GetNumberOfCells(), "block 0 is the simplified cow")
check(read_back(base + "1.off")[:2] == (2904, 5804), "block 1 is the cow")

finish()
