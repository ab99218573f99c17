// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeshSimplificationHelpers.h"

#include "vtkAlgorithm.h"
#include "vtkMultiProcessController.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkUnsignedCharArray.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

namespace vtkMeshSimplificationHelpers
{

namespace
{
std::string TooManyTriangles(std::int64_t count)
{
  return "the input has " + std::to_string(count) + " triangles, more than the " +
    std::to_string(meshsimp::MaximumTriangles) + " the filters take";
}

/// The input, or a shallow copy of it without the point and cell data arrays that are shorter
/// than its points or cells (copying their values would read past their ends), each named in a
/// warning. The input itself is never changed.
vtkSmartPointer<vtkPolyData> WithUsableAttributes(vtkAlgorithm* filter, vtkPolyData* input)
{
  vtkSmartPointer<vtkPolyData> usable = input;
  const struct
  {
    int Association;
    vtkIdType Count;
    const char* What;
  } sets[2] = { { vtkDataObject::POINT, input->GetNumberOfPoints(), "point" },
    { vtkDataObject::CELL, input->GetNumberOfCells(), "cell" } };
  for (const auto& set : sets)
  {
    vtkDataSetAttributes* data = input->GetAttributes(set.Association);
    for (int i = data->GetNumberOfArrays() - 1; i >= 0; --i) // from the end: indices stay valid
    {
      vtkAbstractArray* array = data->GetAbstractArray(i);
      if (array->GetNumberOfTuples() >= set.Count)
      {
        continue;
      }
      vtkWarningWithObjectMacro(filter, << "Not passing " << set.What << " data array '"
                                        << (array->GetName() ? array->GetName() : "") << "': it has "
                                        << array->GetNumberOfTuples() << " tuples for "
                                        << set.Count << " " << set.What << "s.");
      if (usable == input)
      {
        usable = vtkSmartPointer<vtkPolyData>::New();
        usable->ShallowCopy(input); // shares every array; the input keeps its own lists
      }
      usable->GetAttributes(set.Association)->RemoveArray(i);
    }
  }
  return usable;
}
}

bool ExtractTriangles(vtkPolyData* input, TriangleInput& out, std::string& error)
{
  out = TriangleInput();
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints >= std::numeric_limits<std::int32_t>::max())
  {
    error = "the input has more than 2^31 - 1 points";
    return false;
  }
  if (numberOfPoints > 0)
  {
    vtkDataArray* coordinates = input->GetPoints()->GetData();
    auto* doubles = vtkDoubleArray::SafeDownCast(coordinates);
    auto* floats = vtkFloatArray::SafeDownCast(coordinates);
    if (doubles && doubles->GetNumberOfComponents() == 3)
    {
      out.View.Points = doubles->GetPointer(0);
    }
    else if (floats && floats->GetNumberOfComponents() == 3)
    {
      out.View.FloatPoints = floats->GetPointer(0);
    }
    else
    {
      out.PointCopy.resize(3 * numberOfPoints);
      for (vtkIdType i = 0; i < numberOfPoints; ++i)
      {
        coordinates->GetTuple(i, out.PointCopy.data() + 3 * i);
      }
      out.View.Points = out.PointCopy.data();
    }
  }
  out.View.NumberOfPoints = numberOfPoints;
  out.NumberOfVerts = input->GetNumberOfVerts();
  out.NumberOfLines = input->GetNumberOfLines();

