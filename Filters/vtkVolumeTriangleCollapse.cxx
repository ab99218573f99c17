// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVolumeTriangleCollapse.h"

#include "VolumeTriangleCollapse.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkVolumeTriangleCollapse);

vtkVolumeTriangleCollapse::vtkVolumeTriangleCollapse()
{
  this->TargetTolerance = meshsimp::VolumeCollapseOptions().Goal.Tolerance;
}

bool vtkVolumeTriangleCollapse::RunCore(const meshsimp::TriangleMeshView& mesh,
  const meshsimp::SimplificationOptions& common, const meshsimp::ExecutionContext& context,
  meshsimp::SimplifiedMesh& result)
{
  const meshsimp::VolumeCollapseParameters& own = *this;
  return RunWith(meshsimp::VolumeTriangleCollapse, own, mesh, common, context, result);
}

void vtkVolumeTriangleCollapse::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FeatureCurvature: " << this->FeatureCurvature << "\n";
  os << indent << "BoundaryCornerAngle: " << this->BoundaryCornerAngle << "\n";
  os << indent << "UseNormalFactor: " << this->UseNormalFactor << "\n";
  os << indent << "UseShapeFactor: " << this->UseShapeFactor << "\n";
  os << indent << "UseVolumeWeights: " << this->UseVolumeWeights << "\n";
  os << indent << "EdgeCollapses: " << this->EdgeCollapses << "\n";
  os << indent << "SurfaceErrorWeight: " << this->SurfaceErrorWeight << "\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "BatchSize: " << this->BatchSize << "\n";
}
