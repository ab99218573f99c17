// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target over the core: the input's bytes are decoded into a small mesh (points on a
// coarse grid at one of several scales, so that many coincide or line up; triangles with any
// corners, so that many repeat a point or share an edge with three others; now and then a NaN)
// and into options (algorithm, target mode and value, locks, regions, open borders, cracks).
// Each algorithm runs on one thread and on two. What must hold, else the run aborts:
//   - the output is sound: corners name output points, points are finite, every output
//     triangle names an input triangle, sources name input points with finite weights;
//   - Progressive Mesh's sequence validates;
//   - one thread and two give the same output, bit for bit.
// Built with libFuzzer (clang -fsanitize=fuzzer) or with FuzzDriver.cxx's plain main.
#include "OctreeVertexClustering.h"
#include "ParallelDecimation.h"
#include "ProgressiveMesh.h"
#include "VolumeTriangleCollapse.h"

#include "TestHelpers.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
/// The input's bytes, read in order; zeros past the end.
class ByteReader
{
public:
  ByteReader(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t Byte() { return this->At < this->Size ? this->Data[this->At++] : 0; }
  int Word() { return this->Byte() | this->Byte() << 8; }
  double Unit() { return this->Byte() / 255.0; }

private:
  const std::uint8_t* Data;
  std::size_t Size, At = 0;
};

struct FuzzMesh
{
  std::vector<double> Points;
  std::vector<std::int32_t> Triangles;
  std::vector<std::uint8_t> Locks;
  std::vector<std::int32_t> Regions;

  meshsimp::TriangleMeshView View() const
  {
    meshsimp::TriangleMeshView view;
    view.Points = this->Points.data();
    view.NumberOfPoints = static_cast<std::int64_t>(this->Points.size() / 3);
    view.Triangles = this->Triangles.data();
    view.NumberOfTriangles = static_cast<std::int64_t>(this->Triangles.size() / 3);
    return view;
  }
};

FuzzMesh DecodeMesh(ByteReader& bytes)
{
  static const double scales[] = { 1.0, 1e-3, 1e6, 1e-30, 1e30, 0.1 };
  FuzzMesh mesh;
  const int points = 3 + bytes.Byte() % 62;
  const double scale = scales[bytes.Byte() % 6];
  for (int k = 0; k < 3 * points; ++k)
  {
    const std::uint8_t b = bytes.Byte();
    mesh.Points.push_back(b == 255 ? std::numeric_limits<double>::quiet_NaN() : (b % 9) * scale);
  }
  const int triangles = 1 + bytes.Word() % 240;
  for (int k = 0; k < 3 * triangles; ++k)
  {
    mesh.Triangles.push_back(bytes.Byte() % points);
  }
  const std::uint8_t extras = bytes.Byte();
  for (int p = 0; p < points && (extras & 1); ++p)
  {
    mesh.Locks.push_back(bytes.Byte() % 7 == 0);
  }
  for (int p = 0; p < points && (extras & 2); ++p)
  {
    mesh.Regions.push_back(bytes.Byte() % 3);
  }
  return mesh;
}

/// The options every algorithm shares, from the bytes.
void DecodeOptions(ByteReader& bytes, const FuzzMesh& mesh, meshsimp::SimplificationOptions& options)
{
  const int mode = bytes.Byte() % 3;
  const std::int64_t triangles = static_cast<std::int64_t>(mesh.Triangles.size() / 3);
  if (mode == 0)
  {
    options.Goal.SetReduction(bytes.Unit() * 1.2 - 0.1);
  }
  else if (mode == 1)
  {
    options.Goal.SetTriangleCount(bytes.Word() % (triangles + 2) - 1);
  }
  else
  {
    options.Goal.SetMaximumError(bytes.Unit() * bytes.Unit(), bytes.Byte() % 2 == 0);
  }
  const std::uint8_t flags = bytes.Byte();
  options.PreserveBoundary = flags & 1;
  options.CloseCracks = flags & 2;
  options.LockedPoints = mesh.Locks.empty() ? nullptr : mesh.Locks.data();
  options.Regions = mesh.Regions.empty() ? nullptr : mesh.Regions.data();
}

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "FuzzCore: %s\n", what);
    std::abort();
  }
}

