// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParallelDecimation.h"

#include "ParallelDecimation.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkParallelDecimation);

vtkParallelDecimation::vtkParallelDecimation()
{
  this->TargetTolerance = meshsimp::ParallelDecimationOptions().Goal.Tolerance;
}

bool vtkParallelDecimation::RunCore(const meshsimp::TriangleMeshView& mesh,
  const meshsimp::SimplificationOptions& common, const meshsimp::ExecutionContext& context,
  meshsimp::SimplifiedMesh& result)
{
  meshsimp::ParallelDecimationOptions options;
  static_cast<meshsimp::SimplificationOptions&>(options) = common;
  options.FeatureAngle = this->FeatureAngle;
  options.BoundaryCornerAngle = this->BoundaryCornerAngle;
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
  meshsimp::ParallelDecimationResult decimated;
  const bool finished = meshsimp::ParallelDecimation(mesh, options, decimated, context);
  result = std::move(static_cast<meshsimp::SimplifiedMesh&>(decimated));
  return finished;
}

void vtkParallelDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "BoundaryCornerAngle: " << this->BoundaryCornerAngle << "\n";
  os << indent << "ImportanceMeasure: " << this->ImportanceMeasure << "\n";
  os << indent << "AccumulateError: " << this->AccumulateError << "\n";
  os << indent << "MoveSurvivors: " << this->MoveSurvivors << "\n";
  os << indent << "HalfEdgeChoice: " << this->HalfEdgeChoice << "\n";
  os << indent << "MaximumNormalDeviation: " << this->MaximumNormalDeviation << "\n";
  os << indent << "BucketImportance: " << this->BucketImportance << "\n";
  os << indent << "BucketShare: " << this->BucketShare << "\n";
  os << indent << "RoundFraction: " << this->RoundFraction << "\n";
}