  // Cell ids of vtkPolyData run over verts, lines, polys, then strips.
  vtkIdType cellId = out.NumberOfVerts + out.NumberOfLines;
  // Ghost cells (copies of another piece's cells under MPI) and hidden ones are not this
  // piece's to simplify: they are skipped, and the border to them becomes this piece's border.
  vtkUnsignedCharArray* ghosts = input->GetCellGhostArray();
  const unsigned char ghostBits = vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL;
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  if (ghosts && ghosts->GetNumberOfValues() < numberOfCells)
  {
    ghosts = nullptr; // PrepareTriangles leaves out such arrays before
  }
  bool anyGhost = false;
  for (vtkIdType id = cellId; ghosts && id < numberOfCells && !anyGhost; ++id)
  {
    anyGhost = (ghosts->GetValue(id) & ghostBits) != 0;
  }
  auto isGhost = [&](vtkIdType id) { return anyGhost && (ghosts->GetValue(id) & ghostBits) != 0; };
  auto add = [&](vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType source) {
    out.Triangles.push_back(static_cast<std::int32_t>(a));
    out.Triangles.push_back(static_cast<std::int32_t>(b));
    out.Triangles.push_back(static_cast<std::int32_t>(c));
    out.SourceCells.push_back(source);
  };
  vtkCellArray* polyCells = input->GetPolys();
  if (polyCells->IsHomogeneous() == 3 && input->GetNumberOfStrips() == 0 && !anyGhost)
  {
    // Triangles only, the common case: the connectivity is viewed in place.
    const vtkIdType count = polyCells->GetNumberOfCells();
    if (count > meshsimp::MaximumTriangles)
    {
      error = TooManyTriangles(count);
      return false;
    }
    if (polyCells->IsStorage64Bit())
    {
      out.View.Triangles64 = polyCells->GetConnectivityArray64()->GetPointer(0);
    }
    else
    {
      out.View.Triangles = polyCells->GetConnectivityArray32()->GetPointer(0);
    }
    out.FirstCell = cellId;
    out.View.NumberOfTriangles = count;
    return true;
  }
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> triangleIds;
  auto polys = vtk::TakeSmartPointer(polyCells->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell(), ++cellId)
  {
    vtkIdType size;
    const vtkIdType* ids;
    if (isGhost(cellId))
    {
      continue;
    }
    polys->GetCurrentCell(size, ids);
    if (size == 3)
    {
      add(ids[0], ids[1], ids[2], cellId);
    }
    else if (size > 3)
    {
      // Ear-cut triangulation of the polygon (handles non-convex ones); a fan when it fails.
      polygon->Initialize(static_cast<int>(size), ids, input->GetPoints());
      if (polygon->Triangulate(triangleIds) && triangleIds->GetNumberOfIds() == 3 * (size - 2))
      {
        for (vtkIdType k = 0; k < triangleIds->GetNumberOfIds(); k += 3)
        {
          add(ids[triangleIds->GetId(k)], ids[triangleIds->GetId(k + 1)],
            ids[triangleIds->GetId(k + 2)], cellId);
        }
      }
      else
      {
        for (vtkIdType k = 1; k + 1 < size; ++k)
        {
          add(ids[0], ids[k], ids[k + 1], cellId);
        }
      }
    }
  }
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell(), ++cellId)
  {
    vtkIdType size;
    const vtkIdType* ids;
    if (isGhost(cellId))
    {
      continue;
    }
    strips->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k + 2 < size; ++k)
    {
      if (k % 2 == 0)
      {
        add(ids[k], ids[k + 1], ids[k + 2], cellId);
      }
      else
      {
        add(ids[k + 1], ids[k], ids[k + 2], cellId);
      }
    }
  }
  if (static_cast<std::int64_t>(out.SourceCells.size()) > meshsimp::MaximumTriangles)
  {
    error = TooManyTriangles(static_cast<std::int64_t>(out.SourceCells.size()));
    return false;
  }
  out.View.Triangles = out.Triangles.data();
  out.View.NumberOfTriangles = static_cast<std::int64_t>(out.Triangles.size() / 3);
  return true;
}

