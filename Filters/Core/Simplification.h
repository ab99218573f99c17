// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Simplification.h
 * @brief The core's front end: what every simplification algorithm is asked (a Target and the
 * constraints), the preparation they share, and the one result they all fill.
 *
 * An algorithm is a pipeline of stages on this front end:
 *  1. PrepareMesh: the usable triangles as a compact, spatially ordered mesh (MakeCompactMesh,
 *     zero-width cracks closed), normalised, with the target resolved to a count or a bound in
 *     the mesh's units, and each vertex's locks (the user's, piece borders, open borders) and
 *     attribute region;
 *  2. the algorithm's own stages on the prepared mesh;
 *  3. its output as a SimplifiedMesh: points, triangles, what each comes from (point data is
 *     mapped from SourcePoints and SourceWeights), the algorithm's per-point figures, and an
 *     Outcome that says why it stopped where it did.
 */
#ifndef MeshSimplification_Simplification_h
#define MeshSimplification_Simplification_h

#include "Execution.h"
#include "Target.h"
#include "TriangleMesh.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace meshsimp
{

class CollapseMesh;
struct CollapseRecord;

/// What every algorithm takes besides its own settings (their options derive from it).
struct SimplificationOptions
{
  Target Goal;
  /// Optional, one flag per input point: nonzero points are locked (kept where they are, never
  /// removed); SharedPointLock marks points shared with another piece of a distributed mesh.
  const std::uint8_t* LockedPoints = nullptr;
  /// Lock every point of an open border.
  bool PreserveBoundary = false;
  /// Optional, one id per input point: no collapse or cluster joins points of different ids, so
  /// borders between regions of a label or colour array stay sharp.
  const std::int32_t* Regions = nullptr;
  /// Close zero-width cracks (see MakeCompactMesh): two points at exactly the same position on
  /// the two sides of a crack become one vertex when their locks and regions agree and
  /// SamePointData says yes. Off for meshes an algorithm makes itself (whose coincident points
  /// it tells apart).
  bool CloseCracks = true;
  /// Optional: whether two input points (by id) carry the same point data (without it: always).
  std::function<bool(std::int64_t, std::int64_t)> SamePointData;
};

/// Why an algorithm ended where it did.
enum class StopReason : std::uint8_t
{
  TargetMet,        // the count within the tolerance, or as far as the error bound allows
  NothingRemovable, // no change that keeps the mesh valid is left before the count
  AllLocked,        // every usable point is locked
  NearestCount,     // no count nearer the target exists for this algorithm on this input
  Aborted
};

struct Outcome
{
  std::int64_t UsableTriangles = 0; // input triangles the algorithm could use
  std::int64_t UsablePoints = 0;    // input points of those triangles
  double Diagonal = 0.0;            // the usable points' bounding-box diagonal (input units)
  std::int64_t TargetTriangles = 0; // the target's count among them (0 under a bound)
  std::int64_t NonFinitePoints = 0; // input points with a NaN or infinite coordinate
  std::int64_t JoinedPoints = 0;    // input points joined to a coincident one to close a crack
  std::int64_t LockedPoints = 0;    // usable points locked (array, piece borders, open borders)
  StopReason Stop = StopReason::TargetMet;
  /// The algorithm's words for Stop when it is not TargetMet (why no nearer count was possible).
  std::string Reason;
  /// What else the algorithm changed to get there, in order (e.g. an angle lowered).
  std::vector<std::string> Notes;
  /// The largest error of the bound's measure in input units; < 0 when not measured.
  double MaximumError = -1.0;
};

/// A per-point figure of an algorithm (an error to colour by, a class).
struct NamedArray
{
  enum class Kind : std::uint8_t
  {
    Real,
    Integer,
    Byte
  };
  std::string Name;
  Kind Type = Kind::Real;
  std::vector<double> Values;
};

/// The one result every algorithm fills.
struct SimplifiedMesh
{
  std::vector<double> Points;               // 3 per output point, in input coordinates
  std::vector<std::int32_t> Triangles;      // 3 per output triangle
  std::vector<std::int32_t> TriangleSource; // input triangle each output triangle comes from
  /// The input points each output point stands for (CSR: SourceOffsets has one entry per point
  /// and one more): the representative first (a label's value comes from it: the surviving
  /// point of a collapse, the heaviest point of a cluster), then the others, with weights that
  /// sum to one (point data is interpolated with them). Every usable input point is listed by
  /// at most one output point.
  std::vector<std::int32_t> SourceOffsets = { 0 };
  std::vector<std::int32_t> SourcePoints;
  std::vector<double> SourceWeights;
  /// The algorithm's per-point figures and whole-mesh values, added to the output by name.
  std::vector<NamedArray> PointArrays;
  std::vector<std::pair<std::string, double>> FieldValues;
  Outcome Report;
  /// Whether the input's point normals, blended by the sources' weights and renormalised, show
  /// the output's shading (an algorithm that keeps the surface's shape at every point it places
  /// says so), rather than normals recomputed from the output's triangles; and whether, where
  /// the input has no point normals, the output gets them, recomputed from its triangles
  /// (area-weighted), so that a coarse mesh is drawn smooth as the fine one looked, not faceted.
  bool CarriesNormals = false;

  std::int64_t NumberOfPoints() const { return static_cast<std::int64_t>(this->Points.size() / 3); }
  std::int64_t NumberOfTriangles() const { return static_cast<std::int64_t>(this->TriangleSource.size()); }
  /// The representative input point of output point p.
  std::int32_t Representative(std::int64_t p) const { return this->SourcePoints[this->SourceOffsets[p]]; }
  /// The values of the point array of that name, or nullptr.
  const std::vector<double>* PointArray(const std::string& name) const;
  /// Adds a per-point array of these values (one per point).
  void AddPointArray(std::string name, std::vector<double> values, NamedArray::Kind type = NamedArray::Kind::Real);
};

/// How a prepared mesh's coordinates relate to the input's.
enum class Normalization : std::uint8_t
{
  CentreAndDiagonal, // the box centred at the origin, its diagonal 1
  PowerOfTwo         // scaled by a power of two (exact) when the diagonal is outside [2^-64, 2^64]
};

/// How an algorithm's coordinates relate to the input's: frame = (input − Origin) · Scale; and
/// the box of the usable input, which no output point leaves: an algorithm that places points
/// keeps them in it (InBox), and the way back to input units rounds within it (ToInput). So a
/// terrain's peak never rises above its highest point, nor a grid's border leaves its footprint.
struct Frame
{
  Eigen::Vector3d Origin = Eigen::Vector3d::Zero();
  double Scale = 1.0;
  bool Centred = false; // Origin is used (CentreAndDiagonal)
  /// The box, in input units and in frame units (PrepareMesh sets both; unbounded by default).
  Eigen::Vector3d Lower = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  Eigen::Vector3d Upper = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d FrameLower = Lower, FrameUpper = Upper;

  Eigen::Vector3d ToInput(const Eigen::Vector3d& x) const
  {
    const Eigen::Vector3d p = this->Centred ? Eigen::Vector3d(x / this->Scale + this->Origin) : Eigen::Vector3d(x / this->Scale);
    return p.cwiseMax(this->Lower).cwiseMin(this->Upper);
  }
  Eigen::Vector3d ToFrame(const Eigen::Vector3d& p) const
  {
    return this->Centred ? Eigen::Vector3d((p - this->Origin) * this->Scale) : Eigen::Vector3d(p * this->Scale);
  }
  /// x, in frame units, moved into the box.
  Eigen::Vector3d InBox(const Eigen::Vector3d& x) const
  {
    return x.cwiseMax(this->FrameLower).cwiseMin(this->FrameUpper);
  }
};

/// The usable part of the input, ready for an algorithm, in its frame.
struct PreparedMesh : Frame
{
  /// The usable triangles, renumbered (MakeCompactMesh), coordinates normalised.
  CompactMesh Mesh;
  /// The usable points' bounding-box diagonal, in input and in mesh units.
  double Diagonal = 0.0, MeshDiagonal = 0.0;
  /// Per vertex: 0, 1 (locked) or SharedPointLock, from the options' locks and open borders.
  std::vector<std::uint8_t> Locks;
  std::int64_t LockedCount = 0;
  /// Per vertex, the options' region; empty without.
  std::vector<std::int32_t> Regions;
  /// The goal among the usable triangles, and its bound in mesh units (< 0 without one).
  std::int64_t TargetTriangles = 0;
  double Bound = -1.0;

  /// Starts an outcome with the counts every algorithm reports.
  Outcome Report() const;
};

PreparedMesh PrepareMesh(const TriangleMeshView& input, const SimplificationOptions& options,
  Normalization normalization, const ExecutionContext& context = {});

/**
 * The sources of output points that are surviving vertices of collapses: records (vertex ids of
 * the prepared mesh, in collapse order) give each kept vertex the weighted values of the
 * vertices merged into it (CollapseRecord::Weights); the weight of an input point in an output
 * point is the product of the weights along its chain of merges. survivors lists the prepared
 * mesh's vertex of each output point. Appends to mesh's Source arrays, the survivor first.
 */
void AddCollapseSources(const std::vector<CollapseRecord>& records, const std::vector<std::int32_t>& survivors,
  const std::vector<std::int32_t>& inputVertex, SimplifiedMesh& mesh);

/**
 * The output of a collapse-engine algorithm: the surviving triangles (each with its input
 * triangle) and their points, in input coordinates: through the frame where moved is set (an
 * empty moved: none moved), else exactly as the input has them. Returns the mesh vertex of each
 * output point.
 */
std::vector<std::int32_t> WriteSurvivors(const CollapseMesh& mesh, const std::vector<std::uint8_t>& moved,
  const Frame& frame, const TriangleMeshView& input, const std::vector<std::int32_t>& inputVertex,
  const std::vector<std::int32_t>& inputTriangle, SimplifiedMesh& output);

/// The sources of output points that keep one input point each (weight 1), and with mergedInto
/// (CollapseMesh::MergeTargets) the vertices merged into them after it (weight 0).
void AddSurvivorSources(const std::vector<std::int32_t>& survivors, const std::vector<std::int32_t>& inputVertex,
  SimplifiedMesh& mesh, const std::vector<std::int32_t>& mergedInto = {});

/**
 * Two simplifications in a row: second was made from first's points and triangles, and becomes
 * the result, its sources those of the input first was made from (an input point's weight is the
 * product of its weights along the way; representatives stay first), its triangles' sources
 * first's. The outcome keeps first's counts of the input and takes second's stop, reason and
 * notes; its largest error is the sum of both (a bound on the two steps together). The per-point
 * figures and whole-mesh values are second's, measured from first's mesh.
 */
void ComposeSources(SimplifiedMesh& first, SimplifiedMesh&& second);

} // namespace meshsimp

#endif
