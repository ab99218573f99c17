// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLODInterpolation.h"

#include "LODInterpolation.h"
#include "vtkSimplificationInput.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"
#include "vtkStaticPointLocator.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLODInterpolation);

/// The correspondence and what it was built from (the inputs, their modification times, the
/// mode): rebuilt only when one of them changes.
struct vtkLODInterpolation::Cache
{
  vtkPolyData* Detailed = nullptr;
  vtkPolyData* Coarse = nullptr;
  vtkMTimeType DetailedTime = 0, CoarseTime = 0; // their geometry's (GeometryTime)
  int Mode = -1;
  vtkSimplification::TriangleInput DetailedTriangles, CoarseTriangles;
  meshsimp::MorphPartners Partners;
  double Diagonal = 0.0;
};

namespace
{
/// When a surface's points or cells last changed. (Not the data object's time: ParaView's
/// pipeline touches a source's point, cell and field data on every update downstream, which
/// would rebuild the correspondence at every frame.)
vtkMTimeType GeometryTime(vtkPolyData* mesh)
{
  vtkMTimeType time = 0;
  for (vtkObject* part : { static_cast<vtkObject*>(mesh->GetPoints()), static_cast<vtkObject*>(mesh->GetPolys()),
         static_cast<vtkObject*>(mesh->GetStrips()), static_cast<vtkObject*>(mesh->GetVerts()),
         static_cast<vtkObject*>(mesh->GetLines()) })
  {
    time = std::max(time, part ? part->GetMTime() : 0);
  }
  vtkPoints* points = mesh->GetPoints();
  return points && points->GetData() ? std::max(time, points->GetData()->GetMTime()) : time;
}

/// The surface's triangles as the view lists them (polygons triangulated), on the surface's own
/// points, for VTK's cell locator: its cell ids are the view's triangle ids.
vtkSmartPointer<vtkPolyData> Triangles(vtkPolyData* surface, const meshsimp::TriangleMeshView& view)
{
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(view.NumberOfTriangles, 3 * view.NumberOfTriangles);
  for (vtkIdType t = 0; t < view.NumberOfTriangles; ++t)
  {
    const vtkIdType ids[3] = { view.Id(3 * t), view.Id(3 * t + 1), view.Id(3 * t + 2) };
    cells->InsertNextCell(3, ids);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(surface->GetPoints());
  mesh->SetPolys(cells);
  return mesh;
}

/// Per point of from, the id of the nearest point of to (VTK's static point locator).
std::vector<std::int32_t> NearestPoints(const meshsimp::TriangleMeshView& from, vtkPolyData* to)
{
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(to);
  locator->BuildLocator();
  std::vector<std::int32_t> nearest(static_cast<std::size_t>(from.NumberOfPoints), -1);
  vtkSMPTools::For(0, from.NumberOfPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType p = begin; p < end; ++p)
    {
      nearest[p] = static_cast<std::int32_t>(locator->FindClosestPoint(from.Point(p).data()));
    }
  });
  return nearest;
}

/// The barycentric weights of x (on or near the triangle a, b, c) in it.
Eigen::Vector3d Barycentric(const Eigen::Vector3d& x, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
  const Eigen::Vector3d& c)
{
  const Eigen::Vector3d u = b - a, v = c - a, w = x - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
  const double det = uu * vv - uv * uv;
  if (!(det > 0.0))
  {
    return Eigen::Vector3d::Constant(1.0 / 3.0); // a degenerate triangle: its centre
  }
  const double beta = (vv * wu - uv * wv) / det, gamma = (uu * wv - uv * wu) / det;
  return { 1.0 - beta - gamma, beta, gamma };
}

