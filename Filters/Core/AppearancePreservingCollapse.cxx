// SPDX-License-Identifier: BSD-3-Clause
#include "AppearancePreservingCollapse.h"

#include "CollapseLoop.h"
#include "CollapseMesh.h"
#include "PlaneDistanceBound.h"
#include "Quadric.h"
#include "VertexQueue.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace meshsimp
{

Eigen::Vector3d CurvePoint(const Eigen::Vector3d& p1, const Eigen::Vector3d& n1, const Eigen::Vector3d& p2,
  const Eigen::Vector3d& n2, double t)
{
  // The tangents of eq. 7.7–7.8 (each the other normal's part across the own one) have the same
  // squared length 1 − (n1·n2)²; the coefficients of eq. 7.10–7.13 enter f only as the chord's
  // projections onto them (αβ T1 and α'β' T2), so nothing divides by T1·T2, which vanishes for
  // normals at right angles.
  const Eigen::Vector3d chord = p2 - p1;
  const double c = n1.dot(n2);
  const double across = 1.0 - c * c;
  if (!(across > 1e-8)) // within 0.006° of parallel or opposite: no tangent
  {
    return p1 + t * chord;
  }
  const Eigen::Vector3d t1 = n2 - c * n1, t2 = c * n2 - n1;
  const Eigen::Vector3d along1 = (chord.dot(t1) / across) * t1;
  const Eigen::Vector3d along2 = (chord.dot(t2) / across) * t2;
  const Eigen::Vector3d a = 0.5 * (along2 - along1); // eq. 7.14: f(t) = a t² + (chord − a) t + p1
  return p1 + t * (chord - a + t * a);
}

namespace
{
using Vec3 = Eigen::Vector3d;
constexpr double Pi = 3.14159265358979323846;
/// The importance of a vertex whose normals cancel (no mean direction at all).
constexpr double CancelledImportance = 1e30;

double Radians(double degrees)
{
  return degrees * Pi / 180.0;
}

/// An edge around the vertex being planned: its far end, and the far corners of its (up to
/// two) triangles, for the second curve.
struct EdgeAround
{
  std::int32_t Vertex;
  std::int32_t Far[2];
  int Triangles;
};

/// What the error of contracting the edge (x, y) at any point with any blend of its ends' point
/// data needs (Hoppe's quadrics merged): the planes, the fields' part in the position and, with
/// the blend s(v) = s_x + v (s_y − s_x) (v: y's share), the fields' sums
/// E(p, v) = Σ_k area s_k(v)² − 2 s_k(v) F_k(p), F_k(p) = g_k·p + d_k summed over both ends, as
/// the sums over k of s_x·s_x, s_x·Δ, Δ·Δ and of s_x (g, d) and Δ (g, d).
struct EdgeError
{
  std::int32_t X = -1, Y = -1;
  Quadric Planes;       // the geometric part alone, whose minimum places a candidate
  Quadric Whole;        // the planes and the fields' part in the position
  double Area = 0.0;    // the fields' area sum
  double FromFrom = 0.0, FromChange = 0.0, ChangeChange = 0.0;
  Eigen::Vector4d FromField = Eigen::Vector4d::Zero(), ChangeField = Eigen::Vector4d::Zero();
};

class AppearanceCollapser
{
public:
  AppearanceCollapser(const AppearanceCollapseOptions& options, const ExecutionContext& context)
    : Options(options)
    , Context(context)
    , ExtremeImportance(options.Order == AppearanceOrder::NormalSpread
          ? 1.0 / std::max(1e-12, std::cos(Radians(0.5 * options.ExtremeAngle)))
          : std::numeric_limits<double>::infinity())
    , CosFlatTurn(std::cos(Radians(180.0 - options.FlatEdgeAngle)))
    , Deviation(options.MaximumNormalDeviation)
    , CosDeviation(std::cos(Radians(options.MaximumNormalDeviation)))
  {
  }

  bool Run(const TriangleMeshView& input, AppearanceCollapseResult& result);

  /// The vertex queue's policy (VertexQueue.h): a star's normal and importance (Measure), the
  /// order's key, the proposals, and the bookkeeping after a collapse.
  void Measure(std::int32_t v);
  double Key(std::int32_t v);
  void Propose(std::int32_t x, std::vector<CollapseProposal>& out) { this->Proposals(x, out); }
  /// No triangle turned by more than MaximumNormalDeviation, none left without area; the bound.
  bool Accepts(const CollapsePlan& plan) const
  {
    // The chapter's proposals are scored by their change of area, which checked the normals.
    const bool normals = this->Options.Order == AppearanceOrder::NormalSpread || this->AreaChange(plan) >= 0.0;
    return normals && !(this->BoundLimit >= 0.0 && this->Bound.Distance(plan) > this->BoundLimit);
  }
  const char* OwnRules() const
  {
    return "are refused by the filter's own rules (a normal turned by more than MaximumNormalDeviation, the error "
           "bound) or wait for a hub's next measure";
  }
  /// Before a count target, MaximumNormalDeviation raised by 15 degrees (up to 180) when no
  /// collapse is left; never under an error bound, whose end that is.
  bool Relax()
  {
    if (this->BoundLimit >= 0.0 || this->Deviation >= 180.0)
    {
      return false;
    }
    this->Deviation = std::min(180.0, this->Deviation + 15.0);
    this->CosDeviation = std::cos(Radians(this->Deviation));
    ++this->Relaxations;
    return true;
  }
  bool ScoresAreKeys() const { return this->Options.Order == AppearanceOrder::Quadric; }
  void Collapsed(const CollapsePlan& plan);

private:
  /// The prepared mesh in the engine with its locks (seams among them), point data, quadrics
  /// and bound; returns the count.
  std::int64_t Prepare(const TriangleMeshView& input, AppearanceCollapseResult& result);
  /// Border points at one position pair up as seam twins (Twin); where more than two meet, they
  /// are locked.
  void FindSeams();
  /// The seam's other side of a proposal: where it removes a seam point, the same half-edge
  /// collapse of the twins, its error added to the score. False where the twins cannot follow
  /// (no twin edge, a kind that may not go, stars that touch) or the proposal moves a seam point.
  bool AddTwin(CollapseProposal& proposal) const;
  /// Whether the twins' stars share no point with the plan's (then the checks of one do not
  /// depend on the other being made).
  bool StarsApart(const CollapsePlan& plan, std::int32_t twinKept, std::int32_t twinRemoved) const;
  void ReadAttributes();
  /// Each vertex's quadric: the area-weighted planes of its triangles (and of the planes through
  /// its open-border edges perpendicular to them) and its point data's linear fields over them.
  void BuildQuadrics();
  void AddTriangleQuadric(std::int32_t t);
  /// The chapter's order only: in the Quadric order a feature's planes keep its point.
  bool IsExtreme(std::int32_t v) const { return this->Importance[v] >= this->ExtremeImportance; }
  /// Whether the edge's two triangles meet at more than FlatEdgeAngle.
  bool IsFlatEdge(std::int32_t x, std::int32_t y) const;
  /// Whether a half-edge collapse of removed into kept is one the vertex kinds allow.
  bool MayMerge(std::int32_t removed, std::int32_t kept) const;
  /// x's edges with their far corners, into Edges.
  void GatherEdges(std::int32_t x);
  /// The curve parameter of the edge (x, y) by the chapter's rules, or -1 where they refuse it.
  double Parameter(std::int32_t x, std::int32_t y, bool onlyExtreme) const;
  /// The contraction of the edge for x, at parameter t (see the top of the header).
  void PlanEdge(std::int32_t x, const EdgeAround& edge, double t, CollapsePlan& plan) const;
  /// PlanEdge's ends and weights alone: the end nearer parameter t kept (x at 0, y at 1).
  static void SetEnds(std::int32_t x, std::int32_t y, double t, CollapsePlan& plan);
  Vec3 Place(std::int32_t x, const EdgeAround& edge, double t) const;
  /// The plan's change of area, or -1 where a triangle would turn by more than
  /// MaximumNormalDeviation or lose its area.
  double AreaChange(const CollapsePlan& plan) const;
  /// Quadric order: the plan (the chapter's, at parameter t) replaced by the placement of least
  /// error among the chapter's candidates; returns that error.
  double LeastErrorPlacement(std::int32_t x, const EdgeAround& edge, double t, CollapsePlan& plan) const;
  /// The edge's merged quadrics and point data sums, which every candidate of the edge shares.
  EdgeError ErrorTerms(std::int32_t x, std::int32_t y) const;
  /// The plan's point data weights re-fitted: the blend of its ends' of least field error at its
  /// point (meshoptimizer's simplifyWithUpdate re-fits values freely; here within the blends,
  /// which the output's point data follows). Returns the merged quadrics' error there.
  static double FitBlend(const EdgeError& terms, CollapsePlan& plan);
  /// Replaces plan (of error best) by the quadric's point of least error where that is lower.
  void ConsiderOptimum(std::int32_t x, const EdgeAround& edge, const EdgeError& terms, double t, CollapsePlan& plan,
    double& best) const;
  /// x's contractions the chapter's and the borders' rules allow, scored by the order's measure
  /// (the chapter's: the change of area, where the normals allow it).
  void Proposals(std::int32_t x, std::vector<CollapseProposal>& out);
  /// Each free interior vertex moved along its normal to the least distance from its merged
  /// planes, where no triangle turns by more than MaximumNormalDeviation and the move stays
  /// within its star (see the header).
  void SettleAlongNormals();
  /// v's move along normal n to its planes' least distance, or false where the planes do not
  /// fix one, it would leave the ball of v's farthest neighbour or a triangle would turn by more
  /// than MaximumNormalDeviation (as set) from where it was before the pass (unsettled).
  bool SettledPoint(std::int32_t v, const Vec3& n, const std::vector<Vec3>& unsettled, Vec3& point) const;
  void Output(const TriangleMeshView& input, AppearanceCollapseResult& result) const;

  const AppearanceCollapseOptions& Options;
  const ExecutionContext& Context;
  const double ExtremeImportance, CosFlatTurn;
  double Deviation, CosDeviation; // MaximumNormalDeviation in force (raised by Relax) and its cosine
  int Relaxations = 0;
  CollapseMesh Mesh;
  Frame Normalised;
  double Diagonal = 1.0;
  std::vector<std::int32_t> InputVertex, InputTriangle;
  std::vector<Vec3> UnitNormal;    // eq. 7.6's mean, normalised (zero where the normals cancel)
  std::vector<double> Importance;  // its inverse length
  // Point data: Dimension values per vertex, blended through the collapses, and the quadrics'
  // parts for it (Hoppe's): per vertex and component the area-weighted sums of each linear
  // field's gradient and offset (4 values), and one area sum per vertex.
  int Dimension = 0;
  std::vector<double> Attributes, Gradients, FieldArea;
  std::vector<Quadric> Quadrics, FieldQuadrics; // the planes; the fields' part in the position
  std::vector<std::uint8_t> Moved; // a collapse gave the vertex a new position
  std::vector<std::int32_t> Twin;  // a seam point's twin on the seam's other side (-1: none)
  mutable std::vector<std::int32_t> Around; // StarsApart's scratch
  PlaneDistanceBound Bound;
  double BoundLimit = -1.0;        // in mesh units; < 0: no bound
  std::vector<std::int32_t> Ring;
  std::vector<EdgeAround> Edges;
  std::vector<std::int32_t> EdgeSlot; // per vertex, its place in Edges while gathered (-1: none)
  std::vector<CollapseProposal> KeyProposals;
};

void AppearanceCollapser::Measure(std::int32_t v)
{
  // Eq. 7.6: the triangles' unit normals weighted by their apical angles at v, which makes the
  // mean independent of how the fan is cut into triangles (Fig. 7-6).
  const Vec3& p = this->Mesh.Point(v);
  Vec3 sum = Vec3::Zero();
  double angles = 0.0;
  this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
    const Vec3 a = this->Mesh.Point(next) - p, b = this->Mesh.Point(previous) - p;
    const Vec3 cross = a.cross(b);
    const double length = cross.norm();
    if (length > 0.0)
    {
      const double angle = std::atan2(length, a.dot(b));
      sum += (angle / length) * cross;
      angles += angle;
    }
  });
  const double length = angles > 0.0 ? sum.norm() / angles : 0.0;
  this->UnitNormal[v] = length > 0.0 ? Vec3(sum / sum.norm()) : Vec3::Zero();
  this->Importance[v] = length > 0.0 ? std::min(CancelledImportance, 1.0 / length) : CancelledImportance;
}

