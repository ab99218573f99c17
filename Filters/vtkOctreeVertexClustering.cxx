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
  meshsimp::OctreeClusteringOptions options;
  static_cast<meshsimp::SimplificationOptions&>(options) = common;
  options.MaximumCellSize = this->MaximumCellSize;
  options.MaximumVerticesPerCell = this->MaximumVerticesPerCell;
  options.ErrorIterations = this->ErrorIterations;
  options.BoundaryPlanes = this->BoundaryPlanes;
  options.BoundaryWeight = this->BoundaryWeight;
  options.PreventFlips = this->PreventFlips;
  meshsimp::OctreeClusteringResult clustered;
  const bool finished = meshsimp::OctreeVertexClustering(mesh, options, clustered, context);
  result = std::move(static_cast<meshsimp::SimplifiedMesh&>(clustered));
  return finished;
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
