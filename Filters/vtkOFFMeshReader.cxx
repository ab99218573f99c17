// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOFFMeshReader.h"

#include "OFFFile.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <fstream>

vtkStandardNewMacro(vtkOFFMeshReader);

vtkOFFMeshReader::vtkOFFMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

int vtkOFFMeshReader::CanReadFile(const char* fileName)
{
  std::ifstream in(fileName ? fileName : "");
  std::string keyword;
  return (in >> keyword) && keyword == "OFF" ? 1 : 0;
}

int vtkOFFMeshReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  meshsimp::PolygonMesh mesh;
  std::string error;
  if (!meshsimp::ReadOFF(this->FileName, mesh, error))
  {
    vtkErrorMacro(<< error);
    return 1; // the error is said; 0 would add the executive's dump of the request
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(mesh.Points.size() / 3);
  points->SetNumberOfPoints(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    points->SetPoint(i, mesh.Points.data() + 3 * i);
  }
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(mesh.FaceOffsets.size()));
  for (std::size_t i = 0; i < mesh.FaceOffsets.size(); ++i)
  {
    offsets->SetValue(static_cast<vtkIdType>(i), mesh.FaceOffsets[i]);
  }
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(mesh.FaceIds.size()));
  for (std::size_t i = 0; i < mesh.FaceIds.size(); ++i)
  {
    connectivity->SetValue(static_cast<vtkIdType>(i), mesh.FaceIds[i]);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  if (!mesh.Colours.empty())
  {
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetName("RGBA");
    colours->SetNumberOfComponents(4);
    colours->SetNumberOfTuples(numberOfPoints);
    std::copy(mesh.Colours.begin(), mesh.Colours.end(), colours->GetPointer(0));
    output->GetPointData()->SetScalars(colours);
  }
  return 1;
}

void vtkOFFMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
