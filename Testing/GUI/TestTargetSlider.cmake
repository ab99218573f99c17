# A target slider dragged in the ParaView GUI with Auto Apply on (a recorded drag: a middle-button
# press, which takes the handle where it lands, moves, a release). Progressive Mesh, whose hints
# ask for it, applies the slider while it is dragged: one run of the filter per level passed,
# each a different triangle count. Octree Vertex Clustering applies it as ParaView's own slider
# does: where the press put the handle, and on release. Run by
# ctest under an X server; TargetSliderSetup.py writes the log this reads.
set(slider_prefix "pqClientMainWindow/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_viewport/scrollAreaWidgetContents/PropertiesFrame/ProxyPanel")

# Writes the drag to FILE: press at the right of the slider, 30 moves of 2 pixels to its left end.
# The pixels assume a slider at most 62 pixels wide, as the properties panel of a fresh ParaView
# 5.11 has it at any screen size (33-60 pixels): the press lands at or past its right end.
function (write_drag file slider)
  set(events "<?xml version=\"1.0\" ?>\n<pqevents>\n")
  string(APPEND events "  <pqevent object=\"${slider}\" command=\"mousePress\" arguments=\"4,4,0,62,5\" />\n")
  foreach (x RANGE 60 2 -2)
    string(APPEND events "  <pqevent object=\"${slider}\" command=\"mouseMove\" arguments=\"4,4,0,${x},5\" />\n")
  endforeach ()
  string(APPEND events "  <pqevent object=\"${slider}\" command=\"mouseRelease\" arguments=\"4,0,0,2,5\" />\n</pqevents>\n")
  file(WRITE "${file}" "${events}")
endfunction ()

# Drags the slider of PROPERTY (its widget WIDGET) of FILTER on the cow; sets RUNS in the caller
# to the number of runs of the filter during the drag and LEVELS to its distinct triangle counts.
function (drag filter mode property widget)
  set(log "${OUTPUT}/slider_${filter}_${property}.log")
  set(xml "${OUTPUT}/slider_${filter}_${property}.xml")
  write_drag("${xml}" "${slider_prefix}/${property}/${widget}/Slider")
  file(REMOVE "${log}")
  set(ENV{MESHSIMPLIFICATION_PLUGIN} "${PLUGIN}")
  set(ENV{MESHSIMPLIFICATION_MESH} "${MESH}")
  set(ENV{MESHSIMPLIFICATION_FILTER} "${filter}")
  set(ENV{MESHSIMPLIFICATION_TARGET_MODE} "${mode}")
  set(ENV{MESHSIMPLIFICATION_LOG} "${log}")
  execute_process(COMMAND "${PARAVIEW}" --dr "--script=${SCRIPT}" "--test-script=${xml}" --exit
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "${filter}: the GUI or its recorded drag failed (exit ${code}): ${err}")
  endif ()
  if (NOT EXISTS "${log}")
    message(FATAL_ERROR "${filter}: the GUI did not run the set-up script (exit ${code}): ${err}")
  endif ()
  file(STRINGS "${log}" lines)
  list(FIND lines "ready" ready)
  if (ready EQUAL -1)
    file(READ "${log}" text)
    message(FATAL_ERROR "${filter}: the set-up script failed: ${text}")
  endif ()
  set(counts "")
  foreach (line IN LISTS lines)
    if (line MATCHES "^cells ([0-9]+)$")
      list(APPEND counts "${CMAKE_MATCH_1}")
    endif ()
  endforeach ()
  list(LENGTH counts runs)
  list(REMOVE_DUPLICATES counts)
  list(LENGTH counts levels)
  set(largest 0)
  foreach (count IN LISTS counts)
    if (count GREATER largest)
      set(largest "${count}")
    endif ()
  endforeach ()
  message(STATUS "${filter} ${property}: ${runs} runs during the drag, ${levels} levels: ${counts}")
  set(RUNS "${runs}" PARENT_SCOPE)
  set(LEVELS "${levels}" PARENT_SCOPE)
  set(LARGEST "${largest}" PARENT_SCOPE)
endfunction ()

drag(ProgressiveMesh 0 TargetReduction DoubleRangeWidget)
if (LEVELS LESS 8)
  message(FATAL_ERROR "Progressive Mesh showed ${LEVELS} levels while its reduction slider was dragged, expected at least 8")
endif ()
drag(ProgressiveMesh 1 TargetTriangleCount IntRangeWidget)
if (LEVELS LESS 8)
  message(FATAL_ERROR "Progressive Mesh showed ${LEVELS} levels while its count slider was dragged, expected at least 8")
endif ()
# The count slider ends at the input's cells (the press lands at its right end), although the
# filter was made before its input had run.
if (NOT LARGEST EQUAL INPUT_TRIANGLES)
  message(FATAL_ERROR "the count slider's right end gave ${LARGEST} triangles, not the input's ${INPUT_TRIANGLES}")
endif ()
drag(OctreeVertexClustering 0 TargetReduction DoubleRangeWidget)
if (RUNS LESS 1 OR RUNS GREATER 2)
  message(FATAL_ERROR "Octree Vertex Clustering ran ${RUNS} times for one drag of its slider, expected at most twice (where the press put the handle, and on release)")
endif ()
