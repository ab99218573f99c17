// SPDX-License-Identifier: BSD-3-Clause
// vtkOFFWriter: vtkOFFMeshReader reads back what it writes (points bit for bit, polygons of any
// size, the cow's counts); vertex and line cells are left out with a warning; a file that
// cannot be written is an error and Write() returns 0. vtkOFFMeshReader: COFF's colours become RGBA
// point scalars (0-255, or 0-1 scaled); a damaged file is one error, without the executive's
// dump of the request that followed it (issue 45).
#include "vtkOFFMeshReader.h"
#include "vtkOFFWriter.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkPointData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include "TestHelpers.h"

#include <cstdlib>
#include <fstream>
#include <string>

namespace
{
/// A triangle, a quad and a pentagon over points whose coordinates need all 17 digits, and a
/// vertex and a line cell.
vtkSmartPointer<vtkPolyData> MixedCells()
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double coordinates[][3] = { { 0.1, 1.0 / 3.0, -2.5e300 }, { 1e-300, 2.0, 3.0 },
    { -0.7, 0.2, 5e-324 }, { 1.0 / 7.0, 4.0, 0.0 }, { 3.0, 3.0, 3.0 }, { 2.0, -1.0, 1e10 } };
  for (const double* p : coordinates)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType triangle[] = { 0, 1, 2 }, quad[] = { 0, 2, 3, 1 }, pentagon[] = { 1, 3, 4, 5, 0 };
  polys->InsertNextCell(3, triangle);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(5, pentagon);
  vtkNew<vtkCellArray> verts;
  const vtkIdType vertex[] = { 4 }, line[] = { 4, 5 };
  verts->InsertNextCell(1, vertex);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(2, line);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  return mesh;
}

vtkSmartPointer<vtkPolyData> ReadOFF(const std::string& path)
{
  vtkNew<vtkOFFMeshReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

void RoundTripIsExact(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> mesh = MixedCells();
  vtkNew<vtkOFFWriter> writer;
  vtkNew<vtkTest::ErrorObserver> observer;
  writer->AddObserver(vtkCommand::WarningEvent, observer);
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  CHECK(writer->Write() == 1);
  CHECK(observer->GetWarning() && !observer->GetError()); // the vertex and the line
  vtkSmartPointer<vtkPolyData> back = ReadOFF(path);
  CHECK(back->GetNumberOfPoints() == mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints() && i < back->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    mesh->GetPoint(i, a);
    back->GetPoint(i, b);
    CHECK(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]);
  }
  CHECK(back->GetNumberOfCells() == 3 && back->GetNumberOfPolys() == 3);
  for (vtkIdType c = 0; c < 3 && c < back->GetNumberOfPolys(); ++c)
  {
    vtkNew<vtkIdList> written, read;
    mesh->GetPolys()->GetCellAtId(c, written);
    back->GetPolys()->GetCellAtId(c, read);
    CHECK(written->GetNumberOfIds() == read->GetNumberOfIds());
    for (vtkIdType k = 0; k < written->GetNumberOfIds() && k < read->GetNumberOfIds(); ++k)
    {
      CHECK(written->GetId(k) == read->GetId(k));
    }
  }
}

void CowKeepsItsCounts(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> cow = ReadOFF(MESHSIMPLIFICATION_TEST_DATA "/cow.off");
  vtkNew<vtkOFFWriter> writer;
  writer->SetInputData(cow);
  writer->SetFileName(path.c_str());
  CHECK(writer->Write() == 1);
  vtkSmartPointer<vtkPolyData> back = ReadOFF(path);
  CHECK(back->GetNumberOfPoints() == 2904 && back->GetNumberOfPolys() == 5804);
}

