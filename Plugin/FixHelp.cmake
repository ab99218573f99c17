# cmake -Ddir=<the plugin's paraview_help folder> -P FixHelp.cmake
# Completes the help pages that paraview_add_plugin generates from the XML (ParaView 5.11) before
# they are compiled into the plugin's help:
#  1. The converter reads each proxy's own elements only, so a filter's page lacks the properties
#     it inherits from the base proxy (MeshSimplificationFilter.xml): the base page's rows are
#     added to the table of every filter's page.
#  2. Qt's help browser reads a page without a declared encoding as Latin-1: UTF-8 is declared.
#  3. The converter ignores an InputArrayDomain's optional="1" and says the input "must contain"
#     such an array: the sentence says that the array is optional.
#  4. The contents list every page: the pages of the internal proxies (the filters' base, and the
#     OFF writer's inner proxy, a table with no row) are removed once read, so that the contents
#     list what a user can pick.

# The rows of a page's property table, without its header row.
function (table_rows page out)
  file(READ "${page}" text)
  string(FIND "${text}" "</tr>" header_end)
  string(FIND "${text}" "</table>" table_end)
  math(EXPR first "${header_end} + 5")
  math(EXPR length "${table_end} - ${first}")
  string(SUBSTRING "${text}" ${first} ${length} rows)
  set(${out} "${rows}" PARENT_SCOPE)
endfunction ()

file(GLOB base_pages "${dir}/meshsimplification_ubase.*.html")
set(inherited "")
foreach (page IN LISTS base_pages)
  table_rows("${page}" inherited)
endforeach ()

file(GLOB pages "${dir}/*.html")
foreach (page IN LISTS pages)
  file(READ "${page}" text)
  set(original "${text}")
  get_filename_component(name "${page}" NAME)
  if (name MATCHES "^filters\\." AND NOT text MATCHES "inherited from Mesh Simplification")
    string(FIND "${text}" "</tr>" header_end)
    math(EXPR cut "${header_end} + 5")
    string(SUBSTRING "${text}" 0 ${cut} head)
    string(SUBSTRING "${text}" ${cut} -1 tail)
    set(text "${head}<!-- inherited from Mesh Simplification Filter -->${inherited}${tail}")
  endif ()
  if (NOT text MATCHES "charset=")
    string(REPLACE "<head>" "<head>\n<meta http-equiv=\"Content-Type\" content=\"text/html; charset=utf-8\"/>" text "${text}")
  endif ()
  string(REGEX REPLACE "The dataset must contain a field array \\(([a-z_]+)\\)[ \t\r\n]*with ([0-9]+) component\\(s\\)\\."
    "Optional: a \\1 array with \\2 component(s) can be selected." text "${text}")
  string(REGEX REPLACE "The dataset must contain a field array \\(([a-z_]+)\\)"
    "Optional: a \\1 array can be selected." text "${text}")
  if (NOT text STREQUAL original)
    file(WRITE "${page}" "${text}")
  endif ()
endforeach ()

file(GLOB internal_pages "${dir}/meshsimplification_ubase.*.html" "${dir}/internal_u*.html")
if (internal_pages)
  file(REMOVE ${internal_pages})
endif ()
