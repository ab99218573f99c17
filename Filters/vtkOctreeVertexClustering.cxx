// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeVertexClustering.h"

#include "OctreeVertexClustering.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkOctreeVertexClustering);

vtkOctreeVertexClustering::vtkOctreeVertexClustering()
{
  this->TargetTolerance = meshsimp::OctreeClusteringOptions().Goal.Tolerance;
}

bool vtkOctreeVertexClustering::RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result)
{
  const meshsimp::OctreeClusteringParameters& own = *this;
  return RunWith(meshsimp::OctreeVertexClustering, own, piece, result);
}

void vtkOctreeVertexClustering::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  meshsimp::PrintParameters<meshsimp::OctreeClusteringParameters>(*this, os, indent);
}

void vtkOctreeVertexClustering::ForEachOwnSetting(const meshsimp::SettingVisit& visit)
{
  meshsimp::VisitParameters<meshsimp::OctreeClusteringParameters>(*this, visit);
}
