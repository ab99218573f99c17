// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MeshFiles.h
 * @brief meshsimplify's mesh files: reading and writing by extension (.ply .stl .obj .vtp .vtk
 * .off), with every input checked before a reader sees it.
 *
 * A damaged file must give one line that says why, never a crash, a hang or pages of VTK
 * messages. So a file is read in steps, each of which may refuse it with its reason:
 *   1. the common checks, in order: it exists, is a regular file, opens, is not empty;
 *   2. its format's check (MeshFileChecks.h), which walks whatever the VTK 9.2 reader would
 *      trust blindly (counts it allocates by, indices it follows);
 *   3. the reader, whose warnings and errors are collected instead of printed; either fails the
 *      read, the first being the reason (VTK's readers report short reads, and faces they
 *      skip, as warnings);
 *   4. the cells the reader made: offsets in order, every point id naming a point (the filters
 *      trust them as VTK's filters do).
 * Writing collects the writer's messages the same way.
 */
#ifndef MeshSimplification_MeshFiles_h
#define MeshSimplification_MeshFiles_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkPolyData;

namespace meshfiles
{

/// The mesh in path, read by the reader of its extension; nullptr with
/// "cannot read 'path': <reason>" in error when any step refuses the file.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error);

/// Writes mesh to path in the format of its extension (PLY and STL binary, VTP with inline
/// binary data, OFF through vtkOFFWriter); false with "cannot write 'path': <reason>" in error.
/// The file is whole or not there: written beside path and renamed over it (WholeFile.h), so a
/// full disk leaves no partial file and an existing file untouched.
bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error);

/// A mesh with texture coordinates and its texture: .obj with its .mtl and the texture as a .png
/// of the same stem (the .mtl names it relatively); .gltf and .glb with the texture embedded;
/// any other format as WriteMesh writes it, with the texture's .png next to it.
bool WriteTexturedMesh(vtkPolyData* mesh, vtkImageData* texture, const std::string& path, std::string& error);

} // namespace meshfiles

#endif
