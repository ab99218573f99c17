// SPDX-License-Identifier: BSD-3-Clause
// Baseline images of vtkOctreeVertexClustering: the cow at 90 % reduction (flat shading with
// edges) and the Jacksboro terrain at 95 % coloured by the carried elevation array.
//   TestOctreeVertexClusteringImage Cow|Terrain -V baseline.png -T temporary/
#include "vtkOFFReader.h"
#include "vtkOctreeVertexClustering.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkXMLPolyDataReader.h"

#include <cstring>
#include <iostream>

int TestOctreeVertexClusteringImage(int argc, char* argv[])
{
  const bool terrain = argc > 1 && std::strcmp(argv[1], "Terrain") == 0;
  vtkNew<vtkOctreeVertexClustering> filter;
  vtkNew<vtkOFFReader> cow;
  vtkNew<vtkXMLPolyDataReader> dem;
  if (terrain)
  {
    dem->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/jacksboro_dem_half.vtp");
    filter->SetInputConnection(dem->GetOutputPort());
    filter->SetTargetReduction(0.95);
  }
  else
  {
    cow->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/cow.off");
    filter->SetInputConnection(cow->GetOutputPort());
    filter->SetTargetReduction(0.9);
  }
  filter->Update();
  vtkPolyData* output = filter->GetOutput();
  if (output->GetNumberOfPolys() == 0)
  {
    std::cerr << "no output triangles\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(output);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (terrain)
  {
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("elevation");
    mapper->SetScalarRange(output->GetPointData()->GetArray("elevation")->GetRange());
    mapper->ScalarVisibilityOn();
  }
  else
  {
    mapper->ScalarVisibilityOff();
    actor->GetProperty()->SetColor(0.85, 0.75, 0.6);
    actor->GetProperty()->EdgeVisibilityOn();
    actor->GetProperty()->SetEdgeColor(0.2, 0.2, 0.3);
  }
  actor->GetProperty()->SetInterpolationToFlat();

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetMultiSamples(0);
  window->SetSize(400, 300);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  if (terrain)
  {
    camera->Elevation(-55);
  }
  else
  {
    camera->Azimuth(30);
    camera->Elevation(15);
  }
  renderer->ResetCamera();
  camera->Zoom(1.3);
  window->Render();

  const int result = vtkRegressionTestImageThreshold(window, 0.05);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