double AppearanceCollapser::Key(std::int32_t v)
{
  if (this->Options.Order == AppearanceOrder::NormalSpread)
  {
    return this->Importance[v];
  }
  // The error of v's cheapest contraction, before the checks (which run when v is on top).
  std::vector<CollapseProposal>& proposals = this->KeyProposals;
  this->Proposals(v, proposals);
  double best = std::numeric_limits<double>::infinity();
  for (const CollapseProposal& proposal : proposals)
  {
    best = std::min(best, proposal.Score);
  }
  return best;
}

bool AppearanceCollapser::IsFlatEdge(std::int32_t x, std::int32_t y) const
{
  Vec3 normals[2];
  int count = 0;
  this->Mesh.ForEachTriangleOnEdge(x, y, [&](std::int32_t t) {
    if (count < 2)
    {
      normals[count] = this->Mesh.Normal(t);
    }
    ++count;
  });
  // Triangles meeting at an angle φ have normals π − φ apart.
  return count == 2 && normals[0].dot(normals[1]) > this->CosFlatTurn;
}

bool AppearanceCollapser::MayMerge(std::int32_t removed, std::int32_t kept) const
{
  if (this->Mesh.IsLocked(removed))
  {
    return false;
  }
  const VertexClass kind = this->Mesh.Class(removed);
  const CollapseRule rule = HalfEdgeRule(kind, this->Mesh.Class(kept));
  return rule == CollapseRule::Free ||
    (rule == CollapseRule::AlongEdge && IsOwnEdge(kind, this->Mesh.TrianglesOnEdge(removed, kept)));
}

