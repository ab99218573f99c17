// SPDX-License-Identifier: BSD-3-Clause
// vtkLODInterpolation: a sphere morphed towards its simplification. t = 0 is the detailed
// sphere exactly; at t = 1 every point lies on the coarse surface; the distance to the detailed
// surface never falls as t grows; no triangle turns over; a point array of both inputs morphs;
// the correspondence is built once for 11 frames; the geomorph of a recorded simplification
// ends on the coarse triangles, also between two levels of a Progressive Mesh sequence given
// alone; a multiblock morphs block by block; the GPU output carries the places at t = 1; the
// time can set the frame; bad inputs give one-line errors. With -V, the
// cow at t = 0.5 against its baseline image.
#include "vtkAppearancePreservingCollapse.h"
#include "vtkLODInterpolation.h"
#include "vtkOFFMeshReader.h"
#include "vtkProgressiveMesh.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointData.h"
#include "vtkSphereSource.h"
#include "vtkInformation.h"
#include "vtkStaticCellLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include "TestBadInput.h"
#include "TestImageHelpers.h"
#include "TestVTKHelpers.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
/// A sphere with the point array "Height" (its z) and its simplification at 95 %, which carries
/// the array (as z of its own points, so that the morph's value can be checked).
void SphereAndCoarse(vtkSmartPointer<vtkPolyData>& detailed, vtkSmartPointer<vtkPolyData>& coarse)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(60);
  source->SetPhiResolution(60);
  source->Update();
  detailed = vtkSmartPointer<vtkPolyData>::New();
  detailed->DeepCopy(source->GetOutput());
  for (vtkPolyData* mesh : { detailed.GetPointer() })
  {
    vtkNew<vtkDoubleArray> height;
    height->SetName("Height");
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      height->InsertNextValue(mesh->GetPoint(p)[2]);
    }
    mesh->GetPointData()->AddArray(height);
  }
  vtkNew<vtkAppearancePreservingCollapse> simplify;
  simplify->SetInputData(detailed);
  simplify->SetTargetReduction(0.95);
  simplify->Update();
  coarse = vtkSmartPointer<vtkPolyData>::New();
  coarse->DeepCopy(simplify->GetOutput());
  vtkDataArray* height = coarse->GetPointData()->GetArray("Height");
  for (vtkIdType p = 0; p < coarse->GetNumberOfPoints(); ++p)
  {
    height->SetTuple1(p, coarse->GetPoint(p)[2]);
  }
}

/// The largest and the mean distance of the mesh's points to the surface.
std::pair<double, double> Distance(vtkPolyData* mesh, vtkPolyData* surface)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(surface);
  locator->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  double largest = 0.0, sum = 0.0;
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double closest[3], distance2 = 0.0;
    vtkIdType id = -1;
    int sub = 0;
    locator->FindClosestPoint(mesh->GetPoint(p), closest, cell, id, sub, distance2);
    largest = std::max(largest, std::sqrt(distance2));
    sum += std::sqrt(distance2);
  }
  return { largest, sum / std::max<vtkIdType>(1, mesh->GetNumberOfPoints()) };
}

/// Output triangles whose normal turned by more than 90 degrees from their detailed triangle's
/// (the output keeps the detailed triangles in order where no point merged); with ancestors,
/// only the triangles whose corners became three distinct coarse points (those the coarse
/// surface keeps).
vtkIdType Folds(vtkPolyData* output, vtkPolyData* detailed, vtkDataArray* ancestors = nullptr)
{
  vtkIdType folds = 0;
  for (vtkIdType t = 0; t < output->GetNumberOfCells() && output->GetNumberOfCells() == detailed->GetNumberOfCells(); ++t)
  {
    vtkIdType corners = 0;
    const vtkIdType* id = nullptr;
    detailed->GetCellPoints(t, corners, id);
    if (ancestors &&
      (ancestors->GetTuple1(id[0]) == ancestors->GetTuple1(id[1]) || ancestors->GetTuple1(id[1]) == ancestors->GetTuple1(id[2]) ||
        ancestors->GetTuple1(id[2]) == ancestors->GetTuple1(id[0])))
    {
      continue;
    }
    double n[2][3];
    int k = 0;
    for (vtkPolyData* mesh : { output, detailed })
    {
      vtkIdType count = 0;
      const vtkIdType* ids = nullptr;
      mesh->GetCellPoints(t, count, ids);
      double a[3], b[3], c[3];
      mesh->GetPoint(ids[0], a);
      mesh->GetPoint(ids[1], b);
      mesh->GetPoint(ids[2], c);
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
      n[k][0] = u[1] * v[2] - u[2] * v[1];
      n[k][1] = u[2] * v[0] - u[0] * v[2];
      n[k][2] = u[0] * v[1] - u[1] * v[0];
      ++k;
    }
    folds += n[0][0] * n[1][0] + n[0][1] * n[1][1] + n[0][2] * n[1][2] < 0.0 ? 1 : 0;
  }
  return folds;
}

