// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshSimplificationQuickLaunchAliases.h
 * @brief The quick-launch entries of the filters (pqMeshSimplificationQuickLaunch): the text a
 * search matches, and the proxy of the filter it starts. ParaView 5.11 lists every entry whose
 * text holds each typed word (or its letters in order within one word), so a text holds the
 * words users type for the task ("simplify", "simplification", "decimate") and none of its
 * filter's own label: typing a label's word lists the filter once, under its label. The texts
 * are registered with the filters (MeshSimplificationFilterList.h).
 */
#ifndef MeshSimplificationQuickLaunchAliases_h
#define MeshSimplificationQuickLaunchAliases_h

#include "MeshSimplificationFilterList.h" // the filters and their alias texts

struct MeshSimplificationQuickLaunchAlias
{
  const char* Text;
  const char* ProxyName;
};

#define MESHSIMPLIFICATION_QUICK_LAUNCH_ALIAS(name, method, parameters, tolerance, blends, alias) { alias, #name },
constexpr MeshSimplificationQuickLaunchAlias MeshSimplificationQuickLaunchAliases[] = {
  MESHSIMPLIFICATION_FILTERS(MESHSIMPLIFICATION_QUICK_LAUNCH_ALIAS)
};
#undef MESHSIMPLIFICATION_QUICK_LAUNCH_ALIAS

#endif
