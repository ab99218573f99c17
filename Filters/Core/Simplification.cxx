// SPDX-License-Identifier: BSD-3-Clause
#include "Simplification.h"

#include "CollapseMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace meshsimp
{
namespace
{
/// Meshes whose bounding-box diagonal lies outside this range are scaled (PowerOfTwo).
constexpr double MinimumDiagonal = 0x1p-64, MaximumDiagonal = 0x1p64;

void Normalize(PreparedMesh& prepared, Normalization normalization, const ExecutionContext& context)
{
  CompactMesh& mesh = prepared.Mesh;
  const double diagonal = mesh.Diagonal();
  prepared.Diagonal = diagonal;
  prepared.Lower = mesh.Lower;
  prepared.Upper = mesh.Upper;
  if (normalization == Normalization::CentreAndDiagonal)
  {
    // The box centred at the origin with a diagonal of 1: tolerances become relative, and the
    // high powers of lengths some errors use stay within range.
    prepared.Centred = true;
    prepared.Origin = mesh.Centre();
    prepared.Scale = diagonal > 0.0 ? 1.0 / diagonal : 1.0;
    prepared.MeshDiagonal = 1.0;
    const std::int64_t n = static_cast<std::int64_t>(mesh.Points.size());
    context.For(n, [&](std::int64_t begin, std::int64_t end) {
      for (std::int64_t v = begin; v < end; ++v)
      {
        mesh.Points[v] = (mesh.Points[v] - prepared.Origin) * prepared.Scale;
      }
    });
    return;
  }
  if (diagonal > 0.0 && (diagonal < MinimumDiagonal || diagonal > MaximumDiagonal))
  {
    // A power of two keeps every rounding: the result is the one of a mesh of diagonal about 1,
    // scaled back exactly.
    prepared.Scale = std::ldexp(1.0, -std::ilogb(diagonal));
    for (Eigen::Vector3d& p : mesh.Points)
    {
      p *= prepared.Scale;
    }
  }
  // In mesh units, also where the input's exceeds the largest double.
  prepared.MeshDiagonal = (prepared.Scale * mesh.Upper - prepared.Scale * mesh.Lower).norm();
}

/// Per vertex: the options' lock flags, and open-border vertices with PreserveBoundary.
void GatherLocks(PreparedMesh& prepared, const SimplificationOptions& options, const ExecutionContext& context)
{
  const CompactMesh& mesh = prepared.Mesh;
  const std::int64_t n = static_cast<std::int64_t>(mesh.Points.size());
  prepared.Locks.assign(n, 0);
  context.For(n, [&](std::int64_t begin, std::int64_t end) {
    std::vector<std::uint8_t> flags;
    for (std::int64_t v = begin; v < end; ++v)
    {
      const std::uint8_t lock = options.LockedPoints ? options.LockedPoints[mesh.InputVertex[v]] : 0;
      prepared.Locks[v] = lock == 0 ? 0 : lock == SharedPointLock ? SharedPointLock : 1;
      if (options.PreserveBoundary && !prepared.Locks[v])
      {
        flags.resize(static_cast<std::size_t>(mesh.Adjacency.Offsets[v + 1] - mesh.Adjacency.Offsets[v]));
        prepared.Locks[v] = MarkBoundaryCorners(mesh.Adjacency, v, flags.data()) ? 1 : 0;
      }
    }
  });
  prepared.LockedCount = std::count_if(prepared.Locks.begin(), prepared.Locks.end(), [](std::uint8_t l) { return l != 0; });
  if (options.Regions)
  {
    prepared.Regions.resize(n);
    for (std::int64_t v = 0; v < n; ++v)
    {
      prepared.Regions[v] = options.Regions[mesh.InputVertex[v]];
    }
  }
}
} // namespace

const std::vector<double>* SimplifiedMesh::PointArray(const std::string& name) const
{
  for (const NamedArray& array : this->PointArrays)
  {
    if (array.Name == name)
    {
      return &array.Values;
    }
  }
  return nullptr;
}

void SimplifiedMesh::AddPointArray(std::string name, std::vector<double> values, NamedArray::Kind type)
{
  this->PointArrays.push_back({ std::move(name), type, std::move(values) });
}

Outcome PreparedMesh::Report() const
{
  Outcome outcome;
  outcome.UsableTriangles = static_cast<std::int64_t>(this->Mesh.InputTriangle.size());
  outcome.UsablePoints = static_cast<std::int64_t>(this->Locks.size());
  outcome.Diagonal = this->Diagonal;
  outcome.TargetTriangles = this->TargetTriangles;
  outcome.NonFinitePoints = this->Mesh.NonFinitePoints;
  outcome.JoinedPoints = this->Mesh.JoinedPoints;
  outcome.LockedPoints = this->LockedCount;
  if (outcome.LockedPoints > 0 && outcome.LockedPoints == static_cast<std::int64_t>(this->Locks.size()) &&
    outcome.TargetTriangles < outcome.UsableTriangles)
  {
    outcome.Stop = StopReason::AllLocked;
  }
  return outcome;
}

PreparedMesh PrepareMesh(const TriangleMeshView& input, const SimplificationOptions& options,
  Normalization normalization, const ExecutionContext& context)
{
  PreparedMesh prepared;
  const PointMergeTest mayMerge = [&options](std::int64_t a, std::int64_t b) {
    return (!options.LockedPoints || options.LockedPoints[a] == options.LockedPoints[b]) &&
      (!options.Regions || options.Regions[a] == options.Regions[b]) &&
      (!options.SamePointData || options.SamePointData(a, b));
  };
  prepared.Mesh = MakeCompactMesh(input, context, options.CloseCracks ? mayMerge : PointMergeTest());
  Normalize(prepared, normalization, context);
  prepared.FrameLower = prepared.ToFrame(prepared.Lower);
  prepared.FrameUpper = prepared.ToFrame(prepared.Upper);
  GatherLocks(prepared, options, context);
  const Target& goal = options.Goal;
  prepared.TargetTriangles = goal.TriangleCountFor(static_cast<std::int64_t>(prepared.Mesh.InputTriangle.size()));
  if (goal.Bounded())
  {
    // A relative bound in units of the mesh's diagonal, or of the reference length.
    const double unit = goal.ReferenceLength > 0.0 ? goal.ReferenceLength * prepared.Scale : prepared.MeshDiagonal;
    prepared.Bound = goal.MaximumError * (goal.RelativeError ? unit : prepared.Scale);
  }
  return prepared;
}

void AddCollapseSources(const std::vector<CollapseRecord>& records, const std::vector<std::int32_t>& survivors,
  const std::vector<std::int32_t>& inputVertex, SimplifiedMesh& mesh)
{
  // The merges as a forest: vertices are its leaves, each record a node whose children are the
  // nodes its kept and merged vertices stood for, weighted; a vertex stands for its latest node.
  struct Child
  {
    std::int64_t Node;
    double Weight;
  };
  const std::int64_t n = static_cast<std::int64_t>(inputVertex.size());
  std::vector<std::int64_t> current(n);
  std::iota(current.begin(), current.end(), std::int64_t(0));
  std::vector<Child> children(3 * records.size(), Child{ -1, 0.0 });
  for (std::size_t r = 0; r < records.size(); ++r)
  {
    const CollapseRecord& record = records[r];
    children[3 * r] = { current[record.Kept], record.Weights[0] };
    for (int i = 0; i < 2; ++i)
    {
      if (record.Removed[i] >= 0)
      {
        children[3 * r + 1 + i] = { current[record.Removed[i]], record.Weights[i + 1] };
      }
    }
    current[record.Kept] = n + static_cast<std::int64_t>(r);
  }
  // Depth first from each survivor's node, the kept child first: the survivor's own leaf is
  // reached first, and becomes the representative.
  std::vector<Child> stack;
  for (const std::int32_t survivor : survivors)
  {
    stack.assign(1, Child{ current[survivor], 1.0 });
    while (!stack.empty())
    {
      const Child top = stack.back();
      stack.pop_back();
      if (top.Node < n)
      {
        mesh.SourcePoints.push_back(inputVertex[top.Node]);
        mesh.SourceWeights.push_back(top.Weight);
        continue;
      }
      const Child* child = children.data() + 3 * (top.Node - n);
      for (int i = 2; i >= 0; --i)
      {
        if (child[i].Node >= 0)
        {
          stack.push_back({ child[i].Node, top.Weight * child[i].Weight });
        }
      }
    }
    mesh.SourceOffsets.push_back(static_cast<std::int32_t>(mesh.SourcePoints.size()));
  }
}

std::vector<std::int32_t> WriteSurvivors(const CollapseMesh& mesh, const std::vector<std::uint8_t>& moved,
  const Frame& frame, const TriangleMeshView& input, const std::vector<std::int32_t>& inputVertex,
  const std::vector<std::int32_t>& inputTriangle, SimplifiedMesh& output)
{
  std::vector<std::int32_t> used, kept;
  mesh.Surviving(used, output.Triangles, kept);
  for (const std::int32_t v : used)
  {
    // Points that did not move keep their input coordinates bit for bit.
    const Eigen::Vector3d p = !moved.empty() && moved[v] ? frame.ToInput(mesh.Point(v)) : input.Point(inputVertex[v]);
    output.Points.insert(output.Points.end(), { p.x(), p.y(), p.z() });
  }
  for (const std::int32_t t : kept)
  {
    output.TriangleSource.push_back(inputTriangle[t]);
  }
  return used;
}

void AddSurvivorSources(const std::vector<std::int32_t>& survivors, const std::vector<std::int32_t>& inputVertex,
  SimplifiedMesh& mesh, const std::vector<std::int32_t>& mergedInto)
{
  // Each survivor first (weight 1), then the vertices merged into it, directly or through others
  // (weight 0: its own values stay), in vertex order.
  const std::int64_t n = static_cast<std::int64_t>(inputVertex.size());
  std::vector<std::int32_t> owner(mergedInto.empty() ? 0 : n, -1);
  for (std::size_t i = 0; i < survivors.size() && !owner.empty(); ++i)
  {
    owner[survivors[i]] = static_cast<std::int32_t>(i);
  }
  std::vector<std::int32_t> members(survivors.size() + 1, 0);
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(owner.size()); ++v)
  {
    // Down the merges to a survivor (or a vertex already resolved), then the path gets its owner.
    if (owner[v] >= 0 || mergedInto[v] < 0)
    {
      continue;
    }
    std::int32_t root = v;
    while (owner[root] < 0 && mergedInto[root] >= 0)
    {
      root = mergedInto[root];
    }
    for (std::int32_t u = v; owner[root] >= 0 && owner[u] < 0; u = mergedInto[u])
    {
      owner[u] = owner[root];
      ++members[owner[u] + 1];
    }
  }
  std::partial_sum(members.begin(), members.end(), members.begin());
  const std::size_t first = mesh.SourcePoints.size();
  mesh.SourcePoints.resize(first + survivors.size() + static_cast<std::size_t>(members.back()));
  mesh.SourceWeights.resize(mesh.SourcePoints.size(), 0.0);
  std::vector<std::int32_t> next(survivors.size());
  for (std::size_t i = 0; i < survivors.size(); ++i)
  {
    const std::size_t at = first + i + static_cast<std::size_t>(members[i]);
    mesh.SourcePoints[at] = inputVertex[survivors[i]];
    mesh.SourceWeights[at] = 1.0;
    next[i] = static_cast<std::int32_t>(at + 1);
    mesh.SourceOffsets.push_back(static_cast<std::int32_t>(first + i + 1 + static_cast<std::size_t>(members[i + 1])));
  }
  for (std::int64_t v = 0; v < static_cast<std::int64_t>(owner.size()); ++v)
  {
    if (owner[v] >= 0 && survivors[owner[v]] != v)
    {
      mesh.SourcePoints[next[owner[v]]++] = inputVertex[v];
    }
  }
}