/// A morph of detailed towards coarse, its points in doubles, so that the morph's arithmetic
/// can be checked to 1e-9 (the default keeps the sphere's floats: TestFrameKeepsTypes).
vtkSmartPointer<vtkLODInterpolation> MorphOf(vtkPolyData* detailed, vtkPolyData* coarse)
{
  auto morph = vtkSmartPointer<vtkLODInterpolation>::New();
  morph->SetInputData(0, detailed);
  morph->SetCoarseData(coarse);
  morph->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  return morph;
}

void TestMorph()
{
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  const vtkSmartPointer<vtkLODInterpolation> morph = MorphOf(detailed, coarse);
  morph->SetMergeDistance(0.0);
  double previous = -1.0;
  for (int step = 0; step <= 10; ++step)
  {
    const double t = 0.1 * step;
    morph->SetInterpolation(t);
    morph->Update();
    vtkPolyData* out = morph->GetOutput();
    CHECK(out->GetNumberOfPoints() == detailed->GetNumberOfPoints() && out->GetNumberOfPolys() == detailed->GetNumberOfPolys());
    if (step == 0)
    {
      for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
      {
        double a[3], b[3];
        out->GetPoint(p, a);
        detailed->GetPoint(p, b);
        CHECK(std::equal(a, a + 3, b));
      }
    }
    const double away = Distance(out, detailed).second;
    CHECK(away >= previous);
    previous = away;
    if (step % 3 == 1)
    {
      CHECK(Folds(out, detailed) == 0);
    }
    vtkDataArray* normals = out->GetPointData()->GetNormals();
    CHECK(normals != nullptr);
    for (vtkIdType p = 0; normals && p < normals->GetNumberOfTuples(); ++p)
    {
      const double* n = normals->GetTuple3(p);
      CHECK(std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0) < 1e-6);
    }
  }
  vtkPolyData* out = morph->GetOutput();
  CHECK(Distance(out, coarse).first < 1e-9);
  vtkDataArray* height = out->GetPointData()->GetArray("Height");
  for (vtkIdType p = 0; height && p < out->GetNumberOfPoints(); ++p)
  {
    CHECK(std::abs(height->GetTuple1(p) - out->GetPoint(p)[2]) < 1e-9); // morphed to the coarse values
  }
  CHECK(height != nullptr && out->GetPointData()->GetArray("Displacement") != nullptr);
  auto* builds = vtkIntArray::SafeDownCast(out->GetFieldData()->GetArray("CorrespondenceBuilds"));
  CHECK(builds && builds->GetValue(0) == 1 && morph->GetCorrespondenceBuilds() == 1);
  // The paper's nearest vertices: at t = 1 the points stand on coarse points, and those that
  // meet join, leaving about the coarse surface's triangles.
  morph->SetCorrespondence(vtkLODInterpolation::NEAREST_VERTEX);
  morph->SetMergeDistance(1e-6);
  morph->Update();
  CHECK(morph->GetCorrespondenceBuilds() == 2);
  CHECK(morph->GetOutput()->GetNumberOfPolys() <= 1.1 * coarse->GetNumberOfPolys());
  CHECK(Distance(morph->GetOutput(), coarse).first < 1e-9);
}

/// The sphere's simplification at 95 % (or reduction) by filter, with GenerateOriginalIds.
template <typename Filter>
vtkSmartPointer<vtkPolyData> Recorded(vtkPolyData* detailed, double reduction = 0.95)
{
  vtkNew<Filter> simplify;
  simplify->SetInputData(detailed);
  simplify->SetTargetReduction(reduction);
  simplify->GenerateOriginalIdsOn();
  simplify->Update();
  auto coarse = vtkSmartPointer<vtkPolyData>::New();
  coarse->DeepCopy(simplify->GetOutput());
  return coarse;
}

