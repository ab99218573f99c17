// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMeshSimplificationFilter.h"

#include "vtkMeshSimplificationHelpers.h"

#include "vtkAlgorithm.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <functional>

vtkTypeBool vtkMeshSimplificationFilter::ProcessRequest(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
    vtkInformation* outInfo = outputVector->GetInformationObject(0);
    vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
    const bool composite = vtkCompositeDataSet::SafeDownCast(input) != nullptr;
    const int type = composite ? input->GetDataObjectType() : VTK_POLY_DATA;
    if (!output || output->GetDataObjectType() != type)
    {
      vtkSmartPointer<vtkDataObject> created = composite
        ? vtkSmartPointer<vtkDataObject>::Take(input->NewInstance())
        : vtkSmartPointer<vtkDataObject>(vtkSmartPointer<vtkPolyData>::New());
      outInfo->Set(vtkDataObject::DATA_OBJECT(), created);
    }
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int vtkMeshSimplificationFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkMeshSimplificationFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

int vtkMeshSimplificationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  // The pieces to simplify, keyed by their flat index in a composite input (0 for a vtkPolyData).
  std::vector<vtkPolyData*> inputs, outputs;
  std::vector<vtkIdType> keys;
  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  // A leaf to simplify, or a warning; place puts its output into the output's structure.
  const auto add = [&](vtkDataObject* block, vtkIdType key, const std::function<void(vtkPolyData*)>& place) {
    auto* piece = vtkPolyData::SafeDownCast(block);
    if (!piece)
    {
      vtkWarningMacro(<< "Skipping a block of type " << block->GetClassName() << ": not polygonal data.");
      return;
    }
    vtkNew<vtkPolyData> simplified;
    place(simplified);
    inputs.push_back(piece);
    outputs.push_back(simplified);
    keys.push_back(key);
  };
  auto* collection = vtkPartitionedDataSetCollection::SafeDownCast(input);
  auto* partitioned = vtkPartitionedDataSet::SafeDownCast(input);
  if (compositeInput && compositeOutput)
  {
    compositeOutput->CopyStructure(compositeInput);
  }
  if (collection && vtkPartitionedDataSetCollection::SafeDownCast(output))
  {
    // The partitions of one dataset are pieces of it: one key per partitioned dataset.
    auto* out = vtkPartitionedDataSetCollection::SafeDownCast(output);
    for (unsigned int d = 0; d < collection->GetNumberOfPartitionedDataSets(); ++d)
    {
      for (unsigned int p = 0; p < collection->GetNumberOfPartitions(d); ++p)
      {
        if (vtkDataObject* block = collection->GetPartitionAsDataObject(d, p))
        {
          add(block, d, [out, d, p](vtkPolyData* simplified) { out->SetPartition(d, p, simplified); });
        }
      }
    }
  }
  else if (partitioned && vtkPartitionedDataSet::SafeDownCast(output))
  {
    auto* out = vtkPartitionedDataSet::SafeDownCast(output);
    for (unsigned int p = 0; p < partitioned->GetNumberOfPartitions(); ++p)
    {
      if (vtkDataObject* block = partitioned->GetPartitionAsDataObject(p))
      {
        add(block, 0, [out, p](vtkPolyData* simplified) { out->SetPartition(p, simplified); });
      }
    }
  }
  else if (compositeInput && compositeOutput)
  {
    // Other trees (multiblock): a block's pieces on the processes share its flat index.
    vtkSmartPointer<vtkCompositeDataIterator> leaf = vtk::TakeSmartPointer(compositeInput->NewIterator());
    for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
    {
      add(leaf->GetCurrentDataObject(), static_cast<vtkIdType>(leaf->GetCurrentFlatIndex()),
        [&](vtkPolyData* simplified) { compositeOutput->SetDataSet(leaf, simplified); });
    }
  }
  else if (vtkPolyData::SafeDownCast(input) && vtkPolyData::SafeDownCast(output))
  {
    inputs.push_back(vtkPolyData::SafeDownCast(input));
    outputs.push_back(vtkPolyData::SafeDownCast(output));
    keys.push_back(0);
  }
  else
  {
    vtkErrorMacro(<< "Cannot simplify a " << (input ? input->GetClassName() : "missing input")
                  << ": polygonal data or composite data of it is needed.");
    return 0;
  }
  std::vector<std::vector<std::uint8_t>> locks;
  vtkMeshSimplificationHelpers::LockSharedPoints(inputs, keys, locks); // collective under MPI
  int result = 1;
  const double count = static_cast<double>(inputs.size());
  for (std::size_t i = 0; i < inputs.size() && !this->GetAbortExecute(); ++i)
  {
    this->SetProgressShiftScale(static_cast<double>(i) / count, 1.0 / count);
    result = this->SimplifyPiece(inputs[i], outputs[i], locks[i]) && result;
  }
  this->SetProgressShiftScale(0.0, 1.0);
  return result;
}

void vtkMeshSimplificationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