void ComposeSources(SimplifiedMesh& first, SimplifiedMesh&& second)
{
  SimplifiedMesh& result = second;
  std::vector<std::int32_t> offsets = { 0 }, points;
  std::vector<double> weights;
  for (std::int64_t p = 0; p < result.NumberOfPoints(); ++p)
  {
    for (std::int32_t s = result.SourceOffsets[p]; s < result.SourceOffsets[p + 1]; ++s)
    {
      const std::int32_t via = result.SourcePoints[s];
      for (std::int32_t k = first.SourceOffsets[via]; k < first.SourceOffsets[via + 1]; ++k)
      {
        points.push_back(first.SourcePoints[k]);
        weights.push_back(result.SourceWeights[s] * first.SourceWeights[k]);
      }
    }
    offsets.push_back(static_cast<std::int32_t>(points.size()));
  }
  result.SourceOffsets = std::move(offsets);
  result.SourcePoints = std::move(points);
  result.SourceWeights = std::move(weights);
  for (std::int32_t& t : result.TriangleSource)
  {
    t = first.TriangleSource[t];
  }
  Outcome report = first.Report;
  const double firstError = first.Report.MaximumError, secondError = result.Report.MaximumError;
  report.MaximumError = firstError >= 0.0 && secondError >= 0.0 ? firstError + secondError : std::max(firstError, secondError);
  report.Stop = result.Report.Stop;
  report.Reason = result.Report.Reason;
  for (const std::string& note : result.Report.Notes)
  {
    if (std::find(report.Notes.begin(), report.Notes.end(), note) == report.Notes.end())
    {
      report.Notes.push_back(note);
    }
  }
  result.Report = std::move(report);
  first = std::move(result);
}

} // namespace meshsimp
