// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TextureBaking.h
 * @brief The texels of a simplified mesh's atlas filled from the detailed original: Zhou, Zhang,
 * Shi and Pan, "A new simplification algorithm for colored or textured polygonal models", §4,
 * stage 2.
 *
 * Each texel inside a triangle of the atlas (TextureAtlas.h) maps to a point of its simplified
 * triangle; the point of the original surface nearest to it gives the texel its values,
 * interpolated from the original triangle's corners (or that triangle's own). The search is
 * local: from the original points the simplified triangle's corners came from (a filter's
 * vtkOriginalPointIds), or from an exact search for the square's first texel, a walk over the
 * original surface towards each texel, starting where the previous texel's ended (texels of a
 * square are close on the surface). A walk can stop in a hollow of the distance (on the wrong
 * hill of a terrain), so every 4th texel of every 4th row is checked by an exact search within
 * a maximum distance (a tree of the original triangles' boxes, bounded by where the walk
 * ended), and where one finds a nearer triangle, the texels around it are checked too, until
 * no check nearby corrects a walk. Where nothing is that near, the walk's end stands, so every
 * texel gets a value. Gutter texels copy the
 * nearest texel of their own square's triangles. Texels run on all threads, square by square;
 * the result does not depend on the thread count.
 */
#ifndef MeshSimplification_TextureBaking_h
#define MeshSimplification_TextureBaking_h

#include "Execution.h"
#include "TextureAtlas.h"
#include "TriangleMesh.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

/// Values given on the original mesh: Components floats per point, or per triangle.
struct SurfaceValues
{
  const float* Values = nullptr;
  int Components = 0;
  bool PerTriangle = false;
};

struct BakedTexture
{
  int Components = 0;
  /// Size × Size texels, x fastest, Components each; NaN where no square lies.
  std::vector<float> Values;
  std::int64_t InsideTexels = 0; // texels on a triangle (gutter excluded)
  std::int64_t EmptyTexels = 0;  // of those, how many found no point of the original
  std::int64_t ExactSearches = 0;  // squares without a known origin, searched for their first texel
  std::int64_t CorrectedWalks = 0; // texels whose walk ended on a triangle that was not the nearest
  bool Aborted = false;
};

/**
 * Fills atlas's texels (made for mesh) with values from original. seeds: per mesh point, an
 * original point it came from, where known (-1 or out of range: unknown; an empty list: none
 * known). maximumDistance (original's units) bounds the exact search. Progress is reported, and an abort leaves the texture unfinished (Aborted).
 */
BakedTexture BakeTexels(const TriangleMeshView& mesh, const TextureAtlas& atlas, const TriangleMeshView& original,
  const SurfaceValues& values, const std::vector<std::int32_t>& seeds, double maximumDistance,
  const ExecutionContext& context);

} // namespace meshsimp

#endif
