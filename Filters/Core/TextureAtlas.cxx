// SPDX-License-Identifier: BSD-3-Clause
#include "TextureAtlas.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace meshsimp
{
namespace
{
using Vec3 = Eigen::Vector3d;

double EdgeLength(const TriangleMeshView& mesh, std::int64_t t, int k)
{
  return (mesh.Point(mesh.Id(3 * t + (k + 1) % 3)) - mesh.Point(mesh.Id(3 * t + k))).norm();
}

double Area(const TriangleMeshView& mesh, std::int64_t t)
{
  const Vec3 a = mesh.Point(mesh.Id(3 * t));
  return 0.5 * (mesh.Point(mesh.Id(3 * t + 1)) - a).cross(mesh.Point(mesh.Id(3 * t + 2)) - a).norm();
}

/// Per usable triangle and edge k (from corner k to corner k + 1), the usable triangle across it
/// where exactly two share the edge, else -1.
std::vector<std::int32_t> EdgeNeighbours(const TriangleMeshView& mesh, const std::vector<std::uint8_t>& usable)
{
  std::vector<std::tuple<std::int64_t, std::int64_t, std::int32_t>> edges; // (low, high, 3 t + k)
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    for (int k = 0; k < 3 && usable[t]; ++k)
    {
      const std::int64_t a = mesh.Id(3 * t + k), b = mesh.Id(3 * t + (k + 1) % 3);
      edges.emplace_back(std::min(a, b), std::max(a, b), static_cast<std::int32_t>(3 * t + k));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::int32_t> across(static_cast<std::size_t>(3 * mesh.NumberOfTriangles), -1);
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while (j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) && std::get<1>(edges[j]) == std::get<1>(edges[i]))
    {
      ++j;
    }
    if (j == i + 2)
    {
      across[std::get<2>(edges[i])] = std::get<2>(edges[i + 1]) / 3;
      across[std::get<2>(edges[i + 1])] = std::get<2>(edges[i]) / 3;
    }
    i = j;
  }
  return across;
}

/// The squares before packing: each usable triangle paired with an unpaired neighbour across
/// its longest edge that has one (in triangle order), its common edge on the diagonal; the
/// others alone, their longest edge on the diagonal. areas receives each square's triangle area
/// (twice a lone triangle's, which fills half its square).
std::vector<AtlasSquare> PairTriangles(const TriangleMeshView& mesh, std::vector<double>& areas)
{
  std::vector<std::uint8_t> usable(static_cast<std::size_t>(mesh.NumberOfTriangles));
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    usable[t] = UsableTriangle(mesh, t);
  }
  const std::vector<std::int32_t> across = EdgeNeighbours(mesh, usable);
  std::vector<std::uint8_t> placed(usable.size(), 0);
  std::vector<AtlasSquare> squares;
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles; ++t)
  {
    if (!usable[t] || placed[t])
    {
      continue;
    }
    std::array<int, 3> edges = { 0, 1, 2 };
    std::stable_sort(edges.begin(), edges.end(), [&](int a, int b) { return EdgeLength(mesh, t, a) > EdgeLength(mesh, t, b); });
    const auto pairing = std::find_if(edges.begin(), edges.end(), [&](int k) {
      const std::int32_t u = across[3 * t + k];
      return u >= 0 && !placed[u];
    });
    const int k = pairing == edges.end() ? edges[0] : *pairing;
    AtlasSquare square;
    square.Triangles[0] = static_cast<std::int32_t>(t);
    square.Corners[0][0] = static_cast<std::int8_t>((k + 2) % 3);
    square.Corners[0][1] = static_cast<std::int8_t>(k);
    square.Corners[0][2] = static_cast<std::int8_t>((k + 1) % 3);
    placed[t] = 1;
    double area = 2.0 * Area(mesh, t);
    if (pairing != edges.end())
    {
      const std::int32_t u = across[3 * t + k];
      const std::int64_t p = mesh.Id(3 * t + k), q = mesh.Id(3 * t + (k + 1) % 3);
      std::int8_t at[3] = { 0, 0, 0 };
      for (int c = 0; c < 3; ++c)
      {
        const std::int64_t id = mesh.Id(3 * static_cast<std::int64_t>(u) + c);
        at[id == p ? 1 : id == q ? 2 : 0] = static_cast<std::int8_t>(c);
      }
      square.Triangles[1] = u;
      std::copy(at, at + 3, square.Corners[1]);
      placed[u] = 1;
      area = Area(mesh, t) + Area(mesh, u);
    }
    squares.push_back(square);
    areas.push_back(area);
  }
  return squares;
}

/// The side of a square of this area at scale: the gutter on both sides, and at least one
/// texel step between the triangle's corners.
std::int32_t SideAt(double scale, double area, std::int32_t gutter, std::int32_t size)
{
  const double span = std::floor(scale * std::sqrt(area));
  return 2 * gutter + 1 + static_cast<std::int32_t>(std::min<double>(std::max(span, 1.0), size));
}

/// Shelf packing of squares whose sides do not grow along order: left to right in rows, each
/// row as high as its first square. False where they do not fit in size × size.
bool Pack(std::vector<AtlasSquare>& squares, const std::vector<std::int32_t>& order, std::int32_t size)
{
  std::int64_t x = 0, y = 0, row = 0;
  for (const std::int32_t s : order)
  {
    AtlasSquare& square = squares[s];
    if (x + square.Side > size)
    {
      y += row;
      x = 0;
      row = 0;
    }
    if (y + square.Side > size)
    {
      return false;
    }
    square.X = static_cast<std::int32_t>(x);
    square.Y = static_cast<std::int32_t>(y);
    x += square.Side;
    row = std::max<std::int64_t>(row, square.Side);
  }
  return true;
}

