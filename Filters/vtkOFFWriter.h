// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOFFWriter
 * @brief   write the polygons of a vtkPolyData as an ASCII Object File Format (.off) mesh
 *
 * The counterpart of vtkOFFMeshReader, so that ParaView and meshsimplify can save what they read:
 * writes the points and the polygons (triangles and larger faces) through the core's
 * meshsimp::WriteOFF, coordinates with 17 significant digits so that reading the file back
 * gives the same doubles. OFF holds faces only: vertex, line and strip cells are left out with
 * a warning, and point and cell data are not written. With MergeCoincidentPoints, points at
 * exactly the same coordinates are written once: under MPI, ParaView gathers the pieces of a
 * distributed mesh to write them, and each piece brings its own copy of the points on its
 * seams (1 016 points for the cow's 1 588 triangles in two pieces, 784 in one).
 *
 * A file that cannot be written gives one error, an error code, and Write() returns 0.
 *
 * @sa vtkOFFMeshReader
 */
#ifndef vtkOFFWriter_h
#define vtkOFFWriter_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkWriter.h"

#include <string>

class vtkPolyData;

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkOFFWriter : public vtkWriter
{
public:
  static vtkOFFWriter* New();
  vtkTypeMacro(vtkOFFWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to write.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Whether points at exactly the same coordinates (bit for bit) are written as one point, the
   * first in the input's order, with every polygon using it (default off: a mesh may hold such
   * points on purpose, as the cow does, and a file of it keeps them). On for the gathered pieces
   * of a distributed mesh, whose seams each piece repeats; OFF carries no point data, so
   * nothing written tells merged points apart.
   */
  vtkSetMacro(MergeCoincidentPoints, bool);
  vtkGetMacro(MergeCoincidentPoints, bool);
  vtkBooleanMacro(MergeCoincidentPoints, bool);
  ///@}

  /**
   * The polygonal input.
   */
  vtkPolyData* GetInput();

protected:
  vtkOFFWriter() = default;
  ~vtkOFFWriter() override = default;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  std::string FileName;
  bool MergeCoincidentPoints = false;

private:
  vtkOFFWriter(const vtkOFFWriter&) = delete;
  void operator=(const vtkOFFWriter&) = delete;
};

#endif
