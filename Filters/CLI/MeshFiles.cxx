// SPDX-License-Identifier: BSD-3-Clause
#include "MeshFiles.h"

#include "vtkOFFReader.h"
#include "vtkOFFWriter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOBJWriter.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

namespace meshfiles
{
namespace
{
const char* Extensions = "(.off .ply .stl .obj .vtp .vtk)";

std::string Extension(const std::string& path)
{
  const std::size_t dot = path.rfind('.');
  std::string extension = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), ::tolower);
  return extension;
}

/// VTK's reader of the extension, or nullptr.
vtkSmartPointer<vtkAlgorithm> NewReader(const std::string& extension, const std::string& path)
{
  if (extension == "off")
  {
    auto off = vtkSmartPointer<vtkOFFReader>::New();
    off->SetFileName(path.c_str());
    return off;
  }
  if (extension == "ply")
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(path.c_str());
    return ply;
  }
  if (extension == "stl")
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(path.c_str());
    return stl;
  }
  if (extension == "obj")
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(path.c_str());
    return obj;
  }
  if (extension == "vtp")
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    vtp->SetFileName(path.c_str());
    return vtp;
  }
  if (extension == "vtk")
  {
    auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(path.c_str());
    return legacy;
  }
  return nullptr;
}
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error)
{
  vtkSmartPointer<vtkAlgorithm> reader = NewReader(Extension(path), path);
  if (!reader)
  {
    error = "cannot read '" + path + "': unknown extension " + Extensions;
    return nullptr;
  }
  if (FILE* probe = std::fopen(path.c_str(), "rb"))
  {
    std::fclose(probe);
  }
  else
  {
    error = "cannot open '" + path + "'";
    return nullptr;
  }
  // Readers report a bad file through error events, not always through their error code.
  bool failed = false;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&failed);
  onError->SetCallback([](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->Update();
  vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (failed || reader->GetErrorCode() != 0 || !output)
  {
    error = "cannot read '" + path + "'";
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(output);
  return copy;
}

bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error)
{
  const std::string extension = Extension(path);
  int ok = 1;
  if (extension == "off")
  {
    vtkNew<vtkOFFWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    ok = writer->Write();
  }
  else if (extension == "ply")
  {
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    writer->SetFileTypeToBinary();
    ok = writer->Write();
  }
  else if (extension == "stl")
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    writer->SetFileTypeToBinary();
    ok = writer->Write();
  }
  else if (extension == "obj")
  {
    vtkNew<vtkOBJWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    ok = writer->Write();
  }
  else if (extension == "vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    // Inline binary: VTK 9.2's reader rejects some appended base64 files its writer makes.
    writer->SetDataModeToBinary();
    ok = writer->Write();
  }
  else if (extension == "vtk")
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    ok = writer->Write();
  }
  else
  {
    error = "cannot write '" + path + "': unknown extension " + Extensions;
    return false;
  }
  if (!ok)
  {
    error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}

} // namespace meshfiles
