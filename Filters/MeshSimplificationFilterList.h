// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshSimplificationFilterList.h
 * @brief Every simplification filter of the module, registered once.
 *
 * MESHSIMPLIFICATION_FILTERS(X) calls X(Name, method, Parameters, tolerance, blends, alias) for
 * each filter:
 * - Name: vtk<Name> is its VTK class, <Name> its ParaView proxy (Plugin/<Name>.xml) and its
 *   core algorithm (Filters/Core/<Name>.h and .cxx);
 * - method: its name in the command-line tool's --method;
 * - Parameters: its core settings' struct, meshsimp::<Parameters> in Filters/Core/<Parameters>.h,
 *   whose ForEach table lists them;
 * - tolerance: how far from a triangle-count target its output may end (a fraction of it);
 * - blends: whether an output point's floating-point data blends several input points' (a
 *   cluster's, a collapse's); false where every output point keeps one input point's data;
 * - alias: its quick-launch text, which holds the words users type for the task and none of
 *   its label's (see pqMeshSimplificationQuickLaunch).
 * CMake reads the same lines (Filters/FilterList.cmake) for the module's classes, the core's
 * sources, the plugin's XML and the tests that run every filter; the command-line tool, the
 * quick-launch entries and those tests read the macro. A new filter is a line here and its own
 * files.
 */
#ifndef MeshSimplificationFilterList_h
#define MeshSimplificationFilterList_h

// clang-format off
#define MESHSIMPLIFICATION_FILTERS(X) \
  X(OctreeVertexClustering, octree, OctreeClusteringParameters, 0.03, true, "Simplify, decimate (simplification): fastest, by space cells") \
  X(VolumeTriangleCollapse, volume, VolumeCollapseParameters, 0.01, true, "Simplify, decimate (simplification): shape and enclosed space") \
  X(ParallelDecimation, parallel, ParallelDecimationParameters, 0.02, false, "Simplify, decimate (simplification): rounds on every core") \
  X(ProgressiveMesh, progressive, ProgressiveMeshParameters, 0.01, false, "Simplify, decimate (simplification): live levels of detail") \
  X(AppearancePreservingCollapse, appearance, AppearanceCollapseParameters, 0.01, true, "Simplify, decimate (simplification): keeps colours and shading")
// clang-format on

#endif
