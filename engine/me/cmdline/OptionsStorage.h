// OptionsStorage.h: the memory layout of MeCommandLineOptions and the few
// operations on it that the look-ups share.
//
// Options live in one block from MeMemoryAPI.create:
//   [MeCommandLineOptions][const char* argv[count + 1]][argument text]
// m_argv points at the array, whose entries point into the text. Eating an
// argument only removes its entry from the array, so every string handed
// out stays valid until the block is destroyed.
#ifndef KARMA_ME_CMDLINE_OPTIONSSTORAGE_H
#define KARMA_ME_CMDLINE_OPTIONSSTORAGE_H

#include <cstddef>

#include "MeCommandLineOptions.h"

namespace karma::me {

// Allocates options for `count` (>= 1) arguments whose strings need
// `textBytes` bytes in all, terminators included. m_argc is set, every
// argv entry is NULL, and *text points to the text area. NULL (after a
// warning) if memory runs out.
MeCommandLineOptions *allocateOptions(int count, std::size_t textBytes, char **text) noexcept;

// Index (>= 1) of the first argument equal to `name`, or -1.
int findOption(const MeCommandLineOptions &options, const char *name) noexcept;

// Removes `n` arguments starting at `index` (clamped to the list).
void removeArguments(MeCommandLineOptions &options, int index, int n) noexcept;

// The value of option `name` for the named look-up `caller`: NULL if absent
// (silently) or if it is the last argument (warning). Eats the option and
// its value when `eat` is true. *present tells whether the option was found.
const char *takeOptionValue(MeCommandLineOptions *options, const char *name, MeBool eat, const char *caller,
                            bool *present) noexcept;

}  // namespace karma::me

#endif
