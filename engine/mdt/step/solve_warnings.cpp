// solve_warnings.cpp: the reporting rule of solve_warnings.h.
#include "solve_warnings.h"

#include <algorithm>

#include "MeMessage.h"

namespace karma::mdt {

void SolveWarnings::note(UnsolvedCause cause, MeReal residual) {
  Cause &c = causes_[(int)cause];
  ++c.pending;
  c.worst = std::max(c.worst, residual);
}

void SolveWarnings::endStep(MeReal h) {
  clock_ += h;
  for (int k = 0; k < 2; ++k) {
    Cause &c = causes_[k];
    if (c.pending == 0 || clock_ < c.nextReport) continue;
    const char *why = k == (int)UnsolvedCause::Cycle ? "stopped on a detected cycle"
                                                     : "reached the iteration cap (MdtWorldSetKeaMaxIterations)";
    MeWarning(0,
              "MdtWorldStep: %d exact partition solve(s) %s since the last report, largest residual %g; "
              "the impulses are the best iterate found (reported at most once per simulated second)",
              c.pending, why, (double)c.worst);
    c.pending = 0;
    c.worst = 0;
    c.nextReport = clock_ + 1;
  }
}

}  // namespace karma::mdt
