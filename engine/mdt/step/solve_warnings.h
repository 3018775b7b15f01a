// solve_warnings.h: what the step tells the user about exact solves that
// stop short of the tolerance. Not installed.
//
// Rule: a warning is for what a user must act on, so each cause (the
// iteration cap, a detected cycle) is reported at most once per second of
// simulated time: the first time it happens, then, while it keeps
// happening, once a second with the number of partition solves it hit since
// the last report and their largest residual. The step stats count every
// unsolved partition (keaUnsolved, keaCycles) whatever is reported.
#pragma once

#include "MePrecision.h"

namespace karma::mdt {

enum class UnsolvedCause { IterationCap = 0, Cycle = 1 };

class SolveWarnings {
 public:
  // One partition solve that stopped short, with its residual.
  void note(UnsolvedCause cause, MeReal residual);
  // At the end of a step of h seconds: reports each cause that is due.
  void endStep(MeReal h);

 private:
  struct Cause {
    int pending = 0;        // solves since the last report
    MeReal worst = 0;       // their largest residual
    MeReal nextReport = 0;  // simulated time from which it may be reported
  };
  Cause causes_[2];
  MeReal clock_ = 0;  // simulated seconds stepped
};

}  // namespace karma::mdt