/// Sets every square's side at scale and packs them.
bool PackAt(double scale, std::vector<AtlasSquare>& squares, const std::vector<double>& areas,
  const std::vector<std::int32_t>& order, std::int32_t size, std::int32_t gutter)
{
  for (std::size_t s = 0; s < squares.size(); ++s)
  {
    squares[s].Side = SideAt(scale, areas[s], gutter, size);
  }
  return Pack(squares, order, size);
}

/// The texels of the squares' triangles' corners.
std::vector<std::int32_t> CornerTexels(const TriangleMeshView& mesh, const std::vector<AtlasSquare>& squares, std::int32_t gutter)
{
  std::vector<std::int32_t> texels(static_cast<std::size_t>(6 * mesh.NumberOfTriangles), -1);
  for (const AtlasSquare& square : squares)
  {
    const std::int32_t lo = gutter, hi = square.Side - 1 - gutter;
    const std::int32_t places[2][3][2] = { { { lo, lo }, { hi, lo }, { lo, hi } }, { { hi, hi }, { hi, lo }, { lo, hi } } };
    for (int half = 0; half < 2 && square.Triangles[half] >= 0; ++half)
    {
      for (int place = 0; place < 3; ++place)
      {
        const std::size_t corner = 3 * static_cast<std::size_t>(square.Triangles[half]) + square.Corners[half][place];
        texels[2 * corner] = square.X + places[half][place][0];
        texels[2 * corner + 1] = square.Y + places[half][place][1];
      }
    }
  }
  return texels;
}

} // namespace

TextureAtlas MakeTextureAtlas(const TriangleMeshView& mesh, std::int32_t size, std::int32_t gutter)
{
  TextureAtlas atlas;
  atlas.Size = size;
  atlas.Gutter = gutter;
  std::vector<double> areas;
  atlas.Squares = PairTriangles(mesh, areas);
  // Largest squares first (sides never grow along this order at any scale).
  std::vector<std::int32_t> order(atlas.Squares.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return areas[a] > areas[b]; });
  if (!PackAt(0.0, atlas.Squares, areas, order, size, gutter))
  {
    std::int64_t needed = size;
    for (; needed < (std::int64_t(1) << 30) && !PackAt(0.0, atlas.Squares, areas, order, static_cast<std::int32_t>(needed), gutter);)
    {
      needed *= 2;
    }
    atlas.Error = "a texture of " + std::to_string(size) + " x " + std::to_string(size) + " texels cannot hold " +
      std::to_string(mesh.NumberOfTriangles) + " triangles with a gutter of " + std::to_string(gutter) + " texels: it needs " +
      std::to_string(needed) + " x " + std::to_string(needed);
    atlas.Squares.clear();
    return atlas;
  }
  // The largest scale at which the squares fit, by bisection.
  const double largest = areas.empty() ? 0.0 : *std::max_element(areas.begin(), areas.end());
  double fits = 0.0, fails = largest > 0.0 ? 2.0 * size / std::sqrt(largest) : 0.0;
  for (int step = 0; step < 60 && fails > 0.0; ++step)
  {
    const double scale = 0.5 * (fits + fails);
    (PackAt(scale, atlas.Squares, areas, order, size, gutter) ? fits : fails) = scale;
  }
  PackAt(fits, atlas.Squares, areas, order, size, gutter);
  atlas.CornerTexels = CornerTexels(mesh, atlas.Squares, gutter);
  return atlas;
}

SeamSplit SplitAtSeams(const TriangleMeshView& mesh, const TextureAtlas& atlas)
{
  // Each corner as (point, texel x, texel y, corner); equal (point, texel) share an output point.
  std::vector<std::array<std::int64_t, 4>> corners;
  SeamSplit split;
  for (std::int64_t t = 0; t < mesh.NumberOfTriangles && !atlas.CornerTexels.empty(); ++t)
  {
    if (atlas.CornerTexels[6 * t] < 0)
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::int64_t c = 3 * t + k;
      corners.push_back({ mesh.Id(c), atlas.CornerTexels[2 * c], atlas.CornerTexels[2 * c + 1],
        3 * static_cast<std::int64_t>(split.SourceTriangles.size()) + k });
    }
    split.SourceTriangles.push_back(static_cast<std::int32_t>(t));
  }
  std::sort(corners.begin(), corners.end());
  split.Triangles.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i)
  {
    if (i == 0 || corners[i][0] != corners[i - 1][0] || corners[i][1] != corners[i - 1][1] || corners[i][2] != corners[i - 1][2])
    {
      split.SourcePoints.push_back(static_cast<std::int32_t>(corners[i][0]));
      split.TextureCoordinates.push_back(TexelCoordinate(static_cast<std::int32_t>(corners[i][1]), atlas.Size));
      split.TextureCoordinates.push_back(TexelCoordinate(static_cast<std::int32_t>(corners[i][2]), atlas.Size));
    }
    split.Triangles[corners[i][3]] = static_cast<std::int32_t>(split.SourcePoints.size() - 1);
  }
  return split;
}

} // namespace meshsimp
