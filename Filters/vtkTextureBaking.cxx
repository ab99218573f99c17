// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTextureBaking.h"

#include "TextureAtlas.h"
#include "TextureBaking.h"
#include "vtkSimplificationInput.h"
#include "vtkSimplificationThreads.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLookupTable.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTextureBaking);
vtkCxxSetObjectMacro(vtkTextureBaking, LookupTable, vtkScalarsToColors);

namespace
{
/// What the texture shows, and the values the baker interpolates (per original point or
/// triangle).
struct BakeSource
{
  enum Kinds
  {
    COLOURS, // unsigned-char RGB(A), as they are
    MAPPED,  // any other array, through a lookup table
    TEXTURE  // texture coordinates, looked up in an image
  };
  Kinds Kind = COLOURS;
  vtkDataArray* Array = nullptr;
  bool PerTriangle = false;
  std::vector<float> Values;
};

bool IsColours(vtkDataArray* array)
{
  return array && array->GetDataType() == VTK_UNSIGNED_CHAR && (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4);
}

/// The first unsigned-char RGB(A) array of data, or null.
vtkDataArray* FirstColours(vtkDataSetAttributes* data)
{
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    if (IsColours(data->GetArray(a)))
    {
      return data->GetArray(a);
    }
  }
  return nullptr;
}

/// The array input array 0 selects on the original (perCell set for cell data); without a
/// selection, the active point scalars, the first colours among the points, then the cells.
/// Null, with a message in problem, where the selection names no array of the original.
vtkDataArray* ShownArray(vtkAlgorithm* filter, vtkPolyData* original, bool& perCell, std::string& problem)
{
  vtkInformation* selection = filter->GetInputArrayInformation(0);
  const std::string name = selection->Has(vtkDataObject::FIELD_NAME()) ? selection->Get(vtkDataObject::FIELD_NAME()) : "";
  if (!name.empty() && name != "None")
  {
    const int association = selection->Has(vtkDataObject::FIELD_ASSOCIATION()) ? selection->Get(vtkDataObject::FIELD_ASSOCIATION())
                                                                               : vtkDataObject::FIELD_ASSOCIATION_POINTS;
    perCell = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    vtkDataArray* array = (perCell ? static_cast<vtkDataSetAttributes*>(original->GetCellData()) : original->GetPointData())->GetArray(name.c_str());
    problem = array ? "" : "the original has no " + std::string(perCell ? "cell" : "point") + " array '" + name + "' to bake";
    return array;
  }
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(original->GetPointData()), static_cast<vtkDataSetAttributes*>(original->GetCellData()) })
  {
    perCell = data == original->GetCellData();
    if (vtkDataArray* array = data->GetScalars() ? data->GetScalars() : FirstColours(data))
    {
      return array;
    }
  }
  problem = "the original has no colours to bake: give it an unsigned-char RGB point array, select an array, or connect a "
            "texture image for its texture coordinates";
  return nullptr;
}

/// The source's values as floats: per original point, or per original triangle (its cell's).
void ReadValues(BakeSource& source, const vtkSimplification::TriangleInput& original)
{
  vtkDataArray* array = source.Array;
  const int n = source.Kind == BakeSource::TEXTURE ? 2 : array->GetNumberOfComponents();
  const std::int64_t count = source.PerTriangle ? original.View.NumberOfTriangles : original.View.NumberOfPoints;
  source.Values.resize(static_cast<std::size_t>(count) * n);
  for (std::int64_t i = 0; i < count; ++i)
  {
    const vtkIdType tuple = source.PerTriangle ? original.SourceCell(i) : i;
    for (int c = 0; c < n; ++c)
    {
      source.Values[i * n + c] = static_cast<float>(array->GetComponent(tuple, c));
    }
  }
}

/// An image's unsigned-char scalars looked up at texture coordinates: bilinear, repeated.
class TextureImage
{
public:
  explicit TextureImage(vtkImageData* image)
    : Scalars(vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars()))
    , Width(image->GetDimensions()[0])
    , Height(image->GetDimensions()[1])
  {
  }

  /// The first components of the RGBA colour at (u, v); nothing where u or v is not finite.
  void LookUp(float u, float v, unsigned char* to, int components) const
  {
    if (!std::isfinite(u) || !std::isfinite(v))
    {
      return;
    }
    const float x = (u - std::floor(u)) * this->Width - 0.5f, y = (v - std::floor(v)) * this->Height - 0.5f;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    float corners[4][4];
    this->Texel(x0, y0, corners[0]);
    this->Texel(x0 + 1, y0, corners[1]);
    this->Texel(x0, y0 + 1, corners[2]);
    this->Texel(x0 + 1, y0 + 1, corners[3]);
    for (int c = 0; c < components; ++c)
    {
      const float mixed = (1 - fy) * ((1 - fx) * corners[0][c] + fx * corners[1][c]) + fy * ((1 - fx) * corners[2][c] + fx * corners[3][c]);
      to[c] = static_cast<unsigned char>(std::min(255.0f, std::max(0.0f, std::round(mixed))));
    }
  }

  /// Whether the image has RGBA or grey and alpha.
  bool HasAlpha() const { return this->Scalars->GetNumberOfComponents() % 2 == 0; }

