// SPDX-License-Identifier: BSD-3-Clause
// meshsimplify: run a MeshSimplification filter on a mesh file.
//
//   meshsimplify --method octree|volume|parallel|progressive|appearance [--reduction R |
//                --target-triangles N | --max-error E [--relative-error]] [--threads T]
//                [--set Name=Value ...] [--repeat N] [--levels R1,R2,...] [--json] INPUT OUTPUT
//   meshsimplify --method METHOD --settings
//   meshsimplify --morph [--t T | --frames N] [--correspondence vertex|surface|exact]
//                [--merge-distance D] [--json] DETAILED COARSE OUTPUT
//   meshsimplify --method METHOD [target] --bake-texture SIZE [--json] INPUT OUTPUT
//   meshsimplify --bake-texture SIZE --original ORIGINAL [--json] SIMPLIFIED OUTPUT
//
// Reads .ply .stl .obj .vtp .vtk .off and writes by the output extension. With --json it prints
// one JSON object; time_ms is the filter's own work (file I/O excluded), the median of N runs
// with --repeat N (the protocol of the shared benchmark kit's peers). --levels (progressive
// only) builds the sequence once and writes the level of each reduction to OUTPUT with %l
// replaced by the reduction; the JSON then has build_ms and each level's extract_ms.
// --settings lists the method's settings for --set with their defaults, ranges and help.
// --morph runs LoD Interpolation: DETAILED morphed towards COARSE, the frame at T (0.5 by
// default) to OUTPUT, or N frames (t = 0 to 1) to OUTPUT with %f replaced by the frame's number;
// the JSON has first_ms (the correspondence and a frame) and frame_ms (the later frames' median).
// --bake-texture runs Texture Baking: the input simplified by METHOD (or SIMPLIFIED) gets a
// SIZE² texture of the input's (or ORIGINAL's) colours; OUTPUT .obj writes .obj, .mtl and .png,
// .gltf and .glb embed the texture; the JSON has simplify_ms and bake_ms.
#include "MeshFiles.h"
#include "vtkImageData.h"
#include "vtkLODInterpolation.h"
#include "vtkTextureBaking.h"
#include "MeshSimplificationFilters.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <functional>
#include <optional>
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
    if (used == text.size() && std::isfinite(value))
    {
      return value;
    }
  }
  catch (const std::exception&)
  {
  }
  Fail("option " + option + " needs a finite number, not '" + text + "'");
}

