// MessageFormat.cpp: bounded formatting of message text.
#include "MessageFormat.h"

#include <cstdio>
#include <cstring>

namespace karma::me {

void formatMessage(MessageText &out, const char *format, std::va_list args) noexcept {
  constexpr std::size_t capacity = sizeof(out.text);
  if (format == nullptr) {
    std::snprintf(out.text, capacity, "(NULL message format)");
    return;
  }
  const int wanted = std::vsnprintf(out.text, capacity, format, args);
  if (wanted < 0) {
    std::snprintf(out.text, capacity, "(unformattable message: \"%.64s\")", format);
    return;
  }
  if (static_cast<std::size_t>(wanted) >= capacity) {
    // vsnprintf kept capacity-1 characters; mark the cut.
    std::memcpy(out.text + capacity - 4, "...", 4);
    return;
  }
  std::size_t length = static_cast<std::size_t>(wanted);
  while (length > 0 && (out.text[length - 1] == '\n' || out.text[length - 1] == '\r')) out.text[--length] = '\0';
}

}  // namespace karma::me
