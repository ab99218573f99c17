// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParallelDecimation.h"

#include "ParallelDecimation.h"
#include "vtkMeshSimplificationHelpers.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkParallelDecimation);

vtkParallelDecimation::vtkParallelDecimation() = default;

int vtkParallelDecimation::SimplifyPiece(
  vtkPolyData* inputPiece, vtkPolyData* output, std::vector<std::uint8_t>& locked)
{
  vtkSmartPointer<vtkPolyData> input = inputPiece; // PrepareTriangles may replace it
  this->Rounds = 0;
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

  meshsimp::ParallelDecimationOptions options;
  const std::int64_t inputTriangles = triangles.View.NumberOfTriangles;
  const bool bounded = this->TargetMode == TARGET_MAXIMUM_ERROR;
  options.TargetTriangles = bounded ? 0
    : this->TargetMode == TARGET_TRIANGLE_COUNT
    ? static_cast<std::int64_t>(this->TargetTriangleCount)
    : static_cast<std::int64_t>(std::llround(inputTriangles * (1.0 - this->TargetReduction)));
  options.MaximumError = bounded ? this->MaximumError : -1.0;
  options.RelativeError = this->RelativeError;
  options.FeatureAngle = this->FeatureAngle;
  options.BoundaryCornerAngle = this->BoundaryCornerAngle;
  options.PreserveBoundary = this->PreserveBoundary;
  options.Measure = this->ImportanceMeasure == QUADRIC ? meshsimp::ImportanceMeasure::Quadric
                                                       : meshsimp::ImportanceMeasure::AveragePlane;
  options.AccumulateError = this->AccumulateError;
  options.MoveSurvivors = this->MoveSurvivors;
  options.Choice = this->HalfEdgeChoice == SHORTEST_EDGE ? meshsimp::HalfEdgeChoice::ShortestEdge
                                                         : meshsimp::HalfEdgeChoice::LeastAreaChange;
  options.MaximumNormalDeviation = this->MaximumNormalDeviation;
  options.BucketImportance = this->BucketImportance;
  options.BucketShare = this->BucketShare;
  options.RoundFraction = this->RoundFraction;
  vtkMeshSimplificationHelpers::ReadLockedPoints(this, input, locked);
  if (!locked.empty())
  {
    options.LockedPoints = locked.data();
  }

  meshsimp::ParallelDecimationResult result;
  const bool finished = meshsimp::ParallelDecimation(triangles.View, options, result,
    vtkMeshSimplificationHelpers::MakeExecutionContext(this, this->NumberOfThreads));
  if (!vtkMeshSimplificationHelpers::ReportRun(this, finished, result.NonFinitePoints))
  {
    return 1;
  }
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(result.PointSource.size());
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(result.TriangleSource.size());
  if (result.StoppedEarly && !bounded) // with a bound, stopping is how it ends
  {
    vtkWarningMacro(<< "Stopped at " << numberOfTriangles << " triangles ("
                    << result.TargetTriangles
                    << " asked for): no vertex is left that can be removed."
                    << vtkMeshSimplificationHelpers::LockedPointsNote(locked, true));
  }
  else if (result.Relaxations > 0)
  {
    vtkWarningMacro(<< "To reach " << result.TargetTriangles
                    << " triangles, FeatureAngle and MaximumNormalDeviation were raised by "
                    << 15 * result.Relaxations << " degrees.");
  }

  vtkMeshSimplificationHelpers::SetOutputTriangles(input, output, triangles, result.Points,
    result.Triangles, result.TriangleSource, this->OutputPointsPrecision);

  // Survivors keep their own point data.
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  vtkMeshSimplificationHelpers::CopySurvivorPointData(inPD, outPD, result.PointSource);
  if (vtkDataArray* normals = outPD->GetNormals())
  {
    vtkMeshSimplificationHelpers::ComputePointNormals(result.Points, result.Triangles, normals);
  }
  vtkNew<vtkDoubleArray> importance;
  importance->SetName("Importance");
  importance->SetNumberOfValues(numberOfPoints);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetName("VertexType");
  types->SetNumberOfValues(numberOfPoints);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    importance->SetValue(p, result.Importance[p]);
    types->SetValue(p, static_cast<unsigned char>(result.Types[p]));
  }
  outPD->AddArray(importance);
  outPD->AddArray(types);

  this->Rounds = static_cast<vtkIdType>(result.Rounds);
  vtkMeshSimplificationHelpers::AddFieldValue(output, "Rounds", static_cast<double>(result.Rounds));
  vtkMeshSimplificationHelpers::AddFieldValue(output, "MovedPoints", static_cast<double>(result.MovedPoints));
  if (bounded)
  {
    this->AchievedMaximumError = result.AchievedMaximumError;
    vtkMeshSimplificationHelpers::AddFieldValue(output, "MaximumPlaneDistance", result.AchievedMaximumError);
    vtkMeshSimplificationHelpers::AddPointValues(output, "PlaneDistance", result.PlaneDistance);
  }
  return 1;
}

void vtkParallelDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetMode: " << this->TargetMode << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetTriangleCount: " << this->TargetTriangleCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RelativeError: " << this->RelativeError << "\n";
  os << indent << "AchievedMaximumError: " << this->AchievedMaximumError << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "PreserveBoundary: " << this->PreserveBoundary << "\n";
  os << indent << "BoundaryCornerAngle: " << this->BoundaryCornerAngle << "\n";
  os << indent << "ImportanceMeasure: " << this->ImportanceMeasure << "\n";
  os << indent << "AccumulateError: " << this->AccumulateError << "\n";
  os << indent << "MoveSurvivors: " << this->MoveSurvivors << "\n";
  os << indent << "HalfEdgeChoice: " << this->HalfEdgeChoice << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "BucketImportance: " << this->BucketImportance << "\n";
  os << indent << "BucketShare: " << this->BucketShare << "\n";
  os << indent << "RoundFraction: " << this->RoundFraction << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "Rounds: " << this->Rounds << "\n";
}