void LockSharedPoints(const std::vector<vtkPolyData*>& pieces, const std::vector<vtkIdType>& keys,
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
    TriangleInput triangles;
    std::string problem;
    if (!ExtractTriangles(pieces[i], triangles, problem))
    {
      continue; // the piece's own run reports the problem
    }
    const meshsimp::CompactMesh mesh = meshsimp::MakeCompactMesh(triangles.View);
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
  std::vector<vtkIdType> lengths(processes, static_cast<vtkIdType>(sent.size())), offsets(processes + 1, 0);
  if (processes > 1)
  {
    vtkIdType length = static_cast<vtkIdType>(sent.size());
    controller->AllGather(&length, lengths.data(), 1);
  }
  for (int i = 0; i < processes; ++i)
  {
    offsets[i + 1] = offsets[i] + lengths[i];
  }
  std::vector<double> all(sent);
  if (processes > 1)
  {
    all.resize(static_cast<std::size_t>(std::max<vtkIdType>(1, offsets[processes])));
    controller->AllGatherV(sent.data(), all.data(), lengths[self], lengths.data(), offsets.data());
  }
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
          locks[i].assign(static_cast<std::size_t>(pieces[i]->GetNumberOfPoints()), 0);
        }
        locks[i][point] = meshsimp::SharedPointLock;
      }
      mine += 5;
    }
  }
}

bool PrepareTriangles(
  vtkAlgorithm* filter, vtkSmartPointer<vtkPolyData>& input, TriangleInput& triangles, int& requestResult)
{
  input = WithUsableAttributes(filter, input);
  std::string problem;
  if (!ExtractTriangles(input, triangles, problem))
  {
    vtkErrorWithObjectMacro(filter, << "Cannot simplify: " << problem << ".");
    requestResult = 0;
    return false;
  }
  if (triangles.NumberOfVerts + triangles.NumberOfLines > 0)
  {
    vtkWarningWithObjectMacro(filter, << "Dropping " << triangles.NumberOfVerts << " vertex and "
                                      << triangles.NumberOfLines
                                      << " line cells: only triangles, polygons and strips are simplified.");
  }
  requestResult = 1;
  return triangles.View.NumberOfTriangles > 0;
}

bool CheckTarget(vtkAlgorithm* filter, int targetMode, double reduction, double maximumError)
{
  const char* name = targetMode == 0 ? "TargetReduction" : targetMode == 2 ? "MaximumError" : nullptr;
  const double value = targetMode == 0 ? reduction : maximumError;
  if (name && std::isnan(value))
  {
    vtkErrorWithObjectMacro(filter, << "Cannot simplify: " << name << " is not a number.");
    return false;
  }
  return true;
}

std::string LockedPointsNote(const std::vector<std::uint8_t>& locked, bool userArray)
{
  const auto count = std::count_if(locked.begin(), locked.end(), [](std::uint8_t flag) { return flag != 0; });
  return count == 0 ? std::string()
                    : " " + std::to_string(count) + " points are locked (shared with other pieces" +
      (userArray ? ", or chosen by the locked-points array)." : ").");
}

bool ReportRun(vtkAlgorithm* filter, bool finished, std::int64_t nonFinitePoints)
{
  if (nonFinitePoints > 0)
  {
    vtkWarningWithObjectMacro(filter, << "Ignoring the triangles of " << nonFinitePoints
                                      << " points with NaN or infinite coordinates.");
  }
  if (!finished)
  {
    vtkWarningWithObjectMacro(filter, << "Aborted: the output is empty.");
  }
  return finished;
}

void SetOutputTriangles(vtkPolyData* input, vtkPolyData* output, const TriangleInput& triangles,
  const std::vector<double>& points, const std::vector<std::int32_t>& outputTriangles,
  const std::vector<std::int32_t>& sourceTriangles, int outputPointsPrecision)
{
  output->SetPoints(MakePoints(points, outputPointsPrecision, input->GetPoints()));
  output->SetPolys(MakeTriangles(outputTriangles));
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(sourceTriangles.size());
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, numberOfTriangles);
  for (vtkIdType i = 0; i < numberOfTriangles; ++i)
  {
    outCD->CopyData(inCD, triangles.SourceCell(sourceTriangles[i]), i);
  }
  if (vtkDataArray* normals = outCD->GetNormals())
  {
    ComputeCellNormals(points, outputTriangles, normals);
  }
  output->GetFieldData()->PassData(input->GetFieldData());
  AddFieldValue(output, "AchievedReduction",
    1.0 - static_cast<double>(numberOfTriangles) / static_cast<double>(triangles.View.NumberOfTriangles));
}

