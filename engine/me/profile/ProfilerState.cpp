// ProfilerState.cpp: the global profiler object, its section table and the
// default clock.
#include "ProfilerState.h"

#include <chrono>
#include <cstring>

#include "MeMessage.h"

namespace karma::me {
namespace {

void copyName(char (&to)[ME_PROFILE_MAX_NAME], const char *from) noexcept {
  std::size_t i = 0;
  for (; from[i] != '\0' && i + 1 < ME_PROFILE_MAX_NAME; ++i) to[i] = from[i];
  for (; i < ME_PROFILE_MAX_NAME; ++i) to[i] = '\0';
}

ProfilerState makeInitialState() noexcept {
  ProfilerState state;
  state.clock = &steadyClockMilliseconds;
  resetProfiler(state);
  return state;
}

}  // namespace

double MEAPI steadyClockMilliseconds(void *) {
  using Milliseconds = std::chrono::duration<double, std::milli>;
  return Milliseconds(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProfilerState &profiler() noexcept {
  // Initialised on first use (thread-safe), so no static-order issues.
  static ProfilerState state = makeInitialState();
  return state;
}

int findSection(const ProfilerState &state, const char *name) noexcept {
  for (int i = 0; i < state.sectionCount; ++i)
    if (std::strcmp(state.sections[i].name, name) == 0) return i;
  return -1;
}

int findOrAddSection(ProfilerState &state, const char *name) noexcept {
  const int found = findSection(state, name);
  if (found >= 0) return found;
  const bool tooLong = std::strlen(name) >= ME_PROFILE_MAX_NAME;
  if (tooLong || state.sectionCount == ME_PROFILE_MAX_SECTIONS) {
    if (!state.warnedIgnoredName) {
      state.warnedIgnoredName = true;
      if (tooLong)
        MeWarning(0,
                  "MeProfileStartSection: section name \"%s\" is longer than %d "
                  "characters; not timed",
                  name, ME_PROFILE_MAX_NAME - 1);
      else
        MeWarning(0, "MeProfileStartSection: already %d sections; \"%s\" is not timed", ME_PROFILE_MAX_SECTIONS, name);
    }
    return -1;
  }
  ProfileSection &section = state.sections[state.sectionCount];
  section = ProfileSection{};
  copyName(section.name, name);
  return state.sectionCount++;
}

void resetProfiler(ProfilerState &state) noexcept {
  for (ProfileSection &section : state.sections) section = ProfileSection{};
  for (int i = 0; i < builtinSectionCount; ++i) copyName(state.sections[i].name, builtinSectionNames[i]);
  state.sectionCount = builtinSectionCount;
  state.depth = 0;
  state.skippedDepth = 0;
  state.frameOpen = false;
  state.frameStart = 0;
  state.lastFrame = 0;
  state.totalFrames = 0;
  state.frameCount = 0;
  state.warnedIgnoredName = false;
  state.warnedTooDeep = false;
}

void dropOpenFrame(ProfilerState &state) noexcept {
  for (int i = 0; i < state.sectionCount; ++i) {
    state.sections[i].current = 0;
    state.sections[i].openCount = 0;
  }
  state.depth = 0;
  state.skippedDepth = 0;
  state.frameOpen = false;
}

}  // namespace karma::me
