// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOFFWriter.h"

#include "OFFFile.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkOFFWriter);

namespace
{
/// The point each point is written as: the first at the same coordinates (bit for bit, so
/// that NaN and -0 compare as they print), in the input's order; with merge off, itself. The
/// points written are those that are their own, in order.
std::vector<vtkIdType> FirstAtSamePlace(const std::vector<double>& points, bool merge)
{
  const vtkIdType n = static_cast<vtkIdType>(points.size() / 3);
  std::vector<vtkIdType> first(n);
  std::iota(first.begin(), first.end(), vtkIdType(0));
  if (!merge)
  {
    return first;
  }
  const auto bytes = [&points](vtkIdType i) { return points.data() + 3 * i; };
  std::vector<vtkIdType> order = first;
  std::sort(order.begin(), order.end(), [&](vtkIdType a, vtkIdType b) {
    const int byCoordinates = std::memcmp(bytes(a), bytes(b), 3 * sizeof(double));
    return byCoordinates != 0 ? byCoordinates < 0 : a < b;
  });
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    if (std::memcmp(bytes(order[k]), bytes(order[k - 1]), 3 * sizeof(double)) == 0)
    {
      first[order[k]] = first[order[k - 1]];
    }
  }
  return first;
}

/// The points and polygons of mesh in the core's form, coincident points merged or not.
meshsimp::PolygonMesh ToPolygonMesh(vtkPolyData* mesh, bool merge)
{
  std::vector<double> points(3 * mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, points.data() + 3 * i);
  }
  const std::vector<vtkIdType> first = FirstAtSamePlace(points, merge);
  std::vector<std::int64_t> written(first.size(), -1);
  meshsimp::PolygonMesh off;
  for (std::size_t i = 0; i < first.size(); ++i)
  {
    if (first[i] == static_cast<vtkIdType>(i))
    {
      written[i] = static_cast<std::int64_t>(off.Points.size() / 3);
      off.Points.insert(off.Points.end(), points.begin() + 3 * i, points.begin() + 3 * i + 3);
    }
  }
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      off.FaceIds.push_back(written[first[ids[k]]]);
    }
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
  if (!meshsimp::WriteOFF(this->FileName, ToPolygonMesh(input, this->MergeCoincidentPoints), error))
  {
    vtkErrorMacro(<< error);
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  }
}

void vtkOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MergeCoincidentPoints: " << this->MergeCoincidentPoints << "\n";
}
