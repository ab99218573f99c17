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
  meshsimp::PrintParameters<meshsimp::VolumeCollapseParameters>(*this, os, indent);
}

meshsimp::SetResult vtkVolumeTriangleCollapse::SetOwnSetting(const std::string& name, double value)
{
  return meshsimp::SetParameterByName<meshsimp::VolumeCollapseParameters>(*this, name, value);
}
