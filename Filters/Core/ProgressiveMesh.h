// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProgressiveMesh.h
 * @brief Real-time progressive meshes (Wu and Fei): one build of the whole sequence of half-edge
 * collapses, then any level of detail as a prefix of it, without replaying a collapse.
 *
 * The build (BuildProgressiveMesh):
 * - The cost of the half-edge collapse x -> y (x removed, its triangles moved onto y) is a
 *   weighted sum (ProgressiveMeshParameters) of the L1 length |x - y|_1 and the curvature
 *   1 - N_ABC . N_ABD of the edge's two triangles (§4), the L1 distance of extra coordinates such
 *   as colours (§7) and, beyond the paper, the quadric error of y for the planes merged into x
 *   (by default the quadric error alone, chosen by the numbers: see ProgressiveMeshParameters).
 *   Each vertex's cost is that of its cheapest edge (Step 2); one heap of vertices (Step 3);
 *   after a collapse y is re-costed at once and its ring when it reaches the top (Step 5,
 *   lazily: a key that rose goes back under its true cost).
 * - Legality is a vertex-kind table plus an ordered list of checks that says which failed
 *   (named as the collapse engine names them, CollapseCheck): interior, border and fixed vertices (locked, non-manifold, pinched); a border
 *   vertex moves only along its border and never into the interior (§7); regions are never
 *   merged; the link condition; no new edge between two points shared with another piece
 *   (under MPI); no vertex loses its last triangle (nor a closed fan falls below three); no
 *   remaining triangle turns over or degenerates. The checks run when a vertex reaches
 *   the top of the heap, on its candidates in cost order; the first legal one is collapsed.
 * - It runs down to the coarsest mesh the checks allow. Flat arrays, no allocation per collapse.
 *
 * The sequence and its queries are in ProgressiveSequence.h.
 */
#ifndef MeshSimplification_ProgressiveMesh_h
#define MeshSimplification_ProgressiveMesh_h

#include "ProgressiveMeshParameters.h"
#include "ProgressiveSequence.h"
#include "Simplification.h"

#include <cstdint>
#include <vector>

namespace meshsimp
{

struct ProgressiveMeshOptions : SimplificationOptions, ProgressiveMeshParameters
{
  /// Optional extra coordinates per input point (colours, texture coordinates: §7), Dimension
  /// values each; the cost adds AttributeWeight times their L1 distance divided by ExtraScale
  /// (the caller's scale that brings them to [0, 1]).
  const double* ExtraCoordinates = nullptr;
  int ExtraDimension = 0;
  double ExtraScale = 1.0;
  /// The build stops once at most this many triangles remain (0: at the coarsest mesh the
  /// checks allow), for callers that want one level and not the whole sequence.
  std::int64_t StopTriangles = 0;
};


/// Builds the sequence of the usable input; returns false when aborted.
bool BuildProgressiveMesh(const TriangleMeshView& input, const ProgressiveMeshOptions& options,
  ProgressiveMesh& sequence, const ExecutionContext& context = {});

} // namespace meshsimp

#endif
