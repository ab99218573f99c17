// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVolumeTriangleCollapse.h"

#include "VolumeTriangleCollapse.h"
#include "vtkMeshSimplificationHelpers.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkVolumeTriangleCollapse);

vtkVolumeTriangleCollapse::vtkVolumeTriangleCollapse() = default;

namespace
{
/// Every point array of the input, replayed through the collapse records and gathered at the
/// output points; arrays that are not numeric, and labels and flags that VTK does not
/// interpolate (IsInterpolated), take the value of the surviving point.
void InterpolatePointData(vtkPointData* inPD, vtkPointData* outPD,
  const meshsimp::VolumeCollapseResult& result)
{
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(result.PointSource.size());
  vtkMeshSimplificationHelpers::CopySurvivorPointData(inPD, outPD, result.PointSource);
  std::vector<double> table;
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* in = inPD->GetArray(a);
    vtkDataArray* out = in && in->GetName() ? outPD->GetArray(in->GetName()) : nullptr;
    if (!in || !out || in->GetNumberOfTuples() == 0 ||
      !vtkMeshSimplificationHelpers::IsInterpolated(inPD, outPD, a))
    {
      continue;
    }
    const int components = in->GetNumberOfComponents();
    const vtkIdType n = in->GetNumberOfTuples();
    table.resize(static_cast<std::size_t>(n) * components);
    for (vtkIdType i = 0; i < n; ++i)
    {
      in->GetTuple(i, table.data() + i * components);
    }
    meshsimp::InterpolateAttributes(result.Records, table.data(), components);
    const bool integral = in->GetDataType() != VTK_FLOAT && in->GetDataType() != VTK_DOUBLE;
    for (vtkIdType p = 0; p < numberOfPoints; ++p)
    {
      double* value = table.data() + static_cast<vtkIdType>(result.PointSource[p]) * components;
      if (integral)
      {
        for (int c = 0; c < components; ++c)
        {
          value[c] = std::round(value[c]);
        }
      }
      out->SetTuple(p, value);
    }
  }
}
}