/// Each registered filter's --method and how to make it (MeshSimplificationFilterList.h).
struct Method
{
  const char* Name;
  vtkSmartPointer<vtkMeshSimplificationFilter> (*Make)();
};
#define MESHSIMPLIFICATION_METHOD(name, method, parameters, tolerance, blends, alias)               \
  { #method, [] { return vtkSmartPointer<vtkMeshSimplificationFilter>(vtkSmartPointer<vtk##name>::New()); } },
const Method Methods[] = { MESHSIMPLIFICATION_FILTERS(MESHSIMPLIFICATION_METHOD) };
#undef MESHSIMPLIFICATION_METHOD

/// The method of that name, or nullptr.
const Method* FindMethod(const std::string& name)
{
  for (const Method& method : Methods)
  {
    if (name == method.Name)
    {
      return &method;
    }
  }
  return nullptr;
}

/// "octree, volume, ...": the methods for a message.
std::string MethodNames(const char* separator)
{
  std::string names;
  for (const Method& method : Methods)
  {
    names += (names.empty() ? "" : separator) + std::string(method.Name);
  }
  return names;
}

/// The usage text, with the registered methods.
std::string Usage()
{
  return "usage: meshsimplify --method " + MethodNames("|") +
    " [--reduction R |\n"
    "         --target-triangles N | --max-error E [--relative-error]] [--threads T]\n"
    "         [--set Name=Value ...] [--repeat N] [--levels R1,R2,...] [--json] INPUT OUTPUT\n"
    "       meshsimplify --method METHOD --settings\n"
    "  --settings  the method's settings for --set: name=default [range] and a line of help\n"
    "  --repeat N  run the filter N times; time_ms is the median\n"
    "  --levels    progressive: one build, the level of each reduction written to OUTPUT with\n"
    "              %l replaced by the reduction\n"
    "       meshsimplify --morph [--t T | --frames N] [--correspondence vertex|surface|exact]\n"
    "         [--merge-distance D] [--json] DETAILED COARSE OUTPUT\n"
    "  --morph     LoD Interpolation: DETAILED on its way to COARSE at T (default 0.5), or N\n"
    "              frames from 0 to 1 written to OUTPUT with %f replaced by the frame number\n"
    "       meshsimplify --method METHOD [target] --bake-texture SIZE [--json] INPUT OUTPUT\n"
    "       meshsimplify --bake-texture SIZE --original ORIGINAL [--json] SIMPLIFIED OUTPUT\n"
    "  --bake-texture  Texture Baking: a SIZE x SIZE texture (256 to 8192, a power of two) of the\n"
    "              colours of INPUT (or ORIGINAL) for its simplification; OUTPUT .obj also writes\n"
    "              .mtl and .png, .gltf and .glb embed the texture\n";
}

/// The command line.
struct Arguments
{
  std::string Method, Input, Output, Coarse; // with --morph: DETAILED, OUTPUT, COARSE
  double Reduction = 0.9;
  std::optional<double> MaximumError;
  std::optional<long long> TargetTriangles;
  bool RelativeError = false, Json = false, ListSettings = false;
  int Threads = 0, Repeat = 1;
  std::vector<std::pair<std::string, double>> Settings;
  std::vector<std::pair<std::string, double>> Levels; // --levels: as typed (they name the files), and parsed
  bool Morph = false;
  double Interpolation = 0.5, MergeDistance = 0.001;
  int Frames = 0;
  std::string Correspondence = "surface";
  int BakeTexture = 0;  // --bake-texture: the texture's size, 0 for none
  std::string Original; // --original: the mesh whose colours the texture keeps
};

/// An option's effect on the arguments; false for an unknown option.
bool ParseOption(const std::string& arg, const std::function<std::string()>& value, Arguments& a)
{
  if (arg == "--method")
    a.Method = value();
  else if (arg == "--reduction")
    a.Reduction = ParseNumber(arg, value());
  else if (arg == "--target-triangles")
    a.TargetTriangles = static_cast<long long>(ParseNumber(arg, value()));
  else if (arg == "--max-error")
    a.MaximumError = ParseNumber(arg, value());
  else if (arg == "--relative-error")
    a.RelativeError = true;
  else if (arg == "--threads")
    a.Threads = static_cast<int>(ParseNumber(arg, value()));
  else if (arg == "--repeat")
    a.Repeat = static_cast<int>(ParseNumber(arg, value()));
  else if (arg == "--json")
    a.Json = true;
  else if (arg == "--settings")
    a.ListSettings = true;
  else if (arg == "--morph")
    a.Morph = true;
  else if (arg == "--t")
    a.Interpolation = ParseNumber(arg, value());
  else if (arg == "--frames")
    a.Frames = static_cast<int>(ParseNumber(arg, value()));
  else if (arg == "--merge-distance")
    a.MergeDistance = ParseNumber(arg, value());
  else if (arg == "--correspondence")
    a.Correspondence = value();
  else if (arg == "--bake-texture")
    a.BakeTexture = static_cast<int>(ParseNumber(arg, value()));
  else if (arg == "--original")
    a.Original = value();
  else if (arg == "--levels")
  {
    std::string list = value() + ",";
    for (std::size_t comma = list.find(','); comma != std::string::npos; comma = list.find(','))
    {
      const std::string level = list.substr(0, comma);
      a.Levels.emplace_back(level, ParseNumber(arg, level));
      list.erase(0, comma + 1);
    }
  }
  else if (arg == "--set")
  {
    const std::string assignment = value();
    const std::size_t equals = assignment.find('=');
    if (equals == std::string::npos)
    {
      Fail("--set needs Name=Value, not '" + assignment + "'");
    }
    a.Settings.emplace_back(assignment.substr(0, equals), ParseNumber("--set", assignment.substr(equals + 1)));
  }
  else
    return false;
  return true;
}

/// The method's settings for --set, one line each: name=default [range]: help.
void PrintSettings(const std::string& method)
{
  const Method* found = FindMethod(method);
  if (!found)
  {
    Fail("--settings needs a --method (available: " + MethodNames(", ") + ")");
  }
  found->Make()->ForEachSetting([](const meshsimp::SettingEntry& entry) {
    char maximum[32] = "no bound";
    if (entry.Maximum < meshsimp::Unbounded)
    {
      std::snprintf(maximum, sizeof(maximum), "%g", entry.Maximum);
    }
    std::printf("%s=%g [%g, %s]: %s\n", entry.Name, entry.Value, entry.Minimum, maximum, entry.Help);
  });
}

/// The command line, checked: an ordered list of the checks, the first that fails named.
Arguments ParseArguments(int argc, char* argv[])
{
  Arguments a;
  bool reductionGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::fputs(Usage().c_str(), stdout);
      std::exit(0);
    }
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc)
      {
        Fail("option " + arg + " needs a value");
      }
      return argv[++i];
    };
    reductionGiven = reductionGiven || arg == "--reduction";
    if (ParseOption(arg, value, a))
      continue;
    if (!arg.empty() && arg[0] == '-')
      Fail("unknown option " + arg);
    else if (a.Input.empty())
      a.Input = arg;
    else if (a.Output.empty())
      a.Output = arg;
    else if (a.Morph && a.Coarse.empty())
    {
      a.Coarse = a.Output; // DETAILED COARSE OUTPUT
      a.Output = arg;
    }
    else
      Fail("unexpected argument " + arg);
  }
  if (a.ListSettings)
  {
    PrintSettings(a.Method);
    std::exit(0);
  }
  const bool morphTimed = a.Frames != 0;
  const std::pair<bool, std::string> checks[] = {
    { a.Morph && (!a.Method.empty() || !a.Levels.empty() || !a.Settings.empty() || reductionGiven ||
                   a.TargetTriangles || a.MaximumError),
      "--morph takes no --method, --levels, --set or target" },
    { a.Morph && a.Coarse.empty(), "--morph needs DETAILED, COARSE and OUTPUT files" },
    { a.Morph && !(a.Interpolation >= 0.0 && a.Interpolation <= 1.0), "--t must be in [0, 1]" },
    { a.Morph && (a.Frames < 0 || a.Frames == 1), "--frames must be 2 or more" },
    { a.Morph && morphTimed && a.Output.find("%f") == std::string::npos, "--frames needs %f in OUTPUT" },
    { a.Morph && !(a.MergeDistance >= 0.0 && a.MergeDistance <= 1.0), "--merge-distance must be in [0, 1]" },
    { a.Morph && a.Correspondence != "surface" && a.Correspondence != "vertex" && a.Correspondence != "exact",
      "--correspondence is vertex, surface or exact" },
    { !a.Morph && (morphTimed || !a.Coarse.empty()), "--frames needs --morph" },
    { a.Input.empty() || a.Output.empty(), "an INPUT and an OUTPUT file are needed" },
    { a.BakeTexture != 0 && (a.BakeTexture < 256 || a.BakeTexture > 8192 || (a.BakeTexture & (a.BakeTexture - 1)) != 0),
      "--bake-texture must be a power of two from 256 to 8192" },
    { !a.Original.empty() && a.BakeTexture == 0, "--original needs --bake-texture" },
    { !a.Original.empty() && !a.Method.empty(), "--original bakes onto a simplified INPUT: no --method with it" },
    { a.BakeTexture != 0 && (a.Morph || !a.Levels.empty() || a.Repeat != 1), "--bake-texture takes no --morph, --levels or --repeat" },
    { !a.Morph && a.Original.empty() && !FindMethod(a.Method), "unknown --method (available: " + MethodNames(", ") + ")" },
    { !a.Levels.empty() && a.Method != "progressive", "--levels needs --method progressive" },
    { !a.Levels.empty() && a.Output.find("%l") == std::string::npos, "--levels needs %l in OUTPUT" },
    { !a.Levels.empty() && (reductionGiven || a.TargetTriangles || a.MaximumError || a.Repeat != 1),
      "--levels gives the reductions: no --reduction, --target-triangles, --max-error or --repeat with it" },
    { reductionGiven + a.TargetTriangles.has_value() + a.MaximumError.has_value() > 1,
      "give only one of --reduction, --target-triangles, --max-error" },
    { a.MaximumError.value_or(0.0) < 0.0, "--max-error must be 0 or more" },
    { a.TargetTriangles.value_or(0) < 0, "--target-triangles must be 0 or more" },
    { a.Threads < 0, "--threads must be 0 (all cores) or more" },
    { a.Repeat < 1, "--repeat must be 1 or more" },
  };
  for (const auto& [failed, message] : checks)
  {
    if (failed)
    {
      Fail(message);
    }
  }
  return a;
}

