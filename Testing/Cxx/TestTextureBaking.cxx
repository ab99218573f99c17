// SPDX-License-Identifier: BSD-3-Clause
// vtkTextureBaking: a sphere coloured by a linear function of position baked onto itself shows
// that function at every triangle's centre through its texture coordinates; onto its
// simplification, the texture is closer to the colours than the simplification's own vertex
// colours; points split only at seams and carry their data, cells carry theirs; a scalar array
// goes through the lookup table, cell colours fill their triangles, a texture image is looked
// up through the original's coordinates; a multiblock bakes one texture for all its blocks and
// keeps them (each with its own arrays), the texture of the one surface they make together; bad
// inputs give one-line errors and the inputs stay as they were. With -V, the Jacksboro terrain
// at 99 % with its baked elevation against its baseline image.
#include "vtkTextureBaking.h"
#include "vtkVolumeTriangleCollapse.h"
#include "vtkOctreeVertexClustering.h"

#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkTexture.h"
#include "vtkAppendFilter.h"
#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPolyDataReader.h"

#include "TestBadInput.h"
#include "TestImageHelpers.h"
#include "TestVTKHelpers.h"

#include <cmath>
#include <cstring>

namespace
{
/// The colour the spheres carry: a linear function of position (the sphere has radius 0.5).
std::array<double, 3> Linear(const double p[3])
{
  return { 127.5 + 250.0 * p[0], 127.5 + 200.0 * p[1] - 50.0 * p[2], 127.5 - 240.0 * p[2] };
}

/// A sphere with unsigned-char "Colors" of Linear, active scalars.
vtkSmartPointer<vtkPolyData> ColouredSphere(int resolution)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colors");
  colours->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
  {
    const std::array<double, 3> c = Linear(sphere->GetPoint(p));
    colours->InsertNextTuple3(std::round(c[0]), std::round(c[1]), std::round(c[2]));
  }
  sphere->GetPointData()->SetScalars(colours);
  return sphere;
}

vtkSmartPointer<vtkTextureBaking> Bake(vtkDataSet* simplified, vtkDataSet* original, int size = 1024)
{
  auto bake = vtkSmartPointer<vtkTextureBaking>::New();
  bake->SetInputData(0, simplified);
  bake->SetOriginalData(original);
  bake->SetTextureSize(size);
  bake->Update();
  return bake;
}

/// The texture's colour (bilinear) at a point of an output triangle, by its texture coordinates.
std::array<double, 3> Sampled(vtkPolyData* out, vtkImageData* texture, vtkIdType triangle, const double weights[3])
{
  const vtkIdType* ids;
  vtkIdType n;
  out->GetPolys()->GetCellAtId(triangle, n, ids);
  double uv[2] = { 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    const double* t = out->GetPointData()->GetTCoords()->GetTuple2(ids[k]);
    uv[0] += weights[k] * t[0];
    uv[1] += weights[k] * t[1];
  }
  const int size = texture->GetDimensions()[0];
  const double x = uv[0] * size - 0.5, y = uv[1] * size - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  std::array<double, 3> colour = { 0.0, 0.0, 0.0 };
  for (int dy = 0; dy < 2; ++dy)
  {
    for (int dx = 0; dx < 2; ++dx)
    {
      const double w = (dx ? x - x0 : 1 - (x - x0)) * (dy ? y - y0 : 1 - (y - y0));
      for (int c = 0; c < 3; ++c)
      {
        colour[c] += w * texture->GetScalarComponentAsDouble(x0 + dx, y0 + dy, 0, c);
      }
    }
  }
  return colour;
}

/// The point of an output triangle at weights.
std::array<double, 3> At(vtkPolyData* out, vtkIdType triangle, const double weights[3])
{
  const vtkIdType* ids;
  vtkIdType n;
  out->GetPolys()->GetCellAtId(triangle, n, ids);
  std::array<double, 3> p = { 0.0, 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      p[c] += weights[k] * out->GetPoint(ids[k])[c];
    }
  }
  return p;
}