void TestExact()
{
  // The geomorph: every detailed point goes to the coarse point it became (the filters'
  // InputToOutputPointIds). No triangle that the coarse surface keeps turns over on the way
  // (those that vanish, two corners bound for one point, may: they end without area); at t = 1
  // the points stand on the coarse points, and the triangles left are the coarse ones
  // (Progressive Mesh: exactly them; Appearance-Preserving Collapse: about as many).
  vtkSmartPointer<vtkPolyData> detailed, unused;
  SphereAndCoarse(detailed, unused);
  for (const bool progressive : { true, false })
  {
    vtkSmartPointer<vtkPolyData> coarse =
      progressive ? Recorded<vtkProgressiveMesh>(detailed) : Recorded<vtkAppearancePreservingCollapse>(detailed);
    CHECK(coarse->GetFieldData()->GetArray("InputToOutputPointIds") != nullptr);
    const vtkSmartPointer<vtkLODInterpolation> morph = MorphOf(detailed, coarse);
    morph->SetCorrespondence(vtkLODInterpolation::EXACT);
    morph->SetMergeDistance(0.0);
    for (const double t : { 0.25, 0.5, 0.75 })
    {
      morph->SetInterpolation(t);
      morph->Update();
      CHECK(Folds(morph->GetOutput(), detailed, coarse->GetFieldData()->GetArray("InputToOutputPointIds")) == 0);
    }
    morph->SetInterpolation(1.0);
    morph->SetMergeDistance(0.05); // far above the coarse edges: only points bound for one point join
    morph->Update();
    CHECK(Distance(morph->GetOutput(), coarse).first < 1e-9 && morph->GetCorrespondenceBuilds() == 1);
    const vtkIdType triangles = morph->GetOutput()->GetNumberOfPolys();
    CHECK(progressive ? triangles == coarse->GetNumberOfPolys() : triangles <= 1.1 * coarse->GetNumberOfPolys());
    // Without the map, vtkOriginalPointIds place each coarse point's own detailed point, and the
    // other points go to the nearest surface point: still on the coarse surface at t = 1.
    coarse->GetFieldData()->RemoveArray("InputToOutputPointIds");
    morph->Update();
    CHECK(Distance(morph->GetOutput(), coarse).first < 1e-9 && morph->GetCorrespondenceBuilds() == 2);
  }
  // Two levels of one sphere, the finer one also with all its points (in the sequence's order,
  // not the input's): the detailed level's vtkOriginalPointIds lead into the coarse level's
  // record, and the geomorph ends on exactly the coarse level's triangles.
  for (const double finer : { 0.5, 0.0 })
  {
    vtkNew<vtkLODInterpolation> levels;
    levels->SetInputData(0, Recorded<vtkProgressiveMesh>(detailed, finer));
    levels->SetCoarseData(Recorded<vtkProgressiveMesh>(detailed, 0.95));
    levels->SetCorrespondence(vtkLODInterpolation::EXACT);
    levels->SetMergeDistance(0.05);
    levels->SetInterpolation(1.0);
    levels->Update();
    CHECK(levels->GetOutput()->GetNumberOfPolys() ==
      vtkPolyData::SafeDownCast(levels->GetInputDataObject(1, 0))->GetNumberOfPolys());
  }
}

void TestSequenceAlone()
{
  // A Progressive Mesh sequence alone: its levels at 0 and 95 % are the two surfaces, and the
  // geomorph goes from all the sphere's triangles to exactly the 95 % level's.
  vtkSmartPointer<vtkPolyData> detailed, unused;
  SphereAndCoarse(detailed, unused);
  vtkNew<vtkProgressiveMesh> simplify;
  simplify->SetInputData(detailed);
  simplify->SetTargetReduction(0.95);
  simplify->Update();
  vtkNew<vtkLODInterpolation> morph;
  morph->SetInputData(0, simplify->GetSequenceOutput());
  morph->SetCoarseReduction(0.95);
  morph->SetCorrespondence(vtkLODInterpolation::EXACT);
  morph->Update();
  CHECK(morph->GetOutput()->GetNumberOfPolys() == detailed->GetNumberOfPolys());
  morph->SetInterpolation(1.0);
  morph->Update();
  CHECK(morph->GetOutput()->GetNumberOfPolys() == simplify->GetOutput()->GetNumberOfPolys() &&
    morph->GetCorrespondenceBuilds() == 1);
  // Levels the wrong way round: a warning that says so.
  vtkNew<meshsimp_test::MessageLog> reversed;
  morph->AddObserver(vtkCommand::WarningEvent, reversed);
  morph->SetDetailedReduction(0.97);
  morph->Update();
  CHECK(reversed->Warnings.size() == 1 && meshsimp_test::Mentions(reversed->Warnings[0], "Detailed Reduction 0.97 is not below Coarse Reduction 0.95"));
  // A surface alone that is no sequence: the one-line error.
  vtkNew<meshsimp_test::MessageLog> log;
  vtkNew<vtkLODInterpolation> alone;
  alone->AddObserver(vtkCommand::ErrorEvent, log);
  alone->SetInputData(0, detailed);
  alone->Update();
  CHECK(log->Errors.size() == 1 && meshsimp_test::Mentions(log->Errors[0], "or a Progressive Mesh sequence alone"));
}

