// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target over meshsimplify's file reading (MeshFiles.h: the checks, then VTK's readers):
// the input's first byte picks the format (.off .ply .stl .obj .vtp .vtk), the rest is the
// file. Reading must give a mesh whose cells name its points, or a one-line reason; never a
// crash, a sanitizer finding or pages of messages. A VTK reader runs in a child process, where
// a crash or a time-out becomes a reason: those reasons fail here too, since the checks should
// have refused the file with its own reason first. Built with libFuzzer (clang
// -fsanitize=fuzzer) or with FuzzDriver.cxx's plain main; its seeds are files of every format
// with the format byte in front (Testing/Data/Fuzz/files).
#include "MeshFiles.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
const char* const Extensions[] = { "off", "ply", "stl", "obj", "vtp", "vtk" };

/// A file of this process's own in the temporary directory, named like the format.
std::string InputPath(const char* extension)
{
  const char* temporary = std::getenv("TMPDIR");
  return std::string(temporary && *temporary ? temporary : "/tmp") + "/FuzzMeshFiles-" +
    std::to_string(getpid()) + "." + extension;
}

void Require(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::fprintf(stderr, "FuzzMeshFiles: %s\n", what.c_str());
    std::abort();
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const std::string path = InputPath(Extensions[data[0] % 6]);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data + 1),
    static_cast<std::streamsize>(size - 1));
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = meshfiles::ReadMesh(path, error);
  std::remove(path.c_str());
  Require(mesh || (!error.empty() && error.find('\n') == std::string::npos),
    "a failed read without a one-line reason: " + error);
  Require(error.find("the VTK reader crashed") == std::string::npos &&
      error.find("reading took longer") == std::string::npos,
    "a file that passed the checks stopped the reader: " + error);
  for (vtkCellArray* cells : { mesh ? mesh->GetPolys() : nullptr, mesh ? mesh->GetStrips() : nullptr })
  {
    const vtkIdType points = mesh ? mesh->GetNumberOfPoints() : 0;
    for (vtkIdType k = 0; cells && k < cells->GetNumberOfConnectivityIds(); ++k)
    {
      const vtkIdType id = cells->GetConnectivityArray()->GetComponent(k, 0);
      Require(id >= 0 && id < points, "a cell names no point");
    }
  }
  return 0;
}
