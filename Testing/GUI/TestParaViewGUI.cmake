# The plugin in the ParaView GUI: paraview runs Python/GuiLoadPlugin.py and exits; the script
# writes the simplified cow's triangle count to MARKER.
file(REMOVE "${MARKER}")
set(ENV{MESHSIMPLIFICATION_PLUGIN} "${PLUGIN}")
set(ENV{MESHSIMPLIFICATION_COW} "${COW}")
set(ENV{MESHSIMPLIFICATION_MARKER} "${MARKER}")
# --dr: no user settings, so a first start shows no dialog that would wait for a click.
execute_process(COMMAND "${PARAVIEW}" --dr "--script=${SCRIPT}" --exit
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
if (NOT EXISTS "${MARKER}")
  message(FATAL_ERROR "the GUI did not run the script (exit ${code}): ${err}")
endif ()
file(READ "${MARKER}" count)
string(STRIP "${count}" count)
if (NOT count MATCHES "^[0-9]+$" OR count LESS 563 OR count GREATER 598)
  message(FATAL_ERROR "unexpected result from the GUI: ${count}")
endif ()
message(STATUS "ParaView GUI simplified the cow to ${count} triangles")
