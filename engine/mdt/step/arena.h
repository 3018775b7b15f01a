// arena.h: the step's scratch memory. Not installed.
//
// One block, taken from MeMemoryAPI, handed out front to back (bump
// allocation) and given back all at once. Invariants:
//   - take() never returns memory that another live take() also returned;
//     everything taken since a mark() is given back by release(mark);
//   - a step that needs more than the block gets overflow blocks (also from
//     MeMemoryAPI), and the next reset() replaces the lot by one block of the
//     largest size any step used; so once a scene has reached its size the
//     arena takes nothing from MeMemoryAPI any more (what the allocation test
//     checks);
//   - every block is aligned to kBlockAlign and every take to its type's
//     alignment within it, so a type may ask for at most kBlockAlign;
//   - memory is uninitialised: callers fill what they take.
#pragma once

#include <cstddef>
#include <new>
#include <span>
#include <type_traits>

namespace karma::mdt {

class StepArena {
 public:
  // The blocks' alignment (a cache line; the widest vector a take holds,
  // four doubles, needs 32).
  static constexpr std::size_t kBlockAlign = 64;

  StepArena() = default;
  StepArena(const StepArena &) = delete;
  StepArena &operator=(const StepArena &) = delete;
  ~StepArena();

  // Start of a step: everything taken is free again (and the block is
  // resized to the last steps' high-water mark if they overflowed).
  void reset();

  // n objects of a trivially copyable T, uninitialised.
  template <class T>
  std::span<T> take(std::size_t n) {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
    static_assert(alignof(T) <= kBlockAlign);
    if (n == 0) return {};
    void *p = raw(n * sizeof(T), alignof(T));
    return {static_cast<T *>(p), n};
  }
  // n objects, every one set to `value`.
  template <class T>
  std::span<T> filled(std::size_t n, const T &value) {
    std::span<T> s = take<T>(n);
    for (T &x : s) x = value;
    return s;
  }

  // A point to go back to: release(mark) gives back what was taken since.
  struct Mark {
    std::size_t used;
    int overflowCount;
  };
  Mark mark() const { return {used_, overflowCount_}; }
  void release(Mark m);

  std::size_t capacity() const { return size_; }
  std::size_t highWater() const { return highWater_; }

 private:
  static constexpr int kMaxOverflow = 64;
  struct Block {
    void *data;
    std::size_t size;
  };
  void *raw(std::size_t bytes, std::size_t align);
  void *overflow(std::size_t bytes);

  void *block_ = nullptr;
  std::size_t size_ = 0, used_ = 0;
  Block overflow_[kMaxOverflow] = {};
  int overflowCount_ = 0;
  std::size_t overflowBytes_ = 0;  // taken from overflow blocks this step
  std::size_t highWater_ = 0;      // most bytes any step has needed
  bool overflowed_ = false;        // since the last reset
};

}  // namespace karma::mdt