private:
  /// Texel (x, y), repeated, as RGBA.
  void Texel(int x, int y, float rgba[4]) const
  {
    x = ((x % this->Width) + this->Width) % this->Width;
    y = ((y % this->Height) + this->Height) % this->Height;
    const int n = this->Scalars->GetNumberOfComponents();
    const unsigned char* texel = this->Scalars->GetPointer((static_cast<vtkIdType>(y) * this->Width + x) * n);
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] = texel[n < 3 ? 0 : c];
    }
    rgba[3] = n % 2 == 0 ? texel[n - 1] : 255.0f;
  }

  vtkUnsignedCharArray* Scalars;
  int Width, Height;
};

/// The lookup table for a mapped array: the user's, or blue to red over its range (a vector
/// array's magnitude).
vtkSmartPointer<vtkScalarsToColors> TableFor(vtkScalarsToColors* chosen, vtkDataArray* array)
{
  if (chosen)
  {
    return chosen;
  }
  vtkNew<vtkLookupTable> table;
  const int component = array->GetNumberOfComponents() == 1 ? 0 : -1;
  double range[2];
  array->GetRange(range, component);
  table->SetRange(range);
  table->SetHueRange(0.6667, 0.0);
  table->SetVectorModeToMagnitude();
  table->Build();
  return table.GetPointer();
}

/// The baked values as the texture's unsigned-char colours; texels of no triangle are 0.
vtkSmartPointer<vtkUnsignedCharArray> TextureColours(const BakeSource& source, const meshsimp::BakedTexture& baked,
  vtkScalarsToColors* table, vtkImageData* image)
{
  const vtkIdType texels = static_cast<vtkIdType>(baked.Values.size() / baked.Components);
  const int n = baked.Components;
  int components = 3;
  if (source.Kind == BakeSource::COLOURS)
  {
    components = n;
  }
  else if (source.Kind == BakeSource::TEXTURE)
  {
    components = TextureImage(image).HasAlpha() ? 4 : 3;
  }
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("BakedTexture");
  colours->SetNumberOfComponents(components);
  colours->SetNumberOfTuples(texels);
  std::fill_n(colours->GetPointer(0), texels * components, 0);
  vtkSmartPointer<vtkUnsignedCharArray> mapped;
  std::optional<TextureImage> lookup;
  if (source.Kind == BakeSource::TEXTURE)
  {
    lookup.emplace(image);
  }
  if (source.Kind == BakeSource::MAPPED)
  {
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfComponents(n);
    values->SetArray(const_cast<float*>(baked.Values.data()), texels * n, 1);
    mapped.TakeReference(TableFor(table, source.Array)->MapScalars(values, VTK_COLOR_MODE_MAP_SCALARS, -1, VTK_RGB));
  }
  for (vtkIdType t = 0; t < texels; ++t)
  {
    const float* value = baked.Values.data() + t * n;
    unsigned char* to = colours->GetPointer(t * components);
    if (std::isnan(value[0]))
    {
      continue;
    }
    if (source.Kind == BakeSource::COLOURS)
    {
      std::transform(value, value + n, to, [](float v) { return static_cast<unsigned char>(std::min(255.0f, std::max(0.0f, std::round(v)))); });
    }
    else if (source.Kind == BakeSource::TEXTURE)
    {
      lookup->LookUp(value[0], value[1], to, components);
    }
    else
    {
      std::copy_n(mapped->GetPointer(3 * t), 3, to);
    }
  }
  return colours;
}

