// MessageHandlers.h: where the installed message handlers and the debug
// level live (one slot per channel, process-wide).
#ifndef KARMA_ME_MESSAGE_MESSAGEHANDLERS_H
#define KARMA_ME_MESSAGE_MESSAGEHANDLERS_H

#include "MeMessage.h"

namespace karma::me {

enum class MessageChannel { info, warning, fatalError, debug };

// The handler currently installed for `channel`; never null.
MeMessageHandler currentHandler(MessageChannel channel) noexcept;

// The MeDebug threshold (0 = debug output off).
int currentDebugLevel() noexcept;

}  // namespace karma::me

#endif