void AppearanceCollapser::GatherEdges(std::int32_t x)
{
  // One walk around x: the edge (x, next) has the far corner previous in the triangle, the
  // edge (x, previous) the far corner next.
  this->Edges.clear();
  const auto add = [this](std::int32_t y, std::int32_t far) {
    std::int32_t& slot = this->EdgeSlot[y];
    if (slot < 0)
    {
      slot = static_cast<std::int32_t>(this->Edges.size());
      this->Edges.push_back({ y, { far, -1 }, 0 });
    }
    EdgeAround& edge = this->Edges[slot];
    if (edge.Triangles < 2)
    {
      edge.Far[edge.Triangles] = far;
    }
    ++edge.Triangles;
  };
  this->Mesh.ForEachCorner(x, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
    add(next, previous);
    add(previous, next);
  });
  for (const EdgeAround& edge : this->Edges)
  {
    this->EdgeSlot[edge.Vertex] = -1;
  }
}

double AppearanceCollapser::Parameter(std::int32_t x, std::int32_t y, bool onlyExtreme) const
{
  // Extreme ends stay (the more important of two); an edge of two extreme ends goes only if it
  // is sharp; an extreme vertex with an extreme neighbour only along such an edge. Otherwise the
  // importance puts the point (t = 0 at x, 1 at y), and an end that may not move (a border, a
  // lock, a hinge) takes it.
  const bool xExtreme = this->IsExtreme(x), yExtreme = this->IsExtreme(y);
  if (onlyExtreme && !yExtreme)
  {
    return -1.0;
  }
  double t = this->Importance[y] / (this->Importance[x] + this->Importance[y]);
  if (xExtreme && yExtreme)
  {
    if (this->IsFlatEdge(x, y))
    {
      return -1.0;
    }
    t = this->Importance[x] >= this->Importance[y] ? 0.0 : 1.0;
  }
  else if (xExtreme || yExtreme)
  {
    t = xExtreme ? 0.0 : 1.0;
  }
  const bool xFree = this->Mesh.Class(x) == VertexClass::Interior && !this->Mesh.IsLocked(x);
  const bool yFree = this->Mesh.Class(y) == VertexClass::Interior && !this->Mesh.IsLocked(y);
  if (t > 0.0 && t < 1.0 && !(xFree && yFree))
  {
    t = xFree ? 1.0 : yFree ? 0.0 : this->MayMerge(x, y) ? 1.0 : 0.0;
  }
  const bool allowed = t <= 0.0 ? this->MayMerge(y, x) : t >= 1.0 ? this->MayMerge(x, y) : true;
  return allowed ? t : -1.0;
}

