// The exact solver's rule for keeping warm starts (warm_keep_rule.h).
#include "warm_keep_rule.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using karma::kea::KeaResult;
using karma::kea::KeaStatus;
using karma::mdt::kDefaultKeepDivisor;
using karma::mdt::kLooseKeepDivisor;
using karma::mdt::LastAnswer;
using karma::mdt::lastAnswerOf;
using karma::mdt::warmKeepAfter;

TEST(WarmKeepRule, HowTheNextWarmStartIsChecked) {
  EXPECT_TRUE(warmKeepAfter(LastAnswer::Solved).check);
  EXPECT_EQ(warmKeepAfter(LastAnswer::Solved).divisor, kLooseKeepDivisor);
  EXPECT_FALSE(warmKeepAfter(LastAnswer::KeptLoosely).check);
  for (LastAnswer last : {LastAnswer::Unknown, LastAnswer::SolvedAfterLoose, LastAnswer::Kept}) {
    EXPECT_TRUE(warmKeepAfter(last).check);
    EXPECT_EQ(warmKeepAfter(last).divisor, kDefaultKeepDivisor);
  }
  EXPECT_EQ(kDefaultKeepDivisor, 16);
  EXPECT_EQ(kLooseKeepDivisor, 4);
}

KeaResult Result(KeaStatus status, bool kept, MeReal residual) {
  KeaResult r;
  r.status = status;
  r.warmStartAccepted = kept;
  r.threshold = 1;
  r.residual = residual;
  return r;
}

TEST(WarmKeepRule, HowAnAnswerCame) {
  const LastAnswer any[] = {LastAnswer::Unknown, LastAnswer::Solved, LastAnswer::SolvedAfterLoose, LastAnswer::Kept,
                            LastAnswer::KeptLoosely};
  for (LastAnswer before : any) {
    EXPECT_EQ(lastAnswerOf(Result(KeaStatus::Solved, true, MeReal(1) / 16), before), LastAnswer::Kept);
    EXPECT_EQ(lastAnswerOf(Result(KeaStatus::Solved, true, MeReal(0.07)), before), LastAnswer::KeptLoosely);
    EXPECT_EQ(lastAnswerOf(Result(KeaStatus::CycleDetected, false, 2), before), LastAnswer::Unknown);
    EXPECT_EQ(lastAnswerOf(Result(KeaStatus::IterationLimit, false, 2), before), LastAnswer::Unknown);
    EXPECT_EQ(lastAnswerOf(Result(KeaStatus::Solved, false, MeReal(0.5)), before),
              before == LastAnswer::KeptLoosely ? LastAnswer::SolvedAfterLoose : LastAnswer::Solved);
  }
}

// Runs the rule over warm starts whose residuals (over the threshold) are
// `residuals`, one per step, each solved answer meeting the threshold; the
// answers, step by step.
std::vector<LastAnswer> RunRule(const std::vector<MeReal> &residuals) {
  std::vector<LastAnswer> answers;
  LastAnswer last = LastAnswer::Unknown;
  for (MeReal residual : residuals) {
    const karma::mdt::WarmKeep keep = warmKeepAfter(last);
    const bool kept = keep.check && residual <= 1 / keep.divisor;
    last = lastAnswerOf(Result(KeaStatus::Solved, kept, kept ? residual : MeReal(0.01)), last);
    answers.push_back(last);
  }
  return answers;
}

TEST(WarmKeepRule, LooseKeepsNeverFollowEachOtherAndStrictOnesMay) {
  // Every sequence of six steps over residual classes below a sixteenth,
  // between a sixteenth and a quarter, and above a quarter.
  const MeReal classes[] = {MeReal(0.01), MeReal(0.1), MeReal(0.5)};
  int looseKeeps = 0;
  for (int code = 0; code < 729; ++code) {
    std::vector<MeReal> residuals;
    for (int step = 0, c = code; step < 6; ++step, c /= 3) residuals.push_back(classes[c % 3]);
    const std::vector<LastAnswer> answers = RunRule(residuals);
    for (size_t i = 0; i < answers.size(); ++i) {
      if (answers[i] == LastAnswer::KeptLoosely) ++looseKeeps;
      if (i > 0 && answers[i - 1] == LastAnswer::KeptLoosely) {
        EXPECT_NE(answers[i], LastAnswer::KeptLoosely) << code;
      }
      // A warm start within a sixteenth is kept unless it follows a loose keep.
      if (residuals[i] <= 1 / kDefaultKeepDivisor && (i == 0 || answers[i - 1] != LastAnswer::KeptLoosely)) {
        EXPECT_EQ(answers[i], LastAnswer::Kept) << code << " step " << i;
      }
      // Nothing beyond a quarter is ever kept.
      if (residuals[i] > 1 / kLooseKeepDivisor) {
        EXPECT_TRUE(answers[i] == LastAnswer::Solved || answers[i] == LastAnswer::SolvedAfterLoose) << code;
      }
    }
  }
  EXPECT_GT(looseKeeps, 0);
  // A creeping heap: every warm start between the bounds; one in three is
  // kept (solved, kept loosely, solved after it, ...).
  const std::vector<LastAnswer> creep = RunRule(std::vector<MeReal>(9, MeReal(0.1)));
  const std::vector<LastAnswer> expected = {LastAnswer::Solved, LastAnswer::KeptLoosely, LastAnswer::SolvedAfterLoose,
                                            LastAnswer::Solved, LastAnswer::KeptLoosely, LastAnswer::SolvedAfterLoose,
                                            LastAnswer::Solved, LastAnswer::KeptLoosely, LastAnswer::SolvedAfterLoose};
  EXPECT_EQ(creep, expected);
}

}  // namespace
