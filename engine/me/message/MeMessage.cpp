// MeMessage.cpp: the four message functions and MeArgumentWarning.
// Each formats on its own stack, then calls the channel's handler.
#include "MeMessage.h"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "MessageFormat.h"
#include "MessageHandlers.h"

using karma::me::currentDebugLevel;
using karma::me::currentHandler;
using karma::me::formatMessage;
using karma::me::MessageChannel;
using karma::me::MessageText;

extern "C" {

MEPUBLIC void MEAPI MeInfo(int level, const char *format, ...) {
  MessageText message;
  std::va_list args;
  va_start(args, format);
  formatMessage(message, format, args);
  va_end(args);
  currentHandler(MessageChannel::info)(level, message.text);
}

MEPUBLIC void MEAPI MeWarning(int level, const char *format, ...) {
  MessageText message;
  std::va_list args;
  va_start(args, format);
  formatMessage(message, format, args);
  va_end(args);
  currentHandler(MessageChannel::warning)(level, message.text);
}

// Not noexcept on purpose: a C++ handler may throw to take back control.
MEPUBLIC void MEAPI MeFatalError(int level, const char *format, ...) {
  MessageText message;
  std::va_list args;
  va_start(args, format);
  formatMessage(message, format, args);
  va_end(args);
  currentHandler(MessageChannel::fatalError)(level, message.text);
  // The handler returned: Karma cannot continue.
  std::fflush(nullptr);
  std::abort();
}

MEPUBLIC void MEAPI MeDebug(int level, const char *format, ...) {
  const int effective = level < 1 ? 1 : level;
  if (effective > currentDebugLevel()) return;  // filtered before any formatting cost
  MessageText message;
  std::va_list args;
  va_start(args, format);
  formatMessage(message, format, args);
  va_end(args);
  currentHandler(MessageChannel::debug)(level, message.text);
}

MEPUBLIC void MEAPI MeArgumentWarning(const char *function, const char *format, ...) {
  MessageText detail;
  std::va_list args;
  va_start(args, format);
  formatMessage(detail, format, args);
  va_end(args);
  MeWarning(0, "%s: %s", function != nullptr ? function : "(unknown function)", detail.text);
}

}  // extern "C"
