// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of texture baking's core (TextureAtlas.h, TextureBaking.h): the atlas's squares,
// its continuous diagonals and seams, and texels that show the original's values.
#include "TestHelpers.h"
#include "TestMeshes.h"
#include "TextureAtlas.h"
#include "SurfaceSearch.h"
#include "TextureBaking.h"

#include <cmath>
#include <cstring>
#include <random>
#include <set>

namespace
{
using meshsimp::AtlasSquare;
using meshsimp::TextureAtlas;
using Eigen::Vector3d;

/// How many squares cover each texel.
std::vector<int> Coverage(const TextureAtlas& atlas)
{
  std::vector<int> covered(static_cast<std::size_t>(atlas.Size) * atlas.Size, 0);
  for (const AtlasSquare& square : atlas.Squares)
  {
    for (int j = square.Y; j < square.Y + square.Side && j < atlas.Size; ++j)
    {
      for (int i = square.X; i < square.X + square.Side && i < atlas.Size; ++i)
      {
        ++covered[static_cast<std::size_t>(j) * atlas.Size + i];
      }
    }
  }
  return covered;
}

/// A linear function of position, 0 to 255 on the unit cube: the values to bake.
Vector3d Linear(const Vector3d& p)
{
  return { 255.0 * p[0], 127.0 * p[1] + 64.0 * p[2], 200.0 - 100.0 * p[2] };
}

std::vector<float> LinearValues(const Mesh& mesh)
{
  std::vector<float> values;
  for (std::int64_t p = 0; p < mesh.View().NumberOfPoints; ++p)
  {
    const Vector3d value = Linear(mesh.View().Point(p));
    values.insert(values.end(), { float(value[0]), float(value[1]), float(value[2]) });
  }
  return values;
}

/// The 3-D point that texel (i, j) of half h of a square shows, as the atlas lays it out.
Vector3d TexelPoint(const Mesh& mesh, const AtlasSquare& square, int half, int gutter, int i, int j)
{
  const int span = square.Side - 1 - 2 * gutter;
  Vector3d p[3];
  for (int place = 0; place < 3; ++place)
  {
    p[place] = mesh.View().Point(mesh.Triangles[3 * square.Triangles[half] + square.Corners[half][place]]);
  }
  const double s = double(i) / span, t = double(j) / span;
  return half == 0 ? Vector3d(p[0] + s * (p[1] - p[0]) + t * (p[2] - p[0]))
                   : Vector3d(p[0] + (1.0 - s) * (p[2] - p[0]) + (1.0 - t) * (p[1] - p[0]));
}

void SquaresNeitherOverlapNorLeaveTheTexture()
{
  const Mesh sphere = Sphere(8);
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(sphere.View(), 256, 2);
  CHECK(atlas.Error.empty());
  const std::vector<int> covered = Coverage(atlas);
  CHECK(*std::max_element(covered.begin(), covered.end()) == 1);
  std::vector<int> placed(sphere.Triangles.size() / 3, 0);
  for (const AtlasSquare& square : atlas.Squares)
  {
    CHECK(square.X >= 0 && square.Y >= 0 && square.X + square.Side <= 256 && square.Y + square.Side <= 256);
    CHECK(square.Side >= 2 * 2 + 2);
    for (const std::int32_t t : square.Triangles)
    {
      if (t >= 0)
      {
        ++placed[t];
      }
    }
  }
  CHECK(std::all_of(placed.begin(), placed.end(), [](int n) { return n == 1; }));
  // Most triangles share a square with a neighbour, and the squares fill most of the texture.
  const std::size_t pairs = std::count_if(atlas.Squares.begin(), atlas.Squares.end(), [](const AtlasSquare& s) { return s.Triangles[1] >= 0; });
  CHECK(2 * pairs >= 9 * placed.size() / 10);
  CHECK(std::count(covered.begin(), covered.end(), 1) > 256 * 256 / 2);
}

void PairsShareTheirDiagonal()
{
  const Mesh sphere = Sphere(6);
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(sphere.View(), 256, 1);
  for (const AtlasSquare& square : atlas.Squares)
  {
    if (square.Triangles[1] < 0)
    {
      continue;
    }
    for (int place = 1; place < 3; ++place)
    {
      const int a = 3 * square.Triangles[0] + square.Corners[0][place], b = 3 * square.Triangles[1] + square.Corners[1][place];
      CHECK(sphere.Triangles[a] == sphere.Triangles[b]);
      CHECK(atlas.CornerTexels[2 * a] == atlas.CornerTexels[2 * b] && atlas.CornerTexels[2 * a + 1] == atlas.CornerTexels[2 * b + 1]);
    }
  }
  // The split mesh shares a point along each diagonal, and each corner's coordinates are its
  // texel's centre.
  const meshsimp::SeamSplit split = meshsimp::SplitAtSeams(sphere.View(), atlas);
  CHECK(split.SourceTriangles.size() == sphere.Triangles.size() / 3);
  std::set<std::pair<int, int>> keys;
  for (std::size_t p = 0; p < split.SourcePoints.size(); ++p)
  {
    keys.emplace(split.SourcePoints[p], int(split.TextureCoordinates[2 * p] * 256.0f) * 256 + int(split.TextureCoordinates[2 * p + 1] * 256.0f));
  }
  CHECK(keys.size() == split.SourcePoints.size());
  CHECK(split.SourcePoints.size() < split.Triangles.size());
  for (std::size_t c = 0; c < split.Triangles.size(); ++c)
  {
    const std::size_t t = split.SourceTriangles[c / 3], corner = 3 * t + c % 3;
    CHECK(split.SourcePoints[split.Triangles[c]] == sphere.Triangles[corner]);
    CHECK(std::abs(split.TextureCoordinates[2 * split.Triangles[c]] - (atlas.CornerTexels[2 * corner] + 0.5f) / 256.0f) < 1e-7f);
  }
}

/// Baking a mesh from itself: every texel on a triangle is the linear function at its point.
void CheckLinearBake(const Mesh& mesh, const std::vector<std::int32_t>& seeds, const meshsimp::ExecutionContext& context, std::vector<float>& texels)
{
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(mesh.View(), 512, 2);
  const std::vector<float> values = LinearValues(mesh);
  const meshsimp::BakedTexture baked = meshsimp::BakeTexels(mesh.View(), atlas, mesh.View(), { values.data(), 3, false }, seeds, 0.01, context);
  CHECK(baked.InsideTexels > 512 * 256 && baked.EmptyTexels == 0 && !baked.Aborted);
  double worst = 0.0;
  for (const AtlasSquare& square : atlas.Squares)
  {
    const int span = square.Side - 1 - 2 * atlas.Gutter;
    for (int j = 0; j <= span; ++j)
    {
      for (int i = 0; i <= span; ++i)
      {
        const int half = i + j <= span ? 0 : 1;
        if (half == 1 && square.Triangles[1] < 0)
        {
          continue;
        }
        const Vector3d expected = Linear(TexelPoint(mesh, square, half, atlas.Gutter, i, j));
        const float* texel = baked.Values.data() + 3 * ((std::size_t(square.Y + atlas.Gutter + j)) * 512 + square.X + atlas.Gutter + i);
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(texel[c] - expected[c]));
        }
      }
    }
    // A gutter texel copies the nearest corner texel.
    const float* corner = baked.Values.data() + 3 * (std::size_t(square.Y + atlas.Gutter) * 512 + square.X + atlas.Gutter);
    CHECK(std::equal(corner, corner + 3, baked.Values.data() + 3 * (std::size_t(square.Y) * 512 + square.X)));
  }
  CHECK(worst < 0.01); // far within 1/255 of the 0-255 range (1.0)
  texels = baked.Values;
}