Vec3 AppearanceCollapser::Place(std::int32_t x, const EdgeAround& edge, double t) const
{
  // The first curve over the edge; the second across the far corners of its two triangles when
  // their quad is not arrow-shaped (the edge's ends on the two sides of the corners' line), its
  // parameter from their importance over their distance to the first point; the new point
  // midway between the two (Fig. 7-9).
  const std::int32_t y = edge.Vertex;
  const Vec3& p1 = this->Mesh.Point(x);
  const Vec3& p2 = this->Mesh.Point(y);
  const Vec3 first = CurvePoint(p1, this->UnitNormal[x], p2, this->UnitNormal[y], t);
  Vec3 point = first;
  if (edge.Triangles == 2)
  {
    const std::int32_t a = edge.Far[0], b = edge.Far[1];
    const Vec3& c1 = this->Mesh.Point(a);
    const Vec3& c2 = this->Mesh.Point(b);
    const Vec3 up = this->UnitNormal[x] + this->UnitNormal[y];
    const Vec3 line = c2 - c1;
    if (up.dot(line.cross(p1 - c1)) * up.dot(line.cross(p2 - c1)) < 0.0)
    {
      const double w1 = this->Importance[a] / std::max(1e-300, (c1 - first).norm());
      const double w2 = this->Importance[b] / std::max(1e-300, (c2 - first).norm());
      const double across = w1 + w2 > 0.0 && std::isfinite(w1 + w2) ? w2 / (w1 + w2) : 0.5;
      point = 0.5 * (first + CurvePoint(c1, this->UnitNormal[a], c2, this->UnitNormal[b], across));
    }
  }
  return this->Normalised.InBox(point);
}

void AppearanceCollapser::PlanEdge(std::int32_t x, const EdgeAround& edge, double t, CollapsePlan& plan) const
{
  const std::int32_t y = edge.Vertex;
  SetEnds(x, y, t, plan);
  plan.Position = t <= 0.0 ? this->Mesh.Point(x) : t >= 1.0 ? this->Mesh.Point(y) : this->Place(x, edge, t);
}

void AppearanceCollapser::SetEnds(std::int32_t x, std::int32_t y, double t, CollapsePlan& plan)
{
  // The end nearer the new point is kept: its id, and its data first in the output's sources.
  const bool keepX = t <= 0.5;
  plan.Count = 2;
  plan.Vertices[0] = keepX ? x : y;
  plan.Vertices[1] = keepX ? y : x;
  plan.Vertices[2] = -1;
  plan.Weights[0] = keepX ? 1.0 - t : t;
  plan.Weights[1] = 1.0 - plan.Weights[0];
  plan.Weights[2] = 0.0;
}

double AppearanceCollapser::AreaChange(const CollapsePlan& plan) const
{
  // The triangles around both ends: those on the edge go, the others get the new point (each
  // visited once: from the removed end, those without the kept one).
  const std::int32_t kept = plan.Vertices[0], removed = plan.Vertices[1];
  double before = 0.0, after = 0.0;
  bool allowed = true;
  for (const std::int32_t v : { kept, removed })
  {
    this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
      const bool onEdge = next == kept || next == removed || previous == kept || previous == removed;
      if (v == removed && onEdge)
      {
        return; // the triangle on the edge, counted from the kept end
      }
      const Vec3& p = this->Mesh.Point(v);
      const Vec3& q = this->Mesh.Point(next);
      const Vec3& r = this->Mesh.Point(previous);
      const Vec3 old = (q - p).cross(r - p);
      before += 0.5 * old.norm();
      if (onEdge)
      {
        return; // removed
      }
      const Vec3 moved = (q - plan.Position).cross(r - plan.Position);
      const double length = moved.norm();
      allowed = allowed && length > 0.0 && moved.dot(old) >= this->CosDeviation * length * old.norm();
      after += 0.5 * length;
    });
  }
  return allowed ? std::abs(after - before) : -1.0;
}

EdgeError AppearanceCollapser::ErrorTerms(std::int32_t x, std::int32_t y) const
{
  EdgeError terms;
  terms.X = x;
  terms.Y = y;
  terms.Planes = this->Quadrics[x];
  terms.Planes += this->Quadrics[y];
  terms.Whole = terms.Planes;
  if (this->Dimension == 0)
  {
    return terms;
  }
  terms.Whole += this->FieldQuadrics[x];
  terms.Whole += this->FieldQuadrics[y];
  terms.Area = this->FieldArea[x] + this->FieldArea[y];
  const double* gx = this->Gradients.data() + 4 * static_cast<std::int64_t>(x) * this->Dimension;
  const double* gy = this->Gradients.data() + 4 * static_cast<std::int64_t>(y) * this->Dimension;
  const double* sx = this->Attributes.data() + static_cast<std::int64_t>(x) * this->Dimension;
  const double* sy = this->Attributes.data() + static_cast<std::int64_t>(y) * this->Dimension;
  for (int k = 0; k < this->Dimension; ++k)
  {
    using Row = Eigen::Map<const Eigen::Vector4d>;
    const Eigen::Vector4d field = Row(gx + 4 * k) + Row(gy + 4 * k);
    const double from = sx[k], change = sy[k] - sx[k];
    terms.FromFrom += from * from;
    terms.FromChange += from * change;
    terms.ChangeChange += change * change;
    terms.FromField += from * field;
    terms.ChangeField += change * field;
  }
  return terms;
}

