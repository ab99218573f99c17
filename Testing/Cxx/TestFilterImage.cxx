// SPDX-License-Identifier: BSD-3-Clause
// Baseline images of the filters: the cow at 90 % reduction (flat shading with edges) and the
// Jacksboro terrain at 95 % coloured by the carried elevation array.
//   TestFilterImage <a registered filter's Name> Cow|Terrain -V baseline.png -T temporary/
#include "MeshSimplificationFilters.h"
#include "vtkOFFMeshReader.h"

#include "vtkNew.h"
#include "vtkXMLPolyDataReader.h"

#include "TestImageHelpers.h"

#include <cstring>

int TestFilterImage(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestFilterImage <filter name> Cow|Terrain -V baseline -T dir\n";
    return EXIT_FAILURE;
  }
  const bool terrain = std::strcmp(argv[2], "Terrain") == 0;
  vtkSmartPointer<vtkMeshSimplificationFilter> filter;
#define MESHSIMPLIFICATION_MAKE(name, method, parameters, tolerance, blends, alias)                 \
  if (std::strcmp(argv[1], #name) == 0)                                                           \
  {                                                                                                \
    filter = vtkSmartPointer<vtk##name>::New();                                                    \
  }
  MESHSIMPLIFICATION_FILTERS(MESHSIMPLIFICATION_MAKE)
#undef MESHSIMPLIFICATION_MAKE
  if (!filter)
  {
    std::cerr << "TestFilterImage: no filter named " << argv[1] << "\n";
    return EXIT_FAILURE;
  }
  filter->SetTargetReduction(terrain ? 0.95 : 0.9);
  vtkNew<vtkOFFMeshReader> cow;
  vtkNew<vtkXMLPolyDataReader> dem;
  if (terrain)
  {
    dem->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/jacksboro_dem_half.vtp");
    filter->SetInputConnection(dem->GetOutputPort());
  }
  else
  {
    cow->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/cow.off");
    filter->SetInputConnection(cow->GetOutputPort());
  }
  filter->Update();
  return meshsimp_test::CompareWithBaseline(filter->GetOutput(), terrain, argc, argv);
}
