// SPDX-License-Identifier: BSD-3-Clause
#include "TextureBaking.h"
#include "SurfaceSearch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;

/// The point of the original a texel shows: a triangle of the search surface and the weights
/// of its corners 1 and 2 (corner 0 has the rest).
struct Sample
{
  std::int32_t Triangle = -1;
  float Weights[2] = { 0.0f, 0.0f };
};

/// Per thread: one square's samples, (hi − lo + 1)² of them, and its blocks to check.
struct Scratch
{
  std::vector<Sample> Inner;
  std::vector<std::uint8_t> Queued;  // per block of the lattice, whether it is checked
  std::vector<std::int32_t> Pending; // blocks to check
  std::int64_t Inside = 0, Empty = 0, Exact = 0, Corrected = 0;
};

class SquareBaker
{
public:
  /// The exact search checks every CheckStep-th texel of every CheckStep-th row of a square.
  static constexpr std::int32_t CheckStep = 4;

  SquareBaker(const TriangleMeshView& mesh, const TextureAtlas& atlas, const TriangleMeshView& original,
    const SurfaceValues& values, const std::vector<std::int32_t>& seeds, double maximumDistance,
    const ExecutionContext& context)
    : Mesh(mesh)
    , Atlas(atlas)
    , Original(original)
    , Values(values)
    , Seeds(seeds)
    , MaximumDistance(maximumDistance)
    , Search(UsableSurface(original, this->OriginalTriangle))
  {
    this->Search.PrepareNearer(context);
  }

  /// Samples the texels on the square's triangles, then writes all its texels.
  void Bake(const AtlasSquare& square, Scratch& scratch, float* texture) const
  {
    this->SampleTriangles(square, scratch);
    this->Write(square, scratch.Inner, texture);
  }

private:
  /// The 3-D corners of half h of the square, at its places (see AtlasSquare).
  void Places(const AtlasSquare& square, int half, Vec3 corners[3]) const
  {
    for (int place = 0; place < 3; ++place)
    {
      corners[place] = this->Mesh.Point(this->Mesh.Id(3 * static_cast<std::int64_t>(square.Triangles[half]) + square.Corners[half][place]));
    }
  }

