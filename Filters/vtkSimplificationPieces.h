// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkSimplificationPieces.h
 * @brief The surfaces of one execution's input, and what they share (private to the module): the
 * front end's piece handling as a service, for the simplification filters and for a filter of
 * another shape (an image output, a second input) that works on the same surfaces.
 *
 * A vtkPolyData is one piece, any other surface dataset one through AsSurface, and each
 * polygonal leaf of composite data one (a multiblock's, a partitioned dataset's partitions).
 * Under MPI every process holds its own pieces of each, and PreparePieces runs collectively.
 */
#ifndef vtkSimplificationPieces_h
#define vtkSimplificationPieces_h

#include "vtkSimplificationDistributed.h"
#include "vtkSimplificationInput.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformation;
class vtkPolyData;

namespace vtkSimplification
{

/// One surface of the input, with its output and what the preparation found of it.
struct Piece
{
  vtkSmartPointer<vtkPolyData> Input; // with the attribute arrays it can use
  vtkPolyData* Output = nullptr;      // where its result goes (null when the caller's output is not surfaces)
  vtkIdType Key = 0;                  // pieces of one key are parts of one surface (see LockSharedPoints)
  TriangleInput Triangles;
  bool Readable = false;
  std::vector<std::uint8_t> Locks; // shared with other pieces, then the caller's (ReadLockedPoints)
  std::vector<std::uint8_t> UserLocked; // the caller's alone (a shared point may be both)
  std::int64_t SharedLocks = 0, UserLocks = 0; // PreparePieces counts the shared, the filter the user's
  std::string LockArray; // the user's lock array, for messages
};

/// One execution: its pieces, whether they share a target (several pieces, or several
/// processes: a count is shared out and a relative bound refers to the whole input's diagonal),
/// and the totals a count is shared out by.
struct InputPieces
{
  std::vector<Piece> Pieces;
  bool Shared = false;
  vtkSimplification::Totals Totals;

  /// The piece's name in messages ("" for a single piece).
  std::string Name(std::size_t i) const { return this->Shared ? "Block " + std::to_string(i) + ": " : ""; }
};

/**
 * The pieces of input, each with its output placed in output's structure (output may be null
 * for a caller whose output is not the simplified surfaces: then no piece has one); leaves that
 * are not polygonal data pass through unchanged. False with a message in problem when the input
 * is neither a surface nor composite data.
 */
bool CollectPieces(vtkDataObject* input, vtkDataObject* output, std::vector<Piece>& pieces, std::string& problem);

/// The output (of outInfo) that holds the pieces' surfaces: vtkPolyData, or for composite input
/// an empty instance of input's type, made anew only where the output is not of that type
/// already. For the data-object request of a filter whose port declares vtkDataObject.
void MakeSurfacesOutput(vtkDataObject* input, vtkInformation* outInfo);

/**
 * Each piece's triangles read (PrepareTriangles: a one-line error of filter's for a piece that
 * cannot be), the points each piece shares with another piece locked (collective under MPI:
 * every process calls it, whatever it holds), and for a shared execution the totals.
 */
void PreparePieces(vtkAlgorithm* filter, InputPieces& run);

/**
 * Pieces' triangles as one surface, for a filter that treats all of them at once (one texture
 * atlas for every block): their points and triangles one after the other, with where each
 * piece starts. A single piece is viewed in place; a triangle that cannot be used in its piece
 * cannot be used in the joined surface either.
 */
struct JoinedTriangles
{
  JoinedTriangles() = default;
  JoinedTriangles(const JoinedTriangles&) = delete; // View may point into the copies below
  JoinedTriangles& operator=(const JoinedTriangles&) = delete;
  JoinedTriangles(JoinedTriangles&&) = default;
  JoinedTriangles& operator=(JoinedTriangles&&) = default;

  meshsimp::TriangleMeshView View;
  std::vector<std::int64_t> FirstPoint, FirstTriangle; // per piece, then the totals
  std::vector<double> Points;                          // the copies (none for a single piece)
  std::vector<std::int32_t> Triangles;

  /// The piece that point p of View belongs to.
  std::size_t PieceOfPoint(std::int64_t p) const;
};

/// The pieces' triangles joined; false with a message in problem when the joined surface has
/// more points or triangles than 32-bit ids can number.
bool JoinTriangles(const std::vector<Piece>& pieces, JoinedTriangles& joined, std::string& problem);

} // namespace vtkSimplification

#endif