/// The method's filter with the command line's target, threads and --set values.
vtkSmartPointer<vtkMeshSimplificationFilter> MakeFilter(const Arguments& a)
{
  const vtkSmartPointer<vtkMeshSimplificationFilter> filter = FindMethod(a.Method)->Make();
  filter->SetNumberOfThreads(a.Threads);
  filter->SetRelativeError(a.RelativeError);
  if (a.TargetTriangles)
  {
    filter->SetTargetModeToTriangleCount();
    filter->SetTargetTriangleCount(*a.TargetTriangles);
  }
  else if (a.MaximumError)
  {
    filter->SetTargetModeToMaximumError();
    filter->SetMaximumError(*a.MaximumError);
  }
  else
  {
    filter->SetTargetModeToReduction();
    filter->SetTargetReduction(a.Reduction);
  }
  for (const auto& [name, value] : a.Settings)
  {
    if (!filter->SetSettingByName(name, value))
    {
      Fail("unknown --set name '" + name + "' for --method " + a.Method);
    }
  }
  return filter;
}

/// A filter's messages while this lives, one line each: warnings printed (until
/// SilenceWarnings), the first error kept for the failure.
class Messages
{
public:
  explicit Messages(vtkAlgorithm* algorithm)
    : Algorithm(algorithm)
  {
    this->Listener->SetClientData(this);
    this->Listener->SetCallback(Messages::Receive);
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Listener);
    algorithm->AddObserver(vtkCommand::WarningEvent, this->Listener);
  }
  ~Messages()
  {
    this->Algorithm->RemoveObservers(vtkCommand::ErrorEvent);
    this->Algorithm->RemoveObservers(vtkCommand::WarningEvent);
  }
  Messages(const Messages&) = delete;
  Messages& operator=(const Messages&) = delete;

  /// Later warnings are dropped, neither printed nor left to VTK's output window.
  void SilenceWarnings()
  {
    this->Algorithm->RemoveObservers(vtkCommand::WarningEvent);
    this->Algorithm->AddObserver(vtkCommand::WarningEvent, this->Silence);
  }

  std::string Error;

