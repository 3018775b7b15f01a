// pair_table.cpp: the overlap hash (linear probing with backward-shift
// deletion, so no tombstones) and the fixed pool of pair records.
//
// OverlapTable invariant: an entry sits at its home slot or after it in the
// probe sequence, with no empty slot between its home and its position.
#include "pair_table.h"

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
  slots_.assign(cap, OverlapEntry{OverlapEntry::kEmpty, -1, false});
  size_ = 0;
}

OverlapEntry *OverlapTable::Find(std::uint64_t key) {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = Home(key);; i = (i + 1) & mask) {
    OverlapEntry &e = slots_[i];
    if (e.key == key) return &e;
    if (e.key == OverlapEntry::kEmpty) return nullptr;
  }
}

OverlapEntry &OverlapTable::FindOrAdd(std::uint64_t key) {
  if (2 * static_cast<std::size_t>(size_ + 1) > slots_.size()) Grow();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = Home(key);; i = (i + 1) & mask) {
    OverlapEntry &e = slots_[i];
    if (e.key == key) return e;
    if (e.key == OverlapEntry::kEmpty) {
      e = OverlapEntry{key, -1, false};
      ++size_;
      return e;
    }
  }
}

void OverlapTable::Erase(std::uint64_t key) {
  const std::size_t mask = slots_.size() - 1;
  std::size_t i = Home(key);
  while (slots_[i].key != key) {
    if (slots_[i].key == OverlapEntry::kEmpty) return;
    i = (i + 1) & mask;
  }
  // Backward shift: pull later entries of the run into the hole when their
  // home does not lie strictly between the hole and their position.
  std::size_t hole = i;
  for (std::size_t j = (i + 1) & mask; slots_[j].key != OverlapEntry::kEmpty; j = (j + 1) & mask) {
    const std::size_t home = Home(slots_[j].key);
    const bool homeInGap = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
    if (!homeInGap) {
      slots_[hole] = slots_[j];
      hole = j;
    }
  }
  slots_[hole] = OverlapEntry{OverlapEntry::kEmpty, -1, false};
  --size_;
}

void OverlapTable::Grow() {
  std::vector<OverlapEntry> old;
  old.swap(slots_);
  slots_.assign(old.size() * 2, OverlapEntry{OverlapEntry::kEmpty, -1, false});
  const std::size_t mask = slots_.size() - 1;
  for (const OverlapEntry &e : old) {
    if (e.key == OverlapEntry::kEmpty) continue;
    std::size_t i = Home(e.key);
    while (slots_[i].key != OverlapEntry::kEmpty) i = (i + 1) & mask;
    slots_[i] = e;
  }
}

void PairPool::Create(int count) {
  records_.assign(static_cast<std::size_t>(count), PairRecord{});
  free_.clear();
  free_.reserve(static_cast<std::size_t>(count));
  for (int i = count - 1; i >= 0; --i) {
    records_[static_cast<std::size_t>(i)].index = i;
    free_.push_back(i);
  }
}

PairRecord *PairPool::Acquire() {
  if (free_.empty()) return nullptr;
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
