// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTextureBakingColours.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLookupTable.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace vtkSimplification
{
namespace
{
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

/// The array a piece of the original shows: with an image, its texture coordinates; else
/// ShownArray's. Null, with a message in problem, where it has none.
vtkDataArray* PieceArray(vtkAlgorithm* filter, vtkPolyData* piece, vtkImageData* image, bool& perCell, std::string& problem)
{
  if (!image)
  {
    return ShownArray(filter, piece, perCell, problem);
  }
  vtkDataArray* coordinates = piece->GetPointData()->GetTCoords();
  const bool usable = coordinates && coordinates->GetNumberOfComponents() >= 2;
  problem = usable ? "" : "the original has no texture coordinates for the texture image (input 2)";
  return usable ? coordinates : nullptr;
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

/// The lookup table for a mapped array: the user's, or blue to red over its range in every
/// piece (a vector array's magnitude).
vtkSmartPointer<vtkScalarsToColors> TableFor(vtkScalarsToColors* chosen, const std::vector<vtkDataArray*>& arrays)
{
  if (chosen)
  {
    return chosen;
  }
  double range[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkDataArray* array : arrays)
  {
    double own[2];
    if (array && array->GetNumberOfTuples() > 0)
    {
      array->GetRange(own, array->GetNumberOfComponents() == 1 ? 0 : -1);
      range[0] = std::min(range[0], own[0]);
      range[1] = std::max(range[1], own[1]);
    }
  }
  vtkNew<vtkLookupTable> table;
  table->SetRange(range);
  table->SetHueRange(0.6667, 0.0);
  table->SetVectorModeToMagnitude();
  table->Build();
  return table.GetPointer();
}

} // namespace

BakeSource ChooseBakeSource(vtkAlgorithm* filter, const std::vector<Piece>& original, const std::vector<std::string>& names,
  vtkImageData* image, std::string& problem)
{
  BakeSource source;
  source.Kind = image ? BakeSource::TEXTURE : BakeSource::COLOURS;
  source.Arrays.assign(original.size(), nullptr);
  const bool usable = !image ||
    (image->GetPointData()->GetScalars() && image->GetPointData()->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR &&
      image->GetNumberOfPoints() > 0);
  problem = usable ? "" : "the texture image (input 2) has no unsigned-char scalars";
  vtkDataArray* first = nullptr;
  for (std::size_t k = 0; k < original.size() && problem.empty(); ++k)
  {
    if (original[k].Triangles.View.NumberOfTriangles == 0)
    {
      continue;
    }
    bool perCell = false;
    vtkDataArray* array = PieceArray(filter, original[k].Input, image, perCell, problem);
    if (!array)
    {
      problem = names[k] + problem;
      break;
    }
    if (!first)
    {
      first = array;
      source.PerTriangle = perCell;
      source.Components = image ? 2 : array->GetNumberOfComponents();
      source.Kind = image ? BakeSource::TEXTURE : IsColours(array) ? BakeSource::COLOURS : BakeSource::MAPPED;
    }
    else if (!image && (perCell != source.PerTriangle || array->GetNumberOfComponents() != source.Components ||
                         IsColours(array) != IsColours(first)))
    {
      problem = names[k] + "the original shows an array unlike the other pieces' (another kind, place or number of components)";
    }
    source.Arrays[k] = array;
  }
  return source;
}

void ReadBakeValues(BakeSource& source, const std::vector<Piece>& pieces)
{
  const int n = source.Components;
  for (std::size_t k = 0; k < pieces.size(); ++k)
  {
    const TriangleInput& original = pieces[k].Triangles;
    const std::int64_t count = source.PerTriangle ? original.View.NumberOfTriangles : original.View.NumberOfPoints;
    std::size_t at = source.Values.size();
    source.Values.resize(at + static_cast<std::size_t>(count) * n, std::nanf(""));
    for (std::int64_t i = 0; source.Arrays[k] && i < count; ++i, at += n)
    {
      const vtkIdType tuple = source.PerTriangle ? original.SourceCell(i) : i;
      for (int c = 0; c < n; ++c)
      {
        source.Values[at + c] = static_cast<float>(source.Arrays[k]->GetComponent(tuple, c));
      }
    }
  }
}

vtkSmartPointer<vtkUnsignedCharArray> BakedColours(const BakeSource& source, const meshsimp::BakedTexture& baked,
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
    mapped.TakeReference(TableFor(table, source.Arrays)->MapScalars(values, VTK_COLOR_MODE_MAP_SCALARS, -1, VTK_RGB));
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

} // namespace vtkSimplification