double AppearanceCollapser::FitBlend(const EdgeError& terms, CollapsePlan& plan)
{
  // The point data at the plan's point: the blend of least E(p, v), a parabola in v; the plan's
  // whole error with it.
  const Vec3& p = plan.Position;
  double error = terms.Whole.Evaluate(p);
  const double curvature = terms.Area * terms.ChangeChange;
  if (terms.Area > 0.0)
  {
    const Eigen::Vector4d at(p.x(), p.y(), p.z(), 1.0);
    const double fromField = terms.FromField.dot(at), changeField = terms.ChangeField.dot(at);
    const bool keepsX = plan.Vertices[0] == terms.X;
    double share = keepsX ? plan.Weights[1] : plan.Weights[0]; // y's, where the ends agree
    if (curvature > 0.0)
    {
      share = std::min(1.0, std::max(0.0, (changeField - terms.Area * terms.FromChange) / curvature));
      plan.Weights[0] = keepsX ? 1.0 - share : share;
      plan.Weights[1] = 1.0 - plan.Weights[0];
    }
    error += terms.Area * (terms.FromFrom + 2.0 * share * terms.FromChange + share * share * terms.ChangeChange) -
      2.0 * (fromField + share * changeField);
  }
  return std::isfinite(error) ? std::max(0.0, error) : std::numeric_limits<double>::infinity();
}

double AppearanceCollapser::LeastErrorPlacement(std::int32_t x, const EdgeAround& edge, double t, CollapsePlan& plan) const
{
  // The chapter's point (plan, as PlanEdge made it), the first curve's alone (the second, across
  // the far corners, pulls a point on a colour border off it), and the ends the kinds allow:
  // the one of least error.
  const std::int32_t y = edge.Vertex;
  const EdgeError terms = this->ErrorTerms(x, y);
  double best = FitBlend(terms, plan);
  CollapsePlan other;
  const auto consider = [&](double at) {
    SetEnds(x, y, at, other);
    other.Position = at <= 0.0 ? this->Mesh.Point(x)
      : at >= 1.0              ? this->Mesh.Point(y)
                               : this->Normalised.InBox(
                      CurvePoint(this->Mesh.Point(x), this->UnitNormal[x], this->Mesh.Point(y), this->UnitNormal[y], at));
    const double error = FitBlend(terms, other);
    if (error < best)
    {
      best = error;
      plan = other;
    }
  };
  if (t > 0.0 && t < 1.0)
  {
    if (edge.Triangles == 2)
    {
      consider(t);
    }
    this->ConsiderOptimum(x, edge, terms, t, plan, best);
    if (this->MayMerge(y, x))
    {
      consider(0.0);
    }
    if (this->MayMerge(x, y))
    {
      consider(1.0);
    }
  }
  return best;
}

void AppearanceCollapser::ConsiderOptimum(
  std::int32_t x, const EdgeAround& edge, const EdgeError& terms, double t, CollapsePlan& plan, double& best) const
{
  // The point of least distance to the merged planes (Garland and Heckbert's placement, as
  // meshoptimizer's simplifyWithUpdate re-fits positions), where they fix one within the edge's
  // length of the best point so far (the chapter's or the first curve's); the point data blended
  // at its place along the edge. (The fields are left out of the minimisation: with them the
  // point would leave the surface to meet a colour.)
  const std::int32_t y = edge.Vertex;
  const Vec3& p1 = this->Mesh.Point(x);
  const Vec3& p2 = this->Mesh.Point(y);
  const Vec3 chord = p2 - p1;
  const double length2 = chord.squaredNorm();
  if (!(length2 > 0.0))
  {
    return;
  }
  Vec3 optimum;
  if (!MinimizeQuadric(terms.Planes, optimum) || (optimum - plan.Position).squaredNorm() > length2)
  {
    return; // the planes fix no point near the edge (a flat region, a crease): the others stand
  }
  const double along = std::min(1.0, std::max(0.0, (optimum - p1).dot(chord) / length2));
  CollapsePlan other;
  SetEnds(x, y, along > 0.0 && along < 1.0 ? along : t, other);
  other.Position = this->Normalised.InBox(optimum);
  const double error = FitBlend(terms, other);
  if (error < best)
  {
    best = error;
    plan = other;
  }
}

void AppearanceCollapser::Proposals(std::int32_t x, std::vector<CollapseProposal>& out)
{
  out.clear();
  this->GatherEdges(x);
  const bool onlyExtreme = this->IsExtreme(x) && std::any_of(this->Edges.begin(), this->Edges.end(),
    [this](const EdgeAround& edge) { return this->IsExtreme(edge.Vertex); });
  const bool chapter = this->Options.Order == AppearanceOrder::NormalSpread;
  CollapseProposal proposal;
  for (const EdgeAround& edge : this->Edges)
  {
    const double t = this->Parameter(x, edge.Vertex, onlyExtreme);
    if (t < 0.0)
    {
      continue;
    }
    this->PlanEdge(x, edge, t, proposal.Plan);
    proposal.Score = chapter ? this->AreaChange(proposal.Plan) : this->LeastErrorPlacement(x, edge, t, proposal.Plan);
    if (proposal.Score >= 0.0 && this->AddTwin(proposal))
    {
      out.push_back(proposal);
    }
  }
}

