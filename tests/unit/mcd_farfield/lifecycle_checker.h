// lifecycle_checker.h: follows the events of a space step by step and checks
// the pair life cycle: a hello names a pair not alive, with a record no live
// pair holds; a staying or goodbye pair is alive with the same record it said
// hello with; every pair alive before is either staying or says goodbye; each
// list ascends by Order().
#ifndef KARMA_TESTS_MCD_FARFIELD_LIFECYCLE_CHECKER_H
#define KARMA_TESTS_MCD_FARFIELD_LIFECYCLE_CHECKER_H

#include "farfield_test_util.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace karma::mcd::test {

class LifecycleChecker {
 public:
  void Step(const Events &ev) {
    ExpectAscending(ev.goodbyes, "goodbyes");
    ExpectAscending(ev.hellos, "hellos");
    ExpectAscending(ev.stayings, "stayings");
    std::size_t seen = 0;
    for (const PairRecord *r : ev.goodbyes) {
      auto it = alive_.find(r->SerialPair());
      ASSERT_NE(it, alive_.end()) << "goodbye for a pair that never said hello";
      EXPECT_EQ(it->second, r) << "goodbye with another record than its hello";
      EXPECT_EQ(r->state, PairState::Goodbye);
      alive_.erase(it);
      ++goodbyes_;
      ++seen;
    }
    for (const PairRecord *r : ev.stayings) {
      auto it = alive_.find(r->SerialPair());
      ASSERT_NE(it, alive_.end()) << "staying pair that never said hello";
      EXPECT_EQ(it->second, r) << "staying pair changed record";
      EXPECT_EQ(r->state, PairState::Staying);
      ++seen;
    }
    EXPECT_EQ(seen, alive_.size() + ev.goodbyes.size()) << "a pair vanished without a goodbye";
    std::set<const PairRecord *> inUse;
    for (const auto &kv : alive_) inUse.insert(kv.second);
    for (const PairRecord *r : ev.hellos) {
      EXPECT_EQ(alive_.count(r->SerialPair()), 0u) << "hello for a pair already alive";
      EXPECT_EQ(inUse.count(r), 0u) << "hello reuses a live record";
      EXPECT_EQ(r->state, PairState::Hello);
      EXPECT_LT(ProxyRank(r->keyA, r->serialA).Packed(), ProxyRank(r->keyB, r->serialB).Packed());
      alive_[r->SerialPair()] = r;
      inUse.insert(r);
      ++hellos_;
    }
  }
  std::size_t Alive() const { return alive_.size(); }
  long long Hellos() const { return hellos_; }
  long long Goodbyes() const { return goodbyes_; }

 private:
  static void ExpectAscending(const std::vector<const PairRecord *> &list, const char *what) {
    for (std::size_t i = 1; i < list.size(); ++i) {
      EXPECT_LT(list[i - 1]->Order(), list[i]->Order()) << what << " not in order";
    }
  }
  std::map<std::uint64_t, const PairRecord *> alive_;
  long long hellos_ = 0, goodbyes_ = 0;
};

}  // namespace karma::mcd::test

#endif
