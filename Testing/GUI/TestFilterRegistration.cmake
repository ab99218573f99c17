# Every filter of the plugin (a proxy on the common base MeshSimplificationFilter) is in the
# Filters > Mesh Simplification menu and registered (MeshSimplificationFilterList.h), which gives
# it its quick-launch entry, its CLI method and its place in the tests that run every filter:
# Progressive Mesh had neither menu nor quick launch (issue 45). Run with
# -DPLUGIN_DIR=<the Plugin folder> -DFILTER_LIST=<the filter list>.
file(GLOB xmls "${PLUGIN_DIR}/*.xml")
file(READ "${FILTER_LIST}" registered)
set(filters "")
foreach (xml IN LISTS xmls)
  file(READ "${xml}" text)
  string(REGEX MATCHALL "<SourceProxy name=\"[A-Za-z]+\"[^>]*base_proxyname=\"MeshSimplificationFilter\""
    proxies "${text}")
  foreach (proxy IN LISTS proxies)
    string(REGEX REPLACE "<SourceProxy name=\"([A-Za-z]+)\".*" "\\1" name "${proxy}")
    list(APPEND filters "${name}")
    if (NOT text MATCHES "<ShowInMenu category=\"Mesh Simplification\"/>")
      message(FATAL_ERROR "${name} is not in the Mesh Simplification menu (${xml})")
    endif ()
    if (NOT registered MATCHES "\n  X\\(${name}, ")
      message(FATAL_ERROR "${name} is not registered in ${FILTER_LIST}")
    endif ()
  endforeach ()
endforeach ()
list(LENGTH filters count)
if (count LESS 4)
  message(FATAL_ERROR "only ${count} filters found: ${filters}")
endif ()
message(STATUS "in the menu and quick launch: ${filters}")
