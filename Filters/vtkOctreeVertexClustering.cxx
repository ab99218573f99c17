// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOctreeVertexClustering.h"

#include "OctreeVertexClustering.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkOctreeVertexClustering);

vtkOctreeVertexClustering::vtkOctreeVertexClustering()
{
  this->TargetTolerance = meshsimp::OctreeClusteringOptions().Goal.Tolerance;
}

bool vtkOctreeVertexClustering::RunCore(const meshsimp::TriangleMeshView& mesh,
  const meshsimp::SimplificationOptions& common, const meshsimp::ExecutionContext& context,
  meshsimp::SimplifiedMesh& result)
{
  const meshsimp::OctreeClusteringParameters& own = *this;
  return RunWith(meshsimp::OctreeVertexClustering, own, mesh, common, context, result);
}

void vtkOctreeVertexClustering::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumCellSize: " << this->MaximumCellSize << "\n";
  os << indent << "MaximumVerticesPerCell: " << this->MaximumVerticesPerCell << "\n";
  os << indent << "ErrorIterations: " << this->ErrorIterations << "\n";
  os << indent << "BoundaryPlanes: " << this->BoundaryPlanes << "\n";
  os << indent << "BoundaryWeight: " << this->BoundaryWeight << "\n";
  os << indent << "PreventFlips: " << this->PreventFlips << "\n";
}
