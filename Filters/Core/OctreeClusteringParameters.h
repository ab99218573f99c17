// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OctreeClusteringParameters.h
 * @brief The octree vertex clustering's own settings, with their defaults, in one place.
 *
 * Plain data with no dependency, so that the VTK filter can hold them (it derives from this
 * struct, as TTK's filters derive from their base classes) and nothing repeats the defaults.
 */
#ifndef meshsimp_OctreeClusteringParameters_h
#define meshsimp_OctreeClusteringParameters_h

#include "ParameterTable.h"

namespace meshsimp
{

/// See OctreeVertexClustering.h for what each rule does.
struct OctreeClusteringParameters
{
  /// Leaves with a larger edge, relative to the bounding-box diagonal, are always split;
  /// <= 0 or >= 1: no limit.
  double MaximumCellSize = 1.0;
  /// Leaves with more vertices are always split; <= 0: no limit.
  int MaximumVerticesPerCell = 0;
  /// Fixed-point iterations for the e2 term (paper: 3 are enough); 0 uses e1 only.
  int ErrorIterations = 3;
  /// Add planes perpendicular to boundary edges (paper §3) so open borders are kept.
  bool BoundaryPlanes = true;
  double BoundaryWeight = 10.0;
  /// Split leaves whose clustering would flip a related triangle (§2.4), and keep the
  /// representatives' iteration (ErrorIterations) from flipping one. After refinement the
  /// leaves at flipped triangles are split again, while they can be split (mending may still
  /// flip a few); with a count target even past the target, and quadric collapses finish at
  /// it (not at non-surface vertices, nor with cell limits, where collapses cannot finish).
  bool PreventFlips = true;

  /// The settings above by name (see ParameterTable.h): visit(name, member, minimum, maximum, help).
  template <class Self, class Visit>
  static void ForEach(Self& self, Visit&& visit)
  {
    visit("MaximumCellSize", self.MaximumCellSize, 1e-6, 1.0,
      "Cells larger than this fraction of the bounding-box diagonal are always split (1: no limit).");
    visit("MaximumVerticesPerCell", self.MaximumVerticesPerCell, 0.0, double(std::numeric_limits<int>::max()),
      "Cells with more vertices are always split (0: no limit).");
    visit("ErrorIterations", self.ErrorIterations, 0.0, 20.0,
      "Iterations of the second error term, the distances of the clustered vertices to the new triangles.");
    visit("BoundaryPlanes", self.BoundaryPlanes, 0.0, 1.0,
      "Keep open borders in shape with planes perpendicular to boundary edges.");
    visit("BoundaryWeight", self.BoundaryWeight, 0.0, 1000.0,
      "Weight of the boundary planes relative to the surface planes.");
    visit("PreventFlips", self.PreventFlips, 0.0, 1.0,
      "Split octree cells whose representative would turn a neighbouring triangle over.");
  }
};

} // namespace meshsimp

#endif