void AppearanceCollapser::Collapsed(const CollapsePlan& plan)
{
  const std::int32_t kept = plan.Vertices[0], removed = plan.Vertices[1];
  this->Moved[kept] |= plan.Position != this->Mesh.Point(kept) ? 1 : 0; // before the engine applies it
  for (int k = 0; k < this->Dimension; ++k)
  {
    double& value = this->Attributes[static_cast<std::int64_t>(kept) * this->Dimension + k];
    value = plan.Weights[0] * value +
      plan.Weights[1] * this->Attributes[static_cast<std::int64_t>(removed) * this->Dimension + k];
  }
  if (!this->Quadrics.empty())
  {
    this->Quadrics[kept] += this->Quadrics[removed];
  }
  if (this->Dimension > 0)
  {
    this->FieldQuadrics[kept] += this->FieldQuadrics[removed];
    this->FieldArea[kept] += this->FieldArea[removed];
    double* into = this->Gradients.data() + 4 * static_cast<std::int64_t>(kept) * this->Dimension;
    const double* from = this->Gradients.data() + 4 * static_cast<std::int64_t>(removed) * this->Dimension;
    for (int i = 0; i < 4 * this->Dimension; ++i)
    {
      into[i] += from[i];
    }
  }
  if (this->BoundLimit >= 0.0)
  {
    this->Bound.Merge(plan, this->Bound.Distance(plan));
  }
}

void AppearanceCollapser::FindSeams()
{
  // Border points at the same position as another point (after cracks are closed, those whose
  // point data differ: a texture, colour or normal seam).
  std::vector<std::int32_t> border;
  for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
  {
    if (this->Mesh.OnBoundary(v) && this->Mesh.NumberOfTrianglesAround(v) > 0)
    {
      border.push_back(v);
    }
  }
  const auto before = [this](std::int32_t a, std::int32_t b) {
    const Vec3& p = this->Mesh.Point(a);
    const Vec3& q = this->Mesh.Point(b);
    return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3) || (p == q && a < b);
  };
  std::sort(border.begin(), border.end(), before);
  this->Twin.assign(this->Mesh.NumberOfPoints(), -1);
  for (std::size_t first = 0, last = 0; first < border.size(); first = last)
  {
    while (last < border.size() && this->Mesh.Point(border[last]) == this->Mesh.Point(border[first]))
    {
      ++last;
    }
    if (last - first == 2)
    {
      this->Twin[border[first]] = border[first + 1];
      this->Twin[border[first + 1]] = border[first];
    }
    for (std::size_t i = first; last - first > 2 && i < last; ++i)
    {
      if (!this->Mesh.IsLocked(border[i]))
      {
        this->Mesh.Lock(border[i], LockReason::Seam);
      }
    }
  }
}

bool AppearanceCollapser::StarsApart(const CollapsePlan& plan, std::int32_t twinKept, std::int32_t twinRemoved) const
{
  // The twins' checks are made before the plan is: no point may be in both stars (nor the
  // twins in the plan's), or the plan's collapse would change what the twin's checks saw.
  std::vector<std::int32_t>& around = this->Around;
  around.clear();
  for (const std::int32_t v : { plan.Vertices[0], plan.Vertices[1] })
  {
    this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t) { around.push_back(next); });
    around.push_back(v);
  }
  bool apart = true;
  for (const std::int32_t v : { twinKept, twinRemoved })
  {
    apart = apart && std::find(around.begin(), around.end(), v) == around.end();
    this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t) {
      apart = apart && std::find(around.begin(), around.end(), next) == around.end();
    });
  }
  return apart;
}

bool AppearanceCollapser::AddTwin(CollapseProposal& proposal) const
{
  const CollapsePlan& plan = proposal.Plan;
  CollapsePlan& twin = proposal.Twin;
  twin.Count = 0;
  const std::int32_t kept = plan.Vertices[0], removed = plan.Vertices[1];
  const bool keptStays = plan.Position == this->Mesh.Point(kept);
  if (this->Twin[removed] < 0)
  {
    return this->Twin[kept] < 0 || keptStays;
  }
  const std::int32_t twinKept = this->Twin[kept], twinRemoved = this->Twin[removed];
  if (!keptStays || twinKept < 0 || this->Mesh.TrianglesOnEdge(twinRemoved, twinKept) != 1 ||
    !this->MayMerge(twinRemoved, twinKept) || !this->StarsApart(plan, twinKept, twinRemoved))
  {
    return false;
  }
  SetEnds(twinKept, twinRemoved, 0.0, twin);
  twin.Position = this->Mesh.Point(twinKept);
  const double twinScore = this->Options.Order == AppearanceOrder::Quadric
    ? FitBlend(this->ErrorTerms(twinKept, twinRemoved), twin)
    : this->AreaChange(twin); // the chapter's measure, which also holds it to the normal limit
  proposal.Score += twinScore;
  return twinScore >= 0.0;
}