/// The simplified surface's triangles, split at the atlas's seams, with texture coordinates and
/// its point and cell data.
void WriteMesh(vtkPolyData* simplified, const vtkSimplification::TriangleInput& triangles, const meshsimp::SeamSplit& split,
  vtkPolyData* output)
{
  const vtkIdType points = static_cast<vtkIdType>(split.SourcePoints.size());
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataType(simplified->GetPoints()->GetDataType());
  coordinates->SetNumberOfPoints(points);
  vtkNew<vtkIdList> from, to;
  from->SetNumberOfIds(points);
  to->SetNumberOfIds(points);
  for (vtkIdType p = 0; p < points; ++p)
  {
    coordinates->SetPoint(p, simplified->GetPoint(split.SourcePoints[p]));
    from->SetId(p, split.SourcePoints[p]);
    to->SetId(p, p);
  }
  output->SetPoints(coordinates);
  output->GetPointData()->CopyAllocate(simplified->GetPointData(), points);
  output->GetPointData()->CopyData(simplified->GetPointData(), from, to);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(points);
  std::copy(split.TextureCoordinates.begin(), split.TextureCoordinates.end(), tcoords->GetPointer(0));
  output->GetPointData()->SetTCoords(tcoords);

  const vtkIdType cells = static_cast<vtkIdType>(split.SourceTriangles.size());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(cells, 3 * cells);
  from->SetNumberOfIds(cells);
  to->SetNumberOfIds(cells);
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const vtkIdType corners[3] = { split.Triangles[3 * t], split.Triangles[3 * t + 1], split.Triangles[3 * t + 2] };
    polys->InsertNextCell(3, corners);
    from->SetId(t, triangles.SourceCell(split.SourceTriangles[t]));
    to->SetId(t, t);
  }
  output->SetPolys(polys);
  output->GetCellData()->CopyAllocate(simplified->GetCellData(), cells);
  output->GetCellData()->CopyData(simplified->GetCellData(), from, to);
  output->GetFieldData()->PassData(simplified->GetFieldData());
}

/// An input as a surface (vtkSimplification::AsSurface: another dataset's surface cells through
/// vtkGeometryFilter), without the ids of its points and cells in the dataset that that adds.
vtkSmartPointer<vtkPolyData> Surface(vtkDataObject* input, std::string& problem)
{
  vtkSmartPointer<vtkPolyData> surface = vtkSimplification::AsSurface(input, problem);
  if (surface && surface.GetPointer() != input)
  {
    surface->GetPointData()->RemoveArray(vtkSimplification::SurfacePointIdsName);
    surface->GetCellData()->RemoveArray(vtkSimplification::SurfaceCellIdsName);
  }
  return surface;
}

/// Per simplified point, the original point it came from (vtkOriginalPointIds), where in range.
std::vector<std::int32_t> Seeds(vtkPolyData* simplified, vtkIdType originalPoints)
{
  vtkDataArray* ids = simplified->GetPointData()->GetArray("vtkOriginalPointIds");
  std::vector<std::int32_t> seeds;
  if (!ids || ids->GetNumberOfComponents() != 1)
  {
    return seeds;
  }
  seeds.resize(static_cast<std::size_t>(ids->GetNumberOfTuples()), -1);
  for (vtkIdType p = 0; p < ids->GetNumberOfTuples(); ++p)
  {
    const double id = ids->GetComponent(p, 0);
    seeds[p] = id >= 0.0 && id < static_cast<double>(originalPoints) ? static_cast<std::int32_t>(id) : -1;
  }
  return seeds;
}

/// What the texture shows, or why nothing can be baked (problem, in the order of the checks).
BakeSource ChooseSource(vtkAlgorithm* filter, const vtkSimplification::TriangleInput& simplifiedTriangles,
  const vtkSimplification::TriangleInput& originalTriangles, vtkPolyData* original, vtkImageData* image, std::string& problem)
{
  BakeSource source;
  problem = simplifiedTriangles.View.NumberOfTriangles == 0 ? "the simplified surface has no triangles"
    : originalTriangles.View.NumberOfTriangles == 0                    ? "the original has no triangles"
                                                                       : "";
  if (problem.empty() && image)
  {
    source.Kind = BakeSource::TEXTURE;
    source.Array = original->GetPointData()->GetTCoords();
    const bool usable = image->GetPointData()->GetScalars() && image->GetPointData()->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR &&
      image->GetNumberOfPoints() > 0;
    problem = !usable ? "the texture image (input 2) has no unsigned-char scalars"
      : !source.Array ? "the original has no texture coordinates for the texture image (input 2)"
                      : "";
  }
  else if (problem.empty())
  {
    source.Array = ShownArray(filter, original, source.PerTriangle, problem);
    source.Kind = IsColours(source.Array) ? BakeSource::COLOURS : BakeSource::MAPPED;
  }
  return source;
}

