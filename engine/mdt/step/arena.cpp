// arena.cpp: the step's scratch memory (arena.h).
#include "arena.h"

#include <algorithm>
#include <cstdint>

#include "MeMemory.h"
#include "MeMessage.h"

namespace karma::mdt {

namespace {
// v rounded up to a multiple of a, a power of two (every alignof is): a
// mask, not a division, since raw() runs for every array a step takes.
std::size_t alignUp(std::size_t v, std::size_t a) { return (v + a - 1) & ~(a - 1); }
constexpr std::size_t kAlign = alignof(std::max_align_t);
}  // namespace

StepArena::~StepArena() {
  release({0, 0});
  if (block_) MeMemoryAPI.destroyAligned(block_);
}

void StepArena::reset() {
  release({0, 0});
  if (!overflowed_) return;
  overflowed_ = false;
  // Grow to what the busiest step needed, with room to spare.
  const std::size_t want = alignUp(highWater_ + highWater_ / 2, 4096);
  if (block_) MeMemoryAPI.destroyAligned(block_);
  block_ = MeMemoryAPI.createAligned(want, kBlockAlign);
  size_ = block_ ? want : 0;
}

void StepArena::release(Mark m) {
  while (overflowCount_ > m.overflowCount) {
    Block &b = overflow_[--overflowCount_];
    MeMemoryAPI.destroyAligned(b.data);
    overflowBytes_ -= b.size;
    b = {};
  }
  used_ = std::min(used_, m.used);
}

void *StepArena::raw(std::size_t bytes, std::size_t align) {
  const std::size_t start = alignUp(used_, align);
  highWater_ = std::max(highWater_, start + bytes + overflowBytes_);
  if (block_ && start + bytes <= size_) {
    used_ = start + bytes;
    return static_cast<char *>(block_) + start;
  }
  return overflow(bytes);
}

// The block is full: this request gets a block of its own, freed at the
// next release past it or reset (which then grows the main block).
void *StepArena::overflow(std::size_t bytes) {
  if (overflowCount_ == kMaxOverflow) {
    MeFatalError(0, "MdtWorldStep: the step arena ran out of overflow blocks");
    return nullptr;
  }
  const std::size_t size = alignUp(bytes, kAlign);
  void *p = MeMemoryAPI.createAligned(size, (unsigned)kBlockAlign);  // take() allows no wider
  if (!p) {
    MeFatalError(0, "MdtWorldStep: out of memory for %zu bytes of step scratch", bytes);
    return nullptr;
  }
  overflow_[overflowCount_++] = {p, size};
  overflowed_ = true;
  overflowBytes_ += size;
  highWater_ = std::max(highWater_, used_ + overflowBytes_);
  return p;
}

}  // namespace karma::mdt
