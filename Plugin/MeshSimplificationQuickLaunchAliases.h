// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshSimplificationQuickLaunchAliases.h
 * @brief The quick-launch entries of the filters (pqMeshSimplificationQuickLaunch): the text a
 * search matches, and the proxy of the filter it starts. ParaView 5.11 lists every entry whose
 * text holds each typed word (or its letters in order within one word), so a text holds the
 * words users type for the task ("simplify", "simplification", "decimate") and none of its
 * filter's own label: typing a label's word lists the filter once, under its label.
 */
#ifndef MeshSimplificationQuickLaunchAliases_h
#define MeshSimplificationQuickLaunchAliases_h

struct MeshSimplificationQuickLaunchAlias
{
  const char* Text;
  const char* ProxyName;
};

constexpr MeshSimplificationQuickLaunchAlias MeshSimplificationQuickLaunchAliases[] = {
  { "Simplify, decimate (simplification): fastest, by space cells", "OctreeVertexClustering" },
  { "Simplify, decimate (simplification): shape and enclosed space", "VolumeTriangleCollapse" },
  { "Simplify, decimate (simplification): rounds on every core", "ParallelDecimation" },
  { "Simplify, decimate (simplification): live levels of detail", "ProgressiveMesh" },
};

#endif
