// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOFFWriter.h"

#include "OFFFile.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkOFFWriter);

namespace
{
/// The points and polygons of mesh in the core's form.
meshsimp::PolygonMesh ToPolygonMesh(vtkPolyData* mesh)
{
  meshsimp::PolygonMesh off;
  off.Points.resize(3 * mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, off.Points.data() + 3 * i);
  }
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    off.FaceIds.insert(off.FaceIds.end(), ids, ids + size);
    off.FaceOffsets.push_back(static_cast<std::int64_t>(off.FaceIds.size()));
  }
  return off;
}
}

vtkPolyData* vtkOFFWriter::GetInput()
{
  return vtkPolyData::SafeDownCast(this->Superclass::GetInput());
}

int vtkOFFWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkOFFWriter::WriteData()
{
  vtkPolyData* input = this->GetInput();
  if (this->FileName.empty())
  {
    vtkErrorMacro(<< "No FileName to write to.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  const vtkIdType leftOut =
    input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfStrips();
  if (leftOut > 0)
  {
    vtkWarningMacro(<< "Leaving out " << leftOut
                    << " vertex, line and strip cells: OFF holds polygons only.");
  }
  std::string error;
  if (!meshsimp::WriteOFF(this->FileName, ToPolygonMesh(input), error))
  {
    vtkErrorMacro(<< error);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