/// Whether two surfaces have the same points and triangles.
bool SameSurface(vtkPolyData* a, vtkPolyData* b)
{
  if (!a || !b || a->GetNumberOfPoints() != b->GetNumberOfPoints() || a->GetNumberOfPolys() != b->GetNumberOfPolys())
  {
    return false;
  }
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    if (!std::equal(a->GetPoint(p), a->GetPoint(p) + 3, b->GetPoint(p)))
    {
      return false;
    }
  }
  vtkNew<vtkIdList> x, y;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, x);
    b->GetCellPoints(c, y);
    if (x->GetNumberOfIds() != y->GetNumberOfIds() || !std::equal(x->begin(), x->end(), y->begin()))
    {
      return false;
    }
  }
  return true;
}
/// A frame kept by someone (a shallow copy, as ParaView's caches make) stays as it was when the
/// filter makes the next one: the filter writes into its last frame's arrays only where nothing
/// else holds them.
void TestKeptFrameStays()
{
  vtkSmartPointer<vtkPolyData> detailed, unused;
  SphereAndCoarse(detailed, unused);
  const vtkSmartPointer<vtkLODInterpolation> morph = MorphOf(detailed, Recorded<vtkProgressiveMesh>(detailed));
  morph->SetCorrespondence(vtkLODInterpolation::EXACT);
  morph->SetMergeDistance(0.05);
  morph->SetInterpolation(1.0);
  morph->Update();
  vtkNew<vtkPolyData> kept, before;
  kept->ShallowCopy(morph->GetOutput());
  before->DeepCopy(morph->GetOutput());
  morph->SetInterpolation(0.2);
  morph->Update();
  CHECK(morph->GetOutput()->GetNumberOfPolys() != kept->GetNumberOfPolys());
  CHECK(SameSurface(kept, before));
  for (int i = 0; i < kept->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = kept->GetPointData()->GetArray(i);
    vtkDataArray* was = before->GetPointData()->GetArray(array->GetName());
    for (vtkIdType v = 0; was && v < array->GetNumberOfValues(); ++v)
    {
      CHECK(array->GetVariantValue(v) == was->GetVariantValue(v));
    }
  }
}