/// The largest and the mean colour difference between the texture and Linear over a few points
/// of every output triangle.
std::pair<double, double> TextureError(vtkPolyData* out, vtkImageData* texture)
{
  const double places[4][3] = { { 1 / 3.0, 1 / 3.0, 1 / 3.0 }, { 0.6, 0.2, 0.2 }, { 0.2, 0.6, 0.2 }, { 0.2, 0.2, 0.6 } };
  double largest = 0.0, sum = 0.0;
  int count = 0;
  for (vtkIdType t = 0; t < out->GetNumberOfPolys(); ++t)
  {
    for (const double* w : places)
    {
      const std::array<double, 3> p = At(out, t, w), expected = Linear(p.data()), got = Sampled(out, texture, t, w);
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest, std::abs(expected[c] - got[c]));
        sum += std::abs(expected[c] - got[c]);
        ++count;
      }
    }
  }
  return { largest, sum / std::max(1, count) };
}

void TestSelfBake()
{
  // Baked onto itself, every texel is the colour at its own point: the texture shows the linear
  // colours within rounding at any point of any triangle.
  const vtkSmartPointer<vtkPolyData> sphere = ColouredSphere(30);
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(sphere);
  vtkNew<vtkIntArray> cellIds;
  cellIds->SetName("CellLabel");
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    cellIds->InsertNextValue(static_cast<int>(7 * c));
  }
  sphere->GetCellData()->AddArray(cellIds);
  const vtkSmartPointer<vtkTextureBaking> bake = Bake(sphere, sphere);
  vtkPolyData* out = bake->GetOutput();
  CHECK(out->GetNumberOfPolys() == sphere->GetNumberOfPolys());
  CHECK(bake->GetTexture()->GetDimensions()[0] == 1024 && bake->GetTexture()->GetDimensions()[1] == 1024);
  vtkDataArray* texels = bake->GetTexture()->GetPointData()->GetScalars();
  CHECK(texels && std::strcmp(texels->GetName(), "BakedTexture") == 0 && texels->GetNumberOfComponents() == 3);
  const std::pair<double, double> error = TextureError(bake->GetOutput(), bake->GetTexture());
  CHECK(error.first < 1.5 && error.second < 0.6); // rounding to 0..255, and bilinear filtering
  // Points split only at seams: more than the sphere's, and fewer than three per triangle (a
  // pair of triangles shares the two points of its diagonal); each
  // copy carries its point's coordinates and colour; cells carry theirs.
  CHECK(out->GetNumberOfPoints() > sphere->GetNumberOfPoints() && out->GetNumberOfPoints() < 3 * sphere->GetNumberOfPolys());
  vtkDataArray* colours = out->GetPointData()->GetArray("Colors");
  CHECK(colours && out->GetPointData()->GetTCoords());
  for (vtkIdType p = 0; colours && p < out->GetNumberOfPoints(); p += 17)
  {
    const std::array<double, 3> c = Linear(out->GetPoint(p));
    CHECK(std::abs(colours->GetComponent(p, 0) - std::round(c[0])) < 1.01);
  }
  vtkDataArray* labels = out->GetCellData()->GetArray("CellLabel");
  CHECK(labels && labels->GetNumberOfTuples() == out->GetNumberOfPolys());
  const vtkIdType firstTriangle = sphere->GetNumberOfCells() - sphere->GetNumberOfPolys();
  CHECK(labels && labels->GetTuple1(0) == 7.0 * firstTriangle);
  sphere->GetCellData()->RemoveArray("CellLabel");
  meshsimp_test::CheckInputUntouched(sphere, copy);
}

