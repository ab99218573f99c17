// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TextureAtlas.h
 * @brief A texture atlas of half squares for a triangle mesh: Zhou, Zhang, Shi and Pan, "A new
 * simplification algorithm for colored or textured polygonal models", §4, stage 1.
 *
 * Every triangle gets half of a square cell of a Size × Size texture, its corners on texel
 * centres. Adjacent triangles are paired (a greedy matching over the mesh's edges, longest shared
 * edge first) and a pair shares one square, its common edge on the square's diagonal: both
 * triangles map the diagonal's texels to the same points, so colour stays continuous across that
 * edge (the paper's Fig. 6 conditions). A triangle left alone takes a square of its own. A
 * square's side grows with the square root of its triangles' area, so that texels cover the
 * surface about evenly, and the squares are packed in shelves (largest first) at the largest
 * scale that fits. Each square keeps a gutter of Gutter texels around its triangles, which the
 * baker fills with the nearest texel of its own square, so that bilinear filtering and the
 * first mipmap levels never mix in another square's colour.
 */
#ifndef MeshSimplification_TextureAtlas_h
#define MeshSimplification_TextureAtlas_h

#include "TriangleMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace meshsimp
{

/// One square cell of the atlas: its lower-left texel, its side (texels, gutter included), and
/// the one or two triangles on it. In the square's texel coordinates, with lo = Gutter and
/// hi = Side − 1 − Gutter, the first triangle has its corners at (lo, lo), (hi, lo), (lo, hi),
/// the second at (hi, hi), (hi, lo), (lo, hi); the diagonal from (hi, lo) to (lo, hi) is their
/// common edge.
struct AtlasSquare
{
  std::int32_t X = 0, Y = 0, Side = 0;
  std::int32_t Triangles[2] = { -1, -1 };
  /// Per triangle, which of its corners sits at the first, second and third place above.
  std::int8_t Corners[2][3] = { { 0, 1, 2 }, { 0, 1, 2 } };
};

struct TextureAtlas
{
  std::int32_t Size = 0;   // texels along each side of the texture
  std::int32_t Gutter = 0; // texels around the triangles of each square
  std::vector<AtlasSquare> Squares;
  /// Per triangle corner (3 per triangle), the texel its corner sits on: x, y. Triangles the
  /// atlas left out (no usable corners) have -1.
  std::vector<std::int32_t> CornerTexels;
  /// Empty when the atlas was made; otherwise why not (one line).
  std::string Error;
};

/**
 * The atlas of mesh's triangles on a size × size texture (size: a power of two, at least 2) with
 * gutter texels around each square. Triangles whose corners are not three distinct points in
 * range get no square. Where even the smallest squares (2 × gutter + 2 texels) do not fit, Error
 * says how large the texture must be.
 */
TextureAtlas MakeTextureAtlas(const TriangleMeshView& mesh, std::int32_t size, std::int32_t gutter);

/// The texture coordinates of a texel's centre on the atlas: (x + 0.5) / Size.
inline float TexelCoordinate(std::int32_t texel, std::int32_t size)
{
  return (static_cast<float>(texel) + 0.5f) / static_cast<float>(size);
}

/// The mesh with its points split where its triangles' corners sit on different texels (the
/// seams of the atlas): per output point, the mesh point it copies and its texture coordinates;
/// per output triangle (the atlas's triangles, in order), its output corners.
struct SeamSplit
{
  std::vector<std::int32_t> SourcePoints;
  std::vector<float> TextureCoordinates; // 2 per output point
  std::vector<std::int32_t> Triangles;   // 3 per triangle
  std::vector<std::int32_t> SourceTriangles;
};

SeamSplit SplitAtSeams(const TriangleMeshView& mesh, const TextureAtlas& atlas);

} // namespace meshsimp

#endif
