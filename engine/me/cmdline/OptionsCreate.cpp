// OptionsCreate.cpp: copying argc/argv, destroying options, plain access.
#include <cstring>

#include "MeMemory.h"
#include "MeMessage.h"
#include "OptionsStorage.h"

using namespace karma::me;

extern "C" {

MEPUBLIC MeCommandLineOptions *MEAPI MeCommandLineOptionsCreate(int argc, const char *argv[]) {
  if (argv == nullptr || argc < 0) {
    MeWarning(0, "MeCommandLineOptionsCreate: %s; using an empty command line",
              argv == nullptr ? "argv is NULL" : "argc is negative");
    argc = 0;
  }
  // Always keep a program name, so m_argc >= 1 and look-ups start at 1.
  const int count = argc > 0 ? argc : 1;
  std::size_t textBytes = 0;
  for (int i = 0; i < argc; ++i) textBytes += (argv[i] != nullptr ? std::strlen(argv[i]) : 0) + 1;
  if (argc == 0) textBytes = 1;

  char *text = nullptr;
  MeCommandLineOptions *options = allocateOptions(count, textBytes, &text);
  if (options == nullptr) return nullptr;
  for (int i = 0; i < count; ++i) {
    const char *source = (i < argc && argv[i] != nullptr) ? argv[i] : "";
    const std::size_t length = std::strlen(source) + 1;
    std::memcpy(text, source, length);
    options->m_argv[i] = text;
    text += length;
  }
  return options;
}

MEPUBLIC void MEAPI MeCommandLineOptionsDestroy(MeCommandLineOptions *options) {
  // Header, array and text are one block (OptionsStorage.h).
  if (options != nullptr) MeMemoryAPI.destroy(options);
}

MEPUBLIC int MEAPI MeCommandLineOptionsGetCount(const MeCommandLineOptions *options) {
  return options != nullptr ? options->m_argc : 0;
}

MEPUBLIC const char *MEAPI MeCommandLineOptionsGetArg(const MeCommandLineOptions *options, int i) {
  if (options == nullptr || i < 0 || i >= options->m_argc) return nullptr;
  return options->m_argv[i];
}

}  // extern "C"
