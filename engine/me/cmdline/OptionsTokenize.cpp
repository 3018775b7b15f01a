// OptionsTokenize.cpp: MeCommandLineOptionsCreateFromString.
//
// The string is scanned twice with the same scanner: once to count the
// arguments and their bytes, once to copy them into the options' block, so
// there is exactly one allocation and no temporary container.
#include <cstring>

#include "MeMessage.h"
#include "OptionsStorage.h"

namespace karma::me {
namespace {

bool isBlank(char c) noexcept { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Reads one argument starting at `p` (after blanks have been skipped and
// *p is not the end). Writes its characters to `out` unless out is NULL,
// returns how many there are, and leaves `p` after the argument. Sets
// *unterminated if a quote was still open at the end of the string.
std::size_t scanArgument(const char *&p, char *out, bool *unterminated) noexcept {
  std::size_t length = 0;
  bool quoted = false;
  while (*p != '\0' && (quoted || !isBlank(*p))) {
    char c = *p;
    if (c == '\\' && p[1] == '"') {
      ++p;  // \" is a literal quote
      c = '"';
    } else if (c == '"') {
      quoted = !quoted;
      ++p;
      continue;
    }
    if (out != nullptr) out[length] = c;
    ++length;
    ++p;
  }
  if (quoted) *unterminated = true;
  return length;
}

void skipBlanks(const char *&p) noexcept {
  while (isBlank(*p)) ++p;
}

}  // namespace
}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC MeCommandLineOptions *MEAPI MeCommandLineOptionsCreateFromString(const char *commandLine) {
  const char *const start = commandLine != nullptr ? commandLine : "";

  // Pass 1: count.
  int count = 0;
  std::size_t textBytes = 0;
  bool unterminated = false;
  for (const char *p = start;;) {
    skipBlanks(p);
    if (*p == '\0') break;
    textBytes += scanArgument(p, nullptr, &unterminated) + 1;
    ++count;
  }
  if (unterminated)
    MeWarning(0,
              "MeCommandLineOptionsCreateFromString: a double quote is not closed; the "
              "last argument runs to the end of the string");
  if (count == 0) {
    count = 1;  // empty program name
    textBytes = 1;
  }

  // Pass 2: copy.
  char *text = nullptr;
  MeCommandLineOptions *options = allocateOptions(count, textBytes, &text);
  if (options == nullptr) return nullptr;
  const char *p = start;
  for (int i = 0; i < count; ++i) {
    skipBlanks(p);
    const std::size_t length = *p != '\0' ? scanArgument(p, text, &unterminated) : 0;
    text[length] = '\0';
    options->m_argv[i] = text;
    text += length + 1;
  }
  return options;
}

}  // extern "C"
