// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationPieces.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace vtkSimplification
{

bool CollectPieces(vtkDataObject* input, vtkDataObject* output, std::vector<Piece>& pieces, std::string& problem)
{
  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  const auto add = [&](vtkDataObject* block, vtkIdType key, const std::function<void(vtkDataObject*)>& place) {
    auto* surface = vtkPolyData::SafeDownCast(block);
    if (!surface)
    {
      if (compositeOutput)
      {
        vtkSmartPointer<vtkDataObject> copy = vtk::TakeSmartPointer(block->NewInstance());
        copy->ShallowCopy(block);
        place(copy);
      }
      return;
    }
    Piece piece;
    piece.Input = surface;
    piece.Key = key;
    if (compositeOutput)
    {
      vtkNew<vtkPolyData> simplified;
      place(simplified);
      piece.Output = simplified;
    }
    pieces.push_back(std::move(piece));
  };
  if (!compositeInput)
  {
    Piece piece;
    piece.Input = AsSurface(input, problem);
    piece.Output = vtkPolyData::SafeDownCast(output);
    pieces.push_back(std::move(piece));
    return pieces.back().Input && (!output || pieces.back().Output);
  }
  if (compositeOutput)
  {
    compositeOutput->CopyStructure(compositeInput);
  }
  auto* collection = vtkPartitionedDataSetCollection::SafeDownCast(input);
  auto* partitioned = vtkPartitionedDataSet::SafeDownCast(input);
  if (collection)
  {
    // The partitions of one dataset are pieces of it: one key per partitioned dataset.
    auto* out = vtkPartitionedDataSetCollection::SafeDownCast(output);
    for (unsigned int d = 0; d < collection->GetNumberOfPartitionedDataSets(); ++d)
    {
      for (unsigned int p = 0; p < collection->GetNumberOfPartitions(d); ++p)
      {
        if (vtkDataObject* block = collection->GetPartitionAsDataObject(d, p))
        {
          add(block, d, [out, d, p](vtkDataObject* made) { out->SetPartition(d, p, made); });
        }
      }
    }
    return true;
  }
  if (partitioned)
  {
    auto* out = vtkPartitionedDataSet::SafeDownCast(output);
    for (unsigned int p = 0; p < partitioned->GetNumberOfPartitions(); ++p)
    {
      if (vtkDataObject* block = partitioned->GetPartitionAsDataObject(p))
      {
        add(block, 0, [out, p](vtkDataObject* made) { out->SetPartition(p, made); });
      }
    }
    return true;
  }
  // Other trees (multiblock): a block's pieces on the processes share its flat index.
  vtkSmartPointer<vtkCompositeDataIterator> leaf = vtk::TakeSmartPointer(compositeInput->NewIterator());
  for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
  {
    add(leaf->GetCurrentDataObject(), static_cast<vtkIdType>(leaf->GetCurrentFlatIndex()),
      [&](vtkDataObject* made) { compositeOutput->SetDataSet(leaf, made); });
  }
  return true;
}

void MakeSurfacesOutput(vtkDataObject* input, vtkInformation* outInfo)
{
  vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
  const bool composite = vtkCompositeDataSet::SafeDownCast(input) != nullptr;
  const int type = composite ? input->GetDataObjectType() : VTK_POLY_DATA;
  if (!output || output->GetDataObjectType() != type)
  {
    vtkSmartPointer<vtkDataObject> created = composite ? vtk::TakeSmartPointer(input->NewInstance())
                                                       : vtkSmartPointer<vtkDataObject>(vtkSmartPointer<vtkPolyData>::New());
    outInfo->Set(vtkDataObject::DATA_OBJECT(), created);
  }
}

void PreparePieces(vtkAlgorithm* filter, InputPieces& run)
{
  std::vector<const TriangleInput*> triangles;
  std::vector<vtkIdType> keys;
  for (Piece& piece : run.Pieces)
  {
    piece.Readable = PrepareTriangles(filter, piece.Input, piece.Triangles);
    triangles.push_back(piece.Readable ? &piece.Triangles : nullptr);
    keys.push_back(piece.Key);
  }
  run.Shared = run.Pieces.size() > 1 || IsDistributed();
  std::vector<std::vector<std::uint8_t>> locks;
  LockSharedPoints(triangles, keys, locks);
  for (std::size_t i = 0; i < run.Pieces.size(); ++i)
  {
    run.Pieces[i].Locks = std::move(locks[i]);
    run.Pieces[i].SharedLocks =
      std::count(run.Pieces[i].Locks.begin(), run.Pieces[i].Locks.end(), meshsimp::SharedPointLock);
  }
  if (run.Shared)
  {
    run.Totals = GatherTotals(triangles);
  }
}

std::size_t JoinedTriangles::PieceOfPoint(std::int64_t p) const
{
  return static_cast<std::size_t>(std::upper_bound(this->FirstPoint.begin(), this->FirstPoint.end(), p) - this->FirstPoint.begin()) - 1;
}

bool JoinTriangles(const std::vector<Piece>& pieces, JoinedTriangles& joined, std::string& problem)
{
  joined.FirstPoint.assign(1, 0);
  joined.FirstTriangle.assign(1, 0);
  for (const Piece& piece : pieces)
  {
    joined.FirstPoint.push_back(joined.FirstPoint.back() + piece.Triangles.View.NumberOfPoints);
    joined.FirstTriangle.push_back(joined.FirstTriangle.back() + piece.Triangles.View.NumberOfTriangles);
  }
  if (joined.FirstPoint.back() > std::numeric_limits<std::int32_t>::max() ||
    3 * joined.FirstTriangle.back() > std::numeric_limits<std::int32_t>::max())
  {
    problem = "the blocks together have more points or triangles than 32-bit ids can number";
    return false;
  }
  if (pieces.size() == 1)
  {
    joined.View = pieces[0].Triangles.View;
    return true;
  }
  joined.Points.reserve(3 * static_cast<std::size_t>(joined.FirstPoint.back()));
  joined.Triangles.reserve(3 * static_cast<std::size_t>(joined.FirstTriangle.back()));
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    const meshsimp::TriangleMeshView& view = pieces[i].Triangles.View;
    for (std::int64_t p = 0; p < view.NumberOfPoints; ++p)
    {
      const Eigen::Vector3d point = view.Point(p);
      joined.Points.insert(joined.Points.end(), point.data(), point.data() + 3);
    }
    for (std::int64_t t = 0; t < view.NumberOfTriangles; ++t)
    {
      // An unusable triangle's ids could name another piece's points once shifted: it gets
      // one repeated id instead, which keeps it unusable.
      const bool usable = meshsimp::UsableTriangle(view, t);
      for (int k = 0; k < 3; ++k)
      {
        const std::int64_t id = usable ? view.Id(3 * t + k) : 0;
        joined.Triangles.push_back(static_cast<std::int32_t>(joined.FirstPoint[i] + id));
      }
    }
  }
  joined.View.Points = joined.Points.data();
  joined.View.NumberOfPoints = joined.FirstPoint.back();
  joined.View.Triangles = joined.Triangles.data();
  joined.View.NumberOfTriangles = joined.FirstTriangle.back();
  return true;
}

} // namespace vtkSimplification
