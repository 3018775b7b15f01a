// pair_table.h: the two pair stores of the axis-sort farfield.
//
// OverlapTable: every pair of proxies whose intervals overlap on all sorted
// axes (in the axes' rank order, see endpoint_axis.h), whether or not it is
// reported (frozen-frozen, disabled and culled pairs are kept so that an
// unfreeze or an enable can say hello without a search). A flat open-
// addressing hash keyed by the two slots (lower slot in the high half).
// It starts with room for the space's pairCount and grows if more pairs
// overlap; only the reported records below are capped.
//
// PairPool: the PairRecords the space reports, exactly pairCount of them
// (the guide's pairCount). A record keeps its index and address from its
// hello to its goodbye; it returns to the pool when the change block after
// its goodbye begins, and is only then handed to a new pair.
#ifndef KARMA_MCD_FARFIELD_PAIR_TABLE_H
#define KARMA_MCD_FARFIELD_PAIR_TABLE_H

#include <cstdint>
#include <vector>

namespace karma::mcd {

// Where a reported pair is in its life cycle in the current events.
enum class PairState : std::uint8_t { Free, Hello, Staying, Goodbye };

// One reported pair. proxyA was inserted before proxyB (serialA < serialB);
// userA/userB are their user pointers (copied, so they remain readable in a
// goodbye after the proxy was removed).
struct PairRecord {
  int index = 0;  // stable position in the pool, [0, pairCount)
  int proxyA = -1, proxyB = -1;
  void *userA = nullptr, *userB = nullptr;
  std::uint32_t serialA = 0, serialB = 0;
  PairState state = PairState::Free;

  // The deterministic order of reported pairs: by the proxies' insertion
  // serials, never by addresses.
  std::uint64_t OrderKey() const { return (std::uint64_t{serialA} << 32) | serialB; }
};

inline std::uint64_t SlotPairKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (std::uint64_t{lo} << 32) | hi;
}

struct OverlapEntry {
  std::uint64_t key;     // SlotPairKey, or kEmpty
  int record;            // PairRecord index when reported, else -1
  bool overlapping;      // false: overlap ended this block, awaiting its goodbye
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  int SlotLo() const { return static_cast<int>(key >> 32); }
  int SlotHi() const { return static_cast<int>(key & 0xffffffffu); }
};

class OverlapTable {
 public:
  void Reserve(int entries);
  int Size() const { return size_; }
  // The entry for key, or nullptr.
  OverlapEntry *Find(std::uint64_t key);
  // The entry for key, added (record -1, overlapping false) if absent.
  OverlapEntry &FindOrAdd(std::uint64_t key);
  void Erase(std::uint64_t key);
  // Raw slot access for a full walk: entries with key != kEmpty are live.
  int Capacity() const { return static_cast<int>(slots_.size()); }
  OverlapEntry &Slot(int i) { return slots_[static_cast<std::size_t>(i)]; }

 private:
  std::size_t Home(std::uint64_t key) const;
  void Grow();

  std::vector<OverlapEntry> slots_;  // power-of-two size, load <= 1/2
  int size_ = 0;
};

class PairPool {
 public:
  void Create(int count);
  int Capacity() const { return static_cast<int>(records_.size()); }
  int InUse() const { return Capacity() - static_cast<int>(free_.size()); }
  // A free record, or nullptr when all pairCount records are in use.
  PairRecord *Acquire();
  void Release(PairRecord *r);
  PairRecord &At(int index) { return records_[static_cast<std::size_t>(index)]; }
  const PairRecord &At(int index) const { return records_[static_cast<std::size_t>(index)]; }

 private:
  std::vector<PairRecord> records_;  // never reallocated after Create
  std::vector<int> free_;            // LIFO; lowest indices handed out first
};

}  // namespace karma::mcd

#endif