private:
  static void Receive(vtkObject*, unsigned long event, void* self, void* text)
  {
    // VTK's message text ends with a line break; its prefix names the object.
    std::string line = text ? static_cast<const char*>(text) : "";
    const std::size_t colon = line.find("): ");
    line = colon == std::string::npos ? line : line.substr(colon + 3);
    while (!line.empty() && (line.back() == '\n' || line.back() == ' '))
    {
      line.pop_back();
    }
    auto* messages = static_cast<Messages*>(self);
    if (event == vtkCommand::WarningEvent)
    {
      std::fprintf(stderr, "meshsimplify: warning: %s\n", line.c_str());
    }
    else if (messages->Error.empty())
    {
      messages->Error = line;
    }
  }

  vtkAlgorithm* Algorithm;
  vtkNew<vtkCallbackCommand> Listener, Silence;
};

/// Runs the filter `repeat` times; the median time of its own work in milliseconds. Fails with
/// the filter's error. With freshInput the input counts as new at every run (its points are
/// marked modified), so that a cache (Progressive Mesh's) is not what is timed.
double RunRepeated(vtkMeshSimplificationFilter* filter, int repeat, const std::string& input, bool freshInput = true)
{
  Messages messages(filter);
  std::vector<double> times;
  for (int run = 0; run < repeat; ++run)
  {
    filter->Modified();
    vtkPoints* points = vtkPolyData::SafeDownCast(filter->GetInputDataObject(0, 0))->GetPoints();
    if (freshInput && points)
    {
      points->Modified();
    }
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (run == 0)
    {
      messages.SilenceWarnings(); // printed once
    }
  }
  if (!messages.Error.empty() || filter->GetErrorCode() != 0)
  {
    Fail(input + ": " + (messages.Error.empty() ? std::string("the filter failed") : messages.Error));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

/// The triangle count of a mesh as the filters see it (polygons and strips triangulated).
long long CountTriangles(vtkPolyData* mesh)
{
  long long count = 0;
  for (vtkCellArray* cells : { mesh->GetPolys(), mesh->GetStrips() })
  {
    auto cell = vtk::TakeSmartPointer(cells->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      cell->GetCurrentCell(size, ids);
      count += size >= 3 ? size - 2 : 0;
    }
  }
  return count;
}

/// A figure as a JSON value: its number, or null for a value JSON has no number for (NaN and
/// the infinities), noted in notes as what it was.
std::string JsonNumber(const char* key, double value, std::string& notes)
{
  char number[64];
  std::snprintf(number, sizeof(number), "%.9g", value);
  if (std::isfinite(value))
  {
    return number;
  }
  notes += std::string(notes.empty() ? "" : ", ") + "\"" + key + " is " + number + "\"";
  return "null";
}

/// The run as one JSON object: counts, time, threads, and the figures of the output's field
/// data (max_error in MaximumError's units where the method measures it); a figure that is not
/// finite is null, and "notes" says what it was.
void PrintJson(const Arguments& a, vtkPolyData* mesh, vtkMeshSimplificationFilter* filter, double milliseconds)
{
  const std::pair<const char*, const char*> figures[] = { { "max_error", "MaximumError" },
    { "square_volume_error", "SquareVolumeError" }, { "rounds", "Rounds" },
    { "deviation_max", "DeviationMaximum" }, { "deviation_rms", "DeviationRMS" },
    { "joined_points", "JoinedPoints" } };
  vtkPolyData* result = filter->GetOutput();
  std::string extra, notes;
  for (const auto& [key, name] : figures)
  {
    if (vtkDataArray* array = result->GetFieldData()->GetArray(name))
    {
      extra += std::string(", \"") + key + "\": " + JsonNumber(key, array->GetTuple1(0), notes);
    }
  }
  extra += notes.empty() ? "" : ", \"notes\": [" + notes + "]";
  std::printf("{\"method\": \"%s\", \"input_triangles\": %lld, \"output_triangles\": %lld, "
              "\"time_ms\": %.3f, \"threads\": %d%s}\n",
    a.Method.c_str(), CountTriangles(mesh), static_cast<long long>(result->GetNumberOfPolys()), milliseconds,
    a.Threads > 0 ? a.Threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())), extra.c_str());
}
/// --levels: the sequence built once (the first Update, build_ms), then each level extracted
/// from it (extract_ms) and written to OUTPUT with %l replaced by its reduction.
void RunLevels(const Arguments& a, vtkPolyData* mesh, vtkMeshSimplificationFilter* filter)
{
  filter->SetTargetModeToReduction();
  filter->SetTargetReduction(a.Levels.front().second);
  const double build = RunRepeated(filter, 1, a.Input);
  std::string levels;
  for (const auto& [level, reduction] : a.Levels)
  {
    filter->SetTargetReduction(reduction);
    const double extract = RunRepeated(filter, 1, a.Input, false); // the cached sequence serves
    std::string path = a.Output;
    path.replace(path.find("%l"), 2, level);
    std::string fileError;
    if (!meshfiles::WriteMesh(filter->GetOutput(), path, fileError))
    {
      Fail(fileError);
    }
    char entry[256];
    std::snprintf(entry, sizeof(entry), "%s{\"reduction\": %.9g, \"output_triangles\": %lld, \"extract_ms\": %.3f}",
      levels.empty() ? "" : ", ", reduction, static_cast<long long>(filter->GetOutput()->GetNumberOfPolys()), extract);
    levels += entry;
  }
  if (a.Json)
  {
    std::printf("{\"method\": \"%s\", \"input_triangles\": %lld, \"build_ms\": %.3f, \"builds\": %d, \"levels\": [%s]}\n",
      a.Method.c_str(), CountTriangles(mesh), build, vtkProgressiveMesh::SafeDownCast(filter)->GetNumberOfBuilds(),
      levels.c_str());
  }
}
}

