// karma-platforms: lists the platform backends (engine/platform/kernels.h)
// and whether this CPU supports each, or answers for one backend.
//
//   karma-platforms                   each backend: supported or not; the best
//   karma-platforms --names           every backend's name, one per line
//   karma-platforms --supported NAME  exit status only (kExit* below)
//
// The golden tests ask `--supported` before running a backend, so a backend
// the CPU lacks is reported as skipped instead of silently passed.
#include "kernels.h"

#include <cstdio>
#include <cstring>

namespace platform = karma::platform;

namespace {

// Exit statuses of --supported (and of usage errors).
constexpr int kExitSupported = 0;
constexpr int kExitUnsupported = 1;  // a backend by that name exists, this CPU cannot run it
constexpr int kExitUnknown = 2;      // there is no backend by that name
constexpr int kExitUsage = 3;

int Usage() {
  std::fprintf(stderr,
               "usage: karma-platforms [--names | --supported NAME]\n"
               "  (no option)       list the backends and whether this CPU supports each\n"
               "  --names           print every backend's name, one per line\n"
               "  --supported NAME  exit %d if this CPU supports NAME, %d if it does not,\n"
               "                    %d if there is no backend by that name\n",
               kExitSupported, kExitUnsupported, kExitUnknown);
  return kExitUsage;
}

int List() {
  const platform::Kernels &best = platform::BestSupported();
  for (const platform::Kernels *k : platform::AllKernels())
    std::printf("%-10s %s%s\n", k->name, platform::Supported(*k) ? "supported" : "not supported",
                k == &best ? " (the best: the default unless KARMA_PLATFORM names another)" : "");
  return kExitSupported;
}

int Names() {
  for (const platform::Kernels *k : platform::AllKernels()) std::printf("%s\n", k->name);
  return kExitSupported;
}

int Supported(const char *name) {
  const platform::Kernels *k = platform::FindKernels(name);
  if (!k) {
    std::fprintf(stderr, "karma-platforms: there is no backend '%s'\n", name);
    return kExitUnknown;
  }
  return platform::Supported(*k) ? kExitSupported : kExitUnsupported;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc == 1) return List();
  if (argc == 2 && !std::strcmp(argv[1], "--names")) return Names();
  if (argc == 3 && !std::strcmp(argv[1], "--supported")) return Supported(argv[2]);
  return Usage();
}