void AddFieldValue(vtkPolyData* output, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}

void CopySurvivorPointData(
  vtkPointData* inPD, vtkPointData* outPD, const std::vector<std::int32_t>& pointSource)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(pointSource.size());
  outPD->SetCopyAttribute(vtkDataSetAttributes::GLOBALIDS, 1, vtkDataSetAttributes::COPYTUPLE);
  outPD->CopyAllocate(inPD, numberOfPoints);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    outPD->CopyData(inPD, pointSource[p], p);
  }
}

bool IsInterpolated(vtkPointData* inPD, vtkPointData* outPD, int index)
{
  vtkAbstractArray* array = inPD->GetAbstractArray(index);
  if (!array || (array->GetName() && std::string(array->GetName()) == vtkDataSetAttributes::GhostArrayName()))
  {
    return false;
  }
  const int attribute = inPD->IsArrayAnAttribute(index);
  return attribute < 0 || outPD->GetCopyAttribute(attribute, vtkDataSetAttributes::INTERPOLATE) != 0;
}

void AddPointValues(vtkPolyData* output, const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  output->GetPointData()->AddArray(array);
}

int ResolveThreadCount(int numberOfThreads)
{
  return numberOfThreads > 0 ? numberOfThreads
                             : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

bool ReadLockedPoints(vtkAlgorithm* filter, vtkPolyData* input, std::vector<std::uint8_t>& locked)
{
  // Input array 0, as SetInputArrayToProcess or the XML's "Locked Points" selected it.
  vtkInformation* selection = filter->GetInputArrayInformation(0);
  vtkDataArray* array = nullptr;
  std::string name;
  if (selection->Has(vtkDataObject::FIELD_NAME()))
  {
    name = selection->Get(vtkDataObject::FIELD_NAME());
    if (name.empty() || name == "None")
    {
      return false; // ParaView's "no array" choice
    }
    array = input->GetPointData()->GetArray(name.c_str());
  }
  else if (selection->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    array = input->GetPointData()->GetAttribute(selection->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
    name = "of the selected attribute";
  }
  else
  {
    return false; // nothing selected
  }
  if (!array || array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkWarningWithObjectMacro(filter, << "Ignoring the lock array " << name
                                      << ": it is not a point-data array of the input.");
    return false;
  }
  locked.resize(input->GetNumberOfPoints(), 0); // keeps the locks already set
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    if (locked[i] == 0 && array->GetComponent(i, 0) != 0.0)
    {
      locked[i] = 1;
    }
  }
  return true;
}

namespace
{
/**
 * Threads that live for one filter execution and share the chunks of every ParallelFor with
 * the calling thread. VTK 9.2's STDThread backend starts its threads anew for each For (about
 * 0.1 ms for two threads here), and the filters that work in rounds call it hundreds of times.
 * Waking a sleeping thread through the kernel costs 40-60 us here, so both sides poll a while
 * before they sleep: a worker polls for the next loop for about a millisecond, the caller for
 * the workers' last chunks for about 0.1 ms; loops that follow each other closely then start
 * in about a microsecond. (Polling is a plain load: a PAUSE loop makes virtual machines
 * deschedule the polling CPU, which stalled loops by milliseconds.) Chunks go to whichever
 * thread asks first; the filters write disjoint data per index, so the result does not depend
 * on it.
 */
class WorkerPool
{
public:
  using Body = std::function<void(std::int64_t, std::int64_t)>;

  explicit WorkerPool(int threads)
  {
    for (int i = 1; i < threads; ++i)
    {
      this->Workers.emplace_back([this, i] {
        CurrentPool = this;
        CurrentIndex = i;
        this->Serve();
      });
    }
  }

  /// The calling thread's index: 1, 2, ... for the workers, 0 for the thread that calls For
  /// (also when it is a worker of another pool).
  int Worker() const { return CurrentPool == this ? CurrentIndex : 0; }

  ~WorkerPool()
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Stopping = true;
      this->Generation.fetch_add(1, std::memory_order_release);
    }
    this->Wake.notify_all();
    for (std::thread& worker : this->Workers)
    {
      worker.join();
    }
  }

  /// Runs body over [0, n) in chunks of about 64 us of the estimated work (4 to 64 per thread):
  /// fine enough that the threads finish together, though the machine may slow one down.
  void For(std::int64_t n, std::int64_t work, const Body& body)
  {
    const std::int64_t threads = static_cast<std::int64_t>(this->Workers.size()) + 1;
    this->Job = &body;
    this->Size = n;
    this->Chunks = std::min(n, std::max(4 * threads, std::min(64 * threads, work >> 16)));
    this->Next = 0;
    this->Busy.store(static_cast<int>(this->Workers.size()), std::memory_order_relaxed);
    {
      // Under the lock, so that a worker about to sleep either sees the new generation or is
      // counted in Sleepers before it is read below.
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Generation.fetch_add(1, std::memory_order_release);
    }
    if (this->Sleepers.load() > 0)
    {
      this->Wake.notify_all();
    }
    this->Work();
    for (int polls = 1; polls < CallerPolls && !this->Finished(); ++polls)
    {
      if (polls % 1024 == 0)
      {
        std::this_thread::yield();
      }
    }
    if (!this->Finished())
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->CallerWaiting = true;
      this->Done.wait(lock, [this] { return this->Finished(); });
      this->CallerWaiting = false;
    }
  }

