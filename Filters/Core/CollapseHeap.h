// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CollapseHeap.h
 * @brief An addressable binary min-heap of element ids keyed by cost, for collapse decimators.
 *
 * Every id in [0, n) is in the heap at most once; Set() inserts it or moves it to its new cost
 * (decrease- and increase-key in O(log n)), Remove() takes it out. Flat arrays only: the heap of
 * 16-byte {cost, sequence, id} entries and the position of each id. The heap is 4-ary: a node's
 * four children share one cache line, and the tree is half as deep as a binary one.
 *
 * Tie rule, so that results are deterministic: of two equal costs the one set earlier comes
 * first. Each Set() draws a fresh sequence number, so an element whose cost is set again goes
 * behind the others of the same cost — Zhou, Zhang and Cheng, "Mesh Simplification by Volume
 * Variation with Feature Preserving", §3.5, queue a triangle whose new cost is zero behind the
 * triangles already waiting with cost zero. Fill the heap in id order to make the
 * initial order the id order.
 */
#ifndef MeshSimplification_CollapseHeap_h
#define MeshSimplification_CollapseHeap_h

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace meshsimp
{

class CollapseHeap
{
public:
  /// sequenceLimit: how many Set() calls before sequence numbers are renumbered (tests lower it).
  explicit CollapseHeap(std::int32_t size = 0,
    std::uint32_t sequenceLimit = std::numeric_limits<std::uint32_t>::max())
    : SequenceLimit(sequenceLimit)
  {
    this->Reset(size);
  }

  void Reset(std::int32_t size)
  {
    this->Entries.clear();
    this->Entries.reserve(size); // one entry per id at most: no doubling past it
    this->Position.assign(size, -1);
    this->NextSequence = 0;
  }

  bool Empty() const { return this->Entries.empty(); }
  std::size_t Size() const { return this->Entries.size(); }
  bool Contains(std::int32_t id) const { return this->Position[id] >= 0; }
  std::int32_t Top() const { return this->Entries.front().Id; }
  double TopCost() const { return this->Entries.front().Cost; }

  /// Inserts id, or moves it to its new cost, behind the entries of equal cost.
  void Set(std::int32_t id, double cost)
  {
    if (this->NextSequence >= this->SequenceLimit)
    {
      this->Renumber();
    }
    const Entry entry{ cost, this->NextSequence++, id };
    std::int32_t slot = this->Position[id];
    if (slot < 0)
    {
      slot = static_cast<std::int32_t>(this->Entries.size());
      this->Entries.push_back(entry);
    }
    else
    {
      this->Entries[slot] = entry;
    }
    this->Position[id] = slot;
    this->Restore(slot);
  }

  void Remove(std::int32_t id)
  {
    const std::int32_t slot = this->Position[id];
    if (slot < 0)
    {
      return;
    }
    this->Position[id] = -1;
    const Entry last = this->Entries.back();
    this->Entries.pop_back();
    if (slot < static_cast<std::int32_t>(this->Entries.size()))
    {
      this->Entries[slot] = last;
      this->Position[last.Id] = slot;
      this->Restore(slot);
    }
    this->ReleaseUnused();
  }

  std::int32_t Pop()
  {
    const std::int32_t id = this->Top();
    this->Remove(id);
    return id;
  }

private:
  static constexpr std::int32_t Arity = 4;

  struct Entry
  {
    double Cost;
    std::uint32_t Sequence;
    std::int32_t Id;
    bool operator<(const Entry& o) const
    {
      return this->Cost < o.Cost || (this->Cost == o.Cost && this->Sequence < o.Sequence);
    }
  };

  void Place(std::int32_t slot, const Entry& entry)
  {
    this->Entries[slot] = entry;
    this->Position[entry.Id] = slot;
  }

  /// Moves the entry at slot up or down until the heap order holds again.
  void Restore(std::int32_t slot)
  {
    const Entry entry = this->Entries[slot];
    while (slot > 0 && entry < this->Entries[(slot - 1) / Arity])
    {
      this->Place(slot, this->Entries[(slot - 1) / Arity]);
      slot = (slot - 1) / Arity;
    }
    const std::int32_t n = static_cast<std::int32_t>(this->Entries.size());
    for (;;)
    {
      const std::int32_t first = Arity * slot + 1;
      if (first >= n)
      {
        break;
      }
      std::int32_t best = first;
      for (std::int32_t child = first + 1; child < std::min(first + Arity, n); ++child)
      {
        best = this->Entries[child] < this->Entries[best] ? child : best;
      }
      if (!(this->Entries[best] < entry))
      {
        break;
      }
      this->Place(slot, this->Entries[best]);
      slot = best;
    }
    this->Place(slot, entry);
  }

  /// A heap emptied to a quarter of its room gives the rest back: a decimator's heap holds
  /// every triangle at first and few at the end, when its collapse records are the most.
  void ReleaseUnused()
  {
    constexpr std::size_t smallest = 1 << 16;
    if (this->Entries.capacity() > smallest && 4 * this->Entries.size() < this->Entries.capacity())
    {
      this->Entries.shrink_to_fit();
    }
  }

  /// Sequence numbers run out after 2^32 - 1 Set() calls: number the entries again in their
  /// order, which keeps every comparison as it was.
  void Renumber()
  {
    std::vector<Entry> sorted = this->Entries;
    std::sort(sorted.begin(), sorted.end());
    std::uint32_t sequence = 0;
    for (const Entry& e : sorted)
    {
      this->Entries[this->Position[e.Id]].Sequence = sequence++;
    }
    this->NextSequence = sequence;
  }

  std::vector<Entry> Entries;
  std::vector<std::int32_t> Position; // slot of each id, -1 when absent
  std::uint32_t NextSequence = 0;
  std::uint32_t SequenceLimit;
};

} // namespace meshsimp

#endif