/// Per detailed point, the coarse triangle whose closest point it goes to and that point's
/// barycentric weights (VTK's static cell locator).
meshsimp::MorphPartners SurfacePartners(
  const meshsimp::TriangleMeshView& detailed, vtkPolyData* coarseSurface, const meshsimp::TriangleMeshView& coarse)
{
  vtkNew<vtkStaticCellLocator> locator;
  locator->SetDataSet(Triangles(coarseSurface, coarse));
  locator->BuildLocator();
  std::vector<std::int32_t> triangle(static_cast<std::size_t>(detailed.NumberOfPoints), -1);
  std::vector<double> barycentric(3 * triangle.size(), 0.0);
  vtkSMPThreadLocalObject<vtkGenericCell> cells;
  vtkSMPTools::For(0, detailed.NumberOfPoints, [&](vtkIdType begin, vtkIdType end) {
    vtkGenericCell* cell = cells.Local();
    for (vtkIdType p = begin; p < end; ++p)
    {
      double closest[3], distance2 = 0.0;
      vtkIdType id = -1;
      int sub = 0;
      locator->FindClosestPoint(detailed.Point(p).data(), closest, cell, id, sub, distance2);
      if (id < 0)
      {
        continue;
      }
      triangle[p] = static_cast<std::int32_t>(id);
      const Eigen::Vector3d weights = Barycentric(Eigen::Vector3d(closest), coarse.Point(coarse.Id(3 * id)),
        coarse.Point(coarse.Id(3 * id + 1)), coarse.Point(coarse.Id(3 * id + 2)));
      std::copy(weights.data(), weights.data() + 3, barycentric.begin() + 3 * p);
    }
  });
  return meshsimp::PairSurfacePoints(detailed, coarse, triangle, barycentric);
}

/// The detailed surface's point array morphed for the frame: each output point the mean over
/// the detailed points it stands for of (1 − t) their value + t their partners' (from the
/// coarse array of the same name, where there is one and they have partners); integer arrays
/// keep the first source's detailed value.
vtkSmartPointer<vtkDataArray> MorphArray(vtkDataArray* detailed, vtkDataArray* coarse, const meshsimp::MorphPartners& partners,
  const meshsimp::MorphFrame& frame, double t)
{
  const int components = detailed->GetNumberOfComponents();
  const int type = detailed->GetDataType();
  const bool morphs = coarse && coarse->GetNumberOfComponents() == components && (type == VTK_FLOAT || type == VTK_DOUBLE);
  auto out = vtkSmartPointer<vtkDataArray>::Take(detailed->NewInstance());
  out->SetName(detailed->GetName());
  out->SetNumberOfComponents(components);
  out->SetNumberOfTuples(frame.NumberOfPoints());
  std::vector<double> value(components), own(components), towards(components), partner(components);
  for (vtkIdType g = 0; g < frame.NumberOfPoints(); ++g)
  {
    const std::int32_t first = frame.PointOffsets[g], last = morphs ? frame.PointOffsets[g + 1] : first + 1;
    std::fill(value.begin(), value.end(), 0.0);
    for (std::int32_t s = first; s < last; ++s)
    {
      const std::size_t d = static_cast<std::size_t>(frame.PointSources[s]);
      detailed->GetTuple(static_cast<vtkIdType>(d), own.data());
      towards = own;
      if (morphs && partners.Coarse[3 * d] >= 0)
      {
        std::fill(towards.begin(), towards.end(), 0.0);
        for (int j = 0; j < 3 && partners.Coarse[3 * d + j] >= 0; ++j)
        {
          coarse->GetTuple(partners.Coarse[3 * d + j], partner.data());
          for (int k = 0; k < components; ++k)
          {
            towards[k] += partners.Weights[3 * d + j] * partner[k];
          }
        }
      }
      for (int k = 0; k < components; ++k)
      {
        value[k] += ((1.0 - t) * own[k] + t * towards[k]) / (last - first);
      }
    }
    out->SetTuple(g, value.data());
  }
  return out;
}

