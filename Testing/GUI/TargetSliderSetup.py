# SPDX-License-Identifier: BSD-3-Clause
"""Run by the ParaView GUI before a recorded drag of a target slider (paraview --script=...
--test-script=drag.xml, Testing/GUI/TestTargetSlider.cmake): load the plugin, turn Auto Apply
on, show the filter MESHSIMPLIFICATION_FILTER on MESHSIMPLIFICATION_MESH with its target mode
(0 reduction, 1 triangle count), and log every run of the filter and every render with its time
to MESHSIMPLIFICATION_LOG: "filter StartEvent t", "filter EndEvent t", "cells n", "render ...".
The test reads the runs from the log; Testing/Benchmark/target_slider.py the frame times."""
import os
import time
import traceback

log = open(os.environ["MESHSIMPLIFICATION_LOG"], "w")
try:
    from paraview.simple import *  # noqa: F401,F403

    LoadPlugin(os.environ["MESHSIMPLIFICATION_PLUGIN"], ns=globals())
    GetSettingsProxy("GeneralSettings").AutoApply = 1
    mesh = OpenDataFile(os.environ["MESHSIMPLIFICATION_MESH"])
    make = globals()[os.environ["MESHSIMPLIFICATION_FILTER"]]
    simplified = make(Input=mesh, TargetMode=int(os.environ.get("MESHSIMPLIFICATION_TARGET_MODE", "0")),
                      TargetReduction=0.9, TargetTriangleCount=1000,
                      ComputeDeviation=int(os.environ.get("MESHSIMPLIFICATION_DEVIATION", "0")))
    SetActiveSource(simplified)
    Show(simplified)
    Render()

    def stamp(what):
        def observe(caller, event):
            log.write("%s %s %.6f\n" % (what, event, time.time()))
            if what == "filter" and event == "EndEvent":
                log.write("cells %d\n" % caller.GetOutputDataObject(0).GetNumberOfCells())
            log.flush()
        return observe

    for what, observed in (("filter", simplified.GetClientSideObject()),
                           ("render", GetActiveView().GetRenderWindow())):
        observed.AddObserver("StartEvent", stamp(what))
        observed.AddObserver("EndEvent", stamp(what))
    log.write("ready\n")
except Exception:
    log.write("error\n" + traceback.format_exc())
log.flush()  # left open: the observers write to it until the GUI exits
