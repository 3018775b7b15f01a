// pair_table.cpp: the overlap hash (linear probing with backward-shift
// deletion, so no tombstones) and the pool of pair records.
//
// OverlapTable invariants: a hash slot sits at its home or after it in the
// probe sequence with no free slot in between; slots_ and dense_ hold the
// same keys, each slot's index naming its entry in dense_; every entry is in
// exactly the lists of its two slots, prev/next naming its neighbours there
// and head_ the first of each list.
#include "pair_table.h"

#include <algorithm>
#include <limits>

namespace karma::mcd {

std::size_t OverlapTable::Home(std::uint64_t key) const {
  // 64-bit mix (splitmix64 finaliser): slot pairs are dense small integers.
  key ^= key >> 30;
  key *= 0xbf58476d1ce4e5b9ull;
  key ^= key >> 27;
  key *= 0x94d049bb133111ebull;
  key ^= key >> 31;
  return static_cast<std::size_t>(key) & (slots_.size() - 1);
}

void OverlapTable::Reserve(int entries) {
  std::size_t cap = 16;
  while (cap < 2 * static_cast<std::size_t>(entries > 0 ? entries : 1)) cap *= 2;
  slots_.assign(cap, Slot{OverlapEntry::kEmpty, -1});
  dense_.clear();
  dense_.reserve(static_cast<std::size_t>(entries > 0 ? entries : 1));
}

std::size_t OverlapTable::SlotOf(std::uint64_t key) const {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = Home(key);
  while (slots_[i].key != key && slots_[i].key != OverlapEntry::kEmpty) i = (i + 1) & mask;
  return i;
}

OverlapEntry *OverlapTable::Find(std::uint64_t key) {
  const Slot &slot = slots_[SlotOf(key)];
  return slot.key == key ? &dense_[static_cast<std::size_t>(slot.index)] : nullptr;
}

OverlapEntry &OverlapTable::FindOrAdd(std::uint64_t key) {
  if (2 * (dense_.size() + 1) > slots_.size()) Grow();
  Slot &slot = slots_[SlotOf(key)];
  if (slot.key != key) {
    slot = Slot{key, static_cast<int>(dense_.size())};
    dense_.push_back(OverlapEntry{key, -1, false, {-1, -1}, {-1, -1}});
    Link(slot.index);
  }
  return dense_[static_cast<std::size_t>(slot.index)];
}

void OverlapTable::Erase(std::uint64_t key) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = SlotOf(key);
  if (slots_[i].key != key) return;
  // Keep dense_ packed: the last entry moves into the erased one's place.
  const int index = slots_[i].index;
  Unlink(index);
  const std::uint64_t lastKey = dense_.back().key;
  if (lastKey != key) {
    Relocate(static_cast<int>(dense_.size()) - 1, index);
    slots_[SlotOf(lastKey)].index = index;
  }
  dense_.pop_back();
  // Backward shift: pull later slots of the run into the hole when their
  // home does not lie cyclically in (hole, position].
  std::size_t hole = i;
  for (std::size_t j = (i + 1) & mask; slots_[j].key != OverlapEntry::kEmpty; j = (j + 1) & mask) {
    const std::size_t home = Home(slots_[j].key);
    const bool homeInGap = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
    if (!homeInGap) {
      slots_[hole] = slots_[j];
      hole = j;
    }
  }
  slots_[hole] = Slot{OverlapEntry::kEmpty, -1};
}

// The per-slot lists: entry `index` at the front of both its slots' lists.
void OverlapTable::Link(int index) {
  OverlapEntry &e = dense_[static_cast<std::size_t>(index)];
  const int slots[2] = {e.SlotLo(), e.SlotHi()};
  for (int side = 0; side < 2; ++side) {
    int &head = head_[static_cast<std::size_t>(slots[side])];
    e.prev[side] = -1;
    e.next[side] = head;
    if (head >= 0) {
      OverlapEntry &h = dense_[static_cast<std::size_t>(head)];
      h.prev[Side(h, slots[side])] = index;
    }
    head = index;
  }
}

void OverlapTable::Unlink(int index) {
  OverlapEntry &e = dense_[static_cast<std::size_t>(index)];
  const int slots[2] = {e.SlotLo(), e.SlotHi()};
  for (int side = 0; side < 2; ++side) {
    const int p = e.prev[side], n = e.next[side];
    if (p >= 0) {
      OverlapEntry &pe = dense_[static_cast<std::size_t>(p)];
      pe.next[Side(pe, slots[side])] = n;
    } else {
      head_[static_cast<std::size_t>(slots[side])] = n;
    }
    if (n >= 0) {
      OverlapEntry &ne = dense_[static_cast<std::size_t>(n)];
      ne.prev[Side(ne, slots[side])] = p;
    }
  }
}

// Moves the (linked) entry at `from` to the free place `to`, pointing its
// neighbours and heads at the new place.
void OverlapTable::Relocate(int from, int to) {
  OverlapEntry &e = dense_[static_cast<std::size_t>(to)];
  e = dense_[static_cast<std::size_t>(from)];
  const int slots[2] = {e.SlotLo(), e.SlotHi()};
  for (int side = 0; side < 2; ++side) {
    const int p = e.prev[side], n = e.next[side];
    if (p >= 0) {
      OverlapEntry &pe = dense_[static_cast<std::size_t>(p)];
      pe.next[Side(pe, slots[side])] = to;
    } else {
      head_[static_cast<std::size_t>(slots[side])] = to;
    }
    if (n >= 0) {
      OverlapEntry &ne = dense_[static_cast<std::size_t>(n)];
      ne.prev[Side(ne, slots[side])] = to;
    }
  }
}

void OverlapTable::Grow() {
  slots_.assign(slots_.size() * 2, Slot{OverlapEntry::kEmpty, -1});
  for (std::size_t d = 0; d < dense_.size(); ++d) {
    slots_[SlotOf(dense_[d].key)] = Slot{dense_[d].key, static_cast<int>(d)};
  }
}

void PairPool::Create(int count) {
  records_.clear();
  free_.clear();
  limit_ = count;
  Grow(std::min(count, kFirstRecords));
}

void PairPool::Grow(int more) {
  const int first = Capacity();
  for (int i = 0; i < more; ++i) {
    records_.emplace_back();
    records_.back().index = first + i;
  }
  free_.reserve(free_.size() + static_cast<std::size_t>(more));
  for (int i = first + more - 1; i >= first; --i) free_.push_back(i);
}

PairRecord *PairPool::Acquire(bool *grew) {
  if (free_.empty()) {
    const int made = Capacity();
    const int step = std::max(made, 16);
    if (made >= limit_) {
      limit_ = made + std::min(step, std::numeric_limits<int>::max() - made);
      *grew = true;
    }
    Grow(std::min(step, limit_ - made));
  }
  PairRecord &r = records_[static_cast<std::size_t>(free_.back())];
  free_.pop_back();
  return &r;
}

void PairPool::Release(PairRecord *r) {
  const int index = r->index;
  *r = PairRecord{};
  r->index = index;
  free_.push_back(index);
}

}  // namespace karma::mcd