namespace
{
/// --morph: DETAILED towards COARSE, one frame or --frames of them, each written; the first
/// frame's time (the correspondence with it) and the later ones' median.
void RunMorph(const Arguments& a)
{
  std::string fileError;
  vtkSmartPointer<vtkPolyData> surfaces[2];
  for (int i = 0; i < 2; ++i)
  {
    const std::string& path = i == 0 ? a.Input : a.Coarse;
    surfaces[i] = meshfiles::ReadMesh(path, fileError);
    if (!surfaces[i])
    {
      Fail(fileError);
    }
  }
  vtkNew<vtkLODInterpolation> morph;
  morph->SetInputData(0, surfaces[0]);
  morph->SetCoarseData(surfaces[1]);
  morph->SetMergeDistance(a.MergeDistance);
  morph->SetCorrespondence(
    a.Correspondence == "vertex"  ? vtkLODInterpolation::NEAREST_VERTEX
      : a.Correspondence == "exact" ? vtkLODInterpolation::EXACT
                                    : vtkLODInterpolation::NEAREST_SURFACE_POINT);
  Messages messages(morph);
  const int frames = a.Frames > 0 ? a.Frames : 1;
  std::vector<double> times;
  for (int frame = 0; frame < frames; ++frame)
  {
    morph->SetInterpolation(a.Frames > 0 ? static_cast<double>(frame) / (frames - 1) : a.Interpolation);
    const auto start = std::chrono::steady_clock::now();
    morph->Update();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    if (!messages.Error.empty())
    {
      Fail(messages.Error);
    }
    std::string path = a.Output;
    if (a.Frames > 0)
    {
      path.replace(path.find("%f"), 2, std::to_string(frame));
    }
    if (!meshfiles::WriteMesh(morph->GetOutput(), path, fileError))
    {
      Fail(fileError);
    }
  }
  if (a.Json)
  {
    std::vector<double> later(times.begin() + 1, times.end());
    std::nth_element(later.begin(), later.begin() + later.size() / 2, later.end());
    std::printf("{\"method\": \"morph\", \"detailed_triangles\": %lld, \"coarse_triangles\": %lld, \"frames\": %d, "
                "\"first_ms\": %.3f, \"frame_ms\": %.3f, \"output_triangles\": %lld, \"builds\": %d}\n",
      CountTriangles(surfaces[0]), CountTriangles(surfaces[1]), frames, times.front(),
      later.empty() ? times.front() : later[later.size() / 2], static_cast<long long>(morph->GetOutput()->GetNumberOfPolys()),
      morph->GetCorrespondenceBuilds());
  }
}
}

