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

/**
 * Each piece's triangles read (PrepareTriangles: a one-line error of filter's for a piece that
 * cannot be), the points each piece shares with another piece locked (collective under MPI:
 * every process calls it, whatever it holds), and for a shared execution the totals.
 */
void PreparePieces(vtkAlgorithm* filter, InputPieces& run);

} // namespace vtkSimplification

#endif