void TestSimplifiedBake()
{
  // Onto its simplification at 97 %: the texture keeps the colours far better than the
  // simplification's own vertex colours; with and without the record of where points came from.
  const vtkSmartPointer<vtkPolyData> sphere = ColouredSphere(80);
  vtkNew<vtkVolumeTriangleCollapse> simplify;
  simplify->SetInputData(sphere);
  simplify->SetTargetReduction(0.97);
  simplify->GenerateOriginalIdsOn();
  simplify->Update();
  vtkPolyData* simplified = simplify->GetOutput();
  const vtkSmartPointer<vtkTextureBaking> bake = Bake(simplified, sphere);
  const std::pair<double, double> baked = TextureError(bake->GetOutput(), bake->GetTexture());
  vtkFieldData* counts = bake->GetTexture()->GetFieldData();
  CHECK(counts->GetArray("TriangleTexels")->GetTuple1(0) > 0.25 * 1024 * 1024);
  CHECK(counts->GetArray("EmptyTexels")->GetTuple1(0) == 0);
  // The vertex colours' error at the same places (colours interpolated over each triangle).
  double vertexError = 0.0;
  const double centre[3] = { 1 / 3.0, 1 / 3.0, 1 / 3.0 };
  for (vtkIdType t = 0; t < bake->GetOutput()->GetNumberOfPolys(); ++t)
  {
    const vtkIdType* ids;
    vtkIdType n;
    bake->GetOutput()->GetPolys()->GetCellAtId(t, n, ids);
    const std::array<double, 3> p = At(bake->GetOutput(), t, centre), expected = Linear(p.data());
    double mean = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      mean += bake->GetOutput()->GetPointData()->GetArray("Colors")->GetComponent(ids[k], 2) / 3.0;
    }
    vertexError = std::max(vertexError, std::abs(mean - expected[2]));
  }
  CHECK(baked.second < 2.0);
  CHECK(baked.first < vertexError);
  // Without vtkOriginalPointIds (an exact search for each square's first texel): the same
  // texture within rounding.
  vtkNew<vtkPolyData> unrecorded;
  unrecorded->DeepCopy(simplified);
  unrecorded->GetPointData()->RemoveArray("vtkOriginalPointIds");
  const vtkSmartPointer<vtkTextureBaking> searched = Bake(unrecorded, sphere);
  vtkUnsignedCharArray* a = vtkUnsignedCharArray::SafeDownCast(bake->GetTexture()->GetPointData()->GetScalars());
  vtkUnsignedCharArray* b = vtkUnsignedCharArray::SafeDownCast(searched->GetTexture()->GetPointData()->GetScalars());
  vtkIdType differ = 0;
  for (vtkIdType i = 0; a && b && i < a->GetNumberOfValues(); ++i)
  {
    differ += std::abs(int(a->GetValue(i)) - int(b->GetValue(i))) > 1;
  }
  CHECK(a && b && differ < a->GetNumberOfValues() / 1000);
  // Both surfaces as unstructured grids (a dataset of surface cells): the same texture, and the
  // output carries no array of the conversion.
  vtkSmartPointer<vtkDataSet> grids[2];
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkAppendFilter> append;
    append->AddInputData(i == 0 ? simplified : sphere.GetPointer());
    append->Update();
    grids[i] = append->GetOutput();
  }
  const vtkSmartPointer<vtkTextureBaking> fromGrids = Bake(grids[0], grids[1]);
  vtkUnsignedCharArray* c = vtkUnsignedCharArray::SafeDownCast(fromGrids->GetTexture()->GetPointData()->GetScalars());
  CHECK(c && a && c->GetNumberOfValues() == a->GetNumberOfValues() &&
    std::equal(a->GetPointer(0), a->GetPointer(0) + a->GetNumberOfValues(), c->GetPointer(0)));
  CHECK(fromGrids->GetOutput()->GetNumberOfPolys() == bake->GetOutput()->GetNumberOfPolys() &&
    fromGrids->GetOutput()->GetPointData()->GetNumberOfArrays() == bake->GetOutput()->GetPointData()->GetNumberOfArrays() &&
    fromGrids->GetOutput()->GetCellData()->GetNumberOfArrays() == bake->GetOutput()->GetCellData()->GetNumberOfArrays());
}

