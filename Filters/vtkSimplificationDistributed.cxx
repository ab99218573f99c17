// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationDistributed.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace vtkSimplification
{
namespace
{
/// Every process's values, in process order (this one's alone without MPI); offsets[i] is
/// where process i's begin, offsets[processes] the end.
std::vector<double> GatherFromProcesses(const std::vector<double>& values, std::vector<vtkIdType>& offsets)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  const vtkIdType length = static_cast<vtkIdType>(values.size());
  std::vector<vtkIdType> lengths(processes, length);
  if (processes > 1)
  {
    controller->AllGather(&length, lengths.data(), 1);
  }
  offsets.assign(processes + 1, 0);
  for (int i = 0; i < processes; ++i)
  {
    offsets[i + 1] = offsets[i] + lengths[i];
  }
  if (processes < 2)
  {
    return values;
  }
  std::vector<double> all(static_cast<std::size_t>(std::max<vtkIdType>(1, offsets[processes])));
  std::vector<double> sent(values);
  sent.resize(std::max<std::size_t>(1, sent.size()));
  controller->AllGatherV(sent.data(), all.data(), length, lengths.data(), offsets.data());
  all.resize(static_cast<std::size_t>(offsets[processes]));
  return all;
}

/// values reduced element-wise over the processes, in place.
void ReduceOverProcesses(std::vector<double>& values, int operation)
{
  if (!IsDistributed() || values.empty())
  {
    return;
  }
  std::vector<double> local(values);
  vtkMultiProcessController::GetGlobalController()->AllReduce(
    local.data(), values.data(), static_cast<vtkIdType>(values.size()), operation);
}
}

bool IsDistributed()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller && controller->GetNumberOfProcesses() > 1;
}

void LockSharedPoints(const std::vector<const TriangleInput*>& pieces, const std::vector<vtkIdType>& keys,
  std::vector<std::vector<std::uint8_t>>& locks)
{
  locks.assign(pieces.size(), std::vector<std::uint8_t>());
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  if (processes < 2 && pieces.size() < 2)
  {
    return;
  }
  // Each piece's border points (input ids), from its usable triangles: the vertices with a
  // boundary edge; sent as (key, x, y, z, piece).
  std::vector<std::vector<std::int32_t>> borders(pieces.size());
  std::vector<double> sent;
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    if (!pieces[i])
    {
      continue; // the piece's own run reports the problem
    }
    const meshsimp::CompactMesh mesh = meshsimp::MakeCompactMesh(pieces[i]->View);
    std::vector<std::uint8_t> flags;
    for (std::size_t v = 0; v < mesh.Points.size(); ++v)
    {
      flags.resize(static_cast<std::size_t>(mesh.Adjacency.Offsets[v + 1] - mesh.Adjacency.Offsets[v]));
      if (meshsimp::MarkBoundaryCorners(mesh.Adjacency, static_cast<std::int64_t>(v), flags.data()))
      {
        borders[i].push_back(mesh.InputVertex[v]);
        const Eigen::Vector3d& x = mesh.Points[v];
        sent.insert(sent.end(), { static_cast<double>(keys[i]), x.x(), x.y(), x.z(), static_cast<double>(i) });
      }
    }
  }
  // Every process's border points to every process (or this one's alone, without MPI).
  const int self = processes > 1 ? controller->GetLocalProcessId() : 0;
  std::vector<vtkIdType> offsets;
  const std::vector<double> all = GatherFromProcesses(sent, offsets);
  // A point is shared when another piece of its key (on another process, or another piece of
  // this one) has a border point there: (key, x, y, z) then the piece's owner, sorted.
  using Entry = std::pair<std::array<double, 4>, std::int64_t>;
  std::vector<Entry> entries;
  for (int process = 0; process < processes; ++process)
  {
    for (vtkIdType j = offsets[process]; j < offsets[process + 1]; j += 5)
    {
      const std::int64_t owner = static_cast<std::int64_t>(process) << 32 | static_cast<std::int64_t>(all[j + 4]);
      entries.push_back({ { all[j], all[j + 1], all[j + 2], all[j + 3] }, owner });
    }
  }
  std::sort(entries.begin(), entries.end());
  const auto byPlace = [](const Entry& a, const Entry& b) { return a.first < b.first; };
  const double* mine = sent.data();
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    const std::int64_t me = static_cast<std::int64_t>(self) << 32 | static_cast<std::int64_t>(i);
    for (const std::int32_t point : borders[i])
    {
      const auto same = std::equal_range(entries.begin(), entries.end(),
        Entry{ { mine[0], mine[1], mine[2], mine[3] }, 0 }, byPlace);
      if (std::any_of(same.first, same.second, [me](const Entry& e) { return e.second != me; }))
      {
        if (locks[i].empty())
        {
          locks[i].assign(static_cast<std::size_t>(pieces[i]->View.NumberOfPoints), 0);
        }
        locks[i][point] = meshsimp::SharedPointLock;
      }
      mine += 5;
    }
  }
}

