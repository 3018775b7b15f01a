// MessageHandlers.cpp: the default handlers, the handler slots and the
// debug level. Slots are atomics so that a message emitted on a worker
// thread reads a whole pointer even if set-up code changes it.
#include "MessageHandlers.h"

#include <atomic>
#include <cstdio>

namespace karma::me {
namespace {

void MEAPI defaultInfo(int, const char *message) { std::fprintf(stderr, "Karma info: %s\n", message); }

void MEAPI defaultWarning(int, const char *message) { std::fprintf(stderr, "Karma warning: %s\n", message); }

void MEAPI defaultFatalError(int, const char *message) { std::fprintf(stderr, "Karma fatal error: %s\n", message); }

void MEAPI defaultDebug(int, const char *message) { std::fprintf(stderr, "Karma debug: %s\n", message); }

// Invariant: every slot holds a non-null handler (constant-initialised, so
// messages emitted during static initialisation already work).
std::atomic<MeMessageHandler> infoSlot{&defaultInfo};
std::atomic<MeMessageHandler> warningSlot{&defaultWarning};
std::atomic<MeMessageHandler> fatalErrorSlot{&defaultFatalError};
std::atomic<MeMessageHandler> debugSlot{&defaultDebug};
std::atomic<int> debugLevel{0};

std::atomic<MeMessageHandler> &slotOf(MessageChannel channel) noexcept {
  switch (channel) {
    case MessageChannel::info:
      return infoSlot;
    case MessageChannel::warning:
      return warningSlot;
    case MessageChannel::fatalError:
      return fatalErrorSlot;
    case MessageChannel::debug:
      break;
  }
  return debugSlot;
}

MeMessageHandler install(std::atomic<MeMessageHandler> &slot, MeMessageHandler handler,
                         MeMessageHandler fallback) noexcept {
  return slot.exchange(handler != nullptr ? handler : fallback);
}

}  // namespace

MeMessageHandler currentHandler(MessageChannel channel) noexcept { return slotOf(channel).load(); }

int currentDebugLevel() noexcept { return debugLevel.load(std::memory_order_relaxed); }

}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC MeMessageHandler MEAPI MeSetInfoHandler(MeMessageHandler handler) {
  return install(infoSlot, handler, &defaultInfo);
}

MEPUBLIC MeMessageHandler MEAPI MeSetWarningHandler(MeMessageHandler handler) {
  return install(warningSlot, handler, &defaultWarning);
}

MEPUBLIC MeMessageHandler MEAPI MeSetFatalErrorHandler(MeMessageHandler handler) {
  return install(fatalErrorSlot, handler, &defaultFatalError);
}

MEPUBLIC MeMessageHandler MEAPI MeSetDebugHandler(MeMessageHandler handler) {
  return install(debugSlot, handler, &defaultDebug);
}

MEPUBLIC void MEAPI MeSetDebugLevel(int level) { debugLevel.store(level, std::memory_order_relaxed); }

MEPUBLIC int MEAPI MeGetDebugLevel(void) { return debugLevel.load(std::memory_order_relaxed); }

}  // extern "C"
