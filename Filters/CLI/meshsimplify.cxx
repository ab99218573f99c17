// SPDX-License-Identifier: BSD-3-Clause
// meshsimplify: run a MeshSimplification filter on a mesh file.
//
//   meshsimplify --method octree|volume|parallel [--reduction R | --target-triangles N |
//                --max-error E [--relative-error]] [--threads T] [--set Name=Value ...]
//                [--repeat N] [--json] INPUT OUTPUT
//
// Reads .ply .stl .obj .vtp .vtk .off and writes by the output extension. With --json it prints
// one JSON object; time_ms is the filter's own work (file I/O excluded), the median of N runs
// with --repeat N (the protocol of the shared benchmark kit's peers).
#include "MeshFiles.h"
#include "vtkOctreeVertexClustering.h"
#include "vtkParallelDecimation.h"
#include "vtkVolumeTriangleCollapse.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
[[noreturn]] void Fail(const std::string& message)
{
  std::fprintf(stderr, "meshsimplify: %s\n", message.c_str());
  std::exit(1);
}

double ParseNumber(const std::string& option, const std::string& text)
{
  try
  {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size())
    {
      return value;
    }
  }
  catch (const std::exception&)
  {
  }
  Fail("option " + option + " needs a number, not '" + text + "'");
}

/// The --set names of each method's filter.
using Setters = std::map<std::string, std::function<void(double)>>;

Setters OctreeSetters(vtkOctreeVertexClustering* f)
{
  return {
    { "MaximumCellSize", [f](double v) { f->SetMaximumCellSize(v); } },
    { "MaximumVerticesPerCell", [f](double v) { f->SetMaximumVerticesPerCell(static_cast<int>(v)); } },
    { "ErrorIterations", [f](double v) { f->SetErrorIterations(static_cast<int>(v)); } },
    { "BoundaryPlanes", [f](double v) { f->SetBoundaryPlanes(v != 0.0); } },
    { "BoundaryWeight", [f](double v) { f->SetBoundaryWeight(v); } },
    { "PreventFlips", [f](double v) { f->SetPreventFlips(v != 0.0); } },
    { "OutputPointsPrecision", [f](double v) { f->SetOutputPointsPrecision(static_cast<int>(v)); } },
  };
}

Setters VolumeSetters(vtkVolumeTriangleCollapse* f)
{
  return {
    { "FeatureCurvature", [f](double v) { f->SetFeatureCurvature(v); } },
    { "PreserveBoundary", [f](double v) { f->SetPreserveBoundary(v != 0.0); } },
    { "BoundaryCornerAngle", [f](double v) { f->SetBoundaryCornerAngle(v); } },
    { "UseNormalFactor", [f](double v) { f->SetUseNormalFactor(v != 0.0); } },
    { "UseShapeFactor", [f](double v) { f->SetUseShapeFactor(v != 0.0); } },
    { "UseVolumeWeights", [f](double v) { f->SetUseVolumeWeights(v != 0.0); } },
    { "EdgeCollapses", [f](double v) { f->SetEdgeCollapses(v != 0.0); } },
    { "SurfaceErrorWeight", [f](double v) { f->SetSurfaceErrorWeight(v); } },
    { "MinimumAngle", [f](double v) { f->SetMinimumAngle(v); } },
    { "BatchSize", [f](double v) { f->SetBatchSize(static_cast<int>(v)); } },
    { "OutputPointsPrecision", [f](double v) { f->SetOutputPointsPrecision(static_cast<int>(v)); } },
  };
}

