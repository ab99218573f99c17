# The plugin's help pages as ParaView 5.11 shows them: each filter's page lists the properties
# it inherits from the common base (TargetReduction, Locked Points, ComputeDeviation), declares
# its encoding, says that the array selections are optional, and is ASCII like the XML it is
# made from (5.11's help browser reads undeclared pages as Latin-1: "Delta" came out as "ÎV");
# the XML cites the papers by authors and title, not by the project's file numbers. The plugin's
# other filters (OTHERS: LoD Interpolation, Texture Baking), which do not derive from the base, have their
# pages too, declared and ASCII.
#   cmake -DHELP=<build>/Plugin/paraview_help -DXML=<source>/Plugin -DFILTERS=<names> -DOTHERS=<names>
#     -P TestHelpPages.cmake
file(GLOB pages "${HELP}/filters.*.html")
list(LENGTH pages count)
list(LENGTH FILTERS registered)
list(LENGTH OTHERS others)
math(EXPR expected "${registered} + ${others}")
if (NOT count EQUAL expected)
  message(FATAL_ERROR "expected the help pages of the ${registered} registered and ${others} other filters in ${HELP}, found ${count}")
endif ()
foreach (page IN LISTS pages)
  file(READ "${page}" text)
  set(needs "<th>TargetReduction</th>" "<th>Locked Points</th>" "<th>ComputeDeviation</th>" "Optional: a point array")
  foreach (other IN LISTS OTHERS)
    if (page MATCHES "filters\\.${other}\\.html$")
      set(needs "")
    endif ()
  endforeach ()
  foreach (needed IN LISTS needs ITEMS "charset=utf-8")
    string(FIND "${text}" "${needed}" at)
    if (at EQUAL -1)
      message(FATAL_ERROR "${page} lacks '${needed}'")
    endif ()
  endforeach ()
  if (text MATCHES "must contain" OR text MATCHES "[^\t\n\r -~]")
    message(FATAL_ERROR "${page} claims a required array or has characters that are not ASCII")
  endif ()
endforeach ()
# The contents list what a user can pick: the filters, the reader and the writer, not the
# filters' internal base nor the writer's inner proxy (issue 45).
file(READ "${HELP}/MeshSimplification.qhp" contents)
if (contents MATCHES "meshsimplification_ubase|internal_u")
  message(FATAL_ERROR "the help contents list an internal proxy: ${contents}")
endif ()
foreach (title IN ITEMS "Octree Vertex Clustering" "Parallel Decimation" "Progressive Mesh"
                        "Volume Triangle Collapse" "LoD Interpolation" "Texture Baking" "OFF Reader" "OFF Writer")
  if (NOT contents MATCHES "<section title=\"${title}\"")
    message(FATAL_ERROR "the help contents lack ${title}")
  endif ()
endforeach ()
file(GLOB xmls "${XML}/*.xml")
foreach (xml IN LISTS xmls)
  file(READ "${xml}" text)
  if (text MATCHES "[^\t\n\r -~]" OR text MATCHES "paper [0-9][0-9][0-9]")
    message(FATAL_ERROR "${xml} has characters that are not ASCII or cites a paper by number")
  endif ()
endforeach ()
