// SPDX-License-Identifier: BSD-3-Clause
// Baseline images of the filters: the cow at 90 % reduction (flat shading with edges) and the
// Jacksboro terrain at 95 % coloured by the carried elevation array.
//   TestFilterImage Octree|Volume|Parallel|Progressive Cow|Terrain -V baseline.png -T temporary/
#include "vtkOFFMeshReader.h"
#include "vtkOctreeVertexClustering.h"
#include "vtkParallelDecimation.h"
#include "vtkProgressiveMesh.h"
#include "vtkVolumeTriangleCollapse.h"

#include "vtkNew.h"
#include "vtkXMLPolyDataReader.h"

#include "TestImageHelpers.h"

#include <cstring>

int TestFilterImage(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestFilterImage Octree|Volume|Parallel|Progressive Cow|Terrain -V baseline -T dir\n";
    return EXIT_FAILURE;
  }
  const bool terrain = std::strcmp(argv[2], "Terrain") == 0;
  vtkSmartPointer<vtkPolyDataAlgorithm> filter;
  if (std::strcmp(argv[1], "Volume") == 0)
  {
    auto volume = vtkSmartPointer<vtkVolumeTriangleCollapse>::New();
    volume->SetTargetReduction(terrain ? 0.95 : 0.9);
    filter = volume;
  }
  else if (std::strcmp(argv[1], "Parallel") == 0)
  {
    auto parallel = vtkSmartPointer<vtkParallelDecimation>::New();
    parallel->SetTargetReduction(terrain ? 0.95 : 0.9);
    filter = parallel;
  }
  else if (std::strcmp(argv[1], "Progressive") == 0)
  {
    auto progressive = vtkSmartPointer<vtkProgressiveMesh>::New();
    progressive->SetTargetReduction(terrain ? 0.95 : 0.9);
    filter = progressive;
  }
  else
  {
    auto octree = vtkSmartPointer<vtkOctreeVertexClustering>::New();
    octree->SetTargetReduction(terrain ? 0.95 : 0.9);
    filter = octree;
  }
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
