// mdt_test_support.h: warning capture and small helpers for the Mdt tests.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "Mdt.h"

namespace mdt_test {

// While alive, warnings are recorded instead of printed.
class WarningCapture {
 public:
  WarningCapture() : previous_(MeSetWarningHandler(&WarningCapture::handler)) { log().clear(); }
  ~WarningCapture() { MeSetWarningHandler(previous_); }
  WarningCapture(const WarningCapture &) = delete;
  WarningCapture &operator=(const WarningCapture &) = delete;
  static std::vector<std::string> &log() {
    static std::vector<std::string> messages;
    return messages;
  }
  size_t count() const { return log().size(); }
  std::string last() const { return log().empty() ? std::string() : log().back(); }
  void clear() { log().clear(); }

 private:
  static void MEAPI handler(int, const char *message) { log().emplace_back(message); }
  MeMessageHandler previous_;
};

// A world destroyed at the end of the test.
struct World {
  MdtWorldID id;
  World(unsigned bodies = 8, MeReal l = 1, MeReal m = 1) : id(MdtWorldCreate(bodies, 0, l, m)) {}
  ~World() { MdtWorldDestroy(id); }
  World(const World &) = delete;
  World &operator=(const World &) = delete;
  operator MdtWorldID() const { return id; }
};

// Relative tolerance of a few MeReal ulps times `ulps`.
inline double tol(double scale, double ulps = 8) {
  return ulps * (double)ME_REAL_EPSILON * (scale < 1 ? 1 : scale);
}

}  // namespace mdt_test
