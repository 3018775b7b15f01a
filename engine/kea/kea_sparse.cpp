// kea_sparse.cpp: the entry point for problems whose matrix comes in
// compressed sparse rows (what Mdt builds).
//
// TODO(dynamics): this first version expands A to a dense matrix and calls
// the dense solvers, so it costs O(n^2) memory and O(n^3) time per
// factorisation. It fixes the interface; the sparse factorisation replaces
// the body.
#include <vector>

#include "MeMessage.h"
#include "kea_lcp.h"

namespace karma::kea {

KeaResult KeaSolveSparse(const SparseLcpProblem &p, const KeaOptions &options) {
  const int n = p.n;
  bool ok = n >= 0 && (int)p.rowStart.size() == n + 1;
  if (ok && n > 0) ok = p.rowStart[0] == 0 && p.rowStart[n] <= (int)p.col.size() &&
                        p.col.size() == p.val.size();
  if (!ok) {
    MeWarning(0, "Kea: bad sparse problem (row starts or column arrays do not match n = %d)", n);
    KeaResult r;
    r.status = KeaStatus::BadInput;
    if (n > 0) {
      r.lambda.assign((size_t)n, 0);
      r.w.assign((size_t)n, 0);
    }
    return r;
  }
  std::vector<MeReal> dense((size_t)n * (size_t)n, 0);
  for (int i = 0; i < n; ++i)
    for (int k = p.rowStart[i]; k < p.rowStart[i + 1]; ++k)
      dense[(size_t)i * (size_t)n + (size_t)p.col[k]] = p.val[k];
  LcpProblem d;
  d.n = n;
  d.A = dense;
  d.b = p.b;
  d.lo = p.lo;
  d.hi = p.hi;
  d.findex = p.findex;
  d.mu = p.mu;
  return KeaSolve(d, options);
}

}  // namespace karma::kea