/// Every numeric point array of the detailed surface, morphed; the active attributes kept
/// active, the normals renormalised.
void MorphPointData(vtkPointData* detailed, vtkPointData* coarse, const meshsimp::MorphPartners& partners,
  const meshsimp::MorphFrame& frame, double t, vtkPointData* output, vtkIdType detailedPoints)
{
  for (int i = 0; i < detailed->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = detailed->GetArray(i);
    if (!array || array->GetNumberOfTuples() != detailedPoints || !array->GetName())
    {
      continue;
    }
    vtkDataArray* match = coarse->GetArray(array->GetName());
    vtkSmartPointer<vtkDataArray> morphed = MorphArray(array, match, partners, frame, t);
    const int attribute = detailed->IsArrayAnAttribute(i);
    output->AddArray(morphed);
    if (attribute >= 0)
    {
      output->SetActiveAttribute(morphed->GetName(), attribute);
    }
  }
  vtkDataArray* normals = output->GetNormals();
  for (vtkIdType p = 0; normals && normals->GetNumberOfComponents() == 3 && p < normals->GetNumberOfTuples(); ++p)
  {
    Eigen::Vector3d n;
    normals->GetTuple(p, n.data());
    const double length = n.norm();
    if (length > 0.0 && std::isfinite(length))
    {
      n /= length;
      normals->SetTuple(p, n.data());
    }
  }
}

/// The frame's points, and its triangles with the detailed surface's cell data. Where no point
/// joined and the detailed surface is triangles alone, viewed in place, those are the detailed
/// surface's: shared, not copied.
void WriteGeometry(vtkPolyData* detailed, const vtkSimplification::TriangleInput& triangles,
  const meshsimp::MorphFrame& frame, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->SetNumberOfPoints(frame.NumberOfPoints());
  for (vtkIdType p = 0; p < frame.NumberOfPoints(); ++p)
  {
    points->SetPoint(p, frame.Points.data() + 3 * p);
  }
  output->SetPoints(points);
  const meshsimp::TriangleMeshView& view = triangles.View;
  if (frame.NumberOfPoints() == view.NumberOfPoints && frame.NumberOfTriangles() == view.NumberOfTriangles &&
    triangles.Triangles.empty() && triangles.FirstCell == 0 && detailed->GetNumberOfCells() == view.NumberOfTriangles)
  {
    output->SetPolys(detailed->GetPolys());
    output->GetCellData()->ShallowCopy(detailed->GetCellData());
    return;
  }
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(frame.NumberOfTriangles(), 3 * frame.NumberOfTriangles());
  for (vtkIdType t = 0; t < frame.NumberOfTriangles(); ++t)
  {
    const vtkIdType ids[3] = { frame.Triangles[3 * t], frame.Triangles[3 * t + 1], frame.Triangles[3 * t + 2] };
    cells->InsertNextCell(3, ids);
  }
  output->SetPolys(cells);
  output->GetCellData()->CopyAllocate(detailed->GetCellData(), frame.NumberOfTriangles());
  for (vtkIdType t = 0; t < frame.NumberOfTriangles(); ++t)
  {
    output->GetCellData()->CopyData(detailed->GetCellData(), triangles.SourceCell(frame.TriangleSource[t]), t);
  }
}
} // namespace

vtkLODInterpolation::vtkLODInterpolation()
  : Built(new Cache)
{
  this->SetNumberOfInputPorts(2);
}

vtkLODInterpolation::~vtkLODInterpolation() = default;

int vtkLODInterpolation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

