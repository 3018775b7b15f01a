// farfield_test_util.h: shared helpers for the farfield tests: warning
// capture, reading all events through the chunked iterator, and a world of
// moving boxes driven through the space's AABB function.
#ifndef KARMA_TESTS_MCD_FARFIELD_UTIL_H
#define KARMA_TESTS_MCD_FARFIELD_UTIL_H

#include "axis_sort_space.h"
#include "brute_force.h"

#include "MeMessage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace karma::mcd::test {

// Collects every MeWarning while alive (and keeps them off stderr).
class WarningCapture {
 public:
  WarningCapture() {
    Messages().clear();
    previous_ = MeSetWarningHandler(&Handler);
  }
  ~WarningCapture() { MeSetWarningHandler(previous_); }
  static std::vector<std::string> &Messages() {
    static std::vector<std::string> messages;
    return messages;
  }
  int Count() const { return static_cast<int>(Messages().size()); }
  int CountContaining(const std::string &text) const {
    return static_cast<int>(std::count_if(Messages().begin(), Messages().end(),
                                          [&](const std::string &m) { return m.find(text) != std::string::npos; }));
  }
  void Clear() { Messages().clear(); }

 private:
  static void MEAPI Handler(int, const char *message) { Messages().emplace_back(message); }
  MeMessageHandler previous_;
};

struct Events {
  std::vector<const PairRecord *> goodbyes, hellos, stayings;
  int calls = 0;  // GetPairs calls it took
};

// Reads the current events with a container of `chunkSize`, checking the
// chunk layout on every call.
inline Events Collect(AxisSortSpace &space, int chunkSize = 64, bool transitionsOnly = false) {
  Events ev;
  std::vector<const PairRecord *> storage(static_cast<std::size_t>(chunkSize));
  PairIterator it;
  space.PairIteratorBegin(&it);
  bool more = true;
  while (more) {
    PairChunk chunk;
    chunk.array = storage.data();
    chunk.size = chunkSize;
    more = transitionsOnly ? space.GetTransitions(&it, &chunk) : space.GetPairs(&it, &chunk);
    ++ev.calls;
    if (chunk.goodbyeFirst != 0 || chunk.helloFirst != chunk.goodbyeEnd || chunk.stayingEnd > chunkSize ||
        chunk.helloEnd < chunk.helloFirst || chunk.stayingEnd < chunk.helloEnd) {
      ADD_FAILURE() << "bad chunk layout";
      break;
    }
    for (int i = chunk.goodbyeFirst; i < chunk.goodbyeEnd; ++i) ev.goodbyes.push_back(chunk.array[i]);
    for (int i = chunk.helloFirst; i < chunk.helloEnd; ++i) ev.hellos.push_back(chunk.array[i]);
    for (int i = chunk.helloEnd; i < chunk.stayingEnd; ++i) ev.stayings.push_back(chunk.array[i]);
    if (ev.calls > 1000000) {
      ADD_FAILURE() << "GetPairs never stops";
      break;
    }
  }
  return ev;
}

inline std::vector<std::uint64_t> Keys(const std::vector<const PairRecord *> &records) {
  std::vector<std::uint64_t> keys;
  for (const PairRecord *r : records) keys.push_back(r->SerialPair());
  return keys;
}

// The reported set: hellos and stayings, ascending.
inline std::vector<std::uint64_t> ReportedKeys(const Events &ev) {
  std::vector<std::uint64_t> keys = Keys(ev.hellos);
  const std::vector<std::uint64_t> s = Keys(ev.stayings);
  keys.insert(keys.end(), s.begin(), s.end());
  std::sort(keys.begin(), keys.end());
  return keys;
}

inline void SetBox(MeReal min[3], MeReal max[3], MeReal x0, MeReal y0, MeReal z0, MeReal x1, MeReal y1, MeReal z1) {
  min[0] = x0, min[1] = y0, min[2] = z0;
  max[0] = x1, max[1] = y1, max[2] = z1;
}

// A box moving in [0, size]^3 and bouncing off the walls.
struct MovingBox {
  MeReal pos[3], vel[3], half[3];
  ProxyId id = kNoProxy;
};

inline void MovingBoxAabb(void *user, void *, MeReal min[3], MeReal max[3]) {
  const auto *b = static_cast<const MovingBox *>(user);
  for (int k = 0; k < 3; ++k) {
    min[k] = b->pos[k] - b->half[k];
    max[k] = b->pos[k] + b->half[k];
  }
}

class BoxWorld {
 public:
  BoxWorld(int count, MeReal size, unsigned seed, MeReal speed = MeReal(0.3)) : size_(size), rng_(seed) {
    boxes_.resize(static_cast<std::size_t>(count));
    for (MovingBox &b : boxes_) Randomize(b, speed);
  }
  void Randomize(MovingBox &b, MeReal speed) {
    for (int k = 0; k < 3; ++k) {
      b.pos[k] = Uniform(0, size_);
      b.vel[k] = Uniform(-speed, speed);
      b.half[k] = Uniform(MeReal(0.2), MeReal(1.2));
    }
  }
  void Move() {
    for (MovingBox &b : boxes_) {
      for (int k = 0; k < 3; ++k) {
        b.pos[k] += b.vel[k];
        if (b.pos[k] < 0 || b.pos[k] > size_) b.vel[k] = -b.vel[k];
      }
    }
  }
  MeReal Uniform(MeReal lo, MeReal hi) {
    return lo + (hi - lo) * static_cast<MeReal>(std::uniform_int_distribution<int>(0, 1 << 20)(rng_)) /
                    static_cast<MeReal>(1 << 20);
  }
  int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  std::vector<MovingBox> &Boxes() { return boxes_; }
  MovingBox &Box(int i) { return boxes_[static_cast<std::size_t>(i)]; }

 private:
  MeReal size_;
  std::mt19937 rng_;
  std::vector<MovingBox> boxes_;
};

inline ProxyId InsertBox(AxisSortSpace &space, MovingBox &b) {
  MeReal min[3], max[3];
  MovingBoxAabb(&b, nullptr, min, max);
  b.id = space.Insert(&b, min, max);
  return b.id;
}

}  // namespace karma::mcd::test

#endif
