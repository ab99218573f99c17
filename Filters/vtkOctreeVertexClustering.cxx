// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeVertexClustering.h"

#include "OctreeVertexClustering.h"
#include "vtkMeshSimplificationHelpers.h"

#include "vtkArrayListTemplate.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkOctreeVertexClustering);

vtkOctreeVertexClustering::vtkOctreeVertexClustering() = default;

int vtkOctreeVertexClustering::SimplifyPiece(
  vtkPolyData* inputPiece, vtkPolyData* output, std::vector<std::uint8_t>& locked)
{
  vtkSmartPointer<vtkPolyData> input = inputPiece; // PrepareTriangles may replace it
  this->AchievedMaximumError = 0.0;

  vtkMeshSimplificationHelpers::TriangleInput triangles;
  int requestResult = 1;
  if (!vtkMeshSimplificationHelpers::PrepareTriangles(this, input, triangles, requestResult))
  {
    return requestResult;
  }
  if (!vtkMeshSimplificationHelpers::CheckTarget(this, this->TargetMode, this->TargetReduction, this->MaximumError))
  {
    return 0;
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
  options.LockedPoints = locked.empty() ? nullptr : locked.data();

  meshsimp::OctreeClusteringResult result;
  const bool finished = meshsimp::OctreeVertexClustering(triangles.View, options, result,
    vtkMeshSimplificationHelpers::MakeExecutionContext(this, this->NumberOfThreads));
  if (!vtkMeshSimplificationHelpers::ReportRun(this, finished, result.NonFinitePoints))
  {
    return 1;
  }
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(result.ClusterErrors.size());
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(result.SourceTriangles.size());
  // The core meets a count within 3 %, unless clustering has no count near it or cells that
  // may not merge stand in the way.
  if (options.TargetTriangles >= 0 && numberOfTriangles < 0.97 * options.TargetTriangles &&
    static_cast<std::int64_t>(numberOfTriangles) < result.UsableInputTriangles)
  {
    vtkWarningMacro(<< "Reached " << numberOfTriangles << " of the " << options.TargetTriangles
                    << " triangles asked for: the nearest count vertex clustering gives on this input.");
  }
  else if (options.TargetTriangles >= 0 && numberOfTriangles > 1.03 * options.TargetTriangles)
  {
    std::ostringstream reasons;
    reasons << vtkMeshSimplificationHelpers::LockedPointsNote(locked, false);
    if (this->MaximumCellSize < 1.0)
    {
      reasons << " MaximumCellSize (" << this->MaximumCellSize << ") splits larger cells.";
    }
    if (reasons.tellp() == 0)
    {
      reasons << " the nearest count vertex clustering gives on this input.";
    }
    vtkWarningMacro(<< "Reached " << numberOfTriangles << " triangles, more than the "
                    << options.TargetTriangles << " asked for:" << reasons.str());
  }

  vtkMeshSimplificationHelpers::SetOutputTriangles(input, output, triangles, result.Points,
    result.Triangles, result.SourceTriangles, this->OutputPointsPrecision);

  // Point data: the area-weighted average of each cluster, for every array VTK interpolates
  // (not pedigree or global ids: a representative is a new point); ghost flags are bits, so a
  // representative has those its cluster's points all have.
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->InterpolateAllocate(inPD, numberOfPoints);
  ArrayList arrays;
  vtkUnsignedCharArray* inGhosts = input->GetPointGhostArray();
  vtkUnsignedCharArray* outGhosts =
    vtkUnsignedCharArray::SafeDownCast(outPD->GetArray(vtkDataSetAttributes::GhostArrayName()));
  if (inGhosts && outGhosts)
  {
    arrays.ExcludeArray(outGhosts);
    outGhosts->SetNumberOfValues(numberOfPoints);
  }
  arrays.AddArrays(numberOfPoints, inPD, outPD, /*nullValue=*/0.0, /*promote=*/false);
  std::vector<vtkIdType> ids;
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    const std::int32_t begin = result.ClusterOffsets[p], end = result.ClusterOffsets[p + 1];
    ids.assign(result.ClusterVertices.begin() + begin, result.ClusterVertices.begin() + end);
    arrays.WeightedAverage(end - begin, ids.data(), result.ClusterWeights.data() + begin, p);
    if (inGhosts && outGhosts)
    {
      unsigned char common = 0xff;
      for (const vtkIdType id : ids)
      {
        common &= inGhosts->GetValue(id);
      }
      outGhosts->SetValue(p, ids.empty() ? 0 : common);
    }
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

  this->AchievedMaximumError = result.MaximumClusterError;
  vtkMeshSimplificationHelpers::AddFieldValue(output, "MaximumClusterError", result.MaximumClusterError);
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
