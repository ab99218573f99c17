// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProgressiveMeshParameters.h
 * @brief The progressive mesh's own settings, with their defaults, in one place.
 *
 * Plain data with no dependency, so that the VTK filter can hold them (it derives from this
 * struct, as TTK's filters derive from their base classes) and nothing repeats the defaults.
 */
#ifndef meshsimp_ProgressiveMeshParameters_h
#define meshsimp_ProgressiveMeshParameters_h

#include "ParameterTable.h"

namespace meshsimp
{

/// The weights of the cost of a half-edge collapse x -> y (see ProgressiveMesh.h). The defaults
/// (the quadric error alone) are the combination of these weights that keeps the levels
/// closest to the input (ProgressiveMesh.md gives the figures).
struct ProgressiveMeshParameters
{
  /// Weight of the L1 length |x - y|_1 (Wu and Fei, §4), in units of the input's mean L1 edge
  /// length. 0 by default; 1 with CurvatureWeight 1 and QuadricWeight 0 is the paper's cost.
  double LengthWeight = 0.0;
  /// Weight of the curvature 1 - N_ABC . N_ABD of the edge's two triangles (§4); on an open
  /// border, 1 - d1 . d2 of the border's two directions at x. 0 by default.
  double CurvatureWeight = 0.0;
  /// Weight of the quadric error (Garland-Heckbert, beyond the paper): the area-weighted squared
  /// distances of y to the planes of the input triangles merged into x (and to planes along
  /// open borders), in units of the mean triangle area times the squared mean edge length.
  double QuadricWeight = 1.0;
  /// Weight of the L1 distance of the extra coordinates (colours, texture coordinates: §7),
  /// which the caller scales to [0, 1]: a change from black to white costs AttributeWeight.
  double AttributeWeight = 1.0;

  /// The settings above by name (see ParameterTable.h): visit(name, member, minimum, maximum, help).
  template <class Self, class Visit>
  static void ForEach(Self& self, Visit&& visit)
  {
    visit("LengthWeight", self.LengthWeight, 0.0, Unbounded,
      "Weight of a collapse's L1 length, in mean edge lengths (the paper's first term; 0 by default).");
    visit("CurvatureWeight", self.CurvatureWeight, 0.0, Unbounded,
      "Weight of the curvature 1 - N1.N2 of the two triangles on a collapse's edge (on an open border, "
      "of the border's turn): the paper's second term, 0 by default.");
    visit("QuadricWeight", self.QuadricWeight, 0.0, Unbounded,
      "Weight of the quadric error (Garland and Heckbert): the squared distances of the new position to"
      " the planes of the input triangles merged into the removed point, in units of the mean triangle "
      "area times the squared mean edge length.");
    visit("AttributeWeight", self.AttributeWeight, 0.0, Unbounded,
      "Weight of the change of the Attribute Coordinates array: a change from black to white costs as "
      "much as the quadric error of a mean triangle one mean edge length away, times this.");
  }
};

} // namespace meshsimp

#endif
