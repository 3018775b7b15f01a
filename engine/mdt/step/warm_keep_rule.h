// warm_keep_rule.h: which of a partition's warm starts the exact solver
// may keep as its answer (Kea's KeaOptions::acceptWarmStart), from how the
// partition's last answer came. Not installed.
//
// A warm start is last step's impulses. Kea keeps it, with no linear
// solve, when its residual is at most the solved threshold over a divisor.
// Kea's default divisor (16) may keep the same impulses step after step:
// a stack at rest whose fresh answer passes it for several steps. The
// warm starts of a slowly creeping heap miss a sixteenth by a little at
// almost every step (pile1000's columns under the guide's softness), and
// a quarter (kLooseKeepDivisor) would keep most of them; but keeping a
// quarter-good answer step after step lets its error build up against the
// slowly changing problem (a 200-box heap never slept:
// kea_activeset_core.h, kWarmAcceptDivisor). So, by how the last answer
// came:
//   Solved            check within a quarter;
//   KeptLoosely       no check: solve, so loose keeps never follow each
//                     other and their error cannot build up;
//   SolvedAfterLoose  within a sixteenth: that solve corrected the loose
//                     keep's error with an impulse the next step does not
//                     need again, so its answer misses a quarter the way
//                     the loose keep did; keeping it would lock the
//                     partition into keeping every other step, where a
//                     fresh solve's answer passes a sixteenth several
//                     steps in a row (topple's stacks);
//   Kept, Unknown     within a sixteenth.
#pragma once

#include "kea_lcp.h"

namespace karma::mdt {

// How a partition's last answer came.
enum class LastAnswer : unsigned char {
  Unknown,           // a memory new to the partition, an unsolved answer, or one older than last step's
  Solved,            // solved
  SolvedAfterLoose,  // solved, the step after a KeptLoosely
  Kept,              // the warm start, within Kea's default bound
  KeptLoosely,       // the warm start, within kLooseKeepDivisor's bound but not the default one
};

inline constexpr MeReal kLooseKeepDivisor = 4;
inline constexpr MeReal kDefaultKeepDivisor = kea::KeaOptions{}.warmAcceptDivisor;
static_assert(kLooseKeepDivisor >= 1 && kLooseKeepDivisor < kDefaultKeepDivisor);

// How the next warm start is checked: whether at all, and the divisor.
struct WarmKeep {
  bool check;
  MeReal divisor;
};

constexpr WarmKeep warmKeepAfter(LastAnswer last) {
  switch (last) {
    case LastAnswer::Solved:
      return {true, kLooseKeepDivisor};
    case LastAnswer::KeptLoosely:
      return {false, kDefaultKeepDivisor};
    default:
      return {true, kDefaultKeepDivisor};
  }
}

// How `result` came, given how the answer before it came.
inline LastAnswer lastAnswerOf(const kea::KeaResult &result, LastAnswer before) {
  if (result.warmStartAccepted)
    return result.residual <= result.threshold / kDefaultKeepDivisor ? LastAnswer::Kept : LastAnswer::KeptLoosely;
  if (result.status != kea::KeaStatus::Solved) return LastAnswer::Unknown;
  return before == LastAnswer::KeptLoosely ? LastAnswer::SolvedAfterLoose : LastAnswer::Solved;
}

}  // namespace karma::mdt
