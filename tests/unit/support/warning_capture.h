// warning_capture.h: records MeWarning messages while alive instead of
// printing them, so tests can assert that bad input was reported (and by
// which function). Shared by the unit test folders.
#pragma once

#include <string>
#include <vector>

#include "MeMessage.h"

namespace karma_test {

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
  bool lastMentions(const std::string &what) const { return last().find(what) != std::string::npos; }
  // Whether any message recorded so far mentions `what`.
  bool saw(const std::string &what) const {
    for (const std::string &m : log())
      if (m.find(what) != std::string::npos) return true;
    return false;
  }
  void clear() { log().clear(); }

 private:
  static void MEAPI handler(int, const char *message) { log().emplace_back(message); }
  MeMessageHandler previous_;
};

}  // namespace karma_test
