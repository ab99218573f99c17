// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParallelDecimation.h"

#include "ParallelDecimation.h"

#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkParallelDecimation);

vtkParallelDecimation::vtkParallelDecimation()
{
  this->TargetTolerance = meshsimp::ParallelDecimationOptions().Goal.Tolerance;
}

bool vtkParallelDecimation::RunCore(const PieceCall& piece, meshsimp::SimplifiedMesh& result)
{
  const meshsimp::ParallelDecimationParameters& own = *this;
  return RunWith(meshsimp::ParallelDecimation, own, piece, result);
}

namespace
{
static_assert(vtkParallelDecimation::AVERAGE_PLANE == static_cast<int>(meshsimp::ImportanceMeasure::AveragePlane) &&
    vtkParallelDecimation::QUADRIC == static_cast<int>(meshsimp::ImportanceMeasure::Quadric) &&
    vtkParallelDecimation::LEAST_AREA_CHANGE == static_cast<int>(meshsimp::HalfEdgeChoice::LeastAreaChange) &&
    vtkParallelDecimation::SHORTEST_EDGE == static_cast<int>(meshsimp::HalfEdgeChoice::ShortestEdge),
  "the property values are the core's");

/// A setter's clamp for the core's enumerations, which VTK's macros do not take: false when the
/// value does not change.
template <class Enumeration>
bool SetClamped(Enumeration& member, int value, int last)
{
  const auto clamped = static_cast<Enumeration>(std::clamp(value, 0, last));
  const bool changed = member != clamped;
  member = clamped;
  return changed;
}
}

void vtkParallelDecimation::SetImportanceMeasure(int measure)
{
  if (SetClamped(this->Measure, measure, QUADRIC))
  {
    this->Modified();
  }
}

int vtkParallelDecimation::GetImportanceMeasure() const
{
  return static_cast<int>(this->Measure);
}

void vtkParallelDecimation::SetHalfEdgeChoice(int choice)
{
  if (SetClamped(this->Choice, choice, SHORTEST_EDGE))
  {
    this->Modified();
  }
}

int vtkParallelDecimation::GetHalfEdgeChoice() const
{
  return static_cast<int>(this->Choice);
}

void vtkParallelDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  meshsimp::PrintParameters<meshsimp::ParallelDecimationParameters>(*this, os, indent);
}

void vtkParallelDecimation::ForEachOwnSetting(const meshsimp::SettingVisit& visit)
{
  meshsimp::VisitParameters<meshsimp::ParallelDecimationParameters>(*this, visit);
}
