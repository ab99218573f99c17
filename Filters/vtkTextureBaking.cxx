// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTextureBaking.h"

#include "TextureAtlas.h"
#include "TextureBaking.h"
#include "vtkSimplificationDistributed.h"
#include "vtkSimplificationInput.h"
#include "vtkSimplificationPieces.h"
#include "vtkSimplificationThreads.h"
#include "vtkTextureBakingColours.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkScalarsToColors.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTextureBaking);
vtkCxxSetObjectMacro(vtkTextureBaking, LookupTable, vtkScalarsToColors);

namespace
{
/// One input of the bake: its surfaces (the input, or the polygonal leaves of composite data;
/// under MPI every process's, in process order) and their triangles joined into one surface.
struct BakeInput
{
  std::vector<vtkSimplification::Piece> Pieces;
  std::vector<std::size_t> PiecesPerProcess;   // one count without MPI
  std::size_t FirstLocal = 0, LocalPieces = 0; // this process's pieces
  bool Composite = false;
  vtkSimplification::JoinedTriangles Joined;

  bool IsLocal(std::size_t k) const { return k >= this->FirstLocal && k < this->FirstLocal + this->LocalPieces; }

  /// Piece k in messages, before "the original": "" for one surface, else its block (the
  /// index among its process's polygonal blocks) and, under MPI, its process.
  std::string Name(std::size_t k) const
  {
    std::size_t process = 0, first = 0;
    while (process + 1 < this->PiecesPerProcess.size() && k >= first + this->PiecesPerProcess[process])
    {
      first += this->PiecesPerProcess[process++];
    }
    const std::string owner = this->PiecesPerProcess.size() > 1 ? "process " + std::to_string(process) + "'s " : "";
    return this->Composite ? owner + "block " + std::to_string(k - first) + " of " : owner.empty() ? "" : owner + "piece of ";
  }
};

/// This process's pieces of an input, each one's output placed in output's structure (where
/// output is given), without arrays shorter than their points or cells (a warning each). False
/// with a message in problem.
bool CollectInput(vtkAlgorithm* filter, vtkDataObject* input, vtkDataObject* output, BakeInput& side, std::string& problem)
{
  if (!vtkSimplification::CollectPieces(input, output, side.Pieces, problem))
  {
    return false;
  }
  side.Composite = vtkCompositeDataSet::SafeDownCast(input) != nullptr;
  for (vtkSimplification::Piece& piece : side.Pieces)
  {
    // A surface AsSurface made carries its points' and cells' ids in the dataset: not arrays
    // the user gave, so not carried.
    if (!side.Composite && piece.Input.GetPointer() != input)
    {
      piece.Input->GetPointData()->RemoveArray(vtkSimplification::SurfacePointIdsName);
      piece.Input->GetCellData()->RemoveArray(vtkSimplification::SurfaceCellIdsName);
    }
    piece.Input = vtkSimplification::WithUsableAttributes(filter, piece.Input);
  }
  side.LocalPieces = side.Pieces.size();
  return true;
}

/// The other processes' pieces added (collective under MPI: every process then holds every
/// piece, so the checks below agree), every piece's triangles read and joined. False with a
/// message in problem, or after PrepareTriangles' own error (problem empty).
bool PrepareInput(vtkAlgorithm* filter, BakeInput& side, std::string& problem)
{
  std::vector<vtkPolyData*> local;
  for (const vtkSimplification::Piece& piece : side.Pieces)
  {
    local.push_back(piece.Input);
  }
  std::vector<vtkSmartPointer<vtkPolyData>> all;
  if (!vtkSimplification::GatherSurfaces(local, all, side.PiecesPerProcess))
  {
    problem = "the pieces of the other processes did not arrive";
    return false;
  }
  const int process = vtkSimplification::IsDistributed() ? vtkMultiProcessController::GetGlobalController()->GetLocalProcessId() : 0;
  side.FirstLocal = std::accumulate(side.PiecesPerProcess.begin(), side.PiecesPerProcess.begin() + process, std::size_t{ 0 });
  std::vector<vtkSimplification::Piece> pieces(all.size());
  for (std::size_t k = 0; k < all.size(); ++k)
  {
    if (side.IsLocal(k))
    {
      pieces[k] = std::move(side.Pieces[k - side.FirstLocal]);
    }
    pieces[k].Input = all[k];
  }
  side.Pieces = std::move(pieces);
  for (vtkSimplification::Piece& piece : side.Pieces)
  {
    if (!vtkSimplification::PrepareTriangles(filter, piece.Input, piece.Triangles))
    {
      return false;
    }
  }
  return vtkSimplification::JoinTriangles(side.Pieces, side.Joined, problem);
}

/// The atlas's squares whose triangles are this process's: the texels it bakes (under MPI each
/// process bakes its own squares of the one atlas, and the textures are merged).
meshsimp::TextureAtlas OwnSquares(const meshsimp::TextureAtlas& atlas, const BakeInput& simplified)
{
  meshsimp::TextureAtlas own = atlas;
  const std::int64_t first = simplified.Joined.FirstTriangle[simplified.FirstLocal];
  const std::int64_t end = simplified.Joined.FirstTriangle[simplified.FirstLocal + simplified.LocalPieces];
  own.Squares.erase(std::remove_if(own.Squares.begin(), own.Squares.end(),
                      [&](const meshsimp::AtlasSquare& square) { return square.Triangles[0] < first || square.Triangles[0] >= end; }),
    own.Squares.end());
  return own;
}

/// Where the split surface's points and triangles go: per piece, its points and triangles in
/// the split's order, and each point's index among its piece's.
struct SplitParts
{
  std::vector<std::vector<std::int32_t>> Points, Triangles;
  std::vector<std::int32_t> Local;
};

SplitParts SortOut(const meshsimp::SeamSplit& split, const vtkSimplification::JoinedTriangles& joined)
{
  SplitParts parts;
  parts.Points.resize(joined.FirstPoint.size() - 1);
  parts.Triangles.resize(parts.Points.size());
  parts.Local.resize(split.SourcePoints.size());
  for (std::size_t p = 0; p < split.SourcePoints.size(); ++p)
  {
    std::vector<std::int32_t>& piece = parts.Points[joined.PieceOfPoint(split.SourcePoints[p])];
    parts.Local[p] = static_cast<std::int32_t>(piece.size());
    piece.push_back(static_cast<std::int32_t>(p));
  }
  for (std::size_t t = 0; t < split.SourceTriangles.size(); ++t)
  {
    parts.Triangles[joined.PieceOfPoint(split.SourcePoints[split.Triangles[3 * t]])].push_back(static_cast<std::int32_t>(t));
  }
  return parts;
}

/// Piece k of the simplified surface: its triangles, split at the atlas's seams, with texture
/// coordinates and its point and cell data.
void WriteMesh(const BakeInput& simplified, std::size_t k, const meshsimp::SeamSplit& split, const SplitParts& parts)
{
  vtkPolyData* surface = simplified.Pieces[k].Input;
  vtkPolyData* output = simplified.Pieces[k].Output;
  const std::vector<std::int32_t>& pointIds = parts.Points[k];
  const vtkIdType points = static_cast<vtkIdType>(pointIds.size());
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataType(surface->GetPoints()->GetDataType());
  coordinates->SetNumberOfPoints(points);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(points);
  vtkNew<vtkIdList> from, to;
  from->SetNumberOfIds(points);
  to->SetNumberOfIds(points);
  for (vtkIdType p = 0; p < points; ++p)
  {
    const vtkIdType source = split.SourcePoints[pointIds[p]] - simplified.Joined.FirstPoint[k];
    coordinates->SetPoint(p, surface->GetPoint(source));
    tcoords->SetTypedTuple(p, split.TextureCoordinates.data() + 2 * pointIds[p]);
    from->SetId(p, source);
    to->SetId(p, p);
  }
  output->SetPoints(coordinates);
  output->GetPointData()->CopyAllocate(surface->GetPointData(), points);
  output->GetPointData()->CopyData(surface->GetPointData(), from, to);
  output->GetPointData()->SetTCoords(tcoords);

  const std::vector<std::int32_t>& triangleIds = parts.Triangles[k];
  const vtkIdType cells = static_cast<vtkIdType>(triangleIds.size());
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(cells, 3 * cells);
  from->SetNumberOfIds(cells);
  to->SetNumberOfIds(cells);
  for (vtkIdType t = 0; t < cells; ++t)
  {
    const std::int32_t* corners = split.Triangles.data() + 3 * triangleIds[t];
    const vtkIdType local[3] = { parts.Local[corners[0]], parts.Local[corners[1]], parts.Local[corners[2]] };
    polys->InsertNextCell(3, local);
    from->SetId(t, simplified.Pieces[k].Triangles.SourceCell(split.SourceTriangles[triangleIds[t]] - simplified.Joined.FirstTriangle[k]));
    to->SetId(t, t);
  }
  output->SetPolys(polys);
  output->GetCellData()->CopyAllocate(surface->GetCellData(), cells);
  output->GetCellData()->CopyData(surface->GetCellData(), from, to);
  output->GetFieldData()->PassData(surface->GetFieldData());
}

/// Per point of the joined simplified surface, the point of the joined original it came from:
/// its piece's vtkOriginalPointIds, read in the original's piece at the same place, where in
/// range (-1 elsewhere); none when no piece has them or the two inputs' pieces do not match
/// (as many on every process).
std::vector<std::int32_t> Seeds(const BakeInput& simplified, const BakeInput& original)
{
  std::vector<std::int32_t> seeds;
  for (std::size_t k = 0; simplified.PiecesPerProcess == original.PiecesPerProcess && k < simplified.Pieces.size(); ++k)
  {
    vtkDataArray* ids = simplified.Pieces[k].Input->GetPointData()->GetArray("vtkOriginalPointIds");
    if (!ids || ids->GetNumberOfComponents() != 1)
    {
      continue;
    }
    seeds.resize(static_cast<std::size_t>(simplified.Joined.FirstPoint.back()), -1);
    const std::int64_t first = original.Joined.FirstPoint[k], count = original.Joined.FirstPoint[k + 1] - first;
    const vtkIdType points = std::min<vtkIdType>(ids->GetNumberOfTuples(), simplified.Pieces[k].Triangles.View.NumberOfPoints);
    for (vtkIdType p = 0; p < points; ++p)
    {
      const double id = ids->GetComponent(p, 0);
      if (id >= 0.0 && id < static_cast<double>(count))
      {
        seeds[simplified.Joined.FirstPoint[k] + p] = static_cast<std::int32_t>(first + static_cast<std::int64_t>(id));
      }
    }
  }
  return seeds;
}

/// The length of the diagonal of the box around every piece of an input.
double Diagonal(const BakeInput& side)
{
  vtkBoundingBox box;
  for (const vtkSimplification::Piece& piece : side.Pieces)
  {
    box.AddBounds(piece.Input->GetBounds());
  }
  return box.IsValid() ? box.GetDiagonalLength() : 0.0;
}

/// Both inputs read, with a one-line error where one cannot be; false then, and on every
/// process where one could not read its pieces (collective under MPI).
bool ReadInputs(vtkAlgorithm* filter, vtkDataObject* const given[2], vtkDataObject* output, BakeInput& simplified, BakeInput& original)
{
  std::string problem;
  const char* side = "simplified";
  bool read = CollectInput(filter, given[0], output, simplified, problem);
  if (read)
  {
    side = "original";
    read = CollectInput(filter, given[1], nullptr, original, problem);
  }
  if (!read && !problem.empty())
  {
    vtkErrorWithObjectMacro(filter, "Cannot bake: the " << side << " surface: " << problem << ".");
  }
  if (vtkSimplification::SumOverProcesses(read ? 0.0 : 1.0) > 0.0) // one process could not: all stop
  {
    return false;
  }
  read = PrepareInput(filter, simplified, problem);
  side = read ? "original" : "simplified";
  read = read && PrepareInput(filter, original, problem);
  if (!read && !problem.empty())
  {
    vtkErrorWithObjectMacro(filter, "Cannot bake: the " << side << " surface: " << problem << ".");
  }
  return read;
}

/// The texture: the baked colours (under MPI, each process's squares merged into one texture
/// that every process holds) and the counts as field data, summed over the processes.
void WriteTexture(const meshsimp::BakedTexture& baked, vtkUnsignedCharArray* colours, int size, vtkImageData* texture)
{
  vtkSimplification::MaximumOverProcesses(colours->GetPointer(0), colours->GetNumberOfValues());
  texture->SetDimensions(size, size, 1);
  texture->GetPointData()->SetScalars(colours);
  const std::pair<const char*, std::int64_t> counts[] = { { "TriangleTexels", baked.InsideTexels },
    { "EmptyTexels", baked.EmptyTexels }, { "ExactSearches", baked.ExactSearches }, { "CorrectedWalks", baked.CorrectedWalks } };
  for (const auto& [name, count] : counts)
  {
    vtkNew<vtkIdTypeArray> value;
    value->SetName(name);
    value->InsertNextValue(static_cast<vtkIdType>(vtkSimplification::SumOverProcesses(static_cast<double>(count))));
    texture->GetFieldData()->AddArray(value);
  }
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

vtkTypeBool vtkTextureBaking::ProcessRequest(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    vtkSimplification::MakeSurfacesOutput(vtkDataObject::GetData(inputs[0], 0), outputs->GetInformationObject(0));
    return 1;
  }
  return this->Superclass::ProcessRequest(request, inputs, outputs);
}

int vtkTextureBaking::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

int vtkTextureBaking::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkDataObject");
  return 1;
}

