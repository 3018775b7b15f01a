// Kea's workspace entry point allocates nothing once its workspace has
// solved a problem at least as large: repeated warm-started solves of
// same-sized problems (a 6-box stack with and without friction, a car, a
// 300-row chain; the active-set method and PGS) are counted through the
// global operator new (replaced in this executable) and, outside the
// sanitizer builds, through malloc itself (interposed on glibc's, which
// catches Eigen's allocations too).
#include "kea_contact_problems.h"
#include "kea_lcp.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#  define KEA_ALLOC_TEST_COUNTS_MALLOC 1
extern "C" {
void *__libc_malloc(std::size_t);
void *__libc_calloc(std::size_t, std::size_t);
void *__libc_realloc(void *, std::size_t);
void *__libc_memalign(std::size_t, std::size_t);
}
#endif

namespace {

std::atomic<bool> gCounting{false};
std::atomic<long> gAllocations{0};

void Note() {
  if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
}

/* An allocation that is not counted again by the malloc below. */
void *Raw(std::size_t size) {
#if KEA_ALLOC_TEST_COUNTS_MALLOC
  return __libc_malloc(size ? size : 1);
#else
  return std::malloc(size ? size : 1);
#endif
}

void *RawAligned(std::size_t size, std::size_t align) {
#if KEA_ALLOC_TEST_COUNTS_MALLOC
  return __libc_memalign(align, size ? size : 1);
#else
  return std::aligned_alloc(align, (size + align - 1) / align * align);
#endif
}

void *Allocate(std::size_t size) {
  Note();
  if (void *p = Raw(size)) return p;
  throw std::bad_alloc();
}

void *AllocateAligned(std::size_t size, std::align_val_t align) {
  Note();
  if (void *p = RawAligned(size, static_cast<std::size_t>(align))) return p;
  throw std::bad_alloc();
}

}  // namespace

void *operator new(std::size_t size) { return Allocate(size); }
void *operator new[](std::size_t size) { return Allocate(size); }
void *operator new(std::size_t size, const std::nothrow_t &) noexcept {
  Note();
  return Raw(size);
}
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept {
  Note();
  return Raw(size);
}
void *operator new(std::size_t size, std::align_val_t align) { return AllocateAligned(size, align); }
void *operator new[](std::size_t size, std::align_val_t align) { return AllocateAligned(size, align); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }

#if KEA_ALLOC_TEST_COUNTS_MALLOC
// malloc and friends, forwarded to glibc's own entry points, counted.
extern "C" {
void *malloc(std::size_t size) {
  Note();
  return __libc_malloc(size);
}
void *calloc(std::size_t count, std::size_t size) {
  Note();
  return __libc_calloc(count, size);
}
void *realloc(void *p, std::size_t size) {
  Note();
  return __libc_realloc(p, size);
}
void *aligned_alloc(std::size_t align, std::size_t size) {
  Note();
  return __libc_memalign(align, size);
}
int posix_memalign(void **out, std::size_t align, std::size_t size) {
  Note();
  *out = __libc_memalign(align, size);
  return *out ? 0 : 12; /* ENOMEM */
}
}
#endif

using namespace karma::kea;
using kea_test::ContactProblem;

namespace {

// Counts allocations made by f().
template <class F>
long Allocations(F &&f) {
  gAllocations = 0;
  gCounting = true;
  f();
  gCounting = false;
  return gAllocations.load();
}

struct WorkspaceDeleter {
  void operator()(KeaWorkspace *w) const { KeaWorkspaceDestroy(w); }
};

// `steps` variants of `base` with b changed a little, as from one step to
// the next of a resting scene.
std::vector<ContactProblem> Steps(const ContactProblem &base, int steps) {
  std::vector<ContactProblem> all;
  double bMax = 0;
  for (MeReal v : base.b) bMax = std::max(bMax, std::fabs(double(v)));
  for (int s = 0; s < steps; ++s) {
    ContactProblem p = base;
    for (std::size_t i = 0; i < p.b.size(); ++i)
      p.b[i] +=
          static_cast<MeReal>(2e-3 * bMax * kea_test::Jitter(static_cast<unsigned>(s) + 1, static_cast<unsigned>(i)));
    all.push_back(std::move(p));
  }
  return all;
}

// Solves base once (growing the workspace), then every step warm-started
// from the previous answer; returns the allocations of the repeated solves
// and checks that each was solved.
long RepeatedSolves(const ContactProblem &base, KeaMethod method, int maxIterations, const std::string &name) {
  std::unique_ptr<KeaWorkspace, WorkspaceDeleter> workspace(KeaWorkspaceCreate());
  const std::vector<ContactProblem> steps = Steps(base, 30);
  std::vector<SparseLcpProblem> views;
  for (const ContactProblem &p : steps) views.push_back(p.sparse());
  KeaOptions o;
  o.method = method;
  o.maxIterations = maxIterations;
  o.warnings = false;
  /* PGS converges linearly: a tolerance it reaches in both precisions
   * (what is counted is the allocations of full solves). */
  if (method == KeaMethod::PGS) o.tolerance = MeReal(1e-4);
  KeaResult result;
  KeaSolveSparse(base.sparse(), o, *workspace, result);
  EXPECT_EQ(result.status, KeaStatus::Solved) << name;
  std::vector<MeReal> warm(result.lambda);
  o.warmStart = warm;
  std::vector<KeaStatus> statuses(steps.size());
  std::vector<int> iterations(steps.size());
  const long count = Allocations([&] {
    for (std::size_t s = 0; s < views.size(); ++s) {
      KeaSolveSparse(views[s], o, *workspace, result);
      statuses[s] = result.status;
      iterations[s] = result.iterations;
      std::copy(result.lambda.begin(), result.lambda.end(), warm.begin());
    }
  });
  for (std::size_t s = 0; s < steps.size(); ++s)
    EXPECT_EQ(statuses[s], KeaStatus::Solved) << name << " step " << s << " after " << iterations[s];
  return count;
}

}  // namespace