Setters ParallelSetters(vtkParallelDecimation* f)
{
  return {
    { "FeatureAngle", [f](double v) { f->SetFeatureAngle(v); } },
    { "PreserveBoundary", [f](double v) { f->SetPreserveBoundary(v != 0.0); } },
    { "BoundaryCornerAngle", [f](double v) { f->SetBoundaryCornerAngle(v); } },
    { "ImportanceMeasure", [f](double v) { f->SetImportanceMeasure(static_cast<int>(v)); } },
    { "AccumulateError", [f](double v) { f->SetAccumulateError(v != 0.0); } },
    { "MoveSurvivors", [f](double v) { f->SetMoveSurvivors(v != 0.0); } },
    { "HalfEdgeChoice", [f](double v) { f->SetHalfEdgeChoice(static_cast<int>(v)); } },
    { "MaximumNormalDeviation", [f](double v) { f->SetMaximumNormalDeviation(v); } },
    { "BucketImportance", [f](double v) { f->SetBucketImportance(v); } },
    { "BucketShare", [f](double v) { f->SetBucketShare(v); } },
    { "RoundFraction", [f](double v) { f->SetRoundFraction(v); } },
    { "OutputPointsPrecision", [f](double v) { f->SetOutputPointsPrecision(static_cast<int>(v)); } },
  };
}

const char* Usage =
  "usage: meshsimplify --method octree|volume|parallel [--reduction R | --target-triangles N |\n"
  "         --max-error E [--relative-error]] [--threads T] [--set Name=Value ...]\n"
  "         [--repeat N] [--json] INPUT OUTPUT\n"
  "  --repeat N  run the filter N times; time_ms is the median\n";
}