void TestComposite()
{
  // A multiblock of two spheres, simplified block by block: its frame is, block by block, the
  // frame of each pair alone (each with its own correspondence, built once); a Progressive Mesh
  // sequence of the blocks morphs alone too; an empty block stays empty; blocks that do not pair
  // up give one line.
  vtkSmartPointer<vtkPolyData> sphere, unused;
  SphereAndCoarse(sphere, unused);
  vtkNew<vtkPolyData> shifted;
  shifted->DeepCopy(sphere);
  for (vtkIdType p = 0; p < shifted->GetNumberOfPoints(); ++p)
  {
    const double* at = sphere->GetPoint(p);
    shifted->GetPoints()->SetPoint(p, at[0] + 2.0, at[1], at[2]);
  }
  vtkNew<vtkMultiBlockDataSet> detailed;
  detailed->SetBlock(0, sphere);
  detailed->SetBlock(1, shifted);
  vtkNew<vtkAppearancePreservingCollapse> simplify;
  simplify->SetInputData(detailed);
  simplify->SetTargetReduction(0.95);
  simplify->GenerateOriginalIdsOn();
  simplify->Update();
  auto* coarse = vtkMultiBlockDataSet::SafeDownCast(simplify->GetOutputDataObject(0));
  for (const int correspondence : { vtkLODInterpolation::NEAREST_SURFACE_POINT, vtkLODInterpolation::EXACT })
  {
    vtkNew<vtkLODInterpolation> morph;
    morph->SetInputData(0, detailed);
    morph->SetCoarseData(coarse);
    morph->SetCorrespondence(correspondence);
    morph->SetInterpolation(0.5);
    morph->Update();
    auto* frames = vtkMultiBlockDataSet::SafeDownCast(morph->GetOutputDataObject(0));
    CHECK(frames && frames->GetNumberOfBlocks() == 2);
    for (unsigned int b = 0; frames && b < 2; ++b)
    {
      vtkNew<vtkLODInterpolation> alone;
      alone->SetInputData(0, detailed->GetBlock(b));
      alone->SetCoarseData(coarse->GetBlock(b));
      alone->SetCorrespondence(correspondence);
      alone->SetInterpolation(0.5);
      alone->Update();
      CHECK(SameSurface(vtkPolyData::SafeDownCast(frames->GetBlock(b)), alone->GetOutput()));
    }
    morph->SetInterpolation(0.75);
    morph->Update();
    CHECK(morph->GetCorrespondenceBuilds() == 2);
  }
  vtkNew<vtkProgressiveMesh> levels;
  levels->SetInputData(detailed);
  levels->SetTargetReduction(0.95);
  levels->Update();
  vtkNew<vtkLODInterpolation> sequence;
  sequence->SetInputData(0, levels->GetOutputDataObject(1));
  sequence->SetCoarseReduction(0.95);
  sequence->SetCorrespondence(vtkLODInterpolation::EXACT);
  sequence->SetInterpolation(1.0);
  sequence->Update();
  auto* frames = vtkMultiBlockDataSet::SafeDownCast(sequence->GetOutputDataObject(0));
  auto* coarsest = vtkMultiBlockDataSet::SafeDownCast(levels->GetOutputDataObject(0));
  CHECK(frames && coarsest && frames->GetNumberOfBlocks() == 2);
  for (unsigned int b = 0; frames && coarsest && b < 2; ++b)
  {
    CHECK(vtkPolyData::SafeDownCast(frames->GetBlock(b))->GetNumberOfPolys() ==
      vtkPolyData::SafeDownCast(coarsest->GetBlock(b))->GetNumberOfPolys());
  }
  // An empty block (after a clip, say) is left empty with a warning, and the others morph.
  vtkNew<vtkMultiBlockDataSet> withEmpty, coarseWithEmpty;
  vtkNew<vtkPolyData> empty;
  withEmpty->SetBlock(0, sphere);
  withEmpty->SetBlock(1, empty);
  coarseWithEmpty->SetBlock(0, coarse->GetBlock(0));
  coarseWithEmpty->SetBlock(1, empty);
  vtkNew<meshsimp_test::MessageLog> warnings;
  vtkNew<vtkLODInterpolation> partly;
  partly->AddObserver(vtkCommand::WarningEvent, warnings);
  partly->SetInputData(0, withEmpty);
  partly->SetCoarseData(coarseWithEmpty);
  partly->Update();
  frames = vtkMultiBlockDataSet::SafeDownCast(partly->GetOutputDataObject(0));
  CHECK(frames && vtkPolyData::SafeDownCast(frames->GetBlock(0))->GetNumberOfPolys() == sphere->GetNumberOfPolys() &&
    vtkPolyData::SafeDownCast(frames->GetBlock(1))->GetNumberOfPolys() == 0);
  CHECK(warnings->Warnings.size() == 1 && meshsimp_test::Mentions(warnings->Warnings[0], "Block 1: the detailed block has no triangles"));
  vtkNew<vtkMultiBlockDataSet> one;
  one->SetBlock(0, coarse->GetBlock(0));
  vtkNew<meshsimp_test::MessageLog> log;
  vtkNew<vtkLODInterpolation> unpaired;
  unpaired->AddObserver(vtkCommand::ErrorEvent, log);
  unpaired->SetInputData(0, detailed);
  unpaired->SetCoarseData(one);
  unpaired->Update();
  CHECK(log->Errors.size() == 1 && meshsimp_test::Mentions(log->Errors[0], "the detailed input has 2 surfaces and the coarse input 1"));
}

