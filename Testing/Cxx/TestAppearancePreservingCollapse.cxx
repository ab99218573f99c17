// SPDX-License-Identifier: BSD-3-Clause
// vtkAppearancePreservingCollapse on real meshes: counts within 1 %, closed stays closed, every
// point-data array carried, the Importance array, a colour border kept where the geometry alone
// would blur it, a texture seam that stays closed, thread independence, input untouched.
#include "vtkAppearancePreservingCollapse.h"

#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkFeatureEdges.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"

#include "TestVTKHelpers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>

namespace
{
void TestTargetsAndAttributes(vtkPolyData* cow)
{
  const double inputTriangles = cow->GetNumberOfPolys();
  for (const double reduction : { 0.5, 0.9, 0.95 })
  {
    vtkNew<vtkAppearancePreservingCollapse> filter;
    filter->SetInputData(cow);
    filter->SetTargetReduction(reduction);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    const double target = std::round(inputTriangles * (1 - reduction));
    CHECK(std::abs(out->GetNumberOfPolys() - target) <= 0.01 * target + 1);
    CHECK(meshsimp_test::OpenEdges(out) == 0);
    meshsimp_test::CheckCarriedData(cow, out);
    vtkDataArray* importance = out->GetPointData()->GetArray("Importance");
    CHECK(importance && importance->GetNumberOfTuples() == out->GetNumberOfPoints());
    for (vtkIdType i = 0; importance && i < importance->GetNumberOfTuples(); ++i)
    {
      CHECK(importance->GetTuple1(i) >= 1.0);
    }
    CHECK(out->GetFieldData()->GetArray("Passes") != nullptr);
  }
}

/// A sphere whose colour array is red above z = 0.2 and blue below.
vtkSmartPointer<vtkPolyData> TwoColourSphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(80);
  source->SetPhiResolution(80);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colour");
  colours->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < sphere->GetNumberOfPoints(); ++i)
  {
    const bool red = sphere->GetPoint(i)[2] > 0.2;
    colours->InsertNextTuple3(red ? 255 : 0, 0, red ? 0 : 255);
  }
  sphere->GetPointData()->SetScalars(colours);
  return sphere;
}

/// Output points whose colour is a blend (neither red nor blue within 32 of 255).
vtkIdType BlendedPoints(vtkPolyData* mesh)
{
  vtkDataArray* colours = mesh->GetPointData()->GetArray("Colour");
  vtkIdType blended = 0;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double red = colours->GetComponent(i, 0), blue = colours->GetComponent(i, 2);
    blended += (red > 223 && blue < 32) || (blue > 223 && red < 32) ? 0 : 1;
  }
  return blended;
}

void TestColourBorder()
{
  // The colours weigh in the order: their border keeps its points, and fewer output points
  // carry a blend of the two colours than with the geometry alone (AttributeWeight 0) or with
  // the colours' factor at 0 (ColorWeight; the sphere's normals still weigh). With the normals'
  // factor at 0 too, nothing is weighed: the output is the geometry-alone one, point for point.
  struct Weights
  {
    double Attribute, Normal, Color;
  };
  const std::array<Weights, 4> runs = { { { 0.0, 1.0, 1.0 }, { 0.1, 1.0, 0.0 }, { 0.1, 1.0, 1.0 }, { 0.1, 0.0, 0.0 } } };
  vtkSmartPointer<vtkPolyData> sphere = TwoColourSphere();
  std::array<vtkSmartPointer<vtkPolyData>, 4> outputs;
  std::array<vtkIdType, 4> blended{};
  for (std::size_t run = 0; run < runs.size(); ++run)
  {
    vtkNew<vtkAppearancePreservingCollapse> filter;
    filter->SetInputData(sphere);
    filter->SetTargetReduction(0.95);
    filter->SetAttributeWeight(runs[run].Attribute);
    filter->SetNormalWeight(runs[run].Normal);
    filter->SetColorWeight(runs[run].Color);
    filter->Update();
    outputs[run] = filter->GetOutput();
    CHECK(meshsimp_test::OpenEdges(outputs[run]) == 0);
    blended[run] = BlendedPoints(outputs[run]);
  }
  std::cout << "two-colour sphere at 95 %: blended points " << blended[2] << " (geometry alone " << blended[0]
            << ", colours left out " << blended[1] << ")\n";
  CHECK(blended[2] < blended[0] && blended[2] < blended[1]);
  CHECK(outputs[3]->GetNumberOfPoints() == outputs[0]->GetNumberOfPoints());
  for (vtkIdType i = 0; i < outputs[0]->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    outputs[3]->GetPoint(i, a);
    outputs[0]->GetPoint(i, b);
    CHECK(std::equal(a, a + 3, b));
  }
}

/// A bumpy square whose right half has its own copies of the points on x = 0.5, with other
/// texture coordinates (a texture seam, as an atlas makes one): 2 × 20 × 40 triangles.
vtkSmartPointer<vtkPolyData> SeamedSquare()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> triangles;
  const int n = 40;
  for (int half = 0; half < 2; ++half)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n / 2; ++i)
      {
        const double x = 0.5 * half + double(i) / n, y = double(j) / n;
        points->InsertNextPoint(x, y, 0.03 * std::sin(9 * x) * std::sin(7 * y));
        tcoords->InsertNextTuple2(x + half, y);
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n / 2; ++i)
      {
        const vtkIdType a = first + j * (n / 2 + 1) + i, b = a + 1, c = a + n / 2 + 1, d = c + 1;
        triangles->InsertNextCell({ a, b, d });
        triangles->InsertNextCell({ a, d, c });
      }
    }
  }
  auto square = vtkSmartPointer<vtkPolyData>::New();
  square->SetPoints(points);
  square->SetPolys(triangles);
  square->GetPointData()->SetTCoords(tcoords);
  return square;
}