void TestOtherSources()
{
  // A scalar array through a lookup table: one colour for every value gives that colour inside
  // every triangle; by default, blue to red over the range.
  const vtkSmartPointer<vtkPolyData> sphere = ColouredSphere(30);
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
  {
    height->InsertNextValue(static_cast<float>(sphere->GetPoint(p)[2]));
  }
  vtkNew<vtkPolyData> scalar;
  scalar->ShallowCopy(sphere);
  scalar->GetPointData()->SetScalars(height);
  vtkNew<vtkLookupTable> green;
  green->SetTableRange(-1, 1);
  green->SetHueRange(0.333, 0.333);
  green->SetSaturationRange(1, 1);
  green->SetValueRange(1, 1);
  green->Build();
  vtkNew<vtkTextureBaking> bake;
  bake->SetInputData(0, sphere);
  bake->SetOriginalData(scalar);
  bake->SetTextureSize(512);
  bake->Update();
  const double centre[3] = { 1 / 3.0, 1 / 3.0, 1 / 3.0 };
  const std::array<double, 3> top = Sampled(bake->GetOutput(), bake->GetTexture(), 0, centre); // a triangle at the top: red
  CHECK(top[0] > 200 && top[2] < 60);
  bake->SetLookupTable(green);
  bake->Update();
  const std::array<double, 3> greenTop = Sampled(bake->GetOutput(), bake->GetTexture(), 0, centre);
  CHECK(greenTop[0] < 1 && greenTop[1] > 254 && greenTop[2] < 1);
  // Cell colours: every texel of a triangle has its cell's.
  vtkNew<vtkUnsignedCharArray> cellColours;
  cellColours->SetName("CellColors");
  cellColours->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    cellColours->InsertNextTuple3(c % 256, (3 * c) % 256, 200);
  }
  vtkNew<vtkPolyData> cells;
  cells->ShallowCopy(sphere);
  cells->GetCellData()->AddArray(cellColours);
  bake->SetLookupTable(nullptr);
  bake->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "CellColors");
  bake->SetOriginalData(cells);
  bake->Update();
  const vtkIdType triangle = 100, cell = triangle + sphere->GetNumberOfCells() - sphere->GetNumberOfPolys();
  const std::array<double, 3> cellColour = Sampled(bake->GetOutput(), bake->GetTexture(), triangle, centre);
  CHECK(std::abs(cellColour[0] - cell % 256) < 0.01 && std::abs(cellColour[1] - (3 * cell) % 256) < 0.01);
  // A texture image through the original's coordinates: u < 0.5 red, else blue.
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  for (vtkIdType p = 0; p < sphere->GetNumberOfPoints(); ++p)
  {
    tcoords->InsertNextTuple2(sphere->GetPoint(p)[0] + 0.5, 0.5);
  }
  vtkNew<vtkPolyData> textured;
  textured->ShallowCopy(sphere);
  textured->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkImageData> image;
  image->SetDimensions(64, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < 4; ++y)
  {
    for (int x = 0; x < 64; ++x)
    {
      image->SetScalarComponentFromDouble(x, y, 0, 0, x < 32 ? 255 : 0);
      image->SetScalarComponentFromDouble(x, y, 0, 1, 0);
      image->SetScalarComponentFromDouble(x, y, 0, 2, x < 32 ? 0 : 255);
    }
  }
  bake->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None");
  bake->SetOriginalData(textured);
  bake->SetTextureData(image);
  bake->Update();
  int checked = 0;
  for (vtkIdType t = 0; t < bake->GetOutput()->GetNumberOfPolys(); t += 7)
  {
    const std::array<double, 3> p = At(bake->GetOutput(), t, centre), colour = Sampled(bake->GetOutput(), bake->GetTexture(), t, centre);
    if (std::abs(p[0]) > 0.05 && std::abs(p[0]) < 0.4) // away from the edge and the wrap
    {
      CHECK((p[0] < 0 ? colour[0] : colour[2]) > 250 && (p[0] < 0 ? colour[2] : colour[0]) < 5);
      ++checked;
    }
  }
  CHECK(checked > 50);
}

