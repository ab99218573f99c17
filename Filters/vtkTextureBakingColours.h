// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkTextureBakingColours.h
 * @brief What Texture Baking shows (private to the module): the original's array, chosen by one
 * rule in every piece of the original, its values as the baker reads them, and the baked values
 * as the texture's colours.
 */
#ifndef vtkTextureBakingColours_h
#define vtkTextureBakingColours_h

#include "TextureBaking.h"
#include "vtkSimplificationPieces.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkImageData;
class vtkScalarsToColors;
class vtkUnsignedCharArray;

namespace vtkSimplification
{

/// What the texture shows, and the values the baker interpolates: per point or per triangle of
/// the original's pieces, one piece after the other.
struct BakeSource
{
  enum Kinds
  {
    COLOURS, // unsigned-char RGB(A), as they are
    MAPPED,  // any other array, through a lookup table
    TEXTURE  // texture coordinates, looked up in an image
  };
  Kinds Kind = COLOURS;
  std::vector<vtkDataArray*> Arrays; // per piece of the original (null for one without triangles)
  int Components = 0;
  bool PerTriangle = false;
  std::vector<float> Values;
};

/**
 * What the original's pieces show: with a texture image, their texture coordinates looked up in
 * it; else in every piece with triangles the array that input array 0 of filter selects, else
 * its active point scalars, else its first unsigned-char RGB(A) point array, else the same among
 * its cell data; all of one kind (colours or not), place and number of components. A one-line
 * reason in problem where nothing can be shown, which starts with the piece's name (names[k]).
 */
BakeSource ChooseBakeSource(vtkAlgorithm* filter, const std::vector<Piece>& original, const std::vector<std::string>& names,
  vtkImageData* image, std::string& problem);

/// The source's values as floats into source.Values, piece after piece.
void ReadBakeValues(BakeSource& source, const std::vector<Piece>& original);

/// The baked values as the texture's unsigned-char colours: RGB, or RGBA where the colours or the
/// image have alpha; mapped values through table (null: blue to red over the arrays' range).
/// Texels of no triangle are 0.
vtkSmartPointer<vtkUnsignedCharArray> BakedColours(const BakeSource& source, const meshsimp::BakedTexture& baked,
  vtkScalarsToColors* table, vtkImageData* image);

} // namespace vtkSimplification

#endif
