// runtime_test_support.cpp: the state behind MessageCapture and
// CountingAllocator (handlers are plain C function pointers, so the
// recorded data lives in file-level variables).
#include "runtime_test_support.h"

#include <set>

namespace karma_test {
namespace {

std::vector<Message> capturedInfos;
std::vector<Message> capturedWarnings;
std::vector<Message> capturedDebugs;

void MEAPI recordInfo(int level, const char *text) { capturedInfos.push_back({level, text}); }

void MEAPI recordWarning(int level, const char *text) { capturedWarnings.push_back({level, text}); }

void MEAPI recordDebug(int level, const char *text) { capturedDebugs.push_back({level, text}); }

MeMemoryAPIStruct forwardTo{};
int createCalls = 0;
int destroyCalls = 0;
std::size_t lastBytes = 0;
bool failCreates = false;
std::set<void *> liveSet;

void *MEAPI countingCreate(std::size_t bytes) {
  ++createCalls;
  lastBytes = bytes;
  if (failCreates) return nullptr;
  void *block = forwardTo.create(bytes);
  if (block != nullptr) liveSet.insert(block);
  return block;
}

void MEAPI countingDestroy(void *block) {
  ++destroyCalls;
  if (block != nullptr) liveSet.erase(block);
  forwardTo.destroy(block);
}

}  // namespace

MessageCapture::MessageCapture()
    : previousInfo_(MeSetInfoHandler(&recordInfo)),
      previousWarning_(MeSetWarningHandler(&recordWarning)),
      previousDebug_(MeSetDebugHandler(&recordDebug)) {
  clear();
}

MessageCapture::~MessageCapture() {
  MeSetInfoHandler(previousInfo_);
  MeSetWarningHandler(previousWarning_);
  MeSetDebugHandler(previousDebug_);
  clear();
}

const std::vector<Message> &MessageCapture::warnings() const { return capturedWarnings; }
const std::vector<Message> &MessageCapture::infos() const { return capturedInfos; }
const std::vector<Message> &MessageCapture::debugs() const { return capturedDebugs; }

std::string MessageCapture::lastWarning() const {
  return capturedWarnings.empty() ? std::string() : capturedWarnings.back().text;
}

void MessageCapture::clear() {
  capturedInfos.clear();
  capturedWarnings.clear();
  capturedDebugs.clear();
}

CountingAllocator::CountingAllocator() : saved_(MeMemoryAPI) {
  forwardTo = saved_;
  createCalls = 0;
  destroyCalls = 0;
  lastBytes = 0;
  failCreates = false;
  liveSet.clear();
  MeMemoryAPI.create = &countingCreate;
  MeMemoryAPI.destroy = &countingDestroy;
}

CountingAllocator::~CountingAllocator() {
  MeMemoryAPI = saved_;
  failCreates = false;
}

int CountingAllocator::creates() const { return createCalls; }
int CountingAllocator::destroys() const { return destroyCalls; }
std::size_t CountingAllocator::liveBlocks() const { return liveSet.size(); }
std::size_t CountingAllocator::lastCreateBytes() const { return lastBytes; }
void CountingAllocator::setFailing(bool failing) { failCreates = failing; }

}  // namespace karma_test