void TestTextureSeam()
{
  // The seam's points go in twins along it (each position twice, or not at all): fewer than
  // half of them are left, and with coincident points merged no open edge lies on the seam.
  vtkSmartPointer<vtkPolyData> square = SeamedSquare();
  vtkNew<vtkAppearancePreservingCollapse> filter;
  filter->SetInputData(square);
  filter->SetTargetReduction(0.9);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  std::map<std::array<double, 3>, int> inputCount, outputCount;
  for (vtkIdType i = 0; i < square->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    square->GetPoint(i, p.data());
    ++inputCount[p];
  }
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    out->GetPoint(i, p.data());
    ++outputCount[p];
  }
  int seams = 0;
  for (const auto& entry : inputCount)
  {
    if (entry.second == 2)
    {
      ++seams;
      const auto found = outputCount.find(entry.first);
      CHECK(found == outputCount.end() || found->second == 2);
    }
  }
  CHECK(seams == 41);
  const auto left = std::count_if(outputCount.begin(), outputCount.end(),
    [](const std::pair<const std::array<double, 3>, int>& entry) { return entry.second == 2; });
  CHECK(2 * left < seams);
  CHECK(std::abs(out->GetNumberOfPolys() - 320) <= 4);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputData(out);
  merge->PointMergingOn();
  merge->SetTolerance(0.0);
  vtkNew<vtkFeatureEdges> open;
  open->SetInputConnection(merge->GetOutputPort());
  open->BoundaryEdgesOn();
  open->FeatureEdgesOff();
  open->NonManifoldEdgesOff();
  open->ManifoldEdgesOff();
  open->Update();
  vtkPolyData* edges = open->GetOutput();
  int onSeam = 0;
  for (vtkIdType e = 0; e < edges->GetNumberOfCells(); ++e)
  {
    double a[3], b[3];
    edges->GetPoint(edges->GetCell(e)->GetPointId(0), a);
    edges->GetPoint(edges->GetCell(e)->GetPointId(1), b);
    onSeam += a[0] == 0.5 && b[0] == 0.5 ? 1 : 0;
  }
  CHECK(onSeam == 0);
}

void TestThreadsAndInput(vtkPolyData* cow)
{
  meshsimp_test::CheckThreadIndependence(cow, [cow](int threads) {
    vtkNew<vtkAppearancePreservingCollapse> filter;
    filter->SetInputData(cow);
    filter->SetTargetReduction(0.9);
    filter->SetNumberOfThreads(threads);
    filter->Update();
    return vtkSmartPointer<vtkPolyData>(filter->GetOutput());
  });
}

void TestNormalsWhereTheInputHadNone(vtkPolyData* cow)
{
  // Without point normals in the input, the output gets them (active, named Normals): each the
  // area-weighted mean of its triangles' normals, so that the coarse mesh is drawn smooth. The
  // input stays without.
  vtkNew<vtkPolyData> bare;
  bare->DeepCopy(cow);
  bare->GetPointData()->SetNormals(nullptr);
  bare->GetPointData()->RemoveArray("Normals");
  bare->GetCellData()->Initialize();
  CHECK(!bare->GetPointData()->GetNormals() && !bare->GetPointData()->GetArray("Normals"));
  vtkNew<vtkAppearancePreservingCollapse> filter;
  filter->SetInputData(bare);
  filter->SetTargetReduction(0.9);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  CHECK(normals && std::string(normals->GetName()) == "Normals" && !bare->GetPointData()->GetNormals());
  std::vector<std::array<double, 3>> sums(out->GetNumberOfPoints(), { 0.0, 0.0, 0.0 });
  vtkCellArray* polys = out->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    double a[3], b[3], c[3];
    out->GetPoint(ids[0], a);
    out->GetPoint(ids[1], b);
    out->GetPoint(ids[2], c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    for (vtkIdType k = 0; k < 3; ++k)
    {
      for (int i = 0; i < 3; ++i)
      {
        sums[ids[k]][i] += n[i];
      }
    }
  }
  for (vtkIdType p = 0; normals && p < out->GetNumberOfPoints(); ++p)
  {
    const double* n = normals->GetTuple3(p);
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const std::array<double, 3>& m = sums[p];
    const double mean = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    CHECK(std::abs(length - 1.0) < 1e-6 && (n[0] * m[0] + n[1] * m[1] + n[2] * m[2]) > 0.9999 * mean);
  }
}
}

int TestAppearancePreservingCollapse(int, char*[])
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  TestTargetsAndAttributes(cow);
  TestColourBorder();
  TestTextureSeam();
  TestThreadsAndInput(cow);
  TestNormalsWhereTheInputHadNone(cow);
  meshsimp_test::CheckPreservedRim<vtkAppearancePreservingCollapse>(0.01);
  meshsimp_test::CheckPartitionedInput<vtkAppearancePreservingCollapse>(cow);
  meshsimp_test::CheckPointLabels<vtkAppearancePreservingCollapse>(cow);
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