/// The sphere's triangles whose centre lies above z = 0 (upper) or not, on all its points.
vtkSmartPointer<vtkPolyData> Half(vtkPolyData* sphere, bool upper)
{
  auto half = vtkSmartPointer<vtkPolyData>::New();
  half->SetPoints(sphere->GetPoints());
  half->GetPointData()->ShallowCopy(sphere->GetPointData());
  vtkNew<vtkCellArray> polys;
  for (vtkIdType c = 0; c < sphere->GetNumberOfCells(); ++c)
  {
    const double third[3] = { 1 / 3.0, 1 / 3.0, 1 / 3.0 };
    if (sphere->GetCellType(c) == VTK_TRIANGLE && (At(sphere, c - sphere->GetNumberOfVerts() - sphere->GetNumberOfLines(), third)[2] > 0) == upper)
    {
      polys->InsertNextCell(sphere->GetCell(c)->GetPointIds());
    }
  }
  half->SetPolys(polys);
  return half;
}

/// The blocks of composite data that are polygonal data, in order.
std::vector<vtkPolyData*> Surfaces(vtkDataObject* data)
{
  std::vector<vtkPolyData*> surfaces;
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  vtkSmartPointer<vtkCompositeDataIterator> block = vtk::TakeSmartPointer(composite->NewIterator());
  for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
  {
    if (auto* surface = vtkPolyData::SafeDownCast(block->GetCurrentDataObject()))
    {
      surfaces.push_back(surface);
    }
  }
  return surfaces;
}

/// Composite data of polygonal blocks as one surface, without the record of where points came
/// from.
vtkSmartPointer<vtkPolyData> Appended(vtkDataObject* data)
{
  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* surface : Surfaces(data))
  {
    append->AddInputData(surface);
  }
  append->Update();
  auto appended = vtkSmartPointer<vtkPolyData>::New();
  appended->DeepCopy(append->GetOutput());
  appended->GetPointData()->RemoveArray("vtkOriginalPointIds");
  return appended;
}

