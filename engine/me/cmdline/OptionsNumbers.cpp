// OptionsNumbers.cpp: option values read as numbers. The whole value must
// parse (no leading blanks, no trailing characters), be in range, and for
// MeReal be finite; otherwise the look-up fails with a warning and leaves
// the output untouched.
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>

#include "MeMessage.h"
#include "OptionsStorage.h"

namespace karma::me {
namespace {

bool startsWithBlank(const char *text) noexcept {
  const char c = text[0];
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// Decimal integer in int range.
bool parseInt(const char *text, int *out) noexcept {
  if (text[0] == '\0' || startsWithBlank(text)) return false;
  errno = 0;
  char *end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || errno == ERANGE || value < INT_MIN || value > INT_MAX) return false;
  *out = static_cast<int>(value);
  return true;
}

// Finite number representable as MeReal.
bool parseReal(const char *text, MeReal *out) noexcept {
  if (text[0] == '\0' || startsWithBlank(text)) return false;
  errno = 0;
  char *end = nullptr;
  const double value = std::strtod(text, &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(value) || std::fabs(value) > static_cast<double>(ME_REAL_MAX))
    return false;
  *out = static_cast<MeReal>(value);
  return true;
}

}  // namespace
}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC MeBool MEAPI MeCommandLineOptionsGetFloat(MeCommandLineOptions *options, const char *name, MeReal *value,
                                                   MeBool eat) {
  constexpr const char *caller = "MeCommandLineOptionsGetFloat";
  ME_REQUIRE_ARG_RET(value != nullptr, FALSE, caller, "value pointer is NULL");
  bool present = false;
  const char *text = takeOptionValue(options, name, eat, caller, &present);
  if (text == nullptr) return FALSE;
  if (!parseReal(text, value)) {
    MeWarning(0, "%s: option %s needs a finite number, got \"%s\"", caller, name, text);
    return FALSE;
  }
  return TRUE;
}

MEPUBLIC MeBool MEAPI MeCommandLineOptionsGetInt(MeCommandLineOptions *options, const char *name, int *value,
                                                 MeBool eat) {
  constexpr const char *caller = "MeCommandLineOptionsGetInt";
  ME_REQUIRE_ARG_RET(value != nullptr, FALSE, caller, "value pointer is NULL");
  bool present = false;
  const char *text = takeOptionValue(options, name, eat, caller, &present);
  if (text == nullptr) return FALSE;
  if (!parseInt(text, value)) {
    MeWarning(0, "%s: option %s needs a whole number in int range, got \"%s\"", caller, name, text);
    return FALSE;
  }
  return TRUE;
}

}  // extern "C"