void TestMorphInShader()
{
  // For the GPU: the detailed surface as it is, with each point's place at t = 1 as its
  // tangents, on the same correspondence.
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  const vtkSmartPointer<vtkLODInterpolation> morph = MorphOf(detailed, coarse);
  morph->SetMergeDistance(0.0);
  morph->SetInterpolation(1.0);
  morph->Update();
  vtkNew<vtkPolyData> last;
  last->DeepCopy(morph->GetOutput());
  morph->MorphInShaderOn();
  morph->Update();
  vtkPolyData* out = morph->GetOutput();
  vtkDataArray* targets = out->GetPointData()->GetTangents();
  CHECK(morph->GetCorrespondenceBuilds() == 1 && out->GetPoints() == detailed->GetPoints() && targets &&
    std::strcmp(targets->GetName(), "CoarsePoints") == 0);
  for (vtkIdType p = 0; targets && p < last->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    last->GetPoint(p, x);
    targets->GetTuple(p, y);
    CHECK(std::abs(x[0] - y[0]) + std::abs(x[1] - y[1]) + std::abs(x[2] - y[2]) < 1e-6);
  }
}

void TestTimeDrivesTheMorph()
{
  // With InterpolationFromTime the filter reports the times 0, 0.05, ..., 1 and the time asked
  // for sets the frame: time 0.35 gives Interpolation 0.35's points, on one correspondence.
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  const vtkSmartPointer<vtkLODInterpolation> byValue = MorphOf(detailed, coarse);
  byValue->SetInterpolation(0.35);
  byValue->Update();
  const vtkSmartPointer<vtkLODInterpolation> byTime = MorphOf(detailed, coarse);
  byTime->InterpolationFromTimeOn();
  byTime->UpdateInformation();
  vtkInformation* info = byTime->GetOutputInformation(0);
  CHECK(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 21);
  byTime->UpdateTimeStep(0.35);
  byTime->UpdateTimeStep(0.8);
  byTime->UpdateTimeStep(0.35);
  vtkPolyData* a = byValue->GetOutput();
  vtkPolyData* b = byTime->GetOutput();
  CHECK(a->GetNumberOfPoints() == b->GetNumberOfPoints() && byTime->GetCorrespondenceBuilds() == 1);
  for (vtkIdType p = 0; p < std::min(a->GetNumberOfPoints(), b->GetNumberOfPoints()); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    CHECK(std::equal(x, x + 3, y));
  }
}

/// The morph's errors (its own, then the executive's) for these inputs; the detailed input
/// untouched.
std::vector<std::string> MorphErrors(vtkPolyData* detailed, vtkPolyData* coarse)
{
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(detailed);
  vtkNew<meshsimp_test::MessageLog> log, executive;
  vtkNew<vtkLODInterpolation> morph;
  morph->AddObserver(vtkCommand::ErrorEvent, log);
  morph->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  morph->SetInputData(0, detailed);
  if (coarse)
  {
    morph->SetCoarseData(coarse);
  }
  morph->Update();
  meshsimp_test::CheckInputUntouched(detailed, copy);
  std::vector<std::string> errors = log->Errors;
  errors.insert(errors.end(), executive->Errors.begin(), executive->Errors.end());
  return errors;
}