private:
  bool Finished() const { return this->Busy.load(std::memory_order_acquire) == 0; }

  void Work()
  {
    for (std::int64_t chunk = this->Next++; chunk < this->Chunks; chunk = this->Next++)
    {
      (*this->Job)(this->Size * chunk / this->Chunks, this->Size * (chunk + 1) / this->Chunks);
    }
  }

  void Serve()
  {
    std::uint64_t seen = 0;
    for (;;)
    {
      for (int polls = 1; polls < WorkerPolls && this->Generation.load(std::memory_order_acquire) == seen; ++polls)
      {
        if (polls % 1024 == 0)
        {
          std::this_thread::yield(); // lets the caller run if the two share a CPU
        }
      }
      if (this->Generation.load(std::memory_order_acquire) == seen)
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        ++this->Sleepers;
        this->Wake.wait(lock, [&] { return this->Generation.load() != seen; });
        --this->Sleepers;
      }
      seen = this->Generation.load(std::memory_order_acquire);
      if (this->Stopping.load())
      {
        return;
      }
      this->Work();
      if (this->Busy.fetch_sub(1, std::memory_order_acq_rel) == 1)
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        if (this->CallerWaiting)
        {
          this->Done.notify_one();
        }
      }
    }
  }

  static thread_local const WorkerPool* CurrentPool;
  static thread_local int CurrentIndex;
  static constexpr int WorkerPolls = 1 << 20; // about a millisecond
  static constexpr int CallerPolls = 1 << 17;
  std::vector<std::thread> Workers;
  std::mutex Mutex;
  std::condition_variable Wake, Done;
  const Body* Job = nullptr;
  std::int64_t Size = 0, Chunks = 0;
  std::atomic<std::int64_t> Next{ 0 };
  std::atomic<int> Busy{ 0 }, Sleepers{ 0 };
  std::atomic<std::uint64_t> Generation{ 0 };
  std::atomic<bool> Stopping{ false };
  bool CallerWaiting = false; // guarded by Mutex
};
thread_local const WorkerPool* WorkerPool::CurrentPool = nullptr;
thread_local int WorkerPool::CurrentIndex = 0;
}