void TexelsShowTheOriginalsValues()
{
  const Mesh mesh = Sphere(6);
  std::vector<std::int32_t> ids(mesh.Points.size() / 3);
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<float> seeded, searched, threaded;
  CheckLinearBake(mesh, ids, {}, seeded);
  CheckLinearBake(mesh, {}, {}, searched);
  CheckLinearBake(mesh, ids, meshsimp_test::Chunked<meshsimp::ExecutionContext>(3, 5), threaded);
  const auto same = [](const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
  };
  CHECK(same(seeded, threaded));
  CHECK(seeded.size() == searched.size());
  for (std::size_t i = 0; i < seeded.size() && i < searched.size(); ++i)
  {
    CHECK((std::isnan(seeded[i]) && std::isnan(searched[i])) || std::abs(seeded[i] - searched[i]) < 0.01f);
  }
}

void CoarseMeshTakesTheNearestPoint()
{
  // A plane simplified to two triangles: every texel shows the detailed plane's value at its own
  // point, found from the corners' seeds or by the exact search.
  const Mesh detailed = Grid(24), coarse = Grid(1);
  const std::vector<float> values = LinearValues(detailed);
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(coarse.View(), 256, 2);
  const std::vector<std::int32_t> seeds = { 0, 24, 24 * 25, 24 * 25 + 24 };
  const meshsimp::BakedTexture baked = meshsimp::BakeTexels(coarse.View(), atlas, detailed.View(), { values.data(), 3, false }, seeds, 0.01, {});
  CHECK(atlas.Squares.size() == 1 && baked.EmptyTexels == 0);
  const AtlasSquare& square = atlas.Squares[0];
  const Vector3d middle = TexelPoint(coarse, square, 0, 2, (square.Side - 5) / 4, (square.Side - 5) / 4);
  const float* texel = baked.Values.data() + 3 * (std::size_t(2 + (square.Side - 5) / 4) * 256 + 2 + (square.Side - 5) / 4);
  CHECK(std::abs(texel[0] - Linear(middle)[0]) < 1e-3 && std::abs(texel[1] - Linear(middle)[1]) < 1e-3);
  // Per-triangle values: each texel has its original triangle's.
  std::vector<float> perTriangle(detailed.Triangles.size() / 3);
  std::iota(perTriangle.begin(), perTriangle.end(), 0.0f);
  const meshsimp::BakedTexture cells = meshsimp::BakeTexels(coarse.View(), atlas, detailed.View(), { perTriangle.data(), 1, true }, seeds, 0.01, {});
  const float cell = cells.Values[std::size_t(2 + (square.Side - 5) / 4) * 256 + 2 + (square.Side - 5) / 4];
  CHECK(cell == std::floor(cell) && cell >= 0.0f && cell < float(perTriangle.size()));
  const std::int32_t* corners = detailed.Triangles.data() + 3 * static_cast<std::size_t>(cell);
  CHECK(DistanceToTriangle(middle, detailed.View().Point(corners[0]), detailed.View().Point(corners[1]), detailed.View().Point(corners[2])) < 1e-9);
}

