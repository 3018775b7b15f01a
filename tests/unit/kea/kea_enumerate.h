// kea_enumerate.h: the tests' reference for small boxed LCPs. It tries all
// 3^n assignments of each row to free / at lo / at hi (in double), solves
// the free rows exactly, and returns the lambda that satisfies the contract's
// complementarity conditions; for a positive definite A exactly one does
// (*found counts them). Friction rows are not handled (fixed bounds only).
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <limits>
#include <vector>

#include "kea_lcp.h"

namespace kea_test {

inline std::vector<double> EnumerateLcp(const karma::kea::LcpProblem &o, int *found) {
  const int n = o.n;
  Eigen::MatrixXd A(n, n);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    b(i) = o.b[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j) A(i, j) = o.A[static_cast<std::size_t>(i * n + j)];
  }
  auto bound = [](MeReal v) {
    return v >= MEINFINITY    ? std::numeric_limits<double>::infinity()
           : v <= -MEINFINITY ? -std::numeric_limits<double>::infinity()
                              : double(v);
  };
  int combos = 1;
  for (int i = 0; i < n; ++i) combos *= 3;
  std::vector<double> answer;
  *found = 0;
  for (int c = 0; c < combos; ++c) {
    std::vector<int> set(static_cast<std::size_t>(n));
    bool ok = true;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    std::vector<int> freeRows;
    for (int i = 0, code = c; i < n; ++i, code /= 3) {
      set[static_cast<std::size_t>(i)] = code % 3;
      const double lo = bound(o.lo[static_cast<std::size_t>(i)]), hi = bound(o.hi[static_cast<std::size_t>(i)]);
      if (code % 3 == 1) {
        if (std::isinf(lo))
          ok = false;
        else
          x(i) = lo;
      } else if (code % 3 == 2) {
        if (std::isinf(hi))
          ok = false;
        else
          x(i) = hi;
      } else
        freeRows.push_back(i);
    }
    if (!ok) continue;
    const int m = static_cast<int>(freeRows.size());
    if (m > 0) {
      Eigen::MatrixXd Aff(m, m);
      Eigen::VectorXd r(m);
      for (int a = 0; a < m; ++a) {
        r(a) = b(freeRows[static_cast<std::size_t>(a)]);
        for (int j = 0; j < n; ++j)
          if (set[static_cast<std::size_t>(j)] != 0) r(a) -= A(freeRows[static_cast<std::size_t>(a)], j) * x(j);
        for (int k = 0; k < m; ++k)
          Aff(a, k) = A(freeRows[static_cast<std::size_t>(a)], freeRows[static_cast<std::size_t>(k)]);
      }
      const Eigen::VectorXd xf = Aff.ldlt().solve(r);
      for (int a = 0; a < m; ++a) x(freeRows[static_cast<std::size_t>(a)]) = xf(a);
    }
    const Eigen::VectorXd w = A * x - b;
    const double tiny = 1e-12;
    for (int i = 0; i < n && ok; ++i) {
      const double lo = bound(o.lo[static_cast<std::size_t>(i)]), hi = bound(o.hi[static_cast<std::size_t>(i)]);
      switch (set[static_cast<std::size_t>(i)]) {
        case 0:
          ok = x(i) >= lo - tiny && x(i) <= hi + tiny;
          break;
        case 1:
          ok = w(i) >= -tiny;
          break;
        default:
          ok = w(i) <= tiny;
          break;
      }
    }
    if (ok) {
      ++*found;
      answer.assign(x.data(), x.data() + n);
    }
  }
  return answer;
}

}  // namespace kea_test
