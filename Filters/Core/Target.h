// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Target.h
 * @brief How far to simplify: the one target every core takes.
 *
 * A target is a reduction (a fraction of the triangles to remove), a triangle count, or an error
 * bound (simplify as far as the bound allows). A reduction becomes a count once, in the core,
 * against the triangles it can actually use (TriangleCountFor). A count is met within
 * Tolerance (a fraction of it; each algorithm states its own) unless the core says why not. An
 * error bound is a distance, in input units or relative to a reference length (by default the
 * bounding-box diagonal of the usable points), and what the core reports of its error is given
 * back in the bound's units (InBoundUnits).
 */
#ifndef MeshSimplification_Target_h
#define MeshSimplification_Target_h

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace meshsimp
{

enum class TargetMode : std::uint8_t
{
  Reduction,     // remove a fraction of the triangles
  TriangleCount, // keep a number of triangles
  MaximumError   // simplify as far as an error bound allows
};

struct Target
{
  TargetMode Mode = TargetMode::Reduction;
  /// Reduction: the fraction of the usable triangles to remove, in [0, 1].
  double Reduction = 0.9;
  /// TriangleCount: the triangles to keep.
  std::int64_t TriangleCount = 0;
  /// MaximumError: the bound, a distance; relative to ReferenceLength when RelativeError is set.
  double MaximumError = 0.0;
  bool RelativeError = true;
  /// The length a relative bound is a fraction of (input units); 0: the bounding-box diagonal of
  /// the usable points. The VTK filters set the whole dataset's diagonal for a composite or
  /// distributed input, so that every piece has the same bound.
  double ReferenceLength = 0.0;
  /// How far from a count target an algorithm may end, as a fraction of the count.
  double Tolerance = 0.01;

  /// The mode and its value, the other settings as they are.
  void SetReduction(double reduction)
  {
    this->Mode = TargetMode::Reduction;
    this->Reduction = reduction;
  }
  void SetTriangleCount(std::int64_t triangles)
  {
    this->Mode = TargetMode::TriangleCount;
    this->TriangleCount = triangles;
  }
  void SetMaximumError(double maximumError, bool relative)
  {
    this->Mode = TargetMode::MaximumError;
    this->MaximumError = maximumError;
    this->RelativeError = relative;
  }

  bool Bounded() const { return this->Mode == TargetMode::MaximumError; }

  /// The count to reach among usable triangles: the reduction rounded to the nearest count, or
  /// the count, at most usable; 0 under an error bound (which has no count).
  std::int64_t TriangleCountFor(std::int64_t usable) const
  {
    switch (this->Mode)
    {
      case TargetMode::Reduction:
      {
        const double kept = 1.0 - std::min(1.0, std::max(0.0, this->Reduction));
        return static_cast<std::int64_t>(std::llround(static_cast<double>(usable) * kept));
      }
      case TargetMode::TriangleCount:
        return std::min(std::max<std::int64_t>(0, this->TriangleCount), usable);
      default:
        return 0;
    }
  }

  /// How many triangles a count may miss by: Tolerance of it, rounded down.
  std::int64_t Slack(std::int64_t count) const
  {
    return static_cast<std::int64_t>(this->Tolerance * static_cast<double>(count));
  }

  /// The length a relative bound is measured in, for a mesh of the given diagonal.
  double UnitLength(double diagonal) const
  {
    return this->ReferenceLength > 0.0 ? this->ReferenceLength : diagonal;
  }

  /// A distance in input units, in the bound's units (a fraction of the unit length when
  /// RelativeError is set).
  double InBoundUnits(double distance, double diagonal) const
  {
    const double unit = this->UnitLength(diagonal);
    return this->RelativeError && unit > 0.0 ? distance / unit : distance;
  }
};

} // namespace meshsimp

#endif
