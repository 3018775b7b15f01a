// pair_table.h: the two pair stores of the axis-sort farfield.
//
// OverlapTable: every pair of proxies whose intervals overlap on all sorted
// axes (in the axes' rank order, see endpoint_axis.h), whether or not it is
// reported (frozen-frozen, disabled and culled pairs are kept so that an
// unfreeze or an enable can say hello without a search). The entries are
// packed in one array (walked in O(entries) when everything must be looked
// at) and found through an open-addressing hash keyed by the two slots
// (lower slot in the high half); each entry is also in a doubly linked list
// per slot it names, so a proxy's entries are found in O(its entries). It
// grows as more pairs overlap; only the reported records below are capped.
//
// PairPool: the PairRecords the space reports. Its limit starts at the
// guide's pairCount; records are made as needed (the first
// min(pairCount, kFirstRecords) at once, then doubling) up to the limit, so
// a huge pairCount costs nothing until that many pairs overlap. When every
// record up to the limit is in use, the limit grows by as many again (at
// least 16) and Acquire says so, so no overlapping pair goes unreported. A
// record keeps its index and address from its hello to its goodbye (records
// are added at the back of a deque and never move); it returns to the pool
// when the change block after its goodbye begins, and is only then handed
// to a new pair.
#ifndef KARMA_MCD_FARFIELD_PAIR_TABLE_H
#define KARMA_MCD_FARFIELD_PAIR_TABLE_H

#include <compare>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

namespace karma::mcd {

// Where a reported pair is in its life cycle in the current events.
enum class PairState : std::uint8_t { Free, Hello, Staying, Goodbye };

// A proxy's place in the pair order: its sort key first, then its
// insertion serial (which breaks ties between equal keys only).
struct ProxyRank {
  std::uint32_t key = 0;
  std::uint32_t serial = 0;
  std::uint64_t Packed() const { return (std::uint64_t{key} << 32) | serial; }
};

// The order of two reported pairs: lexicographic on (rank of A, rank of B).
struct PairOrder {
  std::uint64_t first = 0, second = 0;
  friend auto operator<=>(const PairOrder &, const PairOrder &) = default;
};

// One reported pair. proxyA ranks before proxyB: keyA < keyB, or equal keys
// and serialA < serialB (see "Pair order" in axis_sort_space.h). userA/userB
// are their user pointers (copied, so they remain readable in a goodbye after
// the proxy was removed).
struct PairRecord {
  int index = 0;  // stable position in the pool, [0, Capacity())
  int proxyA = -1, proxyB = -1;
  void *userA = nullptr, *userB = nullptr;
  std::uint32_t serialA = 0, serialB = 0;
  std::uint32_t keyA = 0, keyB = 0;  // the proxies' sort keys when last ranked
  PairState state = PairState::Free;

  // The identity of the two proxies, whichever is A: (lower serial << 32) |
  // higher serial. Unique among the pairs of a space's life.
  std::uint64_t SerialPair() const {
    const std::uint32_t lo = serialA < serialB ? serialA : serialB;
    const std::uint32_t hi = serialA < serialB ? serialB : serialA;
    return (std::uint64_t{lo} << 32) | hi;
  }
  // The deterministic order of reported pairs: by the proxies' sort keys,
  // then insertion serials, never by addresses.
  PairOrder Order() const { return {ProxyRank{keyA, serialA}.Packed(), ProxyRank{keyB, serialB}.Packed()}; }
};

inline std::uint64_t SlotPairKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (std::uint64_t{lo} << 32) | hi;
}

struct OverlapEntry {
  std::uint64_t key;  // SlotPairKey, or kEmpty
  int record;         // PairRecord index when reported, else -1
  bool overlapping;   // false: overlap ended this block, awaiting its goodbye
  // The entry's place in its two slots' lists (OverlapTable::ForEachOf):
  // [0] in the list of SlotLo(), [1] in that of SlotHi(); -1 ends a list.
  int next[2];
  int prev[2];
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  int SlotLo() const { return static_cast<int>(key >> 32); }
  int SlotHi() const { return static_cast<int>(key & 0xffffffffu); }
};

class OverlapTable {
 public:
  void Reserve(int entries);
  int Size() const { return static_cast<int>(dense_.size()); }
  // The entry for key, or nullptr.
  OverlapEntry *Find(std::uint64_t key);
  // The entry for key, added (record -1, overlapping false) if absent. The
  // reference lives until the next addition.
  OverlapEntry &FindOrAdd(std::uint64_t key);
  // Removes key's entry; the last entry moves into its place.
  void Erase(std::uint64_t key);
  // Dense access for a full walk in O(Size()): entries [0, Size()).
  OverlapEntry &At(int i) { return dense_[static_cast<std::size_t>(i)]; }
  std::span<const OverlapEntry> Entries() const { return dense_; }
  // Room for slots [0, slotCount) in the per-slot lists.
  void ReserveSlots(int slotCount) { head_.assign(static_cast<std::size_t>(slotCount), -1); }
  // Calls fn(entry) for every entry naming `slot` (in no set order); fn
  // must not add or erase entries.
  template <class Fn>
  void ForEachOf(int slot, Fn &&fn) {
    for (int i = head_[static_cast<std::size_t>(slot)]; i >= 0;) {
      OverlapEntry &e = dense_[static_cast<std::size_t>(i)];
      i = e.next[Side(e, slot)];
      fn(e);
    }
  }
  // The head of slot's list, for Validate.
  int Head(int slot) const { return head_[static_cast<std::size_t>(slot)]; }
  static int Side(const OverlapEntry &e, int slot) { return e.SlotLo() == slot ? 0 : 1; }

 private:
  void Link(int index);
  void Unlink(int index);
  void Relocate(int from, int to);
  struct Slot {
    std::uint64_t key;  // OverlapEntry::kEmpty when free
    int index;          // into dense_
  };
  std::size_t Home(std::uint64_t key) const;
  std::size_t SlotOf(std::uint64_t key) const;  // its slot, or a free one
  void Grow();

  std::vector<OverlapEntry> dense_;  // the entries, packed
  std::vector<Slot> slots_;          // power-of-two size, load <= 1/2
  std::vector<int> head_;            // by proxy slot: first entry naming it, or -1
};

class PairPool {
 public:
  static constexpr int kFirstRecords = 4096;
  // An empty pool with limit `count` (>= 1) and its first records.
  void Create(int count);
  // The records made so far (indices [0, Capacity())); <= Limit().
  int Capacity() const { return static_cast<int>(records_.size()); }
  // pairCount, or more once the pool outgrew it.
  int Limit() const { return limit_; }
  int InUse() const { return Capacity() - static_cast<int>(free_.size()); }
  // A free record, the lowest free index first. When none is free the pool
  // first makes more records; when it had made Limit() of them, it first
  // raises the limit by as many (at least 16) and sets *grew.
  PairRecord *Acquire(bool *grew);
  void Release(PairRecord *r);
  PairRecord &At(int index) { return records_[static_cast<std::size_t>(index)]; }
  const PairRecord &At(int index) const { return records_[static_cast<std::size_t>(index)]; }

 private:
  void Grow(int more);

  std::deque<PairRecord> records_;  // grown at the back only: records never move
  std::vector<int> free_;           // LIFO; lowest indices handed out first
  int limit_ = 0;
};

}  // namespace karma::mcd

#endif