  /// A first guess for texels of the square: the original triangles around the points its
  /// corners came from, else the exact nearest.
  Nearest Seed(const Vec3& x, const AtlasSquare& square, Scratch& scratch) const
  {
    Nearest best;
    for (int half = 0; half < 2 && square.Triangles[half] >= 0; ++half)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::int64_t point = this->Mesh.Id(3 * static_cast<std::int64_t>(square.Triangles[half]) + k);
        const std::int32_t seed = point < static_cast<std::int64_t>(this->Seeds.size()) ? this->Seeds[point] : -1;
        if (seed >= 0 && seed < static_cast<std::int64_t>(this->Search.Points.size()))
        {
          this->Search.AroundPoint(x, seed, best);
        }
      }
    }
    if (best.Triangle < 0)
    {
      ++scratch.Exact;
      best = this->Search.Exact(x);
    }
    return best;
  }

  /// The sample of x on triangle t of the search.
  Sample SampleOn(const Vec3& x, std::int32_t t) const
  {
    Sample sample;
    if (t >= 0)
    {
      const Vec3 &a = this->Search.Corner(t, 0), &b = this->Search.Corner(t, 1), &c = this->Search.Corner(t, 2);
      const Vec3 weights = Barycentric(ClosestPointOnTriangle(x, a, b, c), a, b, c);
      sample.Triangle = t;
      sample.Weights[0] = static_cast<float>(weights[1]);
      sample.Weights[1] = static_cast<float>(weights[2]);
    }
    return sample;
  }

  /// The 3-D corners of both triangles of the square at their places (see AtlasSquare).
  void Corners(const AtlasSquare& square, Vec3 corners[2][3]) const
  {
    for (int half = 0; half < 2 && square.Triangles[half] >= 0; ++half)
    {
      this->Places(square, half, corners[half]);
    }
  }

  /// The point texel (i, j) of a square shows: on its first triangle where i + j <= span (the
  /// diagonal included), else on its second; steps from each right angle towards the other two
  /// corners.
  static Vec3 TexelPoint(const Vec3 corners[2][3], std::int32_t span, std::int32_t i, std::int32_t j)
  {
    if (i + j <= span)
    {
      const Vec3* p = corners[0];
      return p[0] + (double(i) / span) * (p[1] - p[0]) + (double(j) / span) * (p[2] - p[0]);
    }
    const Vec3* p = corners[1];
    return p[0] + (double(span - i) / span) * (p[2] - p[0]) + (double(span - j) / span) * (p[1] - p[0]);
  }

  /// Calls visit(i, j, rowFirst, x) for every texel (i, j) of the square's triangles, x its
  /// point: row by row, those of the first triangle, then those of the second.
  template <typename Visit>
  void ForEachTexel(const AtlasSquare& square, Visit&& visit) const
  {
    const std::int32_t span = square.Side - 1 - 2 * this->Atlas.Gutter;
    Vec3 corners[2][3];
    this->Corners(square, corners);
    for (int half = 0; half < 2 && square.Triangles[half] >= 0; ++half)
    {
      for (std::int32_t j = 0; j <= span; ++j)
      {
        const std::int32_t first = half == 0 ? 0 : span - j + 1, last = half == 0 ? span - j : span;
        for (std::int32_t i = first; i <= last; ++i)
        {
          visit(i, j, i == first, TexelPoint(corners, span, i, j));
        }
      }
    }
  }

  /// Whether an exact search within the maximum distance finds a triangle nearer to x than the
  /// sample's (then the sample moves there). hint, a triangle the search starts from (the last
  /// texel's): where it is nearer than the sample's, the search is bounded tighter.
  bool Corrected(const Vec3& x, Sample& sample, std::int32_t hint, Scratch& scratch) const
  {
    Nearest bound;
    bound.Distance = this->MaximumDistance;
    for (const std::int32_t t : { sample.Triangle, hint })
    {
      if (t >= 0)
      {
        bound.Offer(this->Search.Distance(x, t), t);
      }
    }
    const Nearest nearer = this->Search.Nearer(x, bound);
    if (nearer.Triangle < 0 || nearer.Triangle == sample.Triangle)
    {
      return false;
    }
    ++scratch.Corrected;
    sample = this->SampleOn(x, nearer.Triangle);
    return true;
  }

  /// Every texel on the square's triangles: a walk over the original towards its point from
  /// where the last ended (each row from where the last row started), then exact checks where
  /// a walk may have stopped in a hollow of the distance (on the wrong hill of a terrain).
  void SampleTriangles(const AtlasSquare& square, Scratch& scratch) const
  {
    const std::int32_t span = square.Side - 1 - 2 * this->Atlas.Gutter;
    scratch.Inner.assign(static_cast<std::size_t>(span + 1) * (span + 1), Sample());
    const auto at = [&](std::int32_t i, std::int32_t j) -> Sample& { return scratch.Inner[static_cast<std::size_t>(j) * (span + 1) + i]; };
    Nearest best, rowStart;
    this->ForEachTexel(square, [&](std::int32_t i, std::int32_t j, bool rowFirst, const Vec3& x) {
      best = rowFirst && rowStart.Triangle >= 0 ? rowStart : best;
      if (best.Triangle < 0)
      {
        best = this->Seed(x, square, scratch);
      }
      best.Distance = best.Triangle >= 0 ? this->Search.Distance(x, best.Triangle) : best.Distance;
      this->Search.Walk(x, best);
      rowStart = rowFirst ? best : rowStart;
      at(i, j) = this->SampleOn(x, best.Triangle);
      ++scratch.Inside;
      scratch.Empty += best.Triangle < 0; // a check finds none where the walk found none
    });
    this->CheckAroundCorrections(square, scratch);
  }

  /// Exact searches on every CheckStep-th texel of every CheckStep-th row (the lattice); where
  /// one corrects its walk, on every texel of the blocks of the lattice around it, and of the
  /// blocks around any block where a search corrected a walk too, each search bounded by the
  /// last texel's triangle as well.
  void CheckAroundCorrections(const AtlasSquare& square, Scratch& scratch) const
  {
    const std::int32_t span = square.Side - 1 - 2 * this->Atlas.Gutter, blocks = span / CheckStep + 1;
    Vec3 corners[2][3];
    this->Corners(square, corners);
    const auto onTriangle = [&](std::int32_t i, std::int32_t j) {
      return i >= 0 && j >= 0 && i <= span && j <= span && (i + j <= span || square.Triangles[1] >= 0);
    };
    const auto check = [&](std::int32_t i, std::int32_t j, std::int32_t& hint) {
      Sample& sample = scratch.Inner[static_cast<std::size_t>(j) * (span + 1) + i];
      const bool corrected = this->Corrected(TexelPoint(corners, span, i, j), sample, hint, scratch);
      hint = sample.Triangle;
      return corrected;
    };
    scratch.Queued.assign(static_cast<std::size_t>(blocks) * blocks, 0);
    scratch.Pending.clear();
    const auto queue = [&](std::int32_t bi, std::int32_t bj) {
      if (bi >= 0 && bj >= 0 && bi < blocks && bj < blocks && !scratch.Queued[static_cast<std::size_t>(bj) * blocks + bi])
      {
        scratch.Queued[static_cast<std::size_t>(bj) * blocks + bi] = 1;
        scratch.Pending.push_back(bj * blocks + bi);
      }
    };
    std::int32_t hint = -1;
    for (std::int32_t j = 0; j <= span; j += CheckStep)
    {
      for (std::int32_t i = 0; i <= span; i += CheckStep)
      {
        if (onTriangle(i, j) && check(i, j, hint))
        {
          for (const std::int32_t b : { 0, 1, 2, 3 })
          {
            queue(i / CheckStep - (b & 1), j / CheckStep - (b >> 1));
          }
        }
      }
    }
    while (!scratch.Pending.empty())
    {
      const std::int32_t block = scratch.Pending.back(), bi = block % blocks, bj = block / blocks;
      scratch.Pending.pop_back();
      bool corrected = false;
      for (std::int32_t j = bj * CheckStep; j < (bj + 1) * CheckStep; ++j)
      {
        for (std::int32_t i = bi * CheckStep; i < (bi + 1) * CheckStep; ++i)
        {
          corrected = (onTriangle(i, j) && (i % CheckStep != 0 || j % CheckStep != 0) && check(i, j, hint)) || corrected;
        }
      }
      for (std::int32_t b = 0; b < 9 && corrected; ++b)
      {
        queue(bi + b % 3 - 1, bj + b / 3 - 1);
      }
    }
  }

  /// Every texel of the square: its own sample, or (gutter, or the empty half of a lone
  /// triangle's square) the nearest texel's on the square's triangles.
  void Write(const AtlasSquare& square, const std::vector<Sample>& inner, float* texture) const
  {
    const std::int32_t lo = this->Atlas.Gutter, hi = square.Side - 1 - this->Atlas.Gutter, span = hi - lo;
    const int n = this->Values.Components;
    for (std::int32_t j = 0; j < square.Side; ++j)
    {
      for (std::int32_t i = 0; i < square.Side; ++i)
      {
        std::int32_t ci = std::min(std::max(i, lo), hi) - lo, cj = std::min(std::max(j, lo), hi) - lo;
        if (square.Triangles[1] < 0 && ci + cj > span)
        {
          const std::int32_t beyond = ci + cj - span;
          ci -= (beyond + 1) / 2;
          cj -= beyond / 2;
        }
        float* texel = texture + (static_cast<std::size_t>(square.Y + j) * this->Atlas.Size + square.X + i) * n;
        this->Interpolate(inner[static_cast<std::size_t>(cj) * (span + 1) + ci], texel);
      }
    }
  }

  /// The values at a sample, or NaN where it has none.
  void Interpolate(const Sample& sample, float* to) const
  {
    const int n = this->Values.Components;
    if (sample.Triangle < 0)
    {
      std::fill(to, to + n, std::numeric_limits<float>::quiet_NaN());
      return;
    }
    const std::int64_t triangle = this->OriginalTriangle[sample.Triangle];
    if (this->Values.PerTriangle)
    {
      std::copy(this->Values.Values + triangle * n, this->Values.Values + (triangle + 1) * n, to);
      return;
    }
    const float weights[3] = { 1.0f - sample.Weights[0] - sample.Weights[1], sample.Weights[0], sample.Weights[1] };
    std::fill(to, to + n, 0.0f);
    for (int k = 0; k < 3; ++k)
    {
      const float* from = this->Values.Values + this->Original.Id(3 * triangle + k) * n;
      for (int c = 0; c < n; ++c)
      {
        to[c] += weights[k] * from[c];
      }
    }
  }

  const TriangleMeshView& Mesh;
  const TextureAtlas& Atlas;
  const TriangleMeshView& Original;
  const SurfaceValues& Values;
  const std::vector<std::int32_t>& Seeds;
  const double MaximumDistance;
  std::vector<std::int32_t> OriginalTriangle; // per triangle of the search, the original's id
  const Surface Search;
};

} // namespace