void TestCompositeBake()
{
  // A multiblock of the sphere's two halves, simplified block by block at 95 %: one texture for
  // both, found from where each block's points came from; every block of the output keeps its
  // triangles and its own arrays, and the texture shows the linear colours on both.
  const vtkSmartPointer<vtkPolyData> sphere = ColouredSphere(80);
  vtkNew<vtkMultiBlockDataSet> halves;
  halves->SetBlock(0, Half(sphere, true));
  halves->SetBlock(2, Half(sphere, false)); // block 1 stays empty
  vtkNew<vtkIntArray> upperOnly;
  upperOnly->SetName("UpperOnly");
  upperOnly->SetNumberOfTuples(vtkPolyData::SafeDownCast(halves->GetBlock(0))->GetNumberOfCells());
  upperOnly->Fill(1);
  vtkPolyData::SafeDownCast(halves->GetBlock(0))->GetCellData()->AddArray(upperOnly);
  vtkNew<vtkVolumeTriangleCollapse> simplify;
  simplify->SetInputData(halves);
  simplify->SetTargetReduction(0.95);
  simplify->GenerateOriginalIdsOn();
  vtkNew<vtkTextureBaking> bake;
  bake->SetInputConnection(0, simplify->GetOutputPort());
  bake->SetOriginalData(halves);
  bake->SetTextureSize(1024);
  bake->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(bake->GetOutputDataObject(0));
  CHECK(out && out->GetNumberOfBlocks() == 3 && !out->GetBlock(1));
  const std::vector<vtkPolyData*> simplified = Surfaces(simplify->GetOutputDataObject(0)), baked = out ? Surfaces(out) : std::vector<vtkPolyData*>();
  CHECK(baked.size() == 2 && simplified.size() == 2);
  for (std::size_t b = 0; b < baked.size() && b < simplified.size(); ++b)
  {
    CHECK(baked[b]->GetNumberOfPolys() == simplified[b]->GetNumberOfPolys() && baked[b]->GetPointData()->GetTCoords());
    CHECK(TextureError(baked[b], bake->GetTexture()).second < 2.0);
    CHECK((baked[b]->GetCellData()->GetArray("UpperOnly") != nullptr) == (b == 0));
  }
  CHECK(bake->GetTexture()->GetFieldData()->GetArray("ExactSearches")->GetTuple1(0) == 0);
  CHECK(bake->GetTexture()->GetFieldData()->GetArray("EmptyTexels")->GetTuple1(0) == 0);
  // Without the record, the blocks bake the texture of the one surface they make together.
  const vtkSmartPointer<vtkPolyData> joinedSimplified = Appended(simplify->GetOutputDataObject(0)), joinedOriginal = Appended(halves);
  for (vtkPolyData* surface : simplified)
  {
    surface->GetPointData()->RemoveArray("vtkOriginalPointIds");
  }
  bake->SetInputData(0, simplify->GetOutputDataObject(0));
  bake->Update();
  vtkDataArray* blocks = bake->GetTexture()->GetPointData()->GetScalars();
  const vtkSmartPointer<vtkTextureBaking> whole = Bake(joinedSimplified, joinedOriginal);
  vtkDataArray* one = whole->GetTexture()->GetPointData()->GetScalars();
  CHECK(blocks && one && blocks->GetNumberOfValues() == one->GetNumberOfValues());
  for (vtkIdType i = 0; blocks && one && i < one->GetNumberOfValues() && i < blocks->GetNumberOfValues(); i += 7)
  {
    CHECK(blocks->GetComponent(i / 3, i % 3) == one->GetComponent(i / 3, i % 3));
  }
}

/// The errors of a bake, one line each.
std::vector<std::string> BakeErrors(vtkDataObject* simplified, vtkDataObject* original, vtkImageData* image = nullptr,
  int size = 1024, const char* array = nullptr)
{
  vtkNew<vtkTextureBaking> bake;
  vtkNew<meshsimp_test::MessageLog> log;
  bake->AddObserver(vtkCommand::ErrorEvent, log);
  bake->SetInputData(0, simplified);
  bake->SetOriginalData(original);
  bake->SetTextureSize(size);
  if (image)
  {
    bake->SetTextureData(image);
  }
  if (array)
  {
    bake->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, array);
  }
  bake->Update();
  return log->Errors;
}

/// One tetrahedron: a dataset of a 3-D cell, no surface.
vtkSmartPointer<vtkUnstructuredGrid> Tetrahedron()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  grid->SetPoints(points);
  const vtkIdType corners[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, corners);
  return grid;
}

