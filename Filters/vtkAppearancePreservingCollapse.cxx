// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAppearancePreservingCollapse.h"

#include "AppearancePreservingCollapse.h"
#include "vtkSimplificationInput.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkAppearancePreservingCollapse);

namespace
{
/// Appends array's components, each mapped onto [0, 1] (unsigned chars over 255, normals from
/// [-1, 1], others over their range) and times factor, to the attribute coordinates of every
/// point.
void AppendScaled(vtkDataArray* array, bool normals, double factor, std::vector<double>& columns, int& dimension)
{
  const vtkIdType n = array->GetNumberOfTuples();
  for (int k = 0; k < array->GetNumberOfComponents(); ++k)
  {
    double low = 0.0, span = 1.0;
    if (vtkUnsignedCharArray::SafeDownCast(array))
    {
      span = 255.0;
    }
    else if (normals)
    {
      low = -1.0;
      span = 2.0;
    }
    else
    {
      double range[2];
      array->GetRange(range, k);
      low = range[0];
      span = range[1] > range[0] ? range[1] - range[0] : 1.0;
    }
    for (vtkIdType p = 0; p < n; ++p)
    {
      const double value = factor * (array->GetComponent(p, k) - low) / span;
      columns.push_back(std::isfinite(value) ? value : 0.0);
    }
    ++dimension;
  }
}

/// The point data the Quadric order weighs (see the class's notes), one row per point: each
/// array once, the first time it is met, times its kind's factor (kinds of factor 0 left out).
std::vector<double> AttributeCoordinates(
  vtkAlgorithm* filter, const meshsimp::AppearanceCollapseParameters& weights, vtkPolyData* input, int& dimension)
{
  std::vector<double> columns;
  dimension = 0;
  vtkPointData* data = input->GetPointData();
  std::vector<vtkDataArray*> weighed;
  const auto weigh = [&](vtkDataArray* array, bool normals, double factor) {
    if (array && std::find(weighed.begin(), weighed.end(), array) == weighed.end())
    {
      weighed.push_back(array);
      if (factor > 0.0)
      {
        AppendScaled(array, normals, factor, columns, dimension);
      }
    }
  };
  weigh(data->GetNormals(), true, weights.NormalWeight);
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    auto* colours = vtkUnsignedCharArray::SafeDownCast(data->GetArray(i));
    if (colours && (colours->GetNumberOfComponents() == 3 || colours->GetNumberOfComponents() == 4))
    {
      weigh(colours, false, weights.ColorWeight);
    }
  }
  weigh(data->GetTCoords(), false, weights.TextureCoordinateWeight);
  weigh(data->GetScalars(), false, weights.ScalarWeight);
  weigh(vtkDataArray::SafeDownCast(vtkSimplification::SelectedPointArray(filter, 2, input, "attribute coordinates")),
    false, weights.ScalarWeight);
  // Column by column, as gathered, to a row per point.
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<double> rows(columns.size());
  for (int k = 0; k < dimension; ++k)
  {
    for (vtkIdType p = 0; p < n; ++p)
    {
      rows[p * dimension + k] = columns[k * n + p];
    }
  }
  return rows;
}
}

vtkAppearancePreservingCollapse::vtkAppearancePreservingCollapse()
{
  this->TargetTolerance = meshsimp::AppearanceCollapseOptions().Goal.Tolerance;
}

bool vtkAppearancePreservingCollapse::RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result)
{
  meshsimp::AppearanceCollapseOptions options;
  static_cast<meshsimp::SimplificationOptions&>(options) = piece.Common;
  static_cast<meshsimp::AppearanceCollapseParameters&>(options) = *this;
  // The input's point data, unless the core runs on a piece's first result (the border round's
  // last stage), whose points are not the input's.
  std::vector<double> attributes;
  if (!piece.OnFirstResult && this->AttributeWeight > 0.0 && this->Order == meshsimp::AppearanceOrder::Quadric)
  {
    attributes = AttributeCoordinates(this, *this, piece.Input, options.AttributeDimension);
    options.AttributeCoordinates = attributes.empty() ? nullptr : attributes.data();
  }
  meshsimp::AppearanceCollapseResult full;
  const bool finished = meshsimp::AppearancePreservingCollapse(piece.Mesh, options, full, piece.Execution);
  result = std::move(static_cast<meshsimp::SimplifiedMesh&>(full));
  return finished;
}

void vtkAppearancePreservingCollapse::SetOrder(int order)
{
  static_assert(NORMAL_SPREAD == static_cast<int>(meshsimp::AppearanceOrder::NormalSpread) &&
      QUADRIC == static_cast<int>(meshsimp::AppearanceOrder::Quadric),
    "the property values are the core's");
  const auto clamped = static_cast<meshsimp::AppearanceOrder>(std::clamp(order, 0, static_cast<int>(QUADRIC)));
  if (this->Order != clamped)
  {
    this->Order = clamped;
    this->Modified();
  }
}

int vtkAppearancePreservingCollapse::GetOrder() const
{
  return static_cast<int>(this->Order);
}

void vtkAppearancePreservingCollapse::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  meshsimp::PrintParameters<meshsimp::AppearanceCollapseParameters>(*this, os, indent);
}

void vtkAppearancePreservingCollapse::ForEachOwnSetting(const meshsimp::SettingVisit& visit)
{
  meshsimp::VisitParameters<meshsimp::AppearanceCollapseParameters>(*this, visit);
}