/// A frame keeps the detailed surface's types: float points stay floats (the morph's doubles
/// rounded), unsigned-char colours morph as rounded colours, integer labels pass as they are.
void TestFrameKeepsTypes()
{
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  const unsigned char coarseColour[3] = { 200, 10, 30 };
  for (vtkPolyData* mesh : { detailed.GetPointer(), coarse.GetPointer() })
  {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("Colors");
    colours->SetNumberOfComponents(3);
    vtkNew<vtkIntArray> labels;
    labels->SetName("Label");
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      const auto shade = static_cast<unsigned char>(127.5 * (1.0 + mesh->GetPoint(p)[2] / 0.5));
      const unsigned char own[3] = { shade, static_cast<unsigned char>(255 - shade), 0 };
      colours->InsertNextTypedTuple(mesh == coarse ? coarseColour : own);
      labels->InsertNextValue(mesh == coarse ? 7 : static_cast<int>(p % 5));
    }
    mesh->GetPointData()->AddArray(colours);
    mesh->GetPointData()->AddArray(labels);
  }
  CHECK(detailed->GetPoints()->GetDataType() == VTK_FLOAT);
  const vtkSmartPointer<vtkLODInterpolation> morph = MorphOf(detailed, coarse), inDoubles = MorphOf(detailed, coarse);
  morph->SetOutputPointsPrecision(vtkAlgorithm::DEFAULT_PRECISION);
  for (const double t : { 0.5, 1.0 })
  {
    for (vtkLODInterpolation* filter : { morph.GetPointer(), inDoubles.GetPointer() })
    {
      filter->SetMergeDistance(0.0);
      filter->SetInterpolation(t);
      filter->Update();
    }
    vtkPolyData* out = morph->GetOutput();
    vtkPolyData* exact = inDoubles->GetOutput();
    CHECK(out->GetPoints()->GetDataType() == VTK_FLOAT && exact->GetPoints()->GetDataType() == VTK_DOUBLE);
    auto* colours = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetArray("Colors"));
    auto* own = vtkUnsignedCharArray::SafeDownCast(detailed->GetPointData()->GetArray("Colors"));
    CHECK(colours != nullptr && out->GetPointData()->GetArray("Label") == detailed->GetPointData()->GetArray("Label"));
    CHECK(out->GetPointData()->GetArray("Height")->GetDataType() == VTK_DOUBLE);
    for (vtkIdType p = 0; colours && p < out->GetNumberOfPoints(); ++p)
    {
      double a[3], b[3];
      out->GetPoint(p, a);
      exact->GetPoint(p, b);
      for (int k = 0; k < 3; ++k)
      {
        CHECK(a[k] == static_cast<float>(b[k]));
        const double expected = (1.0 - t) * own->GetTypedComponent(p, k) + t * coarseColour[k];
        CHECK(std::abs(colours->GetTypedComponent(p, k) - expected) <= 0.5 + 1e-9);
      }
    }
  }
}

/// A frame's ranges are known before anyone asks: every array the frame writes (points,
/// morphed arrays, Displacement) carries the ranges VTK computes for it, NaN and infinities
/// included, and the next frame's replace them.
void TestFrameRecordsRanges()
{
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (vtkPolyData* mesh : { detailed.GetPointer(), coarse.GetPointer() })
  {
    vtkNew<vtkFloatArray> vectors;
    vectors->SetName("Vectors");
    vectors->SetNumberOfComponents(3);
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("Colors");
    colours->SetNumberOfComponents(4);
    for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    {
      const double* x = mesh->GetPoint(p);
      vectors->InsertNextTuple3(x[1], -x[0], mesh == coarse ? 1.0 : 2.0 * x[2]);
      const auto shade = static_cast<unsigned char>(127.5 * (1.0 + x[2] / 0.5));
      colours->InsertNextTuple4(shade, 255 - shade, mesh == coarse ? 90 : 0, 255);
    }
    mesh->GetPointData()->AddArray(vectors);
    mesh->GetPointData()->AddArray(colours);
  }
  vtkPointData* own = detailed->GetPointData();
  own->GetArray("Height")->SetTuple1(3, nan);
  own->GetArray("Height")->SetTuple1(5, -inf);
  own->GetArray("Vectors")->SetComponent(7, 1, inf);
  own->GetArray("Vectors")->SetComponent(8, 2, nan);
  vtkNew<vtkLODInterpolation> morph;
  morph->SetInputData(0, detailed);
  morph->SetCoarseData(coarse);
  for (const double t : { 0.3, 0.7 })
  {
    morph->SetInterpolation(t);
    morph->Update();
    vtkPolyData* out = morph->GetOutput();
    std::vector<vtkDataArray*> written = { out->GetPoints()->GetData() };
    for (const char* name : { "Height", "Vectors", "Colors", "Displacement" })
    {
      written.push_back(out->GetPointData()->GetArray(name));
    }
    for (vtkDataArray* array : written)
    {
      CHECK(array != nullptr);
      if (array)
      {
        meshsimp_test::CheckRecordedRanges(array);
      }
    }
  }
}

