// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshFiles.h
 * @brief meshsimplify's mesh files: reading and writing by extension (.ply .stl .obj .vtp .vtk
 * .off).
 *
 * Every failure comes back as one line in error, for the tool to print and exit on.
 */
#ifndef MeshSimplification_MeshFiles_h
#define MeshSimplification_MeshFiles_h

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;

namespace meshfiles
{

/// The mesh in path, read by the reader of its extension; nullptr with "cannot read 'path'..."
/// in error on failure.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error);

/// Writes mesh to path in the format of its extension (PLY and STL binary, VTP with inline
/// binary data); false with "cannot write 'path'..." in error on failure.
bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error);

} // namespace meshfiles

#endif
