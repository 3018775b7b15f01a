// The envelope LDL^T refactorised from a row (kea_envelope_ldlt.h): when a
// pivot of the active set frees or clamps the row at position k of the free
// block, the sparse backend keeps the factor's rows before k and
// factorises the rest (kea_sparse_backend.cpp, reusableEnvelopeRows). The
// contract: the result is the whole factorisation's, bit for bit, and its
// solve solves the new block.
#include "kea_envelope_ldlt.h"

#include <gtest/gtest.h>

#include "kea_hash_unit.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using karma::kea::detail::EnvelopeSystem;

namespace {

using kea_test::Unit;

// A symmetric positive definite n x n matrix with a band of half-width
// `band` and a few far couplings (row i to row i - 3 band), like the rows
// of a stack whose contacts also touch a neighbour's: strictly diagonally
// dominant, row-major.
std::vector<double> Banded(int n, int band, std::uint32_t seed) {
  std::vector<double> a((size_t)n * n, 0.0);
  auto couple = [&](int i, int j, double v) { a[(size_t)i * n + j] = a[(size_t)j * n + i] = v; };
  for (int i = 0; i < n; ++i) {
    for (int j = std::max(0, i - band); j < i; ++j) couple(i, j, Unit(seed, (std::uint32_t)(i * n + j)));
    if (i >= 3 * band && i % 5 == 0) couple(i, i - 3 * band, Unit(seed + 1, (std::uint32_t)i));
  }
  for (int i = 0; i < n; ++i) {
    double off = 0;
    for (int j = 0; j < n; ++j) off += j == i ? 0 : std::fabs(a[(size_t)i * n + j]);
    a[(size_t)i * n + i] = off + 1 + 0.5 * Unit(seed + 2, (std::uint32_t)i);
  }
  return a;
}

// Lays out and fills the free block of `a` (n x n) with rows `rows` in
// that order, from row `from` on (a whole fill when from is 0).
void Fill(EnvelopeSystem &e, const std::vector<double> &a, int n, const std::vector<int> &rows, int from) {
  const int m = (int)rows.size();
  e.begin(m);
  for (int r = 0; r < m; ++r) {
    int first = r;
    for (int c = 0; c < r; ++c)
      if (a[(size_t)rows[(size_t)r] * n + rows[(size_t)c]] != 0) {
        first = c;
        break;
      }
    e.first[(size_t)r] = first;
  }
  e.layout(from);
  for (int r = from; r < m; ++r)
    for (int c = e.first[(size_t)r]; c <= r; ++c)
      e.value[e.at(r, c)] = (MeReal)a[(size_t)rows[(size_t)r] * n + rows[(size_t)c]];
}

bool SameBits(const std::vector<MeReal> &x, const std::vector<MeReal> &y, std::size_t count) {
  return x.size() >= count && y.size() >= count && std::memcmp(x.data(), y.data(), count * sizeof(MeReal)) == 0;
}

}  // namespace

TEST(EnvelopeUpdate, RefactorisingFromTheFirstChangedRowGivesTheWholeFactorisationsBits) {
  constexpr int n = 60;
  for (std::uint32_t seed = 1; seed <= 8; ++seed) {
    const int band = 2 + (int)(seed % 4);
    const std::vector<double> a = Banded(n, band, seed);
    // A free set, then a pivot: the row at position k is clamped (removed)
    // or a clamped row is freed (inserted at its place in ascending order).
    std::vector<int> before;
    for (int i = 0; i < n; ++i)
      if (i % 7 != 3) before.push_back(i);
    for (int k : {0, 1, 17, 40, (int)before.size() - 1}) {
      for (bool clamp : {true, false}) {
        std::vector<int> after = before;
        if (clamp) {
          after.erase(after.begin() + k);
        } else {
          const int freed = 7 * (k / 7) + 3;  // a row missing from `before`
          after.insert(std::lower_bound(after.begin(), after.end(), freed), freed);
        }
        int kept = 0;  // the common prefix, as the backend computes it
        while (kept < (int)std::min(before.size(), after.size()) && before[(size_t)kept] == after[(size_t)kept]) ++kept;

        EnvelopeSystem updated;
        Fill(updated, a, n, before, 0);
        updated.factor();
        ASSERT_FALSE(updated.broken);
        Fill(updated, a, n, after, kept);
        updated.factor(kept);

        EnvelopeSystem fresh;
        Fill(fresh, a, n, after, 0);
        fresh.factor();
        ASSERT_FALSE(fresh.broken);
        ASSERT_FALSE(updated.broken);
        ASSERT_EQ(updated.size(), fresh.size());
        EXPECT_TRUE(SameBits(updated.value, fresh.value, fresh.size()))
            << "seed " << seed << ", pivot at " << k << (clamp ? " (clamped)" : " (freed)") << ", " << kept
            << " rows kept";
        EXPECT_TRUE(SameBits(updated.original, fresh.original, fresh.size()));

        // And it solves the new block: A_after x = b to rounding.
        const int m = (int)after.size();
        std::vector<MeReal> b((size_t)m), x((size_t)m);
        for (int r = 0; r < m; ++r) b[(size_t)r] = (MeReal)Unit(seed + 9, (std::uint32_t)r);
        updated.solve(b, x);
        double worst = 0;
        for (int r = 0; r < m; ++r) {
          double s = -b[(size_t)r];
          for (int c = 0; c < m; ++c) s += a[(size_t)after[(size_t)r] * n + after[(size_t)c]] * x[(size_t)c];
          worst = std::max(worst, std::fabs(s));
        }
        EXPECT_LT(worst, sizeof(MeReal) == 4 ? 1e-4 : 1e-12) << "seed " << seed << ", pivot at " << k;
      }
    }
  }
}