void TreeSearchIsExact()
{
  // The tree's search from no guess finds the grid's nearest distance; from a guess nearer than
  // any triangle it keeps the guess; from a far guess it finds the nearest. A tree made on
  // three threads answers as the one made on one.
  Mesh sphere = Sphere(10);
  std::vector<std::int32_t> triangle, alike;
  const meshsimp::Surface surface = meshsimp::UsableSurface(sphere.View(), triangle);
  const meshsimp::Surface threaded = meshsimp::UsableSurface(sphere.View(), alike);
  threaded.PrepareNearer(meshsimp_test::Threaded<meshsimp::ExecutionContext>(3));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-0.3, 1.3);
  for (int i = 0; i < 500; ++i)
  {
    const Vector3d x(coordinate(random), coordinate(random), coordinate(random));
    const meshsimp::Nearest exact = surface.Exact(x), found = surface.Nearer(x, meshsimp::Nearest());
    CHECK(found.Triangle >= 0 && std::abs(found.Distance - exact.Distance) <= 1e-12);
    const meshsimp::Nearest same = threaded.Nearer(x, meshsimp::Nearest());
    CHECK(same.Triangle == found.Triangle && same.Distance == found.Distance);
    meshsimp::Nearest tight;
    tight.Distance = 0.5 * exact.Distance;
    CHECK(surface.Nearer(x, tight).Triangle == -1);
    meshsimp::Nearest far;
    far.Offer(surface.Distance(x, (found.Triangle + 50) % static_cast<std::int32_t>(triangle.size())), (found.Triangle + 50) % static_cast<std::int32_t>(triangle.size()));
    CHECK(std::abs(surface.Nearer(x, far).Distance - exact.Distance) <= 1e-12);
  }
}

void TooSmallATextureSaysHowLarge()
{
  const Mesh sphere = Sphere(8);
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(sphere.View(), 32, 2);
  CHECK(!atlas.Error.empty() && atlas.Squares.empty());
  CHECK(atlas.Error.find("it needs 128 x 128") != std::string::npos); // 384 squares of 6 x 6 texels
}

void SurvivesBadInput()
{
  Mesh broken = Grid(2);
  broken.Triangles.insert(broken.Triangles.end(), { 0, 0, 1, 0, 1, 99, -4, 2, 3 });
  broken.Points[12] = std::numeric_limits<double>::quiet_NaN(); // point 4: its triangles go too
  const TextureAtlas atlas = meshsimp::MakeTextureAtlas(broken.View(), 256, 2);
  std::size_t placed = 0;
  for (const AtlasSquare& square : atlas.Squares)
  {
    placed += (square.Triangles[0] >= 0) + (square.Triangles[1] >= 0);
  }
  CHECK(placed == 2);
  const meshsimp::SeamSplit split = meshsimp::SplitAtSeams(broken.View(), atlas);
  CHECK(split.SourceTriangles.size() == 2);
  // An original with no usable triangle: no texel gets a value, nothing breaks.
  Mesh empty = Grid(1);
  empty.Triangles = { 0, 0, 1 };
  const std::vector<float> values(4, 1.0f);
  const meshsimp::BakedTexture baked = meshsimp::BakeTexels(broken.View(), atlas, empty.View(), { values.data(), 1, false }, { -1, 7, 1 << 30 }, 0.01, {});
  CHECK(baked.InsideTexels > 0 && baked.EmptyTexels == baked.InsideTexels);
  CHECK(std::all_of(baked.Values.begin(), baked.Values.end(), [](float v) { return std::isnan(v); }));
  const TextureAtlas none = meshsimp::MakeTextureAtlas(Mesh().View(), 256, 2);
  CHECK(none.Error.empty() && none.Squares.empty());
}
} // namespace

int main()
{
  return meshsimp_test::RunTests({
    { "SquaresNeitherOverlapNorLeaveTheTexture", SquaresNeitherOverlapNorLeaveTheTexture },
    { "PairsShareTheirDiagonal", PairsShareTheirDiagonal },
    { "TexelsShowTheOriginalsValues", TexelsShowTheOriginalsValues },
    { "CoarseMeshTakesTheNearestPoint", CoarseMeshTakesTheNearestPoint },
    { "TreeSearchIsExact", TreeSearchIsExact },
    { "TooSmallATextureSaysHowLarge", TooSmallATextureSaysHowLarge },
    { "SurvivesBadInput", SurvivesBadInput },
  });
}
