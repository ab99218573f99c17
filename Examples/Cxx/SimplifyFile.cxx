// SPDX-License-Identifier: BSD-3-Clause
// The VTK filters in a C++ program: a mesh file simplified by Volume Triangle Collapse to a
// triangle count, with the two-sided Deviation array, written as .vtp.
//   SimplifyFile input.(off|vtp) output.vtp [triangles, default 1000]
#include "vtkOFFMeshReader.h"
#include "vtkVolumeTriangleCollapse.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: SimplifyFile input.(off|vtp) output.vtp [triangles]\n";
    return EXIT_FAILURE;
  }
  // 1. A reader for the file's format (the module's own for .off).
  const std::string path = argv[1];
  vtkSmartPointer<vtkAlgorithm> reader;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".off")
  {
    auto off = vtkSmartPointer<vtkOFFMeshReader>::New();
    off->SetFileName(path.c_str());
    reader = off;
  }
  else
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }

  // 2. The filter: a triangle count as target, the deviation array on (off by default in C++).
  vtkNew<vtkVolumeTriangleCollapse> simplify;
  simplify->SetInputConnection(reader->GetOutputPort());
  simplify->SetTargetModeToTriangleCount();
  simplify->SetTargetTriangleCount(argc > 3 ? std::atoll(argv[3]) : 1000);
  simplify->ComputeDeviationOn();

  // 3. Written where asked; a reader's or the filter's error shows as VTK's error and the
  //    writer's return value.
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(simplify->GetOutputPort());
  writer->SetFileName(argv[2]);
  if (!writer->Write())
  {
    return EXIT_FAILURE;
  }
  vtkPolyData* output = simplify->GetOutput();
  vtkDataArray* hausdorff = output->GetFieldData()->GetArray("DeviationMaximum");
  std::cout << output->GetNumberOfCells() << " triangles written to " << argv[2];
  if (hausdorff)
  {
    std::cout << "; two-sided deviation " << hausdorff->GetTuple1(0) << " (input units)";
  }
  std::cout << "\n";
  return EXIT_SUCCESS;
}
