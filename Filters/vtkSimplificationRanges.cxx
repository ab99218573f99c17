// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationRanges.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationInformationVectorKey.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeTraits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <set>
#include <vector>

// Why: ParaView asks for every range of every output array after each update, and VTK 9.2
// computes each kind in a pass of its own, so that a level dragged on a slider or a morph played
// frame by frame would wait for them at every frame. The norms' squares are summed as VTK sums
// them (CMakeLists.txt keeps the compiler from fusing the multiply and add, which VTK's own
// build does not), so that the ranges are VTK's to the last bit.
namespace
{
/// Lowest and highest of the values added, as vtkDataArray keeps them: in the values' type for
/// components, in double for the squared norms; a NaN never enters (it compares false).
template <typename Value>
struct Bounds
{
  Value Low = vtkTypeTraits<Value>::Max();
  Value High = vtkTypeTraits<Value>::Min();
  void Add(Value value)
  {
    this->Low = value < this->Low ? value : this->Low;
    this->High = value > this->High ? value : this->High;
  }
  void Add(const Bounds& other)
  {
    this->Low = other.Low < this->Low ? other.Low : this->Low;
    this->High = other.High > this->High ? other.High : this->High;
  }
  /// Whether an infinity was added (then the finite bounds need a pass of their own).
  bool Infinite() const
  {
    return std::numeric_limits<Value>::has_infinity &&
      (this->Low == -std::numeric_limits<Value>::infinity() || this->High == std::numeric_limits<Value>::infinity());
  }
};

/// The ranges of an array or of a run of its tuples: per component, and of the squared norms,
/// with and without infinities.
template <typename Value>
struct Ranges
{
  std::vector<Bounds<Value>> Components, FiniteComponents;
  Bounds<double> Squares, FiniteSquares;
  explicit Ranges(int components)
    : Components(components)
    , FiniteComponents(components)
  {
  }
  void Add(const Ranges& other)
  {
    for (std::size_t c = 0; c < this->Components.size(); ++c)
    {
      this->Components[c].Add(other.Components[c]);
      this->FiniteComponents[c].Add(other.FiniteComponents[c]);
    }
    this->Squares.Add(other.Squares);
    this->FiniteSquares.Add(other.FiniteSquares);
  }
};

template <typename Value>
double Squared(const Value* tuple, int components)
{
  double squares = 0.0;
  for (int c = 0; c < components; ++c)
  {
    squares += static_cast<double>(tuple[c]) * static_cast<double>(tuple[c]);
  }
  return squares;
}

/// Adds the tuples [begin, end) of components values each to found's ranges with infinities;
/// N > 0 when components is that constant, so that the loop keeps its bounds in registers.
template <int N, typename Value>
void AddTuples(const Value* values, int components, std::int64_t begin, std::int64_t end, Ranges<Value>& found)
{
  const int n = N > 0 ? N : components;
  std::array<Bounds<Value>, (N > 0 ? N : 1)> fixed;
  Bounds<Value>* bounds = N > 0 ? fixed.data() : found.Components.data();
  Bounds<double> squares;
  for (std::int64_t tuple = begin; tuple < end; ++tuple)
  {
    const Value* at = values + tuple * n;
    for (int c = 0; c < n; ++c)
    {
      bounds[c].Add(at[c]);
    }
    if (n > 1)
    {
      squares.Add(Squared(at, n));
    }
  }
  if (N > 0)
  {
    std::copy(fixed.begin(), fixed.end(), found.Components.begin());
  }
  found.Squares = squares;
}

/// The ranges of the tuples [begin, end): every value once, and again only where a run holds an
/// infinity.
template <typename Value>
Ranges<Value> RangesOf(const Value* values, int components, std::int64_t begin, std::int64_t end)
{
  Ranges<Value> found(components);
  switch (components)
  {
    case 1: AddTuples<1>(values, components, begin, end, found); break;
    case 2: AddTuples<2>(values, components, begin, end, found); break;
    case 3: AddTuples<3>(values, components, begin, end, found); break;
    case 4: AddTuples<4>(values, components, begin, end, found); break;
    default: AddTuples<0>(values, components, begin, end, found);
  }
  found.FiniteComponents = found.Components;
  for (int c = 0; c < components; ++c)
  {
    if (found.Components[c].Infinite())
    {
      found.FiniteComponents[c] = Bounds<Value>();
      for (std::int64_t tuple = begin; tuple < end; ++tuple)
      {
        const Value value = values[tuple * components + c];
        if (!std::isinf(static_cast<double>(value)))
        {
          found.FiniteComponents[c].Add(value);
        }
      }
    }
  }
  found.FiniteSquares = found.Squares;
  if (found.Squares.Infinite())
  {
    found.FiniteSquares = Bounds<double>();
    for (std::int64_t tuple = begin; tuple < end; ++tuple)
    {
      const double squares = Squared(values + tuple * components, components);
      if (!std::isinf(squares))
      {
        found.FiniteSquares.Add(squares);
      }
    }
  }
  return found;
}

template <typename Value>
void Store(vtkInformation* information, vtkInformationInformationVectorKey* key, const std::vector<Bounds<Value>>& bounds)
{
  vtkNew<vtkInformationVector> perComponent;
  perComponent->SetNumberOfInformationObjects(static_cast<int>(bounds.size()));
  for (std::size_t c = 0; c < bounds.size(); ++c)
  {
    const double range[2] = { static_cast<double>(bounds[c].Low), static_cast<double>(bounds[c].High) };
    perComponent->GetInformationObject(static_cast<int>(c))->Set(vtkDataArray::COMPONENT_RANGE(), range, 2);
  }
  information->Set(key, perComponent);
}

void Store(vtkInformation* information, vtkInformationDoubleVectorKey* key, const Bounds<double>& squares)
{
  const double range[2] = { std::sqrt(squares.Low), std::sqrt(squares.High) };
  information->Set(key, range, 2);
}

template <typename Value>
bool Record(vtkDataArray* array, const meshsimp::ExecutionContext& context)
{
  auto* typed = vtkAOSDataArrayTemplate<Value>::FastDownCast(array);
  if (!typed)
  {
    return false;
  }
  const int components = array->GetNumberOfComponents();
  const Value* values = typed->GetPointer(0);
  Ranges<Value> all(components);
  std::mutex merging;
  context.For(array->GetNumberOfTuples(), [&](std::int64_t begin, std::int64_t end) {
    const Ranges<Value> part = RangesOf(values, components, begin, end);
    const std::lock_guard<std::mutex> lock(merging);
    all.Add(part);
  }, 2 * components * array->GetNumberOfTuples());
  vtkInformation* information = array->GetInformation();
  Store(information, vtkAbstractArray::PER_COMPONENT(), all.Components);
  Store(information, vtkAbstractArray::PER_FINITE_COMPONENT(), all.FiniteComponents);
  if (components > 1)
  {
    Store(information, vtkDataArray::L2_NORM_RANGE(), all.Squares);
    Store(information, vtkDataArray::L2_NORM_FINITE_RANGE(), all.FiniteSquares);
  }
  return true;
}
/// Record for the first of Values that is the array's (none where the array is of another kind).
template <typename... Values>
void RecordOfType(vtkDataArray* array, const meshsimp::ExecutionContext& context)
{
  (Record<Values>(array, context) || ...);
}
} // namespace

