// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOFFWriter
 * @brief   write the polygons of a vtkPolyData as an ASCII Object File Format (.off) mesh
 *
 * The counterpart of vtkOFFReader, so that ParaView and meshsimplify can save what they read:
 * writes the points and the polygons (triangles and larger faces) through the core's
 * meshsimp::WriteOFF, coordinates with 17 significant digits so that reading the file back
 * gives the same doubles. OFF holds faces only: vertex, line and strip cells are left out with
 * a warning, and point and cell data are not written.
 *
 * A file that cannot be written gives one error, an error code, and Write() returns 0.
 *
 * @sa vtkOFFReader
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

private:
  vtkOFFWriter(const vtkOFFWriter&) = delete;
  void operator=(const vtkOFFWriter&) = delete;
};

#endif
