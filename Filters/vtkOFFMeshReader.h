// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOFFMeshReader
 * @brief   read an ASCII Object File Format (.off) mesh into vtkPolyData
 *
 * OFF files (Geomview, CGAL, many mesh repositories) hold points and polygons of any size.
 * The plain "OFF" variant is read (columns after the coordinates ignored), and "COFF", whose
 * per-point colours become the unsigned-char point scalars "RGBA" (as vtkPLYReader names
 * them). A file that cannot be read gives one error line and an empty output.
 */
#ifndef vtkOFFMeshReader_h
#define vtkOFFMeshReader_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string>

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkOFFMeshReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFMeshReader* New();
  vtkTypeMacro(vtkOFFMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /**
   * True when the file's first keyword is OFF (used by ParaView to pick readers).
   */
  static int CanReadFile(const char* fileName);

protected:
  vtkOFFMeshReader();
  ~vtkOFFMeshReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkOFFMeshReader(const vtkOFFMeshReader&) = delete;
  void operator=(const vtkOFFMeshReader&) = delete;
};

#endif
