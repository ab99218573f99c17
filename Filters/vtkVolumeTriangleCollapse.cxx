// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVolumeTriangleCollapse.h"

#include "VolumeTriangleCollapse.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkVolumeTriangleCollapse);

vtkVolumeTriangleCollapse::vtkVolumeTriangleCollapse()
{
  this->TargetTolerance = meshsimp::VolumeCollapseOptions().Goal.Tolerance;
}

bool vtkVolumeTriangleCollapse::RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result)
{
  const meshsimp::VolumeCollapseParameters& own = *this;
  return RunWith(meshsimp::VolumeTriangleCollapse, own, piece, result);
}

void vtkVolumeTriangleCollapse::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  meshsimp::PrintParameters<meshsimp::VolumeCollapseParameters>(*this, os, indent);
}

void vtkVolumeTriangleCollapse::ForEachOwnSetting(const meshsimp::SettingVisit& visit)
{
  meshsimp::VisitParameters<meshsimp::VolumeCollapseParameters>(*this, visit);
}