void AppearanceCollapser::ReadAttributes()
{
  const std::int32_t n = this->Mesh.NumberOfPoints();
  this->Dimension = this->Options.AttributeCoordinates && this->Options.Order == AppearanceOrder::Quadric
    ? std::max(0, this->Options.AttributeDimension)
    : 0;
  this->Attributes.resize(static_cast<std::size_t>(n) * this->Dimension);
  for (std::int32_t v = 0; v < n && this->Dimension > 0; ++v)
  {
    const double* values =
      this->Options.AttributeCoordinates + static_cast<std::int64_t>(this->InputVertex[v]) * this->Dimension;
    std::copy(values, values + this->Dimension, this->Attributes.begin() + static_cast<std::int64_t>(v) * this->Dimension);
  }
}

void AppearanceCollapser::AddTriangleQuadric(std::int32_t t)
{
  // The plane, area-weighted, at each corner; for each component its linear field over the
  // triangle, g·p + d with g in the plane, weighted by area times AttributeWeight² (so that a
  // deviation of 1 counts as that distance); the planes through open-border edges.
  const std::int32_t* tri = this->Mesh.Triangle(t);
  const Vec3& p0 = this->Mesh.Point(tri[0]);
  const Vec3 e1 = this->Mesh.Point(tri[1]) - p0, e2 = this->Mesh.Point(tri[2]) - p0;
  const Vec3 cross = e1.cross(e2);
  const double area = 0.5 * cross.norm();
  if (!(area > 0.0))
  {
    return;
  }
  const Vec3 n = cross.normalized();
  const Quadric plane = Quadric::FromPlane(n, -n.dot(p0), area);
  for (int k = 0; k < 3; ++k)
  {
    this->Quadrics[tri[k]] += plane;
    const std::int32_t a = tri[k], b = tri[(k + 1) % 3];
    Quadric border;
    if (this->Mesh.OnBoundary(a) && this->Mesh.OnBoundary(b) && this->Mesh.TrianglesOnEdge(a, b) == 1 &&
      Quadric::FromBorderEdge(this->Mesh.Point(a), this->Mesh.Point(b), n, border))
    {
      this->Quadrics[a] += border;
      this->Quadrics[b] += border;
    }
  }
  if (this->Dimension == 0)
  {
    return;
  }
  const double weight = area * this->Options.AttributeWeight * this->Options.AttributeWeight;
  const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
  // |e1 × e2|² is the Gram determinant without its cancellation; a sliver thinner than about
  // 1e-6 radians fixes no gradient across it: its field is the corners' mean, constant.
  const double det = cross.squaredNorm();
  const bool flat = !(det > 1e-12 * g11 * g22);
  const std::int64_t row[3] = { static_cast<std::int64_t>(tri[0]) * this->Dimension,
    static_cast<std::int64_t>(tri[1]) * this->Dimension, static_cast<std::int64_t>(tri[2]) * this->Dimension };
  for (int c = 0; c < this->Dimension; ++c)
  {
    const double s0 = this->Attributes[row[0] + c];
    const double d1 = this->Attributes[row[1] + c] - s0;
    const double d2 = this->Attributes[row[2] + c] - s0;
    // g = α e1 + β e2 with g·e1 = d1 and g·e2 = d2.
    const double alpha = flat ? 0.0 : (d1 * g22 - d2 * g12) / det;
    const double beta = flat ? 0.0 : (d2 * g11 - d1 * g12) / det;
    const Vec3 g = alpha * e1 + beta * e2;
    const double offset = flat ? s0 + (d1 + d2) / 3.0 : s0 - g.dot(p0);
    const Quadric field = Quadric::FromPlane(g, offset, weight);
    for (int k = 0; k < 3; ++k)
    {
      this->FieldQuadrics[tri[k]] += field;
      double* gradient = this->Gradients.data() + 4 * (static_cast<std::int64_t>(tri[k]) * this->Dimension + c);
      gradient[0] += weight * g.x();
      gradient[1] += weight * g.y();
      gradient[2] += weight * g.z();
      gradient[3] += weight * offset;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    this->FieldArea[tri[k]] += weight;
  }
}

void AppearanceCollapser::BuildQuadrics()
{
  const std::int32_t n = this->Mesh.NumberOfPoints();
  this->Quadrics.assign(n, Quadric());
  this->FieldQuadrics.assign(this->Dimension > 0 ? n : 0, Quadric());
  this->Gradients.assign(4 * static_cast<std::size_t>(n) * this->Dimension, 0.0);
  this->FieldArea.assign(this->Dimension > 0 ? n : 0, 0.0);
  for (std::int32_t t = 0; t < this->Mesh.NumberOfTriangles(); ++t)
  {
    if (this->Mesh.IsAlive(t))
    {
      this->AddTriangleQuadric(t);
    }
  }
}

std::int64_t AppearanceCollapser::Prepare(const TriangleMeshView& input, AppearanceCollapseResult& result)
{
  PreparedMesh prepared = PrepareMesh(input, this->Options, Normalization::CentreAndDiagonal, this->Context);
  result.Report = prepared.Report();
  this->InputVertex = std::move(prepared.Mesh.InputVertex);
  this->InputTriangle = std::move(prepared.Mesh.InputTriangle);
  this->Normalised = prepared;
  this->Diagonal = prepared.Diagonal > 0.0 ? prepared.Diagonal : 1.0;
  this->Mesh.Load(prepared, this->Options.BoundaryCornerAngle, true, this->Context);
  if (prepared.Bound >= 0.0)
  {
    this->Bound.Build(this->Mesh);
    this->BoundLimit = prepared.Bound;
  }
  const std::int32_t n = this->Mesh.NumberOfPoints();
  this->FindSeams();
  this->ReadAttributes();
  if (this->Options.Order == AppearanceOrder::Quadric)
  {
    this->BuildQuadrics();
  }
  this->UnitNormal.assign(n, Vec3::Zero());
  this->Importance.assign(n, 1.0);
  this->Moved.assign(n, 0);
  this->EdgeSlot.assign(n, -1);
  return prepared.TargetTriangles;
}

bool AppearanceCollapser::SettledPoint(
  std::int32_t v, const Vec3& n, const std::vector<Vec3>& unsettled, Vec3& point) const
{
  // Q(p + s n) is least at s = −(A p + b)·n / nᵀA n.
  const Vec3& p = this->Mesh.Point(v);
  const Quadric& q = this->Quadrics[v];
  const Eigen::Matrix3d a = q.A();
  const double curvature = n.dot(a * n);
  if (!(curvature > 0.0))
  {
    return false;
  }
  point = this->Normalised.InBox(p - ((a * p + q.B()).dot(n) / curvature) * n);
  double reach = 0.0;
  bool allowed = point.allFinite();
  // Each triangle's turn is measured from where it was before any point settled, against the
  // limit as set (not as Relax raised it), so that no triangle turns farther however many of its
  // corners move.
  const double cosLimit = std::cos(Radians(this->Options.MaximumNormalDeviation));
  this->Mesh.ForEachCorner(v, [&](std::int32_t, std::int32_t next, std::int32_t previous) {
    const Vec3& b = this->Mesh.Point(next);
    const Vec3& c = this->Mesh.Point(previous);
    reach = std::max(reach, (b - p).squaredNorm());
    const Vec3 before = (unsettled[next] - unsettled[v]).cross(unsettled[previous] - unsettled[v]);
    const Vec3 after = (b - point).cross(c - point);
    const double length = after.norm();
    allowed = allowed && length > 0.0 && after.dot(before) >= cosLimit * length * before.norm();
  });
  return allowed && (point - p).squaredNorm() <= reach;
}

void AppearanceCollapser::SettleAlongNormals()
{
  // The triangles of a coarse curved surface cut under it while its points stay on it; moved
  // along their normals to the planes of the input triangles merged into them, the points share
  // the distance on both sides (meshoptimizer's simplifyWithUpdate moves its kept vertices to
  // their quadrics' minimum at the end; along the normal alone, a point on a colour border
  // stays on that border). Border, seam and locked points stay.
  std::vector<Vec3> unsettled(static_cast<std::size_t>(this->Mesh.NumberOfPoints()));
  for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
  {
    unsettled[v] = this->Mesh.Point(v);
  }
  for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
  {
    if (this->Mesh.NumberOfTrianglesAround(v) == 0 || this->Mesh.IsLocked(v) ||
      this->Mesh.Class(v) != VertexClass::Interior)
    {
      continue;
    }
    this->Measure(v);
    Vec3 point;
    if (this->UnitNormal[v] != Vec3::Zero() && this->SettledPoint(v, this->UnitNormal[v], unsettled, point))
    {
      this->Mesh.SetPoint(v, point);
      this->Moved[v] = 1;
    }
  }
}

void AppearanceCollapser::Output(const TriangleMeshView& input, AppearanceCollapseResult& result) const
{
  const std::vector<std::int32_t> used =
    WriteSurvivors(this->Mesh, this->Moved, this->Normalised, input, this->InputVertex, this->InputTriangle, result);
  std::vector<double> importance(used.size());
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    importance[i] = this->Importance[used[i]];
  }
  result.AddPointArray("Importance", std::move(importance));
  if (this->BoundLimit >= 0.0)
  {
    AddPlaneDistances(this->Bound, used, this->Diagonal, result);
  }
  AddCollapseSources(this->Mesh.Records(), used, this->InputVertex, result);
  result.FieldValues.emplace_back("Passes", static_cast<double>(result.Passes));
  result.CarriesNormals = true;
}

