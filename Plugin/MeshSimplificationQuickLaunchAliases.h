// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshSimplificationQuickLaunchAliases.h
 * @brief The quick-launch entries of the filters (pqMeshSimplificationQuickLaunch): the text a
 * search matches, and the proxy of the filter it starts. ParaView 5.11 matches each typed word
 * against the letters of one word of the text, so each text holds the words users type.
 */
#ifndef MeshSimplificationQuickLaunchAliases_h
#define MeshSimplificationQuickLaunchAliases_h

struct MeshSimplificationQuickLaunchAlias
{
  const char* Text;
  const char* ProxyName;
};

constexpr MeshSimplificationQuickLaunchAlias MeshSimplificationQuickLaunchAliases[] = {
  { "Mesh Simplification: Octree Vertex Clustering (simplify, decimate)", "OctreeVertexClustering" },
  { "Mesh Simplification: Volume Triangle Collapse (simplify, decimate)", "VolumeTriangleCollapse" },
  { "Mesh Simplification: Parallel Decimation (simplify, decimate)", "ParallelDecimation" },
  { "Mesh Simplification: Progressive Mesh (simplify, decimate, level of detail)", "ProgressiveMesh" },
};

#endif
