// OptionsLookup.cpp: flags and string values. A NULL options pointer reads
// as an empty command line; a NULL name is a caller error (warned).
#include <cstring>

#include "MeMessage.h"
#include "OptionsStorage.h"

using namespace karma::me;

extern "C" {

MEPUBLIC MeBool MEAPI MeCommandLineOptionsCheckFor(MeCommandLineOptions *options, const char *name, MeBool eat) {
  if (options == nullptr) return FALSE;
  ME_REQUIRE_ARG_RET(name != nullptr, FALSE, "MeCommandLineOptionsCheckFor", "option name is NULL");
  const int at = findOption(*options, name);
  if (at < 0) return FALSE;
  if (eat) removeArguments(*options, at, 1);
  return TRUE;
}

MEPUBLIC int MEAPI MeCommandLineOptionsCheckForList(MeCommandLineOptions *options, const char *const *names, int count,
                                                    MeBool eat) {
  if (options == nullptr) return -1;
  ME_REQUIRE_ARG_RET(names != nullptr || count == 0, -1, "MeCommandLineOptionsCheckForList", "names is NULL");
  ME_REQUIRE_ARG_RET(count >= 0, -1, "MeCommandLineOptionsCheckForList", "count is %d, must be >= 0", count);
  // Outer loop over the command line: the earliest argument wins.
  for (int i = 1; i < options->m_argc; ++i) {
    for (int k = 0; k < count; ++k) {
      if (names[k] != nullptr && std::strcmp(options->m_argv[i], names[k]) == 0) {
        if (eat) removeArguments(*options, i, 1);
        return k;
      }
    }
  }
  return -1;
}

MEPUBLIC const char *MEAPI MeCommandLineOptionsGetString(MeCommandLineOptions *options, const char *name, MeBool eat) {
  bool present = false;
  return takeOptionValue(options, name, eat, "MeCommandLineOptionsGetString", &present);
}

}  // extern "C"
