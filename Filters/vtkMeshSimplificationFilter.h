// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMeshSimplificationFilter
 * @brief   the module's filters' common base: polygonal data in, or composite data of it
 *
 * A subclass simplifies one vtkPolyData in SimplifyPiece. This base runs it on a vtkPolyData
 * input, or on every vtkPolyData leaf of a composite input (multiblock, partitioned data) into
 * an output of the same structure. It takes composite inputs itself rather than leaving the
 * leaves to the executive, so that under MPI (a global controller of several processes) the
 * exchange of piece borders is one collective call per execution on every process, whatever
 * leaves a process holds: each piece's border points that lie on another process's piece of
 * the same leaf (same flat index) are locked, so the simplified pieces still fit together.
 * Other leaf types are skipped with a warning; progress runs over the leaves in turn.
 */
#ifndef vtkMeshSimplificationFilter_h
#define vtkMeshSimplificationFilter_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint> // for std::uint8_t
#include <vector>  // for std::vector

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkMeshSimplificationFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMeshSimplificationFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Creates the output's data object: vtkPolyData, or the composite input's type.
  vtkTypeBool ProcessRequest(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

protected:
  vtkMeshSimplificationFilter() = default;
  ~vtkMeshSimplificationFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * Simplifies input into output. pieceLocks flags (meshsimp::SharedPointLock) the input points
   * shared with other processes' pieces, or is empty; the subclass may add its own locks.
   * Returns what RequestData returns (0 after an error).
   */
  virtual int SimplifyPiece(vtkPolyData* input, vtkPolyData* output, std::vector<std::uint8_t>& pieceLocks) = 0;

private:
  vtkMeshSimplificationFilter(const vtkMeshSimplificationFilter&) = delete;
  void operator=(const vtkMeshSimplificationFilter&) = delete;
};

#endif