void TestBadInput()
{
  // An empty coarse surface, one of points alone: one error of the filter's (none of the
  // executive's) that says which input has no triangles. No coarse input, and no sequence: one.
  // Mismatched arrays pass as they are; short ones are left out.
  vtkSmartPointer<vtkPolyData> detailed, coarse;
  SphereAndCoarse(detailed, coarse);
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPolyData> pointsOnly;
  pointsOnly->SetPoints(coarse->GetPoints());
  for (vtkPolyData* bad : { empty.GetPointer(), pointsOnly.GetPointer() })
  {
    const std::vector<std::string> errors = MorphErrors(detailed, bad);
    CHECK(errors.size() == 1 && meshsimp_test::Mentions(errors[0], "Cannot morph: the coarse surface has no triangles."));
  }
  CHECK(MorphErrors(detailed, nullptr).size() == 1); // a surface alone that is no sequence
  // A coarse array of the detailed one's name but other components: the detailed values pass.
  vtkNew<vtkDoubleArray> pairs;
  pairs->SetName("Height");
  pairs->SetNumberOfComponents(2);
  pairs->SetNumberOfTuples(coarse->GetNumberOfPoints());
  pairs->Fill(7.0);
  vtkNew<vtkPolyData> mismatched;
  mismatched->ShallowCopy(coarse);
  mismatched->GetPointData()->AddArray(pairs);
  CHECK(MorphErrors(detailed, mismatched).empty());
  vtkNew<vtkLODInterpolation> passing;
  passing->SetInputData(0, detailed);
  passing->SetCoarseData(mismatched);
  passing->SetInterpolation(1.0);
  passing->Update();
  vtkDataArray* height = passing->GetOutput()->GetPointData()->GetArray("Height");
  CHECK(height && height->GetNumberOfComponents() == 1 && height->GetTuple1(7) == detailed->GetPoint(7)[2]);
  // A coarse array shorter than its points: left out with a warning, the frame made.
  vtkNew<vtkDoubleArray> shortHeight;
  shortHeight->SetName("Height");
  shortHeight->SetNumberOfValues(3);
  vtkNew<vtkPolyData> shortArray;
  shortArray->ShallowCopy(coarse);
  shortArray->GetPointData()->AddArray(shortHeight);
  vtkNew<meshsimp_test::MessageLog> warnings;
  passing->AddObserver(vtkCommand::WarningEvent, warnings);
  passing->SetCoarseData(shortArray);
  passing->Update();
  CHECK(warnings->Warnings.size() == 1 && meshsimp_test::Mentions(warnings->Warnings[0], "Not passing point data array 'Height'"));
  CHECK(passing->GetOutput()->GetNumberOfPoints() == detailed->GetNumberOfPoints());
  // Exact without a record, or with another surface's: one error that says why.
  const std::pair<vtkSmartPointer<vtkPolyData>, const char*> unrecorded[] = {
    { coarse, "Exact needs the coarse surface to carry vtkOriginalPointIds" },
    { Recorded<vtkAppearancePreservingCollapse>(coarse), "(the coarse surface was made from another)" }
  };
  for (const auto& [other, message] : unrecorded)
  {
    vtkNew<meshsimp_test::MessageLog> log;
    vtkNew<vtkLODInterpolation> morph;
    morph->AddObserver(vtkCommand::ErrorEvent, log);
    morph->SetInputData(0, detailed);
    morph->SetCoarseData(other);
    morph->SetCorrespondence(vtkLODInterpolation::EXACT);
    morph->Update();
    CHECK(log->Errors.size() == 1 && meshsimp_test::Mentions(log->Errors[0], message));
    CHECK(morph->GetOutput()->GetNumberOfPoints() == 0);
  }
}
} // namespace

int TestLODInterpolation(int argc, char* argv[])
{
  if (argc > 1 && std::strcmp(argv[1], "Image") == 0)
  {
    // The cow at t = 0.5 between itself and its simplification at 95 %.
    vtkNew<vtkOFFMeshReader> cow;
    cow->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/cow.off");
    vtkNew<vtkAppearancePreservingCollapse> simplify;
    simplify->SetInputConnection(cow->GetOutputPort());
    simplify->SetTargetReduction(0.95);
    vtkNew<vtkLODInterpolation> morph;
    morph->SetInputConnection(0, cow->GetOutputPort());
    morph->SetCoarseConnection(simplify->GetOutputPort());
    morph->SetInterpolation(0.5);
    morph->Update();
    return meshsimp_test::CompareWithBaseline(morph->GetOutput(), false, argc, argv);
  }
  TestMorph();
  TestExact();
  TestKeptFrameStays();
  TestSequenceAlone();
  TestComposite();
  TestMorphInShader();
  TestTimeDrivesTheMorph();
  TestFrameKeepsTypes();
  TestFrameRecordsRanges();
  TestBadInput();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