namespace
{
/// --bake-texture: the texture of original's colours for simplified, written with it; with
/// --json the times (simplifyMs: the simplification's, -1 where the input was simplified).
void RunBake(const Arguments& a, vtkPolyData* simplified, vtkPolyData* original, double simplifyMs)
{
  vtkNew<vtkTextureBaking> bake;
  bake->SetInputData(0, simplified);
  bake->SetOriginalData(original);
  bake->SetTextureSize(a.BakeTexture);
  Messages messages(bake);
  const auto start = std::chrono::steady_clock::now();
  bake->Update();
  const double bakeMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::string fileError;
  if (!messages.Error.empty())
  {
    Fail(messages.Error);
  }
  if (!meshfiles::WriteTexturedMesh(bake->GetOutput(), bake->GetTexture(), a.Output, fileError))
  {
    Fail(fileError);
  }
  if (a.Json)
  {
    std::printf("{\"method\": \"%s\", \"input_triangles\": %lld, \"output_triangles\": %lld, \"texture_size\": %d, "
                "\"simplify_ms\": %.3f, \"bake_ms\": %.3f, \"time_ms\": %.3f}\n",
      a.Method.empty() ? "bake" : a.Method.c_str(), CountTriangles(original), static_cast<long long>(bake->GetOutput()->GetNumberOfPolys()),
      a.BakeTexture, std::max(0.0, simplifyMs), bakeMs, std::max(0.0, simplifyMs) + bakeMs);
  }
}
}

