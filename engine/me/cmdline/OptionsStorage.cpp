// OptionsStorage.cpp: allocating options, finding and removing arguments.
#include "OptionsStorage.h"

#include <cstdint>
#include <cstring>

#include "MeMemory.h"
#include "MeMessage.h"

namespace karma::me {

static_assert(sizeof(MeCommandLineOptions) % alignof(const char *) == 0,
              "the argv array must start aligned right after the header");

MeCommandLineOptions *allocateOptions(int count, std::size_t textBytes, char **text) noexcept {
  const std::size_t arrayBytes = (static_cast<std::size_t>(count) + 1) * sizeof(const char *);
  const std::size_t header = sizeof(MeCommandLineOptions);
  if (textBytes > SIZE_MAX - header - arrayBytes) {
    MeWarning(0, "MeCommandLineOptions: command line too long");
    return nullptr;
  }
  char *block = static_cast<char *>(MeMemoryAPI.create(header + arrayBytes + textBytes));
  if (block == nullptr) {
    MeWarning(0, "MeCommandLineOptions: out of memory copying %d arguments", count);
    return nullptr;
  }
  auto *options = reinterpret_cast<MeCommandLineOptions *>(block);
  auto **argv = reinterpret_cast<const char **>(block + header);
  for (int i = 0; i <= count; ++i) argv[i] = nullptr;
  options->m_argc = count;
  options->m_argv = argv;
  *text = block + header + arrayBytes;
  return options;
}

int findOption(const MeCommandLineOptions &options, const char *name) noexcept {
  for (int i = 1; i < options.m_argc; ++i)
    if (std::strcmp(options.m_argv[i], name) == 0) return i;
  return -1;
}

void removeArguments(MeCommandLineOptions &options, int index, int n) noexcept {
  if (index < 0 || index >= options.m_argc || n <= 0) return;
  if (n > options.m_argc - index) n = options.m_argc - index;
  // Move the tail down, the NULL terminator included.
  std::memmove(&options.m_argv[index], &options.m_argv[index + n],
               static_cast<std::size_t>(options.m_argc - index - n + 1) * sizeof(const char *));
  options.m_argc -= n;
}

const char *takeOptionValue(MeCommandLineOptions *options, const char *name, MeBool eat, const char *caller,
                            bool *present) noexcept {
  *present = false;
  if (options == nullptr) return nullptr;
  ME_REQUIRE_ARG_RET(name != nullptr, nullptr, caller, "option name is NULL");
  const int at = findOption(*options, name);
  if (at < 0) return nullptr;
  *present = true;
  if (at + 1 >= options->m_argc) {
    MeWarning(0, "%s: option %s needs a value but is the last argument", caller, name);
    if (eat) removeArguments(*options, at, 1);
    return nullptr;
  }
  const char *value = options->m_argv[at + 1];
  if (eat) removeArguments(*options, at, 2);
  return value;
}

}  // namespace karma::me
