// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParallelDecimationParameters.h
 * @brief The parallel decimation's own settings, with their defaults, in one place.
 *
 * Plain data with no dependency, so that the VTK filter can hold them (it derives from this
 * struct, as TTK's filters derive from their base classes) and nothing repeats the defaults.
 */
#ifndef meshsimp_ParallelDecimationParameters_h
#define meshsimp_ParallelDecimationParameters_h

#include "ParameterTable.h"

#include <cstdint>

namespace meshsimp
{

enum class HalfEdgeChoice : std::uint8_t
{
  LeastAreaChange, // §5.3
  ShortestEdge     // §5.5 step 6
};

enum class ImportanceMeasure : std::uint8_t
{
  AveragePlane, // eq. (5.1)–(5.4)
  Quadric       // accumulated plane quadrics: the least error of the vertex's own half-edges
};

/// See ParallelDecimation.h for what each rule does and why its default is what it is.
struct ParallelDecimationParameters
{
  /// An edge whose two triangles' normals differ by more than this (degrees) is sharp. 75 by
  /// default: a lower angle marks more edges sharp, and the more constrained decimation ends
  /// farther from the input; a higher one lets AveragePlane wear away the creases of CAD parts
  /// (ParallelDecimation.md gives the figures).
  double FeatureAngle = 75.0;
  /// A boundary vertex where the boundary turns by more than this is a corner.
  double BoundaryCornerAngle = 60.0;
  /// Quadric by default: it remembers the planes of every removed vertex, where AveragePlane
  /// forgets the error of removed vertices (even accumulated), so its output stays closer to
  /// the input (ParallelDecimation.md gives the figures).
  ImportanceMeasure Measure = ImportanceMeasure::Quadric;
  /// Quadric: move each survivor to the point of least error of its accumulated quadric after
  /// the last round, within half its shortest edge (MinimizeQuadricWithin). Off: survivors keep
  /// their input coordinates (a larger distance to the input; see ParallelDecimation.md).
  bool MoveSurvivors = true;
  /// AveragePlane: a survivor adds the importance of each vertex collapsed into it to its own,
  /// so that error does not vanish from the ordering when its vertex goes.
  bool AccumulateError = true;
  /// The half-edge of an AveragePlane vertex (Quadric picks the half-edge of least error).
  HalfEdgeChoice Choice = HalfEdgeChoice::LeastAreaChange;
  /// §5.3: the largest turn (degrees) of a remaining triangle's normal a collapse may cause.
  /// 90 by default: a lower limit refuses collapses the quadric would choose, which leaves the
  /// output farther from the input (ParallelDecimation.md gives the figures); fold-overs are the
  /// engine's plane-side test's job.
  double MaximumNormalDeviation = 90.0;
  /// The bucketing function's a (a fraction of the largest importance) and α (the share of the
  /// buckets it fills), eq. (5.13); the paper's 2 % and 80 %.
  double BucketImportance = 0.02;
  double BucketShare = 0.8;
  /// The share of the candidates, least important first, that one round considers.
  double RoundFraction = 0.1;

  /// The settings above by name (see ParameterTable.h): visit(name, member, minimum, maximum, help).
  template <class Self, class Visit>
  static void ForEach(Self& self, Visit&& visit)
  {
    visit("FeatureAngle", self.FeatureAngle, 0.0, 180.0,
      "An edge whose two triangles' normals differ by more than this angle (degrees) is sharp.");
    visit("BoundaryCornerAngle", self.BoundaryCornerAngle, 0.0, 180.0,
      "A border vertex where the border turns by more than this angle (degrees) is a corner and is kept.");
    visit("ImportanceMeasure", self.Measure, 0.0, 1.0,
      "The order of removal: Average Plane (0) or Quadric (1, the default).");
    visit("MoveSurvivors", self.MoveSurvivors, 0.0, 1.0,
      "Quadric: after the last round, move each surviving point to the point of least error of the "
      "planes of the input triangles collapsed into it.");
    visit("AccumulateError", self.AccumulateError, 0.0, 1.0,
      "Average Plane: a surviving vertex adds the importance of the vertices collapsed into it, so "
      "removed error is not forgotten.");
    visit("HalfEdgeChoice", self.Choice, 0.0, 1.0,
      "Average Plane: the edge a vertex collapses along, the one of least area change within the normal"
      " deviation limit (0, the paper's section 5.3) or the shortest legal one (1, section 5.5).");
    visit("MaximumNormalDeviation", self.MaximumNormalDeviation, 0.0, 180.0,
      "The largest turn (degrees) a collapse may give a remaining triangle's normal.");
    visit("BucketImportance", self.BucketImportance, 1e-6, 1.0,
      "The bucketing function that orders vertices without a sort (paper eq. 5.13): this least "
      "important fraction a of the importance range fills Bucket Share of the buckets.");
    visit("BucketShare", self.BucketShare, 1e-6, 1.0,
      "The share (alpha) of the buckets that the least important Bucket Importance of the range fills, "
      "so that the many small importances are ordered finely.");
    visit("RoundFraction", self.RoundFraction, 0.001, 1.0,
      "The share of the removable vertices, least important first, one round considers.");
  }
};

} // namespace meshsimp

#endif
