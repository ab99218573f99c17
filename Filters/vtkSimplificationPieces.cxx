// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSimplificationPieces.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <functional>

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

} // namespace vtkSimplification