/// Two triangles of two pieces whose shared edge each brings its own points: merged on request
/// (4 points, the faces sharing two), kept by default (6).
void CoincidentPointsMergeOnRequest(const std::string& path)
{
  const double corners[6][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 1, 1, 0 },
    { 0, 1, 0 } };
  vtkNew<vtkPoints> points;
  for (const double* p : corners)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType first[] = { 0, 1, 2 }, second[] = { 3, 4, 5 };
  polys->InsertNextCell(3, first);
  polys->InsertNextCell(3, second);
  vtkNew<vtkPolyData> pieces;
  pieces->SetPoints(points);
  pieces->SetPolys(polys);
  for (const bool merge : { false, true })
  {
    vtkNew<vtkOFFWriter> writer;
    writer->SetInputData(pieces);
    writer->SetFileName(path.c_str());
    writer->SetMergeCoincidentPoints(merge);
    CHECK(writer->Write() == 1);
    vtkSmartPointer<vtkPolyData> back = ReadOFF(path);
    CHECK(back->GetNumberOfPoints() == (merge ? 4 : 6) && back->GetNumberOfPolys() == 2);
    vtkNew<vtkIdList> a, b;
    back->GetPolys()->GetCellAtId(0, a);
    back->GetPolys()->GetCellAtId(1, b);
    CHECK(!merge || (b->GetId(0) == a->GetId(1) && b->GetId(2) == a->GetId(2)));
  }
}

void UnwritablePathFails()
{
  vtkNew<vtkOFFWriter> writer;
  vtkNew<vtkTest::ErrorObserver> observer;
  writer->AddObserver(vtkCommand::ErrorEvent, observer);
  writer->AddObserver(vtkCommand::WarningEvent, observer);
  writer->SetInputData(MixedCells());
  writer->SetFileName("/nonexistent-directory/mesh.off");
  CHECK(writer->Write() == 0);
  CHECK(observer->GetError() && writer->GetErrorCode() != 0);
  CHECK(observer->GetErrorMessage().find("/nonexistent-directory/mesh.off") != std::string::npos);
}

/// The text written to path.
void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

void ColouredOFFIsRead(const std::string& path)
{
  const std::string faces = "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n";
  WriteText(path, "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 128 0 255\n0 1 0 0 0 255 255\n"
                  "0 0 1 10 20 30 40\n" + faces);
  vtkSmartPointer<vtkPolyData> bytes = ReadOFF(path);
  vtkDataArray* colours = bytes->GetPointData()->GetScalars();
  CHECK(bytes->GetNumberOfPolys() == 4 && colours && colours->GetNumberOfComponents() == 4 &&
    colours->GetDataType() == VTK_UNSIGNED_CHAR && std::string(colours->GetName()) == "RGBA");
  CHECK(colours && colours->GetComponent(1, 1) == 128 && colours->GetComponent(3, 3) == 40);
  WriteText(path, "COFF\n4 4 0\n0 0 0 1 0 0 1\n1 0 0 0 0.5 0 1\n0 1 0 0 0 1 1\n0 0 1 0 0 0 1\n" + faces);
  vtkSmartPointer<vtkPolyData> fractions = ReadOFF(path);
  vtkDataArray* units = fractions->GetPointData()->GetScalars();
  CHECK(units && units->GetComponent(1, 1) == 128 && units->GetComponent(0, 0) == 255);
}

void DamagedOFFIsOneError(const std::string& path)
{
  WriteText(path, "OFF\n4 9 0\n0 0 0\n");
  vtkNew<vtkOFFMeshReader> reader;
  vtkNew<vtkTest::ErrorObserver> observer, executive;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  reader->SetFileName(path.c_str());
  reader->Update();
  CHECK(observer->GetError() && !executive->GetError());
  CHECK(observer->GetErrorMessage().find("bad or missing point 1") != std::string::npos);
  CHECK(reader->GetOutput()->GetNumberOfPoints() == 0);
}
}

int TestOFFWriter(int, char*[])
{
  ColouredOFFIsRead(MESHSIMPLIFICATION_TEST_OUTPUT "/TestOFFReaderColours.off");
  DamagedOFFIsOneError(MESHSIMPLIFICATION_TEST_OUTPUT "/TestOFFReaderDamaged.off");
  RoundTripIsExact(MESHSIMPLIFICATION_TEST_OUTPUT "/TestOFFWriterMixed.off");
  CowKeepsItsCounts(MESHSIMPLIFICATION_TEST_OUTPUT "/TestOFFWriterCow.off");
  CoincidentPointsMergeOnRequest(MESHSIMPLIFICATION_TEST_OUTPUT "/TestOFFWriterPieces.off");
  UnwritablePathFails();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
