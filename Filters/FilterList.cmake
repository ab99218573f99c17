# The filters as Filters/MeshSimplificationFilterList.h registers them, read from its lines
# "  X(Name, method, Parameters, ...)": MESHSIMPLIFICATION_FILTER_NAMES (Name: the VTK class
# vtk<Name>, the proxy and the core algorithm's files), MESHSIMPLIFICATION_FILTER_METHODS (the
# CLI's --method) and MESHSIMPLIFICATION_FILTER_PARAMETERS (the core settings' header), in order.
file(READ "${CMAKE_CURRENT_LIST_DIR}/MeshSimplificationFilterList.h" _filter_list)
string(REGEX MATCHALL "\n  X\\([A-Za-z]+, [a-z]+, [A-Za-z]+," _filter_entries "${_filter_list}")
set(MESHSIMPLIFICATION_FILTER_NAMES "")
set(MESHSIMPLIFICATION_FILTER_METHODS "")
set(MESHSIMPLIFICATION_FILTER_PARAMETERS "")
foreach (_entry IN LISTS _filter_entries)
  string(REGEX MATCH "X\\(([A-Za-z]+), ([a-z]+), ([A-Za-z]+)," _ "${_entry}")
  list(APPEND MESHSIMPLIFICATION_FILTER_NAMES "${CMAKE_MATCH_1}")
  list(APPEND MESHSIMPLIFICATION_FILTER_METHODS "${CMAKE_MATCH_2}")
  list(APPEND MESHSIMPLIFICATION_FILTER_PARAMETERS "${CMAKE_MATCH_3}")
endforeach ()
if (NOT MESHSIMPLIFICATION_FILTER_NAMES)
  message(FATAL_ERROR "no filter registered in ${CMAKE_CURRENT_LIST_DIR}/MeshSimplificationFilterList.h")
endif ()