TEST(KeaAllocations, CountingSeesAllocations) {
  // The counter itself works: a vector's first growth is one allocation.
  std::vector<int> v;
  EXPECT_EQ(Allocations([&] { v.resize(100); }), 1);
#if KEA_ALLOC_TEST_COUNTS_MALLOC
  void *p = nullptr;
  EXPECT_EQ(Allocations([&] { p = std::malloc(64); }), 1);
  std::free(p);
#endif
}

TEST(KeaAllocations, ActiveSetWarmSolvesAllocateNothing) {
  EXPECT_EQ(RepeatedSolves(kea_test::Stack(6, 1), KeaMethod::ActiveSet, 0, "stack6"), 0);
  EXPECT_EQ(RepeatedSolves(kea_test::Stack(6, 2, false), KeaMethod::ActiveSet, 0, "stack6 frictionless"), 0);
  EXPECT_EQ(RepeatedSolves(kea_test::Car(1), KeaMethod::ActiveSet, 0, "car"), 0);
  EXPECT_EQ(RepeatedSolves(kea_test::Chain(100, 1), KeaMethod::ActiveSet, 0, "chain300"), 0);
}

TEST(KeaAllocations, PgsWarmSolvesAllocateNothing) {
  EXPECT_EQ(RepeatedSolves(kea_test::Stack(6, 1), KeaMethod::PGS, 2000, "stack6"), 0);
  EXPECT_EQ(RepeatedSolves(kea_test::Car(1), KeaMethod::PGS, 5000, "car"), 0);
}

TEST(KeaAllocations, SmallerProblemsInAGrownWorkspaceAllocateNothing) {
  std::unique_ptr<KeaWorkspace, WorkspaceDeleter> workspace(KeaWorkspaceCreate());
  const ContactProblem big = kea_test::Stack(6, 3);
  const std::vector<ContactProblem> small{kea_test::Stack(3, 4), kea_test::Car(2), kea_test::Stack(5, 5, false),
                                          kea_test::Stack(2, 6)};
  std::vector<SparseLcpProblem> views;
  for (const ContactProblem &p : small) views.push_back(p.sparse());
  KeaOptions o;
  o.warnings = false;
  KeaResult result;
  KeaSolveSparse(big.sparse(), o, *workspace, result);
  ASSERT_EQ(result.status, KeaStatus::Solved);
  std::vector<KeaStatus> statuses;
  statuses.reserve(small.size());
  const long count = Allocations([&] {
    for (const SparseLcpProblem &p : views) {
      KeaSolveSparse(p, o, *workspace, result);
      statuses.push_back(result.status);
    }
  });
  EXPECT_EQ(count, 0);
  for (KeaStatus s : statuses) EXPECT_EQ(s, KeaStatus::Solved);
}

TEST(KeaAllocations, TheAllocatingEntryPointIsSeenAllocating) {
  // The counter sees a solve's allocations: the entry point that makes its
  // own workspace and result allocates on every call.
  const ContactProblem p = kea_test::Stack(6, 1);
  const SparseLcpProblem view = p.sparse();
  KeaResult r;
  EXPECT_GT(Allocations([&] { r = KeaSolveSparse(view, KeaOptions{}); }), 0);
  EXPECT_EQ(r.status, KeaStatus::Solved);
}
