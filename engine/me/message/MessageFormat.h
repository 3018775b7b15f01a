// MessageFormat.h: turning a printf-style format into one bounded line of text.
#ifndef KARMA_ME_MESSAGE_MESSAGEFORMAT_H
#define KARMA_ME_MESSAGE_MESSAGEFORMAT_H

#include <cstdarg>

#include "MeMessage.h"

namespace karma::me {

// A message's text. Always zero-terminated, at most ME_MESSAGE_MAX_LENGTH
// bytes with the terminator; lives on the caller's stack so that formatting
// needs neither a lock nor an allocation (it works when memory is exhausted).
struct MessageText {
  char text[ME_MESSAGE_MAX_LENGTH];
};

// Formats `format` with `args` into `out`. Text that does not fit is cut and
// ends in "..."; trailing newlines are removed; a NULL format or an encoding
// error yields a short placeholder instead of failing.
void formatMessage(MessageText &out, const char *format, std::va_list args) noexcept;

}  // namespace karma::me

#endif
