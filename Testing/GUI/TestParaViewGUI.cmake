# The plugin in the ParaView GUI: paraview runs Python/GuiLoadPlugin.py and exits; the script
# writes the triangle counts of the cow simplified by each filter to MARKER (the progressive
# mesh's at two targets, and its number of builds), then Texture Baking's six flags (its surface
# shown with its texture, by Solid Color, rendered in the texture's colours; the texture renamed
# with its filter, one after a state's round trip, unregistered with its filter).
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
file(READ "${MARKER}" counts)
string(STRIP "${counts}" counts)
if (NOT counts MATCHES "^([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([0-9]+) ([01] [01] [01] [01] [01] [01])$")
  message(FATAL_ERROR "unexpected result from the GUI: ${counts}")
endif ()
set(octree "${CMAKE_MATCH_1}")
set(volume "${CMAKE_MATCH_2}")
set(parallel "${CMAKE_MATCH_3}")
set(coarse "${CMAKE_MATCH_4}")
set(fine "${CMAKE_MATCH_5}")
set(builds "${CMAKE_MATCH_6}")
set(texture "${CMAKE_MATCH_7}")
if (octree LESS 563 OR octree GREATER 598 OR volume LESS 575 OR volume GREATER 585
    OR parallel LESS 568 OR parallel GREATER 592)
  message(FATAL_ERROR
    "unexpected counts from the GUI: octree ${octree}, volume ${volume}, parallel ${parallel}")
endif ()
# Progressive Mesh: 90 % and then 50 % from one build, each level within one triangle.
if (NOT coarse EQUAL 580 OR NOT fine EQUAL 2902 OR NOT builds EQUAL 1)
  message(FATAL_ERROR
    "unexpected progressive mesh from the GUI: ${coarse} and ${fine} triangles, ${builds} builds")
endif ()
if (NOT texture STREQUAL "1 1 1 1 1 1")
  message(FATAL_ERROR "Texture Baking in the GUI (textured, solid colour, rendered, renamed, one "
    "texture after a state's round trip, removed with the filter): ${texture}")
endif ()
message(STATUS "ParaView GUI simplified the cow to ${octree} (octree), ${volume} (volume) and ${parallel} (parallel) triangles")
