// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VertexQueue.h
 * @brief The collapse engine's vertex-priority scheduler: the least important vertex goes
 * first, by the best of the collapses its policy proposes that passes the engine's checks. A
 * scheduler of the collapse loop (CollapseLoop.h) over a CollapseMesh.
 *
 * This is the main loop of Franc's "Similarity of Appearance" (dissertation "Methods for
 * Polygonal Mesh Simplification", ch. 7): take the least important vertex, price every edge
 * around it, contract the best that keeps the mesh valid, evaluate the changed area again. As in
 * OpenMesh's Decimater the algorithm is a policy, a class with
 * - `void Measure(std::int32_t v)`: what the policy keeps of v's star (a normal, say). Called for
 *   every vertex with triangles at the start, and after each collapse for the kept vertex and
 *   its neighbours (the vertices whose stars changed), before any of them is keyed;
 * - `double Key(std::int32_t v)`: v's priority, least first (infinite: v waits outside the queue
 *   until a collapse changes its star). Called after Measure, for the same vertices; locked ones
 *   are measured but never keyed;
 * - `void Propose(std::int32_t v, std::vector<CollapseProposal>& out)`: v's candidate collapses
 *   (plans that remove v, with scores, least best). A proposal may carry a twin plan, made with
 *   it or not at all (a seam's other side: points at the same positions, with other point
 *   data, collapsing alike so that no crack opens); the twin's stars must not touch the plan's;
 * - `bool Accepts(const CollapsePlan& plan)`: the policy's own filter (a normal turned too far,
 *   an error bound), asked in score order before the engine's checks, so that a dear filter
 *   runs only until a proposal passes; `const char* OwnRules() const` says what it refuses,
 *   for the refusal summary ("are refused by ..."); `bool Relax()` loosens those rules a step
 *   when no collapse is left before the target (false: nothing left to loosen), as Parallel
 *   Decimation raises its angles;
 * - `bool ScoresAreKeys() const`: whether a proposal's score is in the key's measure (v's key then
 *   is its best proposal's score before the engine's checks): a vertex whose best legal
 *   proposal scores above the next vertex's key then waits at that score; and a collapse keys
 *   only its kept vertex again at once, its queued neighbours when they reach the top (lazily,
 *   as Progressive Mesh's builder does: a neighbour whose key fell waits at its older one), so
 *   the order is that of the collapses made but for such neighbours;
 * - `void Collapsed(const CollapsePlan& plan)`: the collapse is made (the visitor: what the
 *   removed vertices held goes to the kept one); called just before the engine applies it, so
 *   the mesh is still as the plan found it.
 * The queue owns the rest: the heap (equal keys in the order they were set, vertex order at the
 * start, so the result is deterministic), the engine's ordered checks on each proposal in score order (the first that
 * passes is made; a vertex with none leaves the queue until a collapse changes its star), the
 * keys after a collapse (a hub's, the centre of a large fan, only now and then: HubTriangles)
 * and, with deferral on, the chapter's vertex memory: no collapse in a pass over the queue
 * involves a vertex whose star an earlier one in that pass changed; such a vertex, or one whose
 * proposals all involve one, is set aside, and the vertices set aside make the next pass when
 * the queue runs dry. Reduction then spreads over the whole surface instead of eating flat
 * regions first (ch. 7, Fig. 7-12).
 */
#ifndef MeshSimplification_VertexQueue_h
#define MeshSimplification_VertexQueue_h

#include "CollapseHeap.h"
#include "CollapseMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace meshsimp
{

/// A collapse a policy proposes for a vertex, with its score (least best), and the twin plan
/// made with it (Count 0: none).
struct CollapseProposal
{
  CollapsePlan Plan;
  CollapsePlan Twin;
  double Score = 0.0;
};

template <class Policy>
class VertexQueue
{
public:
  /// defer: the vertex memory (see the top of the file).
  VertexQueue(CollapseMesh& mesh, Policy& policy, bool defer)
    : Mesh(mesh)
    , Rules(policy)
    , Defer(defer)
    , Heap(mesh.NumberOfPoints())
    , Touched(defer ? mesh.NumberOfPoints() : 0, 0u)
    , MeasuredCount(mesh.NumberOfPoints(), 0)
  {
  }

  /// Keys every vertex (the policy measures each star once here).
  void QueueAll()
  {
    for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
    {
      this->MeasuredCount[v] = this->Mesh.NumberOfTrianglesAround(v);
      if (this->MeasuredCount[v] > 0)
      {
        this->Rules.Measure(v);
      }
    }
    for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
    {
      this->Requeue(v);
    }
  }

  std::int64_t AliveTriangles() const { return this->Mesh.NumberOfAliveTriangles(); }
  /// Passes over the queue so far (1 without deferral).
  std::int64_t Passes() const { return this->Pass; }

  /// The top vertex: collapsed, set aside for the next pass, or out of the queue without a legal
  /// collapse. False when the queue is empty.
  bool Step(std::int64_t)
  {
    if (this->Heap.Empty())
    {
      return false;
    }
    const std::int32_t v = this->Heap.Pop();
    if (this->Defer && this->Touched[v] == this->Pass)
    {
      this->SetAside.push_back(v);
      return true;
    }
    this->Rules.Propose(v, this->Proposals);
    std::stable_sort(this->Proposals.begin(), this->Proposals.end(),
      [](const CollapseProposal& a, const CollapseProposal& b) { return a.Score < b.Score; });
    bool waits = false; // a proposal with a vertex changed in this pass (memory)
    for (const CollapseProposal& proposal : this->Proposals)
    {
      if (this->Defer && (this->ChangedInThisPass(proposal.Plan) || this->ChangedInThisPass(proposal.Twin)))
      {
        waits = true;
        continue;
      }
      if (!this->PassesChecks(proposal.Plan) || (proposal.Twin.Count > 0 && !this->PassesChecks(proposal.Twin)))
      {
        continue;
      }
      if (this->Rules.ScoresAreKeys() && !this->Heap.Empty() && proposal.Score > this->Heap.TopCost())
      {
        this->Heap.Set(v, proposal.Score); // dearer than the next: it waits at its true price
        return true;
      }
      this->Collapse(proposal.Plan);
      if (proposal.Twin.Count > 0)
      {
        this->Collapse(proposal.Twin);
      }
      return true;
    }
    if (waits)
    {
      this->SetAside.push_back(v); // its next pass may make one
    }
    return true; // else v waits outside the queue for a change around it
  }

  /// With deferral, the next pass: the vertices set aside go back into the queue.
  /// With nothing set aside, the policy's own rules relaxed a step (Relax) and every vertex keyed
  /// again.
  bool Unstick(std::int64_t)
  {
    if (!this->SetAside.empty())
    {
      ++this->Pass;
      for (const std::int32_t v : this->SetAside)
      {
        if (this->Mesh.NumberOfTrianglesAround(v) > 0)
        {
          this->Requeue(v);
        }
      }
      this->SetAside.clear();
      return true;
    }
    if (!this->Rules.Relax())
    {
      return false;
    }
    for (std::int32_t v = 0; v < this->Mesh.NumberOfPoints(); ++v)
    {
      this->Requeue(v);
    }
    return true;
  }

  /// ": of the N points left, L are locked (...); of the others' M proposed collapses, x % ...".
  std::string RefusalSummary()
  {
    std::array<std::int64_t, NumberOfLockReasons> lockedBy{};
    RefusalCounts refused;
    const std::int64_t left = this->Mesh.ForEachUnlockedLeft(lockedBy, [&](std::int32_t v) {
      this->Rules.Propose(v, this->Proposals);
      for (const CollapseProposal& proposal : this->Proposals)
      {
        // Passed counts those the policy's own rules refuse.
        const CollapseCheck failed =
          this->Rules.Accepts(proposal.Plan) ? this->Mesh.FirstFailedCheck(proposal.Plan) : CollapseCheck::Passed;
        this->Mesh.CountRefusal(proposal.Plan, failed, refused);
      }
    });
    return DescribeLeft(left, "points", lockedBy, refused, "proposed collapses", this->Rules.OwnRules());
  }

private:
  /// A star of more triangles than this is a hub's: measured and keyed again after a collapse
  /// only once it has lost an eighth of its triangles since it was last, so that the collapses
  /// around the centre of a fan of n triangles cost n log n, not n².
  static constexpr std::int32_t HubTriangles = 64;

  /// The policy's own filter, then the engine's checks.
  bool PassesChecks(const CollapsePlan& plan)
  {
    return this->Rules.Accepts(plan) && this->Mesh.FirstFailedCheck(plan) == CollapseCheck::Passed;
  }

  bool ChangedInThisPass(const CollapsePlan& plan) const
  {
    for (int i = 0; i < plan.Count; ++i)
    {
      if (this->Touched[plan.Vertices[i]] == this->Pass)
      {
        return true;
      }
    }
    return false;
  }

  /// Whether w's star, changed by a collapse, is to be measured again now (see HubTriangles;
  /// always where force).
  bool MeasureAgain(std::int32_t w, bool force)
  {
    const std::int32_t count = this->Mesh.NumberOfTrianglesAround(w);
    if (force || count <= HubTriangles || 8 * count <= 7 * this->MeasuredCount[w])
    {
      this->MeasuredCount[w] = count;
      return true;
    }
    return false;
  }

  void Requeue(std::int32_t v)
  {
    const double key = this->Mesh.NumberOfTrianglesAround(v) == 0 || this->Mesh.IsLocked(v)
      ? std::numeric_limits<double>::infinity()
      : this->Rules.Key(v);
    if (key < std::numeric_limits<double>::infinity())
    {
      this->Heap.Set(v, key);
    }
    else
    {
      this->Heap.Remove(v);
    }
  }

  void Collapse(const CollapsePlan& plan)
  {
    this->Rules.Collapsed(plan);
    this->Mesh.Apply(plan, false);
    const std::int32_t kept = plan.Vertices[0];
    for (int i = 1; i < plan.Count; ++i)
    {
      this->Heap.Remove(plan.Vertices[i]);
    }
    this->Mesh.Neighbours(kept, this->Ring);
    this->Ring.push_back(kept);
    std::size_t measured = 0;
    for (const std::int32_t w : this->Ring)
    {
      if (this->Defer)
      {
        this->Touched[w] = this->Pass;
      }
      if (this->MeasureAgain(w, w == kept))
      {
        this->Rules.Measure(w);
        this->Ring[measured++] = w;
      }
    }
    this->Ring.resize(measured);
    for (const std::int32_t w : this->Ring)
    {
      // Keyed by score, a neighbour still queued keeps its key until it is on top, where its
      // proposals are scored again (and it waits if dearer than the next): only the kept vertex
      // and the neighbours out of the queue are keyed now.
      if (w == kept || !this->Rules.ScoresAreKeys() || !this->Heap.Contains(w))
      {
        this->Requeue(w);
      }
    }
  }

  CollapseMesh& Mesh;
  Policy& Rules;
  const bool Defer;
  CollapseHeap Heap;
  std::vector<std::uint32_t> Touched; // the pass in which a collapse last changed the star
  std::vector<std::int32_t> MeasuredCount; // the star's triangles when it was last measured
  std::uint32_t Pass = 1;
  std::vector<std::int32_t> SetAside, Ring;
  std::vector<CollapseProposal> Proposals;
};

} // namespace meshsimp

#endif
