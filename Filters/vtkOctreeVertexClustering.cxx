// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeVertexClustering.h"

#include "OctreeVertexClustering.h"
#include "vtkMeshSimplificationHelpers.h"

#include "vtkArrayListTemplate.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>

vtkStandardNewMacro(vtkOctreeVertexClustering);

vtkOctreeVertexClustering::vtkOctreeVertexClustering() = default;

int vtkOctreeVertexClustering::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->AchievedMaximumError = 0.0;

  vtkMeshSimplificationHelpers::TriangleInput triangles;
  std::string problem;
  if (!vtkMeshSimplificationHelpers::ExtractTriangles(input, triangles, problem))
  {
    vtkErrorMacro(<< "Cannot simplify: " << problem << ".");
    return 0;
  }
  if (triangles.NumberOfVerts + triangles.NumberOfLines > 0)
  {
    vtkWarningMacro(<< "Dropping " << triangles.NumberOfVerts << " vertex and "
                    << triangles.NumberOfLines
                    << " line cells: only triangles, polygons and strips are simplified.");
  }
  if (triangles.View.NumberOfTriangles == 0)
  {
    vtkDebugMacro(<< "No triangles to simplify.");
    return 1;
  }

  meshsimp::OctreeClusteringOptions options;
  const std::int64_t inputTriangles = triangles.View.NumberOfTriangles;
  switch (this->TargetMode)
  {
    case TARGET_REDUCTION:
      options.TargetTriangles =
        static_cast<std::int64_t>(std::llround(inputTriangles * (1.0 - this->TargetReduction)));
      break;
    case TARGET_TRIANGLE_COUNT:
      options.TargetTriangles = this->TargetTriangleCount;
      break;
    default:
      options.TargetTriangles = -1;
      options.MaximumError = this->MaximumError;
      options.RelativeError = this->RelativeError;
      break;
  }
  options.MaximumCellSize = this->MaximumCellSize;
  options.MaximumVerticesPerCell = this->MaximumVerticesPerCell;
  options.ErrorIterations = this->ErrorIterations;
  options.BoundaryPlanes = this->BoundaryPlanes;
  options.BoundaryWeight = this->BoundaryWeight;
  options.PreventFlips = this->PreventFlips;

  meshsimp::OctreeClusteringResult result;
  const bool finished = meshsimp::OctreeVertexClustering(triangles.View, options, result,
    vtkMeshSimplificationHelpers::MakeExecutionContext(this, this->NumberOfThreads));
  if (result.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< "Ignoring the triangles of " << result.NonFinitePoints
                    << " points with NaN or infinite coordinates.");
  }
  if (!finished)
  {
    vtkWarningMacro(<< "Aborted: the output is empty.");
    return 1;
  }
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(result.ClusterErrors.size());
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(result.SourceTriangles.size());
  if (options.TargetTriangles >= 0 && numberOfTriangles < options.TargetTriangles &&
    static_cast<std::int64_t>(numberOfTriangles) < result.UsableInputTriangles &&
    numberOfTriangles < 0.97 * options.TargetTriangles)
  {
    vtkWarningMacro(<< "Reached " << numberOfTriangles << " of the " << options.TargetTriangles
                    << " triangles asked for: the input has too few distinct points.");
  }

  output->SetPoints(vtkMeshSimplificationHelpers::MakePoints(
    result.Points, this->OutputPointsPrecision, input->GetPoints()));
  output->SetPolys(vtkMeshSimplificationHelpers::MakeTriangles(result.Triangles));

  // Point data: the area-weighted average of each cluster, for every array.
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->InterpolateAllocate(inPD, numberOfPoints);
  ArrayList arrays;
  arrays.AddArrays(numberOfPoints, inPD, outPD, /*nullValue=*/0.0, /*promote=*/false);
  std::vector<vtkIdType> ids;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    const std::int32_t begin = result.ClusterOffsets[p], end = result.ClusterOffsets[p + 1];
    ids.assign(result.ClusterVertices.begin() + begin, result.ClusterVertices.begin() + end);
    arrays.WeightedAverage(end - begin, ids.data(), result.ClusterWeights.data() + begin, p);
  }
  if (vtkDataArray* normals = outPD->GetNormals())
  {
    vtkMeshSimplificationHelpers::ComputePointNormals(result.Points, result.Triangles, normals);
  }
  vtkNew<vtkIntArray> clusterSize;
  clusterSize->SetName("ClusterSize");
  clusterSize->SetNumberOfValues(numberOfPoints);
  vtkNew<vtkDoubleArray> clusterError;
  clusterError->SetName("ClusterError");
  clusterError->SetNumberOfValues(numberOfPoints);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    clusterSize->SetValue(p, result.ClusterOffsets[p + 1] - result.ClusterOffsets[p]);
    clusterError->SetValue(p, result.ClusterErrors[p]);
  }
  outPD->AddArray(clusterSize);
  outPD->AddArray(clusterError);

  // Cell data: copied from the input cell of each surviving triangle.
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, numberOfTriangles);
  for (vtkIdType i = 0; i < numberOfTriangles; ++i)
  {
    outCD->CopyData(inCD, triangles.SourceCell(result.SourceTriangles[i]), i);
  }
  if (vtkDataArray* normals = outCD->GetNormals())
  {
    vtkMeshSimplificationHelpers::ComputeCellNormals(result.Points, result.Triangles, normals);
  }

  output->GetFieldData()->PassData(input->GetFieldData());
  this->AchievedMaximumError = result.MaximumClusterError;
  vtkNew<vtkDoubleArray> maximumError;
  maximumError->SetName("MaximumClusterError");
  maximumError->InsertNextValue(result.MaximumClusterError);
  output->GetFieldData()->AddArray(maximumError);
  vtkNew<vtkDoubleArray> reduction;
  reduction->SetName("AchievedReduction");
  reduction->InsertNextValue(1.0 - static_cast<double>(numberOfTriangles) / inputTriangles);
  output->GetFieldData()->AddArray(reduction);
  return 1;
}

void vtkOctreeVertexClustering::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetMode: " << this->TargetMode << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetTriangleCount: " << this->TargetTriangleCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RelativeError: " << this->RelativeError << "\n";
  os << indent << "MaximumCellSize: " << this->MaximumCellSize << "\n";
  os << indent << "MaximumVerticesPerCell: " << this->MaximumVerticesPerCell << "\n";
  os << indent << "ErrorIterations: " << this->ErrorIterations << "\n";
  os << indent << "BoundaryPlanes: " << this->BoundaryPlanes << "\n";
  os << indent << "BoundaryWeight: " << this->BoundaryWeight << "\n";
  os << indent << "PreventFlips: " << this->PreventFlips << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "AchievedMaximumError: " << this->AchievedMaximumError << "\n";
}