int vtkTextureBaking::RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputs)
{
  const int last = PowerOfTwo(this->TextureSize) - 1;
  const int extent[6] = { 0, last, 0, last, 0, 0 };
  outputs->GetInformationObject(1)->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

int vtkTextureBaking::RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  this->Superclass::RequestUpdateExtent(request, inputs, outputs);
  if (!vtkSimplification::IsDistributed())
  {
    return 1;
  }
  // Under MPI every process takes its own piece of both surfaces whichever output asks, so that
  // all bake the one texture of the whole surface (a texture consumer asks for the whole image,
  // one piece), and the whole texture image, which every piece looks its colours up in.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  for (int port = 0; port < 3; ++port)
  {
    for (int connection = 0; connection < inputs[port]->GetNumberOfInformationObjects(); ++connection)
    {
      vtkInformation* input = inputs[port]->GetInformationObject(connection);
      const bool whole = port == 2;
      input->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), whole ? 0 : controller->GetLocalProcessId());
      input->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), whole ? 1 : controller->GetNumberOfProcesses());
      if (whole && input->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
      {
        input->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), input->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      }
    }
  }
  return 1;
}

int vtkTextureBaking::RequestData(vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  // Until the texels are baked, the texture has the declared extent and no texels: a consumer
  // that asks for the whole image then does not run a filter that failed again (and repeat its
  // error) until something changes.
  vtkImageData::GetData(outputs, 1)->SetExtent(outputs->GetInformationObject(1)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()));
  vtkImageData* image = vtkImageData::GetData(inputs[2]);
  vtkDataObject* given[2] = { vtkDataObject::GetData(inputs[0]), vtkDataObject::GetData(inputs[1]) };
  if (!given[0] || !given[1])
  {
    vtkErrorMacro("Cannot bake: Texture Baking needs the simplified surface (input 0) and the original (input 1).");
    return 1;
  }
  BakeInput simplified, original;
  if (!ReadInputs(this, given, vtkDataObject::GetData(outputs, 0), simplified, original))
  {
    return 1;
  }
  std::string problem = simplified.Joined.View.NumberOfTriangles == 0 ? "the simplified surface has no triangles"
    : original.Joined.View.NumberOfTriangles == 0                     ? "the original has no triangles"
                                                                      : "";
  vtkSimplification::BakeSource source;
  if (problem.empty())
  {
    std::vector<std::string> names;
    for (std::size_t k = 0; k < original.Pieces.size(); ++k)
    {
      names.push_back(original.Name(k));
    }
    source = vtkSimplification::ChooseBakeSource(this, original.Pieces, names, image, problem);
  }
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot bake: " << problem << ".");
    return 1;
  }
  const meshsimp::TextureAtlas atlas = meshsimp::MakeTextureAtlas(simplified.Joined.View, PowerOfTwo(this->TextureSize), this->GutterWidth);
  if (!atlas.Error.empty())
  {
    vtkErrorMacro("Cannot bake: " << atlas.Error << "; raise Texture Size or lower Gutter Width.");
    return 1;
  }
  vtkSimplification::ReadBakeValues(source, original.Pieces);
  this->UpdateProgress(0.05);
  const bool distributed = vtkSimplification::IsDistributed();
  const meshsimp::ExecutionContext context = vtkSimplification::MakeExecutionContext(this, 0);
  const meshsimp::BakedTexture baked = meshsimp::BakeTexels(simplified.Joined.View, distributed ? OwnSquares(atlas, simplified) : atlas,
    original.Joined.View, { source.Values.data(), source.Components, source.PerTriangle }, Seeds(simplified, original),
    this->MaximumDistance * Diagonal(original), context);
  if (vtkSimplification::SumOverProcesses(baked.Aborted ? 1.0 : 0.0) > 0.0)
  {
    return 1;
  }
  const meshsimp::SeamSplit split = meshsimp::SplitAtSeams(simplified.Joined.View, atlas);
  const SplitParts parts = SortOut(split, simplified.Joined);
  for (std::size_t k = simplified.FirstLocal; k < simplified.FirstLocal + simplified.LocalPieces; ++k)
  {
    WriteMesh(simplified, k, split, parts);
  }
  WriteTexture(baked, vtkSimplification::BakedColours(source, baked, this->LookupTable, image), atlas.Size, vtkImageData::GetData(outputs, 1));
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
