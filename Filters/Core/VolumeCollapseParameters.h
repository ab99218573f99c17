// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VolumeCollapseParameters.h
 * @brief The volume triangle collapse's own settings, with their defaults, in one place.
 *
 * Plain data with no dependency, so that the VTK filter can hold them (it derives from this
 * struct, as TTK's filters derive from their base classes) and nothing repeats the defaults.
 */
#ifndef meshsimp_VolumeCollapseParameters_h
#define meshsimp_VolumeCollapseParameters_h

#include "ParameterTable.h"

namespace meshsimp
{

/// See VolumeTriangleCollapse.h for what each rule does and why its default is what it is.
struct VolumeCollapseParameters
{
  /// Threshold of the dimensionless Gauss curvature K_t · (mean triangle area); <= 0 (the
  /// default: the rule costs more distance to the input than it keeps, see
  /// VolumeTriangleCollapse.h) disables the feature rule.
  double FeatureCurvature = 0.0;
  /// A boundary vertex where the boundary turns by more than this is a corner.
  double BoundaryCornerAngle = 60.0;
  /// The engine's angle guard (degrees, at most 60; 0 turns it off): no collapse makes a new
  /// angle below it unless the neighbourhood had one as small.
  double MinimumAngle = 10.0;
  /// Let a triangle collapse its cheapest edge instead when that costs under a quarter of the
  /// triangle's error (beyond the paper; off gives the paper's triangle collapses only).
  bool EdgeCollapses = true;
  /// Weight of the surface term of the heap key (beyond the paper; 0 gives the paper's order):
  /// the new point's squared distance to the input planes (faces by area, open-border edges by
  /// length²) merged into the collapsing vertices, times the squared mean input triangle area.
  double SurfaceErrorWeight = 3000.0;
  bool UseShapeFactor = false; // off by default: it makes slivers cheap, and creases go first
  bool UseNormalFactor = true;
  bool UseVolumeWeights = true;
  /// Collapses made per batch (1 or more): the cheapest queued triangles whose neighbourhoods
  /// (every vertex of the triangles around their corners) are disjoint are evaluated, checked
  /// and, once collapsed in key order, updated on the context's threads. 1 keeps the strict heap
  /// order. The result depends on this, never on the thread count.
  int BatchSize = 64;

  /// The settings above by name (see ParameterTable.h): visit(name, member, minimum, maximum, help).
  template <class Self, class Visit>
  static void ForEach(Self& self, Visit&& visit)
  {
    visit("FeatureCurvature", self.FeatureCurvature, 0.0, Unbounded,
      "Gauss-curvature threshold of strong features, times the mean triangle area (dimensionless; a "
      "cube corner scores about 0.1): above it a triangle collapses onto its sharpest corner.");
    visit("BoundaryCornerAngle", self.BoundaryCornerAngle, 0.0, 180.0,
      "A border vertex where the border turns by more than this angle (degrees) is a corner and never "
      "moves.");
    visit("MinimumAngle", self.MinimumAngle, 0.0, 30.0,
      "Angle guard in degrees: no collapse may create an angle below it unless the collapsed "
      "neighbourhood already had one as small (0: off).");
    visit("EdgeCollapses", self.EdgeCollapses, 0.0, 1.0,
      "Let a triangle collapse its cheapest edge instead when that costs under a quarter of the "
      "triangle's error (beyond the paper).");
    visit("SurfaceErrorWeight", self.SurfaceErrorWeight, 0.0, Unbounded,
      "Weight of the surface term of the collapse order (beyond the paper; 0 gives the paper's order by"
      " volume alone).");
    visit("UseShapeFactor", self.UseShapeFactor, 0.0, 1.0,
      "Weight each triangle's volume term by its shape (the paper's shape factor): thin triangles "
      "become cheap to collapse.");
    visit("UseNormalFactor", self.UseNormalFactor, 0.0, 1.0,
      "Weight each triangle's volume term by how much it bends against its neighbours (the paper's "
      "normal constraint factor).");
    visit("UseVolumeWeights", self.UseVolumeWeights, 0.0, 1.0,
      "Make regions that already absorbed much volume change dearer (the paper's constraint weights), "
      "spreading the error evenly.");
    visit("BatchSize", self.BatchSize, 1.0, 4096.0,
      "Collapses made per batch (1: the strict order of the paper's heap).");
  }
};

} // namespace meshsimp

#endif