namespace vtkSimplification
{

void RecordRanges(vtkDataArray* array, const meshsimp::ExecutionContext& context)
{
  if (array && array->GetNumberOfTuples() > 0)
  {
    RecordOfType<float, double, char, signed char, unsigned char, short, unsigned short, int, unsigned int, long,
      unsigned long, long long, unsigned long long>(array, context);
  }
}

void RecordOutputRanges(vtkPolyData* input, vtkPolyData* output, const meshsimp::ExecutionContext& context)
{
  const auto arrays = [](vtkPolyData* mesh) {
    std::vector<vtkDataArray*> all = { mesh->GetPoints() ? mesh->GetPoints()->GetData() : nullptr };
    for (vtkFieldData* data : { static_cast<vtkFieldData*>(mesh->GetPointData()), static_cast<vtkFieldData*>(mesh->GetCellData()) })
    {
      for (int a = 0; a < data->GetNumberOfArrays(); ++a)
      {
        all.push_back(data->GetArray(a));
      }
    }
    return all;
  };
  const std::vector<vtkDataArray*> inputs = arrays(input);
  const std::set<vtkDataArray*> shared(inputs.begin(), inputs.end());
  for (vtkDataArray* array : arrays(output))
  {
    if (shared.count(array) == 0)
    {
      RecordRanges(array, context);
    }
  }
}

}
