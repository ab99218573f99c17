// SPDX-License-Identifier: BSD-3-Clause
// vtkOctreeVertexClustering on bad input: each case gives a clear message or the documented
// result, never a crash, and leaves the input untouched.
#include "vtkOctreeVertexClustering.h"

#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"

#include "TestVTKHelpers.h"

#include <cmath>
#include <iostream>
#include <limits>

namespace
{

struct Run
{
  vtkSmartPointer<vtkPolyData> Output;
  bool Warned = false;
  bool Failed = false;
};

Run Simplify(vtkPolyData* input, double reduction = 0.5)
{
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(input);
  vtkNew<vtkTest::ErrorObserver> observer;
  vtkNew<vtkOctreeVertexClustering> filter;
  filter->AddObserver(vtkCommand::WarningEvent, observer);
  filter->AddObserver(vtkCommand::ErrorEvent, observer);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  filter->SetInputData(input);
  filter->SetTargetReduction(reduction);
  filter->Update();
  Run run;
  run.Output = filter->GetOutput();
  run.Warned = observer->GetWarning();
  run.Failed = observer->GetError();
  meshsimp_test::CheckInputUntouched(input, copy);
  // Whatever happened, the output is well formed.
  for (vtkIdType i = 0; i < run.Output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    run.Output->GetPoint(i, p);
    CHECK(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
  return run;
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(sphere->GetOutput());
  return mesh;
}
}

int TestOctreeVertexClusteringBadInput(int, char*[])
{
  // Empty input: empty output, no error.
  {
    vtkNew<vtkPolyData> empty;
    const Run run = Simplify(empty);
    CHECK(!run.Failed && run.Output->GetNumberOfPoints() == 0);
  }
  // Points only, no cells: nothing to simplify, empty output.
  {
    vtkNew<vtkPolyData> cloud;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    cloud->SetPoints(points);
    const Run run = Simplify(cloud);
    CHECK(!run.Failed && run.Output->GetNumberOfCells() == 0);
  }
  // NaN points: their triangles are ignored with a warning; the rest is simplified.
  {
    vtkSmartPointer<vtkPolyData> sphere = Sphere();
    sphere->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0, 0);
    sphere->GetPoints()->SetPoint(40, 0, std::numeric_limits<double>::infinity(), 0);
    const Run run = Simplify(sphere);
    CHECK(run.Warned && !run.Failed);
    CHECK(run.Output->GetNumberOfPolys() > 0);
  }
  // Degenerate (repeated ids, zero area) and non-manifold (three triangles on an edge) triangles.
  {
    vtkSmartPointer<vtkPolyData> sphere = Sphere();
    vtkCellArray* polys = sphere->GetPolys();
    const vtkIdType repeated[3] = { 3, 3, 4 };
    const vtkIdType fin[3] = { 10, 11, 0 }; // shares edge (10, 11) with two sphere triangles
    polys->InsertNextCell(3, repeated);
    polys->InsertNextCell(3, fin);
    const vtkIdType collinear = sphere->GetPoints()->InsertNextPoint(sphere->GetPoint(10));
    const vtkIdType flat[3] = { 10, collinear, 11 };
    polys->InsertNextCell(3, flat);
    sphere->Modified();
    const Run run = Simplify(sphere);
    CHECK(!run.Failed && run.Output->GetNumberOfPolys() > 0);
  }
  // Quads and strips are triangulated first and simplified like triangles.
  {
    vtkNew<vtkPolyData> mixed;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    vtkNew<vtkCellArray> strips;
    const int n = 20;
    for (int j = 0; j <= n; ++j)
    {
      for (int i = 0; i <= n; ++i)
      {
        points->InsertNextPoint(i, j, 0.1 * std::sin(0.5 * i) * j);
      }
    }
    for (int j = 0; j < n; ++j)
    {
      if (j % 2 == 0)
      {
        for (int i = 0; i < n; ++i)
        {
          const vtkIdType a = j * (n + 1) + i;
          const vtkIdType quad[4] = { a, a + 1, a + n + 2, a + n + 1 };
          quads->InsertNextCell(4, quad);
        }
      }
      else
      {
        strips->InsertNextCell(2 * (n + 1));
        for (int i = 0; i <= n; ++i)
        {
          strips->InsertCellPoint((j + 1) * (n + 1) + i);
          strips->InsertCellPoint(j * (n + 1) + i);
        }
      }
    }
    mixed->SetPoints(points);
    mixed->SetPolys(quads);
    mixed->SetStrips(strips);
    const Run run = Simplify(mixed, 0.75);
    const double target = 0.25 * 2 * n * n;
    CHECK(!run.Failed && std::abs(run.Output->GetNumberOfPolys() - target) <= 0.03 * target);
    CHECK(run.Output->GetNumberOfStrips() == 0);
  }
  // Lines and vertices only: dropped with a warning, empty output.
  {
    vtkNew<vtkPolyData> wires;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkCellArray> verts;
    for (int i = 0; i < 10; ++i)
    {
      points->InsertNextPoint(i, 0, 0);
    }
    const vtkIdType line[2] = { 0, 1 };
    const vtkIdType vertex[1] = { 5 };
    lines->InsertNextCell(2, line);
    verts->InsertNextCell(1, vertex);
    wires->SetPoints(points);
    wires->SetLines(lines);
    wires->SetVerts(verts);
    const Run run = Simplify(wires);
    CHECK(run.Warned && !run.Failed && run.Output->GetNumberOfCells() == 0);
  }
  // Out-of-range targets are clamped: reduction 1.5 → 1 (no triangle left), −1 → 0 (no
  // triangle removed but duplicates), and a negative error bound → 0 (exact).
  {
    vtkSmartPointer<vtkPolyData> sphere = Sphere();
    vtkNew<vtkOctreeVertexClustering> filter;
    filter->SetInputData(sphere);
    filter->SetTargetReduction(1.5);
    CHECK(filter->GetTargetReduction() == 1.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() == 0);
    filter->SetTargetReduction(-1);
    CHECK(filter->GetTargetReduction() == 0.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() == sphere->GetNumberOfPolys());
    filter->SetTargetModeToMaximumError();
    filter->SetMaximumError(-3);
    CHECK(filter->GetMaximumError() == 0.0);
    filter->Update();
    CHECK(filter->GetOutput()->GetNumberOfPolys() > 0.9 * sphere->GetNumberOfPolys());
    CHECK(filter->GetAchievedMaximumError() < 1e-9);
  }
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