bool vtkLODInterpolation::Pair(vtkPolyData* detailed, vtkPolyData* coarse)
{
  Cache& built = *this->Built;
  if (built.Detailed == detailed && built.Coarse == coarse && built.DetailedTime == GeometryTime(detailed) &&
    built.CoarseTime == GeometryTime(coarse) && built.Mode == this->Correspondence)
  {
    return true;
  }
  built = Cache();
  std::string problem;
  if (!vtkSimplification::ExtractTriangles(detailed, built.DetailedTriangles, problem) ||
    !vtkSimplification::ExtractTriangles(coarse, built.CoarseTriangles, problem))
  {
    vtkErrorMacro(<< "Cannot morph: " << problem << ".");
    built = Cache();
    return false;
  }
  const meshsimp::TriangleMeshView& d = built.DetailedTriangles.View;
  const meshsimp::TriangleMeshView& c = built.CoarseTriangles.View;
  if (d.NumberOfTriangles == 0 || c.NumberOfTriangles == 0)
  {
    vtkErrorMacro(<< "Cannot morph: the " << (d.NumberOfTriangles == 0 ? "detailed" : "coarse")
                  << " surface has no triangles.");
    built = Cache();
    return false;
  }
  built.Partners = this->Correspondence == NEAREST_VERTEX
    ? meshsimp::PairNearestVertices(d, c, NearestPoints(c, detailed), NearestPoints(d, coarse))
    : SurfacePartners(d, coarse, c);
  built.Diagonal = detailed->GetLength();
  built.Detailed = detailed;
  built.Coarse = coarse;
  built.DetailedTime = GeometryTime(detailed);
  built.CoarseTime = GeometryTime(coarse);
  built.Mode = this->Correspondence;
  ++this->CorrespondenceBuilds;
  return true;
}

int vtkLODInterpolation::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  vtkInformation* info = outputs->GetInformationObject(0);
  if (!this->InterpolationFromTime)
  {
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    return 1;
  }
  constexpr int steps = 21;
  double times[steps];
  for (int i = 0; i < steps; ++i)
  {
    times[i] = static_cast<double>(i) / (steps - 1);
  }
  const double range[2] = { 0.0, 1.0 };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times, steps);
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkLODInterpolation::RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  vtkPolyData* detailed = vtkPolyData::GetData(inputs[0]);
  vtkPolyData* coarse = vtkPolyData::GetData(inputs[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputs);
  output->Initialize(); // empty unless a frame is made
  if (!detailed || !coarse)
  {
    vtkErrorMacro("Cannot morph: LoD Interpolation needs two surfaces, the detailed one (input 0) and the coarse one "
                  "(input 1).");
    return 1;
  }
  if (!this->Pair(detailed, coarse))
  {
    return 1;
  }
  this->UpdateProgress(0.5);
  vtkInformation* request = outputs->GetInformationObject(0);
  const double t = this->InterpolationFromTime && request->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? std::min(1.0, std::max(0.0, request->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())))
    : this->Interpolation;
  const Cache& built = *this->Built;
  meshsimp::MorphFrame frame;
  meshsimp::Morph(built.DetailedTriangles.View, built.Partners, t, this->MergeDistance * built.Diagonal, frame);
  WriteGeometry(detailed, built.DetailedTriangles, frame, output);
  MorphPointData(detailed->GetPointData(), coarse->GetPointData(), built.Partners, frame, t,
    output->GetPointData(), built.DetailedTriangles.View.NumberOfPoints);
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("Displacement");
  displacement->SetNumberOfValues(frame.NumberOfPoints());
  std::copy(frame.Displacement.begin(), frame.Displacement.end(), displacement->GetPointer(0));
  output->GetPointData()->AddArray(displacement);
  output->GetFieldData()->PassData(detailed->GetFieldData());
  vtkNew<vtkIntArray> builds;
  builds->SetName("CorrespondenceBuilds");
  builds->InsertNextValue(this->CorrespondenceBuilds);
  output->GetFieldData()->AddArray(builds);
  return 1;
}

void vtkLODInterpolation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Interpolation: " << this->Interpolation << "\n";
  os << indent << "MergeDistance: " << this->MergeDistance << "\n";
  os << indent << "Correspondence: " << this->Correspondence << "\n";
  os << indent << "InterpolationFromTime: " << this->InterpolationFromTime << "\n";
  os << indent << "CorrespondenceBuilds: " << this->CorrespondenceBuilds << "\n";
}