int main(int argc, char* argv[])
{
  std::string method, input, output;
  double reduction = -1.0, maxError = -1.0;
  long long targetTriangles = -1;
  bool relativeError = false, json = false;
  int threads = 0, repeat = 1;
  std::vector<std::pair<std::string, double>> settings;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
      {
        Fail("option " + arg + " needs a value");
      }
      return argv[++i];
    };
    if (arg == "--help" || arg == "-h")
    {
      std::fputs(Usage, stdout);
      return 0;
    }
    else if (arg == "--method")
      method = value();
    else if (arg == "--reduction")
      reduction = ParseNumber(arg, value());
    else if (arg == "--target-triangles")
      targetTriangles = static_cast<long long>(ParseNumber(arg, value()));
    else if (arg == "--max-error")
    {
      maxError = ParseNumber(arg, value());
      if (!(maxError >= 0.0))
      {
        Fail("--max-error must be 0 or more");
      }
    }
    else if (arg == "--relative-error")
      relativeError = true;
    else if (arg == "--threads")
      threads = static_cast<int>(ParseNumber(arg, value()));
    else if (arg == "--repeat")
      repeat = static_cast<int>(ParseNumber(arg, value()));
    else if (arg == "--json")
      json = true;
    else if (arg == "--set")
    {
      const std::string assignment = value();
      const std::size_t equals = assignment.find('=');
      if (equals == std::string::npos)
      {
        Fail("--set needs Name=Value, not '" + assignment + "'");
      }
      settings.emplace_back(
        assignment.substr(0, equals), ParseNumber("--set", assignment.substr(equals + 1)));
    }
    else if (!arg.empty() && arg[0] == '-')
      Fail("unknown option " + arg);
    else if (input.empty())
      input = arg;
    else if (output.empty())
      output = arg;
    else
      Fail("unexpected argument " + arg);
  }
  if (input.empty() || output.empty())
  {
    Fail(std::string("an INPUT and an OUTPUT file are needed\n") + Usage);
  }
  if (method != "octree" && method != "volume" && method != "parallel")
  {
    Fail("unknown --method '" + method + "' (available: octree, volume, parallel)");
  }
  if ((reduction >= 0.0) + (targetTriangles >= 0) + (maxError >= 0.0) > 1)
  {
    Fail("give only one of --reduction, --target-triangles, --max-error");
  }
  if (reduction >= 0.0 && reduction >= 1.0)
  {
    Fail("--reduction must be in [0, 1)");
  }
  if (threads < 0)
  {
    Fail("--threads must be 0 (all cores) or more");
  }
  if (repeat < 1)
  {
    Fail("--repeat must be 1 or more");
  }

  std::string fileError;
  vtkSmartPointer<vtkPolyData> mesh = meshfiles::ReadMesh(input, fileError);
  if (!mesh)
  {
    Fail(fileError);
  }
  const double reductionWanted = reduction >= 0.0 ? reduction : 0.9;
  vtkSmartPointer<vtkPolyDataAlgorithm> filter;
  Setters setters;
  // The three filters share the target properties.
  auto setTarget = [&](auto* f) {
    f->SetNumberOfThreads(threads);
    if (targetTriangles >= 0)
    {
      f->SetTargetModeToTriangleCount();
      f->SetTargetTriangleCount(targetTriangles);
    }
    else if (maxError >= 0.0)
    {
      f->SetTargetModeToMaximumError();
      f->SetMaximumError(maxError);
      f->SetRelativeError(relativeError);
    }
    else
    {
      f->SetTargetModeToReduction();
      f->SetTargetReduction(reductionWanted);
    }
    filter = f;
  };
  if (method == "octree")
  {
    vtkNew<vtkOctreeVertexClustering> octree;
    setTarget(octree.Get());
    setters = OctreeSetters(octree);
  }
  else if (method == "parallel")
  {
    vtkNew<vtkParallelDecimation> parallel;
    setTarget(parallel.Get());
    setters = ParallelSetters(parallel);
  }
  else
  {
    vtkNew<vtkVolumeTriangleCollapse> volume;
    setTarget(volume.Get());
    setters = VolumeSetters(volume);
  }
  filter->SetInputData(mesh);
  for (const auto& setting : settings)
  {
    const auto setter = setters.find(setting.first);
    if (setter == setters.end())
    {
      Fail("unknown --set name '" + setting.first + "' for --method " + method);
    }
    setter->second(setting.second);
  }

  std::vector<double> times;
  for (int run = 0; run < repeat; ++run)
  {
    filter->Modified();
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  const double milliseconds = times[times.size() / 2];
  if (filter->GetErrorCode() != 0)
  {
    Fail("the filter failed on '" + input + "'");
  }
  vtkPolyData* result = filter->GetOutput();
  if (!meshfiles::WriteMesh(result, output, fileError))
  {
    Fail(fileError);
  }

  if (json)
  {
    // The triangle count of the input as the filter sees it (polygons and strips triangulated).
    vtkIdType inputTriangles = 0;
    auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
    for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      polys->GetCurrentCell(size, ids);
      inputTriangles += size >= 3 ? size - 2 : 0;
    }
    auto strips = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
    for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      strips->GetCurrentCell(size, ids);
      inputTriangles += size >= 3 ? size - 2 : 0;
    }
    // Each method's own figures: the largest cluster error (the octree's always, the collapse
    // filters' with an error bound), the total squared volume, the rounds.
    auto field = [](const char* name, double value) {
      char number[64];
      std::snprintf(number, sizeof(number), "%.9g", value);
      return std::string(", \"") + name + "\": " + number;
    };
    std::string error;
    if (auto* octree = vtkOctreeVertexClustering::SafeDownCast(filter))
    {
      error = field("max_error", octree->GetAchievedMaximumError());
    }
    else if (auto* volume = vtkVolumeTriangleCollapse::SafeDownCast(filter))
    {
      error = field("square_volume_error", volume->GetSquareVolumeError()) +
        (maxError >= 0.0 ? field("max_error", volume->GetAchievedMaximumError()) : std::string());
    }
    else if (auto* parallel = vtkParallelDecimation::SafeDownCast(filter))
    {
      error = ", \"rounds\": " + std::to_string(parallel->GetRounds()) +
        (maxError >= 0.0 ? field("max_error", parallel->GetAchievedMaximumError()) : std::string());
    }
    std::printf("{\"method\": \"%s\", \"input_triangles\": %lld, \"output_triangles\": %lld, "
                "\"time_ms\": %.3f, \"threads\": %d%s}\n",
      method.c_str(), static_cast<long long>(inputTriangles),
      static_cast<long long>(result->GetNumberOfPolys()), milliseconds,
      threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
      error.c_str());
  }
  return 0;
}