bool AppearanceCollapser::Run(const TriangleMeshView& input, AppearanceCollapseResult& result)
{
  result = AppearanceCollapseResult();
  const std::int64_t target = this->Prepare(input, result);
  if (!this->Context.Report(0.1))
  {
    result.Report.Stop = StopReason::Aborted;
    return false;
  }
  VertexQueue<AppearanceCollapser> queue(this->Mesh, *this, this->Options.VertexMemory);
  queue.QueueAll();
  CollapseLoopEnd end;
  if (result.Report.Stop != StopReason::AllLocked)
  {
    end = RunCollapseLoop(queue, target, { 0.1, 0.95 }, this->Context);
  }
  if (end.Why == CollapseLoopEnd::Reason::Aborted)
  {
    result.Report.Stop = StopReason::Aborted;
    return false;
  }
  result.Passes = queue.Passes();
  if (this->Options.Order == AppearanceOrder::Quadric && this->BoundLimit < 0.0)
  {
    this->SettleAlongNormals();
  }
  this->Output(input, result);
  end.Judge(result.Report, this->BoundLimit >= 0.0, "no collapse is left that keeps the mesh valid");
  if (this->Relaxations > 0)
  {
    result.Report.Notes.push_back("MaximumNormalDeviation was raised by " + std::to_string(15 * this->Relaxations) +
      " degrees to go on");
  }
  return this->Context.Report(1.0);
}

} // namespace

bool AppearancePreservingCollapse(const TriangleMeshView& input, const AppearanceCollapseOptions& options,
  AppearanceCollapseResult& result, const ExecutionContext& context)
{
  return AppearanceCollapser(options, context).Run(input, result);
}

} // namespace meshsimp
