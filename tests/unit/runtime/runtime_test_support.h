// runtime_test_support.h: RAII helpers for the runtime tests: capture the
// messages Karma emits, and route MeMemoryAPI through counting functions.
#ifndef KARMA_TESTS_RUNTIME_TEST_SUPPORT_H
#define KARMA_TESTS_RUNTIME_TEST_SUPPORT_H

#include <cstddef>
#include <string>
#include <vector>

#include "MeMemory.h"
#include "MeMessage.h"

namespace karma_test {

struct Message {
  int level;
  std::string text;
};

// While alive, info, warning and debug messages are recorded instead of
// printed. The previous handlers come back on destruction.
class MessageCapture {
 public:
  MessageCapture();
  ~MessageCapture();
  MessageCapture(const MessageCapture &) = delete;
  MessageCapture &operator=(const MessageCapture &) = delete;

  const std::vector<Message> &warnings() const;
  const std::vector<Message> &infos() const;
  const std::vector<Message> &debugs() const;
  // Text of the last warning ("" if none).
  std::string lastWarning() const;
  void clear();

 private:
  MeMessageHandler previousInfo_;
  MeMessageHandler previousWarning_;
  MeMessageHandler previousDebug_;
};

// While alive, MeMemoryAPI.create / destroy count calls and track live
// blocks (forwarding to the functions installed before). The table is
// restored on destruction. setFailing(true) makes create return NULL.
class CountingAllocator {
 public:
  CountingAllocator();
  ~CountingAllocator();
  CountingAllocator(const CountingAllocator &) = delete;
  CountingAllocator &operator=(const CountingAllocator &) = delete;

  int creates() const;
  int destroys() const;
  std::size_t liveBlocks() const;
  std::size_t lastCreateBytes() const;
  void setFailing(bool failing);

 private:
  MeMemoryAPIStruct saved_;
};

}  // namespace karma_test

#endif
