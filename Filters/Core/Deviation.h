// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Deviation.h
 * @brief How far a simplified mesh is from its input, both ways, per output point: the error
 * array users colour by.
 *
 * Each output point p gets the largest of
 *  - its own distance to the input surface,
 *  - the distances to the input surface of points inside its triangles (their centres and
 *    edge middles: a triangle's inside can stand off the input where its corners do not,
 *    across a hole or a handle), and
 *  - the distances to the output surface of the input points it stands for
 *    (SimplifiedMesh::SourcePoints: the correspondence every algorithm keeps),
 * so that the largest value over the points is the two-sided (Hausdorff) distance between the
 * two meshes' vertices and surfaces, where one-way distances miss what a simplification cut off
 * (a peak flattened, a thin part removed) or, for an algorithm that keeps input points (a
 * progressive mesh), everything.
 *
 * The search starts where the correspondence puts each point: an output point's distance to the
 * input from the input triangles around the points it stands for, a sample inside an output
 * triangle from the input triangle it comes from, an input point's distance to the output from
 * the triangles around the output point that stands for it. From there a walk moves to a
 * triangle around a corner of the nearest while one is nearer, and stops where the point
 * stands over the nearest triangle's inside: a few triangle distances per point, no locator.
 * A walk can stop short where a surface folds back (the other side of a thin plate), which
 * only overestimates; so the largest values are measured again exactly (a grid of each
 * surface's triangles), from the top, until the next cannot exceed the largest measured: the
 * maximum is exact for the samples, and no point shows more than it. Input points that no
 * output point stands for (a part an algorithm dropped, a point the front end joined with
 * another at its place) are measured exactly and counted at the output point nearest to where
 * they land.
 *
 * Samples: the points of both meshes and the centres and edge middles of the output's
 * triangles; the input's triangles are sampled at their corners only, which a large input
 * triangle far from the output can exceed (see Deviation.md for the comparison with a sampled
 * two-sided distance over the corpus).
 */
#ifndef MeshSimplification_Deviation_h
#define MeshSimplification_Deviation_h

#include "Execution.h"
#include "Simplification.h"
#include "TriangleMesh.h"

#include <memory>
#include <vector>

namespace meshsimp
{

/**
 * The input side of the deviation, made once for several outputs of one input (the levels of a
 * progressive mesh): a copy of its points, its usable triangles (distinct points in range,
 * finite coordinates) and their adjacency, and its exact search when first needed.
 */
class DeviationInput
{
public:
  explicit DeviationInput(const TriangleMeshView& input);
  ~DeviationInput();
  struct Data;
  std::unique_ptr<Data> Impl;
};

/**
 * The deviation of each of output's points (in input units; see the top of the file).
 * Progress goes from 0 to 1 through context; returns an empty list when aborted.
 */
std::vector<double> TwoSidedDeviation(
  const DeviationInput& input, const SimplifiedMesh& output, const ExecutionContext& context);
/// The same for one output of input.
std::vector<double> TwoSidedDeviation(
  const TriangleMeshView& input, const SimplifiedMesh& output, const ExecutionContext& context);

} // namespace meshsimp

#endif