double SumOverProcesses(double value)
{
  std::vector<double> values{ value };
  ReduceOverProcesses(values, vtkCommunicator::SUM_OP);
  return values[0];
}

void MaximumOverProcesses(unsigned char* values, vtkIdType count)
{
  if (!IsDistributed() || count == 0)
  {
    return;
  }
  std::vector<unsigned char> local(values, values + count);
  vtkMultiProcessController::GetGlobalController()->AllReduce(local.data(), values, count, vtkCommunicator::MAX_OP);
}

bool GatherSurfaces(const std::vector<vtkPolyData*>& surfaces, std::vector<vtkSmartPointer<vtkPolyData>>& all,
  std::vector<std::size_t>& counts)
{
  all.assign(surfaces.begin(), surfaces.end());
  counts.assign(1, surfaces.size());
  if (!IsDistributed())
  {
    return true;
  }
  // One multiblock a process, its surfaces as blocks in order.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkNew<vtkMultiBlockDataSet> sent;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    sent->SetBlock(static_cast<unsigned int>(i), surfaces[i]);
  }
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  bool arrived = controller->AllGather(sent, received) != 0 && received.size() == static_cast<std::size_t>(controller->GetNumberOfProcesses());
  all.clear();
  counts.clear();
  for (int process = 0; arrived && process < static_cast<int>(received.size()); ++process)
  {
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(received[process]);
    arrived = process == controller->GetLocalProcessId() || blocks;
    counts.push_back(process == controller->GetLocalProcessId() ? surfaces.size() : blocks ? blocks->GetNumberOfBlocks() : 0);
    for (std::size_t b = 0; arrived && b < counts.back(); ++b)
    {
      vtkSmartPointer<vtkPolyData> surface = process == controller->GetLocalProcessId()
        ? surfaces[b]
        : vtkPolyData::SafeDownCast(blocks->GetBlock(static_cast<unsigned int>(b)));
      all.push_back(surface ? surface : vtkSmartPointer<vtkPolyData>::New());
    }
  }
  return SumOverProcesses(arrived ? 0.0 : 1.0) == 0.0;
}

meshsimp::BorderExchange MakeBorderExchange()
{
  meshsimp::BorderExchange exchange;
  exchange.Gather = [](const std::vector<double>& values) {
    std::vector<vtkIdType> offsets;
    return GatherFromProcesses(values, offsets);
  };
  exchange.Maximum = [](std::vector<double>& values) { ReduceOverProcesses(values, vtkCommunicator::MAX_OP); };
  exchange.Minimum = [](std::vector<double>& values) { ReduceOverProcesses(values, vtkCommunicator::MIN_OP); };
  return exchange;
}

Totals GatherTotals(const std::vector<const TriangleInput*>& pieces)
{
  // Sums and extremes over this process's pieces, then over the processes.
  double local[7] = { 0.0, std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
    std::numeric_limits<double>::lowest() };
  for (const TriangleInput* piece : pieces)
  {
    if (!piece)
    {
      continue;
    }
    local[0] += static_cast<double>(piece->View.NumberOfTriangles);
    for (std::int64_t v = 0; v < piece->View.NumberOfPoints; ++v)
    {
      const Eigen::Vector3d p = piece->View.Point(v);
      for (int k = 0; k < 3; ++k)
      {
        if (std::isfinite(p[k]))
        {
          local[1 + k] = std::min(local[1 + k], p[k]);
          local[4 + k] = std::max(local[4 + k], p[k]);
        }
      }
    }
  }
  double global[7];
  std::copy(local, local + 7, global);
  if (IsDistributed())
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    controller->AllReduce(local, global, 1, vtkCommunicator::SUM_OP);
    controller->AllReduce(local + 1, global + 1, 3, vtkCommunicator::MIN_OP);
    controller->AllReduce(local + 4, global + 4, 3, vtkCommunicator::MAX_OP);
  }
  Totals totals;
  totals.Triangles = global[0];
  if (global[1] <= global[4])
  {
    const Eigen::Vector3d lower(global[1], global[2], global[3]), upper(global[4], global[5], global[6]);
    totals.Diagonal = (0.5 * upper - 0.5 * lower).stableNorm() * 2.0;
  }
  return totals;
}

}
