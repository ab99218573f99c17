// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkTextureBaking
 * @brief Keeps the colours of a detailed surface on its simplified version in a texture: Zhou,
 * Zhang, Shi and Pan, "A new simplification algorithm for colored or textured polygonal
 * models", §4.
 *
 * Input 0 is the simplified surface, input 1 the detailed original (each polygonal data, any
 * dataset of surface cells, taken through vtkGeometryFilter as the simplifiers take it, or
 * composite data whose polygonal blocks together make the surface: one texture for all of
 * them), and what the original shows: an
 * unsigned-char RGB or RGBA point or cell array, shown as it is; any other array, through the
 * LookupTable (by default blue to red over the array's range, VTK's default colour map; a
 * vector array by its magnitude); or, with a texture image on input 2, the original's texture
 * coordinates looked up in that image (bilinear, repeated). The array is the one selected as
 * input array 0 (SetInputArrayToProcess on port 1), else the original's active point scalars,
 * else its first unsigned-char RGB(A) point array, else the same among its cell data; in
 * composite data, each block's by that rule, and the blocks' arrays must agree in kind, place
 * and components.
 *
 * Stage 1 gives every simplified triangle half of a square of a TextureSize² atlas, adjacent
 * triangles paired on one square along their common edge (meshsimp::MakeTextureAtlas); stage 2
 * gives each texel the colour of the original's point nearest to the point of the simplified
 * triangle it maps to, interpolated from that original triangle's corners (the values, before
 * any lookup table). The nearest point is found by walking over the original from the points
 * the simplified corners came from (the point data vtkOriginalPointIds, which every filter of
 * this module writes with GenerateOriginalIds; in composite data, ids into the original's block
 * at the same place) or else from an exact search for each square's
 * first texel; exact searches within MaximumDistance check the walks on a lattice of texels
 * and around every walk they correct (a walk can stop on the wrong hill of a rugged terrain).
 * Texels run on all threads (the result does not depend on how many). Under MPI every process
 * gathers all pieces of both inputs and bakes its own triangles' squares of the one atlas, and
 * the textures are merged: every process holds the whole texture, its piece the coordinates
 * into it; each process asks its inputs for its own piece, whichever output asks.
 *
 * Output 0 is the simplified surface's triangles with texture coordinates "TCoords" (points
 * split where the atlas puts a point's triangles apart, each copy with the point's data) and
 * its cell data, for composite input 0 in its blocks (other blocks passed unchanged); output 1
 * is the texture, vtkImageData of TextureSize² unsigned-char RGB (RGBA where the colours have
 * alpha) in the point array "BakedTexture"; texels of no triangle are 0. Its field data count
 * the texels on triangles (TriangleTexels), those that found no point of the original
 * (EmptyTexels), the squares searched for without a record (ExactSearches) and the texels whose
 * walk the exact search corrected (CorrectedWalks).
 * In the ParaView GUI the plugin shows output 0 with output 1 as its texture; elsewhere feed
 * output 1 to a texture of the representation (see the module's README); vtkOBJWriter takes it
 * on its second input.
 *
 * @sa vtkMeshSimplificationFilter vtkLODInterpolation
 */
#ifndef vtkTextureBaking_h
#define vtkTextureBaking_h

#include "MeshSimplificationFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class vtkImageData;
class vtkScalarsToColors;

class MESHSIMPLIFICATIONFILTERS_EXPORT vtkTextureBaking : public vtkPolyDataAlgorithm
{
public:
  static vtkTextureBaking* New();
  vtkTypeMacro(vtkTextureBaking, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Texels along each side of the texture: a power of two from 256 to 8192 (default 2048;
   * other values are rounded down to a power of two).
   */
  vtkSetClampMacro(TextureSize, int, 256, 8192);
  vtkGetMacro(TextureSize, int);
  ///@}

  ///@{
  /**
   * Texels around each square's triangles, filled with the nearest texel of its triangles, so
   * that bilinear filtering and the first mipmap levels do not mix in other squares (0 to 16;
   * default 2).
   */
  vtkSetClampMacro(GutterWidth, int, 0, 16);
  vtkGetMacro(GutterWidth, int);
  ///@}

  ///@{
  /**
   * How far from a texel's point (a fraction of the original's bounding-box diagonal; default
   * 0.05) the exact search looks for a point of the original nearer than where the texel's walk
   * ended. A texel with none that near keeps the walk's point however far it is: none is left
   * without a colour.
   */
  vtkSetClampMacro(MaximumDistance, double, 0.0, 1.0);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * The colours of an array that is not unsigned-char RGB(A); null (default): blue to red over
   * the array's range (a vector array by its magnitude).
   */
  virtual void SetLookupTable(vtkScalarsToColors* table);
  vtkGetObjectMacro(LookupTable, vtkScalarsToColors);
  ///@}

  /// The original (input 1) and a texture image for its texture coordinates (input 2).
  void SetOriginalConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetOriginalData(vtkDataObject* data) { this->SetInputData(1, data); }
  void SetTextureConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  void SetTextureData(vtkDataObject* data) { this->SetInputData(2, data); }

  /// The texture (output 1).
  vtkImageData* GetTexture();

  vtkMTimeType GetMTime() override;

protected:
  vtkTextureBaking();
  ~vtkTextureBaking() override;
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkTextureBaking(const vtkTextureBaking&) = delete;
  void operator=(const vtkTextureBaking&) = delete;

  int TextureSize = 2048;
  int GutterWidth = 2;
  double MaximumDistance = 0.05;
  vtkScalarsToColors* LookupTable = nullptr;
};

#endif
