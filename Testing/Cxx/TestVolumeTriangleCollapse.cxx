// SPDX-License-Identifier: BSD-3-Clause
// vtkVolumeTriangleCollapse on real meshes: counts within 1 %, closed stays closed and
// manifold, every point-data array carried, cell data copied, error arrays, a sphere's volume
// kept better than by vtkQuadricDecimation, thread independence, input untouched.
#include "vtkVolumeTriangleCollapse.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkMassProperties.h"
#include "vtkMath.h"
#include "vtkQuadricDecimation.h"
#include "vtkSphereSource.h"

#include "TestVTKHelpers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace
{
void TestTargetsAndAttributes(vtkPolyData* cow)
{
  const double inputTriangles = cow->GetNumberOfPolys();
  CHECK(meshsimp_test::OpenEdges(cow) == 0);
  for (const double reduction : { 0.5, 0.7, 0.9, 0.95 })
  {
    vtkNew<vtkVolumeTriangleCollapse> filter;
    filter->SetInputData(cow);
    filter->SetTargetReduction(reduction);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    const double target = std::round(inputTriangles * (1 - reduction));
    CHECK(std::abs(out->GetNumberOfPolys() - target) <= 0.01 * target);
    CHECK(out->GetNumberOfPolys() == out->GetNumberOfCells());
    CHECK(meshsimp_test::OpenEdges(out) == 0);

    meshsimp_test::CheckCarriedData(cow, out);
    vtkPointData* pd = out->GetPointData();

    // Error arrays: per point, and the total in the field data.
    vtkDataArray* errors = pd->GetArray("SquareVolumeError");
    CHECK(errors && errors->GetNumberOfTuples() == out->GetNumberOfPoints());
    double largest = 0.0;
    for (vtkIdType i = 0; errors && i < errors->GetNumberOfTuples(); ++i)
    {
      CHECK(errors->GetTuple1(i) >= 0.0);
      largest = std::max(largest, errors->GetTuple1(i));
    }
    vtkDataArray* total = out->GetFieldData()->GetArray("SquareVolumeError");
    CHECK(total && total->GetTuple1(0) > 0.0 && largest <= total->GetTuple1(0) * (1 + 1e-9));
    vtkDataArray* achieved = out->GetFieldData()->GetArray("AchievedReduction");
    CHECK(achieved &&
      std::abs(achieved->GetTuple1(0) - (1 - out->GetNumberOfPolys() / inputTriangles)) < 1e-12);
  }
}

double Volume(vtkPolyData* mesh)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(mesh);
  mass->Update();
  return mass->GetVolume();
}

void TestSphereVolume()
{
  // At 90 % the sphere's volume changes less than under vtkQuadricDecimation.
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(96);
  source->SetPhiResolution(96);
  source->Update();
  vtkPolyData* sphere = source->GetOutput();
  const double volume = Volume(sphere);
  vtkNew<vtkVolumeTriangleCollapse> ours;
  ours->SetInputData(sphere);
  ours->SetTargetReduction(0.9);
  ours->Update();
  vtkNew<vtkQuadricDecimation> quadric;
  quadric->SetInputData(sphere);
  quadric->SetTargetReduction(0.9);
  quadric->Update();
  const double oursChange = std::abs(Volume(ours->GetOutput()) / volume - 1.0);
  const double quadricChange = std::abs(Volume(quadric->GetOutput()) / volume - 1.0);
  std::cout << "sphere volume change at 90 %: ours " << oursChange << ", vtkQuadricDecimation "
            << quadricChange << "\n";
  CHECK(oursChange < quadricChange);
  CHECK(meshsimp_test::OpenEdges(ours->GetOutput()) == 0);
}

void TestThreadsAndInput(vtkPolyData* cow)
{
  meshsimp_test::CheckThreadIndependence(cow, [cow](int threads) {
    vtkNew<vtkVolumeTriangleCollapse> filter;
    filter->SetInputData(cow);
    filter->SetTargetReduction(0.9);
    filter->SetNumberOfThreads(threads);
    filter->Update();
    return vtkSmartPointer<vtkPolyData>(filter->GetOutput());
  });
}

void TestLockedPoints(vtkPolyData* cow)
{
  // Every 40th point locked by a point array selected as input array 0: each stays, exactly.
  vtkSmartPointer<vtkPolyData> marked = meshsimp_test::WithLockArray(cow, 40);
  vtkNew<vtkVolumeTriangleCollapse> filter;
  filter->SetInputData(marked);
  filter->SetTargetReduction(0.9);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Locked");
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  CHECK(std::abs(out->GetNumberOfPolys() - 580) <= 6);
  const std::set<std::array<double, 3>> outputPoints = meshsimp_test::PointSet(out);
  for (vtkIdType i = 0; i < cow->GetNumberOfPoints(); i += 40)
  {
    std::array<double, 3> p;
    cow->GetPoint(i, p.data());
    CHECK(outputPoints.count(p) == 1);
  }
}

}

int TestVolumeTriangleCollapse(int, char*[])
{
  vtkSmartPointer<vtkPolyData> cow = meshsimp_test::DecoratedCow();
  TestTargetsAndAttributes(cow);
  TestSphereVolume();
  TestThreadsAndInput(cow);
  // An open mesh at a triangle count, its rim kept in place.
  meshsimp_test::CheckPreservedRim<vtkVolumeTriangleCollapse>(0.01);
  TestLockedPoints(cow);
  meshsimp_test::CheckPartitionedInput<vtkVolumeTriangleCollapse>(cow);
  meshsimp_test::CheckPointLabels<vtkVolumeTriangleCollapse>(cow);
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