void TestBadInput()
{
  const vtkSmartPointer<vtkPolyData> sphere = ColouredSphere(60);
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(sphere);
  vtkNew<vtkPolyData> plain, empty, grey;
  plain->ShallowCopy(sphere);
  plain->GetPointData()->Initialize();
  grey->ShallowCopy(plain);
  vtkNew<vtkFloatArray> level;
  level->SetNumberOfTuples(sphere->GetNumberOfPoints());
  level->Fill(0.5);
  grey->GetPointData()->SetScalars(level);
  vtkNew<vtkMultiBlockDataSet> partlyPlain, mixed;
  partlyPlain->SetBlock(0, sphere);
  partlyPlain->SetBlock(1, plain);
  mixed->SetBlock(0, sphere);
  mixed->SetBlock(1, grey);
  const std::pair<std::vector<std::string>, const char*> cases[] = {
    { BakeErrors(sphere, plain), "Cannot bake: the original has no colours to bake" },
    { BakeErrors(empty, sphere), "Cannot bake: the simplified surface has no triangles." },
    { BakeErrors(sphere, empty), "Cannot bake: the original has no triangles." },
    { BakeErrors(sphere, sphere, nullptr, 256), "cannot hold 6960 triangles with a gutter of 2 texels: it needs 512 x 512" },
    { BakeErrors(sphere, sphere, nullptr, 1024, "Nothing"), "the original has no point array 'Nothing' to bake" },
    { BakeErrors(sphere, Tetrahedron()), "Cannot bake: the original surface: the vtkUnstructuredGrid has 3-D cells" },
    { BakeErrors(sphere, partlyPlain), "Cannot bake: block 1 of the original has no colours to bake" },
    { BakeErrors(sphere, mixed), "Cannot bake: block 1 of the original shows an array unlike the other pieces'" },
  };
  for (const auto& [errors, expected] : cases)
  {
    CHECK(errors.size() == 1 && meshsimp_test::Mentions(errors[0], expected));
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const std::vector<std::string> untextured = BakeErrors(sphere, sphere, image);
  CHECK(untextured.size() == 1 && meshsimp_test::Mentions(untextured[0], "the original has no texture coordinates"));
  // A failed bake is not run again when its texture is asked for next: one error per change.
  vtkNew<meshsimp_test::MessageLog> once;
  vtkNew<vtkTextureBaking> failed;
  failed->AddObserver(vtkCommand::ErrorEvent, once);
  failed->SetInputData(0, sphere);
  failed->SetOriginalData(plain);
  failed->Update(0);
  failed->Update(1);
  CHECK(once->Errors.size() == 1);
  // NaN points in the simplified surface: their triangles get no square, the rest bake.
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(sphere);
  broken->GetPoints()->SetPoint(5, std::nan(""), 0.0, 0.0);
  vtkNew<vtkTextureBaking> bake;
  bake->SetInputData(0, broken);
  bake->SetOriginalData(sphere);
  bake->Update();
  CHECK(bake->GetOutput()->GetNumberOfPolys() > 0 && bake->GetOutput()->GetNumberOfPolys() < sphere->GetNumberOfPolys());
  meshsimp_test::CheckInputUntouched(sphere, copy);
}

/// The Jacksboro terrain at 99 % by the octree, textured with its baked elevation.
int CompareBakedTerrain(int argc, char* argv[])
{
  vtkNew<vtkXMLPolyDataReader> terrain;
  terrain->SetFileName(MESHSIMPLIFICATION_TEST_DATA "/jacksboro_dem_half.vtp");
  vtkNew<vtkOctreeVertexClustering> simplify;
  simplify->SetInputConnection(terrain->GetOutputPort());
  simplify->SetTargetReduction(0.99);
  simplify->GenerateOriginalIdsOn();
  vtkNew<vtkTextureBaking> bake;
  bake->SetInputConnection(0, simplify->GetOutputPort());
  bake->SetOriginalConnection(terrain->GetOutputPort());
  bake->SetTextureSize(1024);
  bake->Update();
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(bake->GetOutputPort(1));
  texture->InterpolateOn();
  return meshsimp_test::CompareWithBaseline(bake->GetOutput(), true, argc, argv, texture);
}
} // namespace

int TestTextureBaking(int argc, char* argv[])
{
  if (argc > 1 && std::strcmp(argv[1], "Image") == 0)
  {
    return CompareBakedTerrain(argc, argv);
  }
  TestSelfBake();
  TestSimplifiedBake();
  TestOtherSources();
  TestCompositeBake();
  TestBadInput();
  return meshsimp_test::Failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
