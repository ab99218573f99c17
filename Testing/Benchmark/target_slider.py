# SPDX-License-Identifier: BSD-3-Clause
"""Frames per second of a target slider dragged in the ParaView GUI, and where a frame's time goes.

  xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 target_slider.py MESH
      [--plugin build/lib/paraview-5.11/plugins/MeshSimplification/MeshSimplification.so]
      [--filter ProgressiveMesh] [--deviation 0 1] [--moves 30] [--paraview paraview]

For each Deviation setting, the ParaView GUI shows the filter on MESH with Auto Apply on
(Testing/GUI/TargetSliderSetup.py, which logs every run of the filter and every render), then
plays a recorded drag of Target Reduction from its right end to its left (a middle-button press,
MOVES moves of 2 pixels, a release: the GUI test's drag, longer). A frame is one run of the
filter and the render that follows; per frame (medians): the filter's run, what lies between its
end and the render's start (the representation's update and the data's delivery to it), the
render, and their sum as frames per second. The recorded playback waits between events, so the
sum, not the wall time, is the rate a hand drag reaches.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SETUP = os.path.join(HERE, "..", "GUI", "TargetSliderSetup.py")
SLIDER = ("pqClientMainWindow/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_viewport/"
          "scrollAreaWidgetContents/PropertiesFrame/ProxyPanel/TargetReduction/DoubleRangeWidget/Slider")


def write_drag(path, moves):
    start = 2 * moves + 2
    events = ['<pqevent object="%s" command="mousePress" arguments="4,4,0,%d,5" />' % (SLIDER, start)]
    events += ['<pqevent object="%s" command="mouseMove" arguments="4,4,0,%d,5" />' % (SLIDER, x)
               for x in range(start - 2, 1, -2)]
    events.append('<pqevent object="%s" command="mouseRelease" arguments="4,0,0,2,5" />' % SLIDER)
    with open(path, "w") as out:
        out.write('<?xml version="1.0" ?>\n<pqevents>\n  %s\n</pqevents>\n' % "\n  ".join(events))


def frames(log_path):
    """(filter ms, between ms, render ms, triangles) of each run of the filter after set-up."""
    result, current, ready = [], None, False
    for words in (line.split() for line in open(log_path)):
        if words[0] == "ready":
            ready = True
        elif not ready:
            continue
        elif words[:2] == ["filter", "StartEvent"]:
            current = {"start": float(words[2])}
        elif current is None:
            continue
        elif words[:2] == ["filter", "EndEvent"]:
            current["end"] = float(words[2])
        elif words[0] == "cells":
            current["cells"] = int(words[1])
        elif words[:2] == ["render", "StartEvent"] and "end" in current and "render" not in current:
            current["render"] = float(words[2])
        elif words[:2] == ["render", "EndEvent"] and "render" in current:
            result.append((1e3 * (current["end"] - current["start"]), 1e3 * (current["render"] - current["end"]),
                           1e3 * (float(words[2]) - current["render"]), current["cells"]))
            current = None
    return result


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh")
    ap.add_argument("--plugin", default=os.path.join(HERE, "..", "..", "build", "lib", "paraview-5.11",
                                                     "plugins", "MeshSimplification", "MeshSimplification.so"))
    ap.add_argument("--filter", default="ProgressiveMesh")
    ap.add_argument("--deviation", type=int, nargs="+", default=[0, 1])
    ap.add_argument("--moves", type=int, default=30)
    ap.add_argument("--paraview", default="paraview")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="target_slider_")
    drag = os.path.join(work, "drag.xml")
    write_drag(drag, a.moves)
    print("| %s, Deviation | frames | triangles | filter | representation | render | frame | fps |" % a.filter)
    print("|---|---|---|---|---|---|---|---|")
    for deviation in a.deviation:
        log = os.path.join(work, "log_%d.txt" % deviation)
        env = dict(os.environ, MESHSIMPLIFICATION_PLUGIN=os.path.abspath(a.plugin),
                   MESHSIMPLIFICATION_MESH=os.path.abspath(a.mesh), MESHSIMPLIFICATION_FILTER=a.filter,
                   MESHSIMPLIFICATION_LOG=log, MESHSIMPLIFICATION_DEVIATION=str(deviation))
        subprocess.run([a.paraview, "--dr", "--script=" + os.path.abspath(SETUP), "--test-script=" + drag, "--exit"],
                       env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
        shown = frames(log)
        if len(shown) < 2:
            print("| %s | %d frames: see %s |" % (["off", "on"][deviation], len(shown), log))
            continue
        filt, between, render = (statistics.median(f[k] for f in shown) for k in range(3))
        frame = statistics.median(f[0] + f[1] + f[2] for f in shown)
        print("| %s | %d | %d-%d | %.1f ms | %.1f ms | %.1f ms | %.1f ms | %.1f |" % (
            ["off", "on"][deviation], len(shown), min(f[3] for f in shown), max(f[3] for f in shown),
            filt, between, render, frame, 1e3 / frame))
    sys.stdout.flush()


if __name__ == "__main__":
    main()