meshsimp::ExecutionContext MakeExecutionContext(vtkAlgorithm* algorithm, int numberOfThreads)
{
  meshsimp::ExecutionContext context;
  const int threads = ResolveThreadCount(numberOfThreads);
  if (threads > 1)
  {
    context.Threads = threads;
    // Work is estimated in nanoseconds (ExecutionContext). The threads start with the first
    // loop of a millisecond or more, so small inputs never pay for them (about 0.1 ms); then
    // loops of 30 us or more are shared (a polled start costs about 1 us, see WorkerPool).
    constexpr std::int64_t StartWork = 1 << 20, LoopWork = 1 << 15;
    auto pool = std::make_shared<std::unique_ptr<WorkerPool>>();
    context.ParallelFor = [pool, threads](
                            std::int64_t n, std::int64_t work, const WorkerPool::Body& body) {
      if (work < (*pool ? LoopWork : StartWork))
      {
        body(0, n); // too little work to pay for the threads
        return;
      }
      if (!*pool)
      {
        *pool = std::make_unique<WorkerPool>(threads);
      }
      (*pool)->For(n, work, body);
    };
    context.Worker = [pool] { return *pool ? (*pool)->Worker() : 0; };
  }
  context.Progress = [algorithm](double progress) {
    algorithm->UpdateProgress(progress);
    return !algorithm->CheckAbort();
  };
  return context;
}

vtkSmartPointer<vtkPoints> MakePoints(
  const std::vector<double>& coordinates, int outputPointsPrecision, vtkPoints* inputPoints)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  if (outputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION ||
    (outputPointsPrecision == vtkAlgorithm::DEFAULT_PRECISION && inputPoints &&
      inputPoints->GetDataType() == VTK_DOUBLE))
  {
    points->SetDataTypeToDouble();
  }
  else
  {
    points->SetDataTypeToFloat();
  }
  const vtkIdType count = static_cast<vtkIdType>(coordinates.size() / 3);
  points->SetNumberOfPoints(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    points->SetPoint(i, coordinates.data() + 3 * i);
  }
  return points;
}

vtkSmartPointer<vtkCellArray> MakeTriangles(const std::vector<std::int32_t>& triangles)
{
  const vtkIdType count = static_cast<vtkIdType>(triangles.size() / 3);
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(3 * count);
  for (vtkIdType i = 0; i <= count; ++i)
  {
    offsets->SetValue(i, 3 * i);
  }
  for (vtkIdType i = 0; i < 3 * count; ++i)
  {
    connectivity->SetValue(i, triangles[i]);
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

namespace
{
Eigen::Vector3d TriangleAreaNormal(
  const std::vector<double>& points, const std::vector<std::int32_t>& triangles, std::size_t t)
{
  auto corner = [&](int k) {
    const double* p = points.data() + 3 * static_cast<std::size_t>(triangles[3 * t + k]);
    return Eigen::Vector3d(p[0], p[1], p[2]);
  };
  return (corner(1) - corner(0)).cross(corner(2) - corner(0));
}
}

void ComputePointNormals(const std::vector<double>& points,
  const std::vector<std::int32_t>& triangles, vtkDataArray* normals)
{
  std::vector<Eigen::Vector3d> sums(points.size() / 3, Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < triangles.size() / 3; ++t)
  {
    const Eigen::Vector3d n = TriangleAreaNormal(points, triangles, t);
    for (int k = 0; k < 3; ++k)
    {
      sums[triangles[3 * t + k]] += n;
    }
  }
  for (std::size_t i = 0; i < sums.size(); ++i)
  {
    const double length = sums[i].norm();
    const Eigen::Vector3d n = length > 0.0 ? Eigen::Vector3d(sums[i] / length) : Eigen::Vector3d(0, 0, 1);
    normals->SetTuple(static_cast<vtkIdType>(i), n.data());
  }
}

void ComputeCellNormals(const std::vector<double>& points,
  const std::vector<std::int32_t>& triangles, vtkDataArray* normals)
{
  for (std::size_t t = 0; t < triangles.size() / 3; ++t)
  {
    Eigen::Vector3d n = TriangleAreaNormal(points, triangles, t);
    const double length = n.norm();
    n = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d(0, 0, 1);
    normals->SetTuple(static_cast<vtkIdType>(t), n.data());
  }
}

}
