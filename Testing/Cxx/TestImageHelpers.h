// SPDX-License-Identifier: BSD-3-Clause
// The baseline-image scenes of the filter tests: the cow in flat shading with edges, and the
// Jacksboro terrain coloured by its carried elevation array (or by a texture, where one is given).
#ifndef MeshSimplification_TestImageHelpers_h
#define MeshSimplification_TestImageHelpers_h

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
#include "vtkTexture.h"

#include <cstdlib>
#include <iostream>

namespace meshsimp_test
{
/// Renders a filter's output in one of the two scenes and compares it with the baseline given
/// by -V in argv; returns a process exit code.
inline int CompareWithBaseline(vtkPolyData* output, bool terrain, int argc, char* argv[], vtkTexture* texture = nullptr)
{
  if (output->GetNumberOfPolys() == 0)
  {
    std::cerr << "no output triangles\n";
    return EXIT_FAILURE;
  }

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(output);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  if (texture)
  {
    mapper->ScalarVisibilityOff();
    actor->SetTexture(texture);
  }
  else if (terrain)
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
}

#endif