int vtkVolumeTriangleCollapse::SimplifyPiece(
  vtkPolyData* inputPiece, vtkPolyData* output, std::vector<std::uint8_t>& locked)
{
  vtkSmartPointer<vtkPolyData> input = inputPiece; // PrepareTriangles may replace it
  this->SquareVolumeError = 0.0;
  this->AchievedMaximumError = 0.0;

  vtkMeshSimplificationHelpers::TriangleInput triangles;
  int requestResult = 1;
  if (!vtkMeshSimplificationHelpers::PrepareTriangles(this, input, triangles, requestResult))
  {
    return requestResult;
  }
  if (!vtkMeshSimplificationHelpers::CheckTarget(this, this->TargetMode, this->TargetReduction, this->MaximumError))
  {
    return 0;
  }

  meshsimp::VolumeCollapseOptions options;
  const std::int64_t inputTriangles = triangles.View.NumberOfTriangles;
  const bool bounded = this->TargetMode == TARGET_MAXIMUM_ERROR;
  options.TargetTriangles = bounded ? 0
    : this->TargetMode == TARGET_TRIANGLE_COUNT
    ? static_cast<std::int64_t>(this->TargetTriangleCount)
    : static_cast<std::int64_t>(std::llround(inputTriangles * (1.0 - this->TargetReduction)));
  options.MaximumError = bounded ? this->MaximumError : -1.0;
  options.RelativeError = this->RelativeError;
  options.FeatureCurvature = this->FeatureCurvature;
  options.PreserveBoundary = this->PreserveBoundary;
  options.BoundaryCornerAngle = this->BoundaryCornerAngle;
  options.UseNormalFactor = this->UseNormalFactor;
  options.UseShapeFactor = this->UseShapeFactor;
  options.UseVolumeWeights = this->UseVolumeWeights;
  options.EdgeCollapses = this->EdgeCollapses;
  options.SurfaceErrorWeight = this->SurfaceErrorWeight;
  options.MinimumAngle = this->MinimumAngle;
  options.BatchSize = this->BatchSize;

  vtkMeshSimplificationHelpers::ReadLockedPoints(this, input, locked);
  if (!locked.empty())
  {
    options.LockedPoints = locked.data();
  }

  meshsimp::VolumeCollapseResult result;
  const bool finished = meshsimp::VolumeTriangleCollapse(triangles.View, options, result,
    vtkMeshSimplificationHelpers::MakeExecutionContext(this, this->NumberOfThreads));
  if (!vtkMeshSimplificationHelpers::ReportRun(this, finished, result.NonFinitePoints))
  {
    return 1;
  }
  const vtkIdType numberOfPoints = static_cast<vtkIdType>(result.PointSource.size());
  const vtkIdType numberOfTriangles = static_cast<vtkIdType>(result.TriangleSource.size());
  if (result.FinalMinimumAngle < this->MinimumAngle)
  {
    vtkWarningMacro(<< "The angle guard refused every collapse left before the target: lowered from "
                    << this->MinimumAngle << " to " << result.FinalMinimumAngle << " degrees.");
  }
  if (result.StoppedEarly && !bounded) // with a bound, stopping is how it ends
  {
    vtkWarningMacro(<< "Stopped at " << numberOfTriangles << " triangles ("
                    << result.TargetTriangles
                    << " asked for): no collapse is left that keeps the mesh valid."
                    << vtkMeshSimplificationHelpers::LockedPointsNote(locked, true));
  }

  vtkMeshSimplificationHelpers::SetOutputTriangles(input, output, triangles, result.Points,
    result.Triangles, result.TriangleSource, this->OutputPointsPrecision);

  vtkPointData* outPD = output->GetPointData();
  InterpolatePointData(input->GetPointData(), outPD, result);
  if (vtkDataArray* normals = outPD->GetNormals())
  {
    vtkMeshSimplificationHelpers::ComputePointNormals(result.Points, result.Triangles, normals);
  }
  vtkNew<vtkDoubleArray> pointError;
  pointError->SetName("SquareVolumeError");
  pointError->SetNumberOfValues(numberOfPoints);
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    pointError->SetValue(p, result.PointError[p]);
  }
  outPD->AddArray(pointError);

  this->SquareVolumeError = result.SquareVolumeError;
  vtkMeshSimplificationHelpers::AddFieldValue(output, "SquareVolumeError", result.SquareVolumeError);
  if (bounded)
  {
    this->AchievedMaximumError = result.AchievedMaximumError;
    vtkMeshSimplificationHelpers::AddFieldValue(output, "MaximumPlaneDistance", result.AchievedMaximumError);
    vtkMeshSimplificationHelpers::AddPointValues(output, "PlaneDistance", result.PlaneDistance);
  }
  return 1;
}

void vtkVolumeTriangleCollapse::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetMode: " << this->TargetMode << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetTriangleCount: " << this->TargetTriangleCount << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "RelativeError: " << this->RelativeError << "\n";
  os << indent << "AchievedMaximumError: " << this->AchievedMaximumError << "\n";
  os << indent << "FeatureCurvature: " << this->FeatureCurvature << "\n";
  os << indent << "PreserveBoundary: " << this->PreserveBoundary << "\n";
  os << indent << "BoundaryCornerAngle: " << this->BoundaryCornerAngle << "\n";
  os << indent << "UseNormalFactor: " << this->UseNormalFactor << "\n";
  os << indent << "UseShapeFactor: " << this->UseShapeFactor << "\n";
  os << indent << "UseVolumeWeights: " << this->UseVolumeWeights << "\n";
  os << indent << "EdgeCollapses: " << this->EdgeCollapses << "\n";
  os << indent << "SurfaceErrorWeight: " << this->SurfaceErrorWeight << "\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "BatchSize: " << this->BatchSize << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "SquareVolumeError: " << this->SquareVolumeError << "\n";
}
