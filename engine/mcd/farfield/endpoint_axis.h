// endpoint_axis.h: one sorted axis of the axis-sort farfield.
//
// Each proxy in the sorted arrays owns two endpoints on every sorted axis:
// its interval's min and max. An endpoint is (value, slot, isMax), the value
// kept as an order-preserving integer key (KeyOf). The array
// is kept in ascending order of the key (value, isMax): at equal values a min
// comes before a max, so intervals that only touch (a.max == b.min) count as
// overlapping, the same closed-interval test as the brute force
// (a.min <= b.max && b.min <= a.max).
//
// Invariants (outside the member functions):
//  - minPos[s] / maxPos[s] are the array indices of slot s's endpoints, for
//    every slot in the array; minPos[s] < maxPos[s].
//  - After Sort(), the array is sorted by key. Between a value change
//    (SetInterval) and the next Sort() the array is in "rank order": it is
//    still a permutation of the endpoints, and the overlap of two intervals
//    on this axis is defined by the ranks (Overlaps()), not by the values.
//    The space's pair set is kept exact with respect to that rank order, so
//    once every axis is sorted, rank order and value order agree.
//
// Temporal coherence: Sort() is an insertion sort starting from last frame's
// order, O(n + swaps); coherent motion makes few swaps.
#ifndef KARMA_MCD_FARFIELD_ENDPOINT_AXIS_H
#define KARMA_MCD_FARFIELD_ENDPOINT_AXIS_H

#include "MePrecision.h"

#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace karma::mcd {

// Endpoint values are stored as unsigned integers that order like the
// MeReals they encode (sign-magnitude flipped to offset binary), so the sort
// compares integers. -0 is stored as +0, so the order agrees with MeReal's
// == and < for every non-NaN value, infinities included.
#if KARMA_DOUBLE
using SortKey = std::uint64_t;
#else
using SortKey = std::uint32_t;
#endif
static_assert(sizeof(SortKey) == sizeof(MeReal));

inline SortKey KeyOf(MeReal v) {
  if (v == 0) v = 0;  // -0 -> +0
  SortKey bits;
  std::memcpy(&bits, &v, sizeof bits);
  constexpr SortKey sign = SortKey{1} << (8 * sizeof(SortKey) - 1);
  return (bits & sign) ? ~bits : (bits | sign);
}

inline MeReal ValueOf(SortKey key) {
  constexpr SortKey sign = SortKey{1} << (8 * sizeof(SortKey) - 1);
  const SortKey bits = (key & sign) ? (key & ~sign) : ~key;
  MeReal v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

struct Endpoint {
  SortKey key;         // KeyOf(value)
  std::uint32_t data;  // slot << 1 | isMax

  MeReal Value() const { return ValueOf(key); }
  int Slot() const { return static_cast<int>(data >> 1); }
  bool IsMax() const { return (data & 1u) != 0; }
  // The sort order: value first, then min (0) before max (1).
  friend bool Greater(const Endpoint &l, const Endpoint &r) {
    return l.key > r.key || (l.key == r.key && (l.data & 1u) > (r.data & 1u));
  }
};

// A proxy entering the arrays in a batch (EndpointAxis::Merge).
struct NewInterval {
  int slot;
  MeReal min, max;
};

class EndpointAxis {
 public:
  // Room for slot indices in [0, slotCount).
  void Reserve(int slotCount);
  int Size() const { return static_cast<int>(ends_.size()); }
  const Endpoint &At(int i) const { return ends_[static_cast<std::size_t>(i)]; }

  // Writes new values into slot s's endpoints in place (the array may be out
  // of order until the next Sort()).
  void SetInterval(int s, MeReal min, MeReal max) {
    ends_[static_cast<std::size_t>(minPos_[static_cast<std::size_t>(s)])].key = KeyOf(min);
    ends_[static_cast<std::size_t>(maxPos_[static_cast<std::size_t>(s)])].key = KeyOf(max);
  }

  // Overlap of slots a and b on this axis in rank order.
  bool Overlaps(int a, int b) const {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    return minPos_[ua] < maxPos_[ub] && minPos_[ub] < maxPos_[ua];
  }

  // Insertion sort. For every adjacent swap that changes whether two
  // intervals overlap on this axis, calls
  //   onSwap(int slotA, int slotB, bool begins)
  // just after the swap (the positions already reflect it): begins is true
  // when a min moved left past another slot's max (overlap starts), false
  // when a max moved left past another slot's min (overlap ends).
  template <class OnSwap>
  void Sort(OnSwap &&onSwap) {
    const int n = Size();
    for (int i = 1; i < n; ++i) {
      if (Greater(ends_[static_cast<std::size_t>(i - 1)], ends_[static_cast<std::size_t>(i)])) Insert(i, onSwap);
    }
  }
  // The same insertion sort, the same swaps in the same order, visiting
  // only the indices where it can do anything, when the array was sorted
  // and then only the endpoints now at `positions` (ascending, distinct)
  // changed value. The endpoints that kept their values are still in order
  // among themselves, so the sort has nothing to do at index i > p + 1 once
  // e[i - 1] <= e[i] past the last changed position p: the run from p stops
  // there and resumes at the next changed position. Cost: O(changed + swaps).
  template <class OnSwap>
  void SortNear(std::span<const int> positions, OnSwap &&onSwap) {
    const int n = Size();
    int next = 1;  // the first index not yet visited
    for (int p : positions) {
      int i = p > next ? p : next;
      for (; i < n; ++i) {
        if (Greater(ends_[static_cast<std::size_t>(i - 1)], ends_[static_cast<std::size_t>(i)])) {
          Insert(i, onSwap);
        } else if (i > p) {
          break;
        }
      }
      next = i + 1;
    }
  }

  // Adds a batch of intervals (slots not yet in the array) in one merge,
  // O(n + k log k). The array must be sorted on entry and is sorted on exit.
  void Merge(std::span<const NewInterval> added);

  // Removes every endpoint whose slot has gone[slot] != 0, keeping the order.
  void Compact(const std::vector<std::uint8_t> &gone);

  // True when the array is in ascending key order (tests and assertions).
  bool IsSorted() const;
  int MinPos(int s) const { return minPos_[static_cast<std::size_t>(s)]; }
  int MaxPos(int s) const { return maxPos_[static_cast<std::size_t>(s)]; }

 private:
  // One step of the insertion sort: e[i] moves left past every endpoint
  // greater than it (the prefix [0, i) being sorted), with the swap calls.
  template <class OnSwap>
  void Insert(int i, OnSwap &onSwap) {
    Endpoint *e = ends_.data();
    const Endpoint moving = e[i];
    int j = i;
    do {
      const Endpoint passed = e[j - 1];
      e[j] = passed;
      Place(passed, j);
      --j;
      if (moving.IsMax() != passed.IsMax()) {
        // A min passing a max leftwards starts an overlap; a max passing
        // a min leftwards ends one.
        e[j] = moving;
        Place(moving, j);
        onSwap(moving.Slot(), passed.Slot(), !moving.IsMax());
      }
    } while (j > 0 && Greater(e[j - 1], moving));
    e[j] = moving;
    Place(moving, j);
  }
  void Place(const Endpoint &e, int i) {
    auto &pos = e.IsMax() ? maxPos_ : minPos_;
    pos[static_cast<std::size_t>(e.Slot())] = i;
  }
  void Reindex();

  std::vector<Endpoint> ends_;
  std::vector<int> minPos_, maxPos_;  // by slot
  std::vector<Endpoint> scratch_;
};

}  // namespace karma::mcd

#endif
