// The platform backends' conformance test (engine/platform/kernels.h):
// every kernel of every backend this CPU supports gives the reference's
// result to the bit, on random and structured inputs; a backend the CPU
// lacks is reported as skipped. The reference itself is checked against the
// lane order written out by hand.
#include "kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace platform = karma::platform;
using platform::Kernels;

namespace {

const Kernels &Reference() { return platform::ReferenceKernels(); }

bool SameBits(MeReal a, MeReal b) {
  if (std::isnan(a) && std::isnan(b)) return true; /* NaN payloads may differ */
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/* Inputs of one kernel call: two arrays and an index array into b. */
struct Inputs {
  std::vector<MeReal> a, b;
  std::vector<int> index;
};

Inputs RandomInputs(std::mt19937 &rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Inputs in;
  const int xs = n + 5;
  for (int k = 0; k < n; ++k) in.a.push_back(static_cast<MeReal>(u(rng)));
  for (int k = 0; k < xs; ++k) in.b.push_back(static_cast<MeReal>(u(rng)));
  std::uniform_int_distribution<int> pick(0, xs - 1);
  for (int k = 0; k < n; ++k) in.index.push_back(pick(rng));
  return in;
}

/* Values where the order of the sums shows: huge terms that cancel, tiny
 * ones, signed zeros, subnormals. */
Inputs StructuredInputs(std::mt19937 &rng, int n) {
  const MeReal big = std::sqrt(std::numeric_limits<MeReal>::max()) / 4;
  const MeReal sub = std::numeric_limits<MeReal>::denorm_min();
  const MeReal pool[] = {0, -0.0, 1, -1, big, -big, sub, -sub, std::numeric_limits<MeReal>::epsilon(), 3, MeReal(1e-3)};
  std::uniform_int_distribution<int> pick(0, static_cast<int>(std::size(pool)) - 1);
  Inputs in = RandomInputs(rng, n, 1);
  for (MeReal &v : in.a) v = pool[pick(rng)];
  for (MeReal &v : in.b) v = pool[pick(rng)];
  return in;
}

/* Indices in runs of consecutive values (as a sparse row's columns come,
 * which a backend may load as one vector), of random lengths, starts and
 * alignments; every third run is a block of eight whose first and last are
 * seven apart but whose order is shuffled, which must not pass as a run. */
Inputs RunInputs(std::mt19937 &rng, int n) {
  Inputs in = RandomInputs(rng, n, 10);
  const int xs = static_cast<int>(in.b.size());
  std::uniform_int_distribution<int> length(1, 17), start(0, xs > 17 ? xs - 17 : 0);
  in.index.clear();
  for (int run = 0; static_cast<int>(in.index.size()) < n; ++run) {
    const int first = start(rng);
    if (run % 3 == 2 && first + 8 <= xs) {
      int block[8] = {0, 1, 2, 3, 4, 5, 6, 7};
      std::shuffle(block + 1, block + 7, rng);
      for (int v : block) in.index.push_back(first + v);
      continue;
    }
    const int len = std::min(length(rng), xs - first);
    for (int v = 0; v < len; ++v) in.index.push_back(first + v);
  }
  in.index.resize(static_cast<std::size_t>(n));
  return in;
}

void ExpectSameAsReference(const Kernels &k, const Inputs &in, const std::string &what) {
  const int n = static_cast<int>(in.a.size());
  const Kernels &r = Reference();
  const MeReal dot = k.dot(in.a.data(), in.b.data(), n), refDot = r.dot(in.a.data(), in.b.data(), n);
  EXPECT_TRUE(SameBits(dot, refDot)) << k.name << " dot, " << what << ", n " << n << ": " << dot << " vs " << refDot;
  const MeReal g = k.gatherDot(in.a.data(), in.index.data(), in.b.data(), n);
  const MeReal refG = r.gatherDot(in.a.data(), in.index.data(), in.b.data(), n);
  EXPECT_TRUE(SameBits(g, refG)) << k.name << " gatherDot, " << what << ", n " << n << ": " << g << " vs " << refG;
  // sparseRowsTimes: the inputs as three CSR rows of about n / 3 entries,
  // every row and then rows 2 and 0 alone.
  const std::vector<int> rowStart = {0, n / 3, (2 * n) / 3, n}, some = {2, 0};
  for (const std::vector<int> *rows : {static_cast<const std::vector<int> *>(nullptr), &some}) {
    const int count = rows ? static_cast<int>(rows->size()) : 3;
    const int *at = rows ? rows->data() : nullptr;
    std::vector<MeReal> y(3, MeReal(-7)), refY = y;
    k.sparseRowsTimes(rowStart.data(), in.index.data(), in.a.data(), at, count, in.b.data(), y.data());
    r.sparseRowsTimes(rowStart.data(), in.index.data(), in.a.data(), at, count, in.b.data(), refY.data());
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_TRUE(SameBits(y[i], refY[i])) << k.name << " sparseRowsTimes, " << what << ", n " << n << ", y " << i;
    if (count < 3) {
      EXPECT_EQ(y[static_cast<std::size_t>(count)], MeReal(-7)) << k.name << " wrote past count";
    }
  }
}

class Backend : public ::testing::TestWithParam<std::string> {
 protected:
  const Kernels &kernels() {
    const Kernels *k = platform::FindKernels(GetParam().c_str());
    EXPECT_NE(k, nullptr);
    return *k;
  }
};

TEST_P(Backend, EveryKernelGivesTheReferenceBits) {
  const Kernels &k = kernels();
  if (!platform::Supported(k)) GTEST_SKIP() << "this CPU does not support the " << k.name << " backend";
  std::mt19937 rng(2026);
  for (int n = 0; n <= 70; ++n) {
    ExpectSameAsReference(k, RandomInputs(rng, n, 10), "random");
    ExpectSameAsReference(k, RandomInputs(rng, n, 1e-30), "random tiny");
    ExpectSameAsReference(k, StructuredInputs(rng, n), "structured");
    ExpectSameAsReference(k, RunInputs(rng, n), "runs of indices");
  }
  for (int n : {255, 256, 1000, 4099}) ExpectSameAsReference(k, RandomInputs(rng, n, 1), "long");
}

TEST_P(Backend, ReductionsAreNotSequentialSums) {
  // With eight lanes, 1 + 2^24 + ... in float (2^53 in double) keeps terms a
  // left-to-right sum would lose: the lane order, not the sequential one.
  const Kernels &k = kernels();
  if (!platform::Supported(k)) GTEST_SKIP() << "this CPU does not support the " << k.name << " backend";
  const MeReal big = MeReal(1) / std::numeric_limits<MeReal>::epsilon() * 2;
  std::vector<MeReal> a = {big, 1, 1, 1, 1, 1, 1, 1, -big}, ones(9, 1);
  // Lane 0 holds big + (-big) = 0; lanes 1..7 hold 1 each: 7 exactly. A
  // left-to-right sum gives big + 7 rounded, minus big: not 7.
  EXPECT_EQ(k.dot(a.data(), ones.data(), 9), 7);
}

INSTANTIATE_TEST_SUITE_P(PlatformConformance, Backend, ::testing::Values("reference", "sse4", "avx2", "avx512"),
                         [](const ::testing::TestParamInfo<std::string> &info) { return info.param; });

TEST(PlatformReference, ReductionsFollowTheLaneOrderWrittenOut) {
  std::mt19937 rng(7);
  for (int n = 0; n <= 40; ++n) {
    const Inputs in = RandomInputs(rng, n, 5);
    MeReal s[8] = {0, 0, 0, 0, 0, 0, 0, 0}, g[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < n; ++k) {
      const auto u = static_cast<std::size_t>(k);
      s[k % 8] += in.a[u] * in.b[u];
      g[k % 8] += in.a[u] * in.b[static_cast<std::size_t>(in.index[u])];
    }
    const MeReal want = ((s[0] + s[4]) + (s[2] + s[6])) + ((s[1] + s[5]) + (s[3] + s[7]));
    const MeReal wantG = ((g[0] + g[4]) + (g[2] + g[6])) + ((g[1] + g[5]) + (g[3] + g[7]));
    EXPECT_TRUE(SameBits(Reference().dot(in.a.data(), in.b.data(), n), want)) << "n " << n;
    EXPECT_TRUE(SameBits(Reference().gatherDot(in.a.data(), in.index.data(), in.b.data(), n), wantG)) << "n " << n;
    // One CSR row of all n entries is one gatherDot.
    const int rowStart[2] = {0, n};
    MeReal row = -1;
    Reference().sparseRowsTimes(rowStart, in.index.data(), in.a.data(), nullptr, 1, in.b.data(), &row);
    EXPECT_TRUE(SameBits(row, wantG)) << "n " << n;
  }
}

TEST(PlatformChoice, NamesAndSupport) {
  ASSERT_EQ(platform::AllKernels().size(), 4u);
  EXPECT_EQ(platform::AllKernels()[0], &Reference());
  for (const Kernels *k : platform::AllKernels()) EXPECT_EQ(platform::FindKernels(k->name), k);
  EXPECT_EQ(platform::FindKernels("neon"), nullptr);
  EXPECT_EQ(platform::FindKernels(nullptr), nullptr);
  EXPECT_TRUE(platform::Supported(Reference()));
  EXPECT_TRUE(platform::Supported(platform::BestSupported()));
  // The best is the last supported one in the order of preference.
  const Kernels *last = nullptr;
  for (const Kernels *k : platform::AllKernels())
    if (platform::Supported(*k)) last = k;
  EXPECT_EQ(&platform::BestSupported(), last);
}

TEST(PlatformChoice, AnUnknownRequestFallsBack) {
  EXPECT_EQ(&platform::KernelsForRequest("neon", Reference()), &Reference());
  EXPECT_EQ(&platform::KernelsForRequest("reference", platform::BestSupported()), &Reference());
  for (const Kernels *k : platform::AllKernels())
    EXPECT_EQ(&platform::KernelsForRequest(k->name, Reference()), platform::Supported(*k) ? k : &Reference());
}

}  // namespace
