// Once a scene has reached its size, MdtWorldStep allocates nothing: not
// through MeMemoryAPI (the step arena, Kea's workspace) and not through the
// global operator new (std::vector growth, Eigen). This executable replaces
// the global operator new and MeMemoryAPI's create functions to count.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "MeMemory.h"
#include "anchor_scene.h"

namespace {

std::atomic<long> gNew{0};
long gMe = 0;
void *(MEAPI *gCreate)(size_t) = nullptr;
void *(MEAPI *gCreateZeroed)(size_t) = nullptr;
void *(MEAPI *gCreateAligned)(size_t, unsigned) = nullptr;
void *(MEAPI *gResize)(void *, size_t) = nullptr;

void *MEAPI CountCreate(size_t n) { return ++gMe, gCreate(n); }
void *MEAPI CountCreateZeroed(size_t n) { return ++gMe, gCreateZeroed(n); }
void *MEAPI CountCreateAligned(size_t n, unsigned a) { return ++gMe, gCreateAligned(n, a); }
void *MEAPI CountResize(void *p, size_t n) { return ++gMe, gResize(p, n); }

struct Counts {
  long newCalls, memoryApiCalls;
};

// Allocations during `steps` steps of the scene.
Counts CountDuring(karma::scenes::AnchorScene &scene, int steps) {
  gCreate = MeMemoryAPI.create, gCreateZeroed = MeMemoryAPI.createZeroed;
  gCreateAligned = MeMemoryAPI.createAligned, gResize = MeMemoryAPI.resize;
  MeMemoryAPI.create = CountCreate, MeMemoryAPI.createZeroed = CountCreateZeroed;
  MeMemoryAPI.createAligned = CountCreateAligned, MeMemoryAPI.resize = CountResize;
  const long new0 = gNew.load(), me0 = gMe;
  MdtWorldID world = scene.world();
  for (int i = 0; i < steps; ++i) MdtWorldStep(world, karma::scenes::AnchorScene::kStep);
  const Counts c{gNew.load() - new0, gMe - me0};
  MeMemoryAPI.create = gCreate, MeMemoryAPI.createZeroed = gCreateZeroed;
  MeMemoryAPI.createAligned = gCreateAligned, MeMemoryAPI.resize = gResize;
  return c;
}

// The world steps alone (the contacts frozen as the bridge left them), so
// only the dynamics step is counted.
void ExpectNoAllocationOnceSettled(std::unique_ptr<karma::scenes::AnchorScene> scene, int settle) {
  for (int i = 0; i < settle; ++i) scene->step();
  const Counts c = CountDuring(*scene, 100);
  std::printf("%s: %ld operator new and %ld MeMemoryAPI calls in 100 settled steps\n", scene->name(), c.newCalls,
              c.memoryApiCalls);
  EXPECT_EQ(c.newCalls, 0);
  EXPECT_EQ(c.memoryApiCalls, 0);
}

TEST(StepAllocation, ToppleAtRestAllocatesNothing) { ExpectNoAllocationOnceSettled(karma::scenes::MakeTopple(), 120); }
TEST(StepAllocation, TheCarAllocatesNothing) { ExpectNoAllocationOnceSettled(karma::scenes::MakeCar(), 60); }
TEST(StepAllocation, TheRagdollAllocatesNothing) { ExpectNoAllocationOnceSettled(karma::scenes::MakeRagdoll(), 300); }

}  // namespace

// Every form of the global operators is replaced, so whatever the library
// allocates with one form it frees with the matching one (ASan checks).
namespace {
void *Counted(std::size_t n) {
  ++gNew;
  return std::malloc(n ? n : 1);
}
void *CountedAligned(std::size_t n, std::align_val_t a) {
  ++gNew;
  const std::size_t align = static_cast<std::size_t>(a);
  return std::aligned_alloc(align, (n + align - 1) / align * align);
}
}  // namespace

void *operator new(std::size_t n) {
  if (void *p = Counted(n)) return p;
  throw std::bad_alloc();
}
void *operator new[](std::size_t n) {
  if (void *p = Counted(n)) return p;
  throw std::bad_alloc();
}
void *operator new(std::size_t n, const std::nothrow_t &) noexcept { return Counted(n); }
void *operator new[](std::size_t n, const std::nothrow_t &) noexcept { return Counted(n); }
void *operator new(std::size_t n, std::align_val_t a) {
  if (void *p = CountedAligned(n, a)) return p;
  throw std::bad_alloc();
}
void *operator new[](std::size_t n, std::align_val_t a) {
  if (void *p = CountedAligned(n, a)) return p;
  throw std::bad_alloc();
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
void operator delete(void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