int main(int argc, char* argv[])
{
  // Past a file size limit (ulimit -f) a write fails with EFBIG, which is reported, rather
  // than the signal ending the process.
  std::signal(SIGXFSZ, SIG_IGN);
  const Arguments arguments = ParseArguments(argc, argv);
  if (arguments.Morph)
  {
    RunMorph(arguments);
    return 0;
  }
  std::string fileError;
  vtkSmartPointer<vtkPolyData> mesh = meshfiles::ReadMesh(arguments.Input, fileError);
  if (!mesh)
  {
    Fail(fileError);
  }
  if (CountTriangles(mesh) == 0)
  {
    Fail(arguments.Input + ": no triangle to simplify (" + std::to_string(mesh->GetNumberOfPoints()) +
      " points, " + std::to_string(mesh->GetNumberOfCells()) + " cells, no polygon of 3 or more points)");
  }
  if (!arguments.Original.empty())
  {
    const vtkSmartPointer<vtkPolyData> original = meshfiles::ReadMesh(arguments.Original, fileError);
    if (!original)
    {
      Fail(fileError);
    }
    RunBake(arguments, mesh, original, -1.0);
    return 0;
  }
  vtkSmartPointer<vtkMeshSimplificationFilter> filter = MakeFilter(arguments);
  filter->SetInputData(mesh);
  filter->SetGenerateOriginalIds(filter->GetGenerateOriginalIds() || arguments.BakeTexture != 0);
  if (!arguments.Levels.empty())
  {
    RunLevels(arguments, mesh, filter);
    return 0;
  }
  const double milliseconds = RunRepeated(filter, arguments.Repeat, arguments.Input);
  if (arguments.BakeTexture != 0)
  {
    RunBake(arguments, filter->GetOutput(), mesh, milliseconds);
    return 0;
  }
  if (!meshfiles::WriteMesh(filter->GetOutput(), arguments.Output, fileError))
  {
    Fail(fileError);
  }
  if (arguments.Json)
  {
    PrintJson(arguments, mesh, filter, milliseconds);
  }
  return 0;
}