BakedTexture BakeTexels(const TriangleMeshView& mesh, const TextureAtlas& atlas, const TriangleMeshView& original,
  const SurfaceValues& values, const std::vector<std::int32_t>& seeds, double maximumDistance,
  const ExecutionContext& context)
{
  BakedTexture baked;
  baked.Components = values.Components;
  baked.Values.assign(static_cast<std::size_t>(atlas.Size) * atlas.Size * values.Components, std::numeric_limits<float>::quiet_NaN());
  const SquareBaker baker(mesh, atlas, original, values, seeds, maximumDistance, context);
  // In batches of squares, so that progress moves and an abort is heard.
  const std::int64_t squares = static_cast<std::int64_t>(atlas.Squares.size()), batches = 20;
  std::vector<Scratch> scratches;
  for (std::int64_t batch = 0; batch < batches && !baked.Aborted; ++batch)
  {
    const std::int64_t first = squares * batch / batches, last = squares * (batch + 1) / batches;
    const std::int64_t texels = static_cast<std::int64_t>(atlas.Size) * atlas.Size / batches;
    context.ForEachWithScratch(scratches, last - first, 300 * texels / std::max<std::int64_t>(1, last - first),
      [&](std::int64_t s, Scratch& scratch) { baker.Bake(atlas.Squares[first + s], scratch, baked.Values.data()); });
    baked.Aborted = !context.Report(double(batch + 1) / batches);
  }
  for (const Scratch& scratch : scratches)
  {
    baked.InsideTexels += scratch.Inside;
    baked.EmptyTexels += scratch.Empty;
    baked.ExactSearches += scratch.Exact;
    baked.CorrectedWalks += scratch.Corrected;
  }
  return baked;
}

} // namespace meshsimp