void CheckSound(const meshsimp::SimplifiedMesh& out, const meshsimp::TriangleMeshView& input)
{
  const std::int64_t points = out.NumberOfPoints();
  Require(out.Triangles.size() == 3 * out.TriangleSource.size(), "a triangle without its source");
  for (const std::int32_t corner : out.Triangles)
  {
    Require(corner >= 0 && corner < points, "a corner names no output point");
  }
  for (const std::int32_t source : out.TriangleSource)
  {
    Require(source >= 0 && source < input.NumberOfTriangles, "a triangle source names no input triangle");
  }
  for (const double x : out.Points)
  {
    Require(std::isfinite(x), "an output point is not finite");
  }
  Require(static_cast<std::int64_t>(out.SourceOffsets.size()) == points + 1 &&
      out.SourceOffsets.back() == static_cast<std::int32_t>(out.SourcePoints.size()) &&
      out.SourceWeights.size() == out.SourcePoints.size(),
    "point sources do not span the points");
  for (std::int64_t p = 0; p < points; ++p)
  {
    Require(out.SourceOffsets[p] < out.SourceOffsets[p + 1], "an output point without a source");
  }
  for (std::size_t k = 0; k < out.SourcePoints.size(); ++k)
  {
    Require(out.SourcePoints[k] >= 0 && out.SourcePoints[k] < input.NumberOfPoints &&
        std::isfinite(out.SourceWeights[k]),
      "a point source names no input point or has a weight that is not finite");
  }
}

bool Same(const meshsimp::SimplifiedMesh& a, const meshsimp::SimplifiedMesh& b)
{
  return a.Points == b.Points && a.Triangles == b.Triangles && a.TriangleSource == b.TriangleSource &&
    a.SourceOffsets == b.SourceOffsets && a.SourcePoints == b.SourcePoints &&
    a.SourceWeights == b.SourceWeights;
}

/// A core algorithm's output, with the shared options and its own defaults.
template <typename Options, typename Result>
meshsimp::SimplifiedMesh RunCore(bool (*core)(const meshsimp::TriangleMeshView&, const Options&,
                                   Result&, const meshsimp::ExecutionContext&),
  const meshsimp::SimplificationOptions& shared, const meshsimp::TriangleMeshView& view,
  const meshsimp::ExecutionContext& context)
{
  Options options;
  static_cast<meshsimp::SimplificationOptions&>(options) = shared;
  Result result;
  core(view, options, result, context);
  return result;
}

/// Progressive Mesh's level for the target, its sequence validated.
meshsimp::SimplifiedMesh RunProgressive(const meshsimp::SimplificationOptions& shared,
  const meshsimp::TriangleMeshView& view, const meshsimp::ExecutionContext& context)
{
  meshsimp::ProgressiveMeshOptions options;
  static_cast<meshsimp::SimplificationOptions&>(options) = shared;
  meshsimp::ProgressiveMesh sequence;
  meshsimp::BuildProgressiveMesh(view, options, sequence, context);
  Require(sequence.Validate(view.NumberOfPoints).empty(), "the progressive sequence is not valid");
  meshsimp::SimplifiedMesh level;
  meshsimp::ExtractTarget(sequence, shared.Goal, view, level);
  return level;
}

/// One algorithm's output on the mesh with the given context.
meshsimp::SimplifiedMesh Run(int algorithm, const meshsimp::SimplificationOptions& shared,
  const FuzzMesh& mesh, const meshsimp::ExecutionContext& context)
{
  const meshsimp::TriangleMeshView view = mesh.View();
  switch (algorithm)
  {
    case 0:
      return RunCore(meshsimp::OctreeVertexClustering, shared, view, context);
    case 1:
      return RunCore(meshsimp::VolumeTriangleCollapse, shared, view, context);
    case 2:
      return RunCore(meshsimp::ParallelDecimation, shared, view, context);
    default:
      return RunProgressive(shared, view, context);
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader bytes(data, size);
  const int algorithm = bytes.Byte() % 4;
  const FuzzMesh mesh = DecodeMesh(bytes);
  meshsimp::SimplificationOptions options;
  DecodeOptions(bytes, mesh, options);
  const meshsimp::SimplifiedMesh one = Run(algorithm, options, mesh, {});
  CheckSound(one, mesh.View());
  const meshsimp::SimplifiedMesh two =
    Run(algorithm, options, mesh, meshsimp_test::Threaded<meshsimp::ExecutionContext>(2));
  Require(Same(one, two), "one thread and two give different outputs");
  return 0;
}
