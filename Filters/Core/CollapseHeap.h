// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CollapseHeap.h
 * @brief An addressable binary min-heap of element ids keyed by cost, for collapse decimators.
 *
 * Every id in [0, n) is in the heap at most once; Set() inserts it or moves it to its new cost
 * (decrease- and increase-key in O(log n)), Remove() takes it out. Flat arrays only: the heap of
 * {cost, sequence, id} and the position of each id.
 *
 * Tie rule, so that results are deterministic: of two equal costs the one set earlier comes
 * first. Each Set() draws a fresh sequence number, so an element whose cost is set again goes
 * behind the others of the same cost — paper 004 §3.5 queues a triangle whose new cost is zero
 * behind the triangles already waiting with cost zero. Fill the heap in id order to make the
 * initial order the id order.
 */
#ifndef MeshSimplification_CollapseHeap_h
#define MeshSimplification_CollapseHeap_h

#include <cstdint>
#include <vector>

namespace meshsimp
{

class CollapseHeap
{
public:
  explicit CollapseHeap(std::int32_t size = 0) { this->Reset(size); }

  void Reset(std::int32_t size)
  {
    this->Entries.clear();
    this->Position.assign(size, -1);
    this->NextSequence = 0;
  }

  bool Empty() const { return this->Entries.empty(); }
  std::size_t Size() const { return this->Entries.size(); }
  bool Contains(std::int32_t id) const { return this->Position[id] >= 0; }
  std::int32_t Top() const { return this->Entries.front().Id; }
  double TopCost() const { return this->Entries.front().Cost; }
  /// The cost of an id in the heap.
  double Cost(std::int32_t id) const { return this->Entries[this->Position[id]].Cost; }

  /// Inserts id, or moves it to its new cost, behind the entries of equal cost.
  void Set(std::int32_t id, double cost)
  {
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
  }

  std::int32_t Pop()
  {
    const std::int32_t id = this->Top();
    this->Remove(id);
    return id;
  }

private:
  struct Entry
  {
    double Cost;
    std::uint64_t Sequence;
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
    while (slot > 0 && entry < this->Entries[(slot - 1) / 2])
    {
      this->Place(slot, this->Entries[(slot - 1) / 2]);
      slot = (slot - 1) / 2;
    }
    const std::int32_t n = static_cast<std::int32_t>(this->Entries.size());
    for (;;)
    {
      std::int32_t child = 2 * slot + 1;
      if (child >= n)
      {
        break;
      }
      if (child + 1 < n && this->Entries[child + 1] < this->Entries[child])
      {
        ++child;
      }
      if (!(this->Entries[child] < entry))
      {
        break;
      }
      this->Place(slot, this->Entries[child]);
      slot = child;
    }
    this->Place(slot, entry);
  }

  std::vector<Entry> Entries;
  std::vector<std::int32_t> Position; // slot of each id, -1 when absent
  std::uint64_t NextSequence = 0;
};

} // namespace meshsimp

#endif