/// TextureSize rounded down to a power of two.
int PowerOfTwo(int size)
{
  int power = 1;
  while (2 * power <= size)
  {
    power *= 2;
  }
  return power;
}
} // namespace

vtkTextureBaking::vtkTextureBaking()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
}

vtkTextureBaking::~vtkTextureBaking()
{
  this->SetLookupTable(nullptr);
}

vtkMTimeType vtkTextureBaking::GetMTime()
{
  const vtkMTimeType own = this->Superclass::GetMTime();
  return this->LookupTable ? std::max(own, this->LookupTable->GetMTime()) : own;
}

vtkImageData* vtkTextureBaking::GetTexture()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkTextureBaking::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 2 ? "vtkImageData" : "vtkDataSet");
  if (port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkTextureBaking::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

int vtkTextureBaking::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  const int last = PowerOfTwo(this->TextureSize) - 1;
  const int extent[6] = { 0, last, 0, last, 0, 0 };
  outputs->GetInformationObject(1)->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

int vtkTextureBaking::RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  vtkPolyData* output = vtkPolyData::GetData(outputs, 0);
  vtkImageData* texture = vtkImageData::GetData(outputs, 1);
  vtkDataObject* given[2] = { vtkDataObject::GetData(inputs[0]), vtkDataObject::GetData(inputs[1]) };
  vtkImageData* image = vtkImageData::GetData(inputs[2]);
  if (!given[0] || !given[1])
  {
    vtkErrorMacro("Cannot bake: Texture Baking needs the simplified surface (input 0) and the original (input 1).");
    return 1;
  }
  std::string problem;
  vtkSmartPointer<vtkPolyData> simplified = Surface(given[0], problem);
  vtkSmartPointer<vtkPolyData> original = simplified ? Surface(given[1], problem) : nullptr;
  if (!simplified || !original)
  {
    vtkErrorMacro("Cannot bake: the " << (simplified ? "original" : "simplified") << " surface: " << problem << ".");
    return 1;
  }
  vtkSimplification::TriangleInput simplifiedTriangles, originalTriangles;
  if (!vtkSimplification::PrepareTriangles(this, simplified, simplifiedTriangles) ||
    !vtkSimplification::PrepareTriangles(this, original, originalTriangles))
  {
    return 1;
  }
  BakeSource source = ChooseSource(this, simplifiedTriangles, originalTriangles, original, image, problem);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot bake: " << problem << ".");
    return 1;
  }
  const meshsimp::TextureAtlas atlas = meshsimp::MakeTextureAtlas(simplifiedTriangles.View, PowerOfTwo(this->TextureSize), this->GutterWidth);
  if (!atlas.Error.empty())
  {
    vtkErrorMacro("Cannot bake: " << atlas.Error << "; raise Texture Size or lower Gutter Width.");
    return 1;
  }
  ReadValues(source, originalTriangles);
  this->UpdateProgress(0.05);
  const meshsimp::ExecutionContext context = vtkSimplification::MakeExecutionContext(this, 0);
  const meshsimp::BakedTexture baked = meshsimp::BakeTexels(simplifiedTriangles.View, atlas, originalTriangles.View,
    { source.Values.data(), source.Kind == BakeSource::TEXTURE ? 2 : source.Array->GetNumberOfComponents(), source.PerTriangle },
    Seeds(simplified, original->GetNumberOfPoints()), this->MaximumDistance * original->GetLength(), context);
  if (baked.Aborted)
  {
    return 1;
  }
  WriteMesh(simplified, simplifiedTriangles, meshsimp::SplitAtSeams(simplifiedTriangles.View, atlas), output);
  texture->SetDimensions(atlas.Size, atlas.Size, 1);
  texture->GetPointData()->SetScalars(TextureColours(source, baked, this->LookupTable, image));
  const std::pair<const char*, std::int64_t> counts[] = { { "TriangleTexels", baked.InsideTexels },
    { "EmptyTexels", baked.EmptyTexels }, { "ExactSearches", baked.ExactSearches }, { "CorrectedWalks", baked.CorrectedWalks } };
  for (const auto& [name, count] : counts)
  {
    vtkNew<vtkIdTypeArray> value;
    value->SetName(name);
    value->InsertNextValue(static_cast<vtkIdType>(count));
    texture->GetFieldData()->AddArray(value);
  }
  return 1;
}

void vtkTextureBaking::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TextureSize: " << this->TextureSize << "\n";
  os << indent << "GutterWidth: " << this->GutterWidth << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "LookupTable: " << this->LookupTable << "\n";
}
