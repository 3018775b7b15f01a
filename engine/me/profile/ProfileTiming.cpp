// ProfileTiming.cpp: frames, sections, the clock and the on/off switch.
#include <cstring>

#include "MeMessage.h"
#include "ProfilerState.h"

namespace karma::me {
namespace {

// Pops the innermost open section at time `now`, adding its time unless an
// outer entry of the same section is still open (then the outer one counts).
void popSection(ProfilerState &state, double now) noexcept {
  const OpenSection &top = state.stack[--state.depth];
  ProfileSection &section = state.sections[top.section];
  if (--section.openCount == 0) section.current += now - top.start;
}

void endFrameAt(ProfilerState &state, double now) noexcept {
  if (state.depth > 0 || state.skippedDepth > 0) {
    MeWarning(0, "MeProfileEndFrame: section \"%s\" is still open; closing it",
              state.depth > 0 ? state.sections[state.stack[state.depth - 1].section].name : "(nested too deep)");
    while (state.depth > 0) popSection(state, now);
    state.skippedDepth = 0;
  }
  const double frame = now - state.frameStart;
  state.lastFrame = frame;
  state.totalFrames += frame;
  ++state.frameCount;
  for (int i = 0; i < state.sectionCount; ++i) {
    ProfileSection &section = state.sections[i];
    section.last = section.current;
    section.total += section.current;
    section.current = 0;
  }
  state.frameOpen = false;
}

}  // namespace
}  // namespace karma::me

using namespace karma::me;

extern "C" {

MEPUBLIC void MEAPI MeProfileSetClock(MeProfileClock clock, void *user) {
  ProfilerState &state = profiler();
  dropOpenFrame(state);
  state.clock = clock != nullptr ? clock : &steadyClockMilliseconds;
  state.clockUser = clock != nullptr ? user : nullptr;
}

MEPUBLIC void MEAPI MeProfileSetEnabled(MeBool enabled) {
  ProfilerState &state = profiler();
  if (!enabled && state.enabled) dropOpenFrame(state);
  state.enabled = enabled != 0;
}

MEPUBLIC MeBool MEAPI MeProfileIsEnabled(void) { return profiler().enabled ? TRUE : FALSE; }

MEPUBLIC void MEAPI MeProfileStartFrame(void) {
  ProfilerState &state = profiler();
  if (!state.enabled) return;
  const double now = profileNow(state);
  if (state.frameOpen) {
    MeWarning(0, "MeProfileStartFrame: the previous frame was not ended; ending it now");
    endFrameAt(state, now);
  }
  state.frameOpen = true;
  state.frameStart = now;
}

MEPUBLIC void MEAPI MeProfileEndFrame(void) {
  ProfilerState &state = profiler();
  if (!state.enabled) return;
  if (!state.frameOpen) {
    MeWarning(0, "MeProfileEndFrame: no frame is open (call MeProfileStartFrame first)");
    return;
  }
  endFrameAt(state, profileNow(state));
}

MEPUBLIC void MEAPI MeProfileStartSection(const char *name) {
  ProfilerState &state = profiler();
  // Outside a frame, sections are ignored silently so that library code
  // can be instrumented whether or not anybody is profiling.
  if (!state.enabled || !state.frameOpen) return;
  ME_REQUIRE_ARG(name != nullptr, "MeProfileStartSection", "section name is NULL");
  if (state.depth == ME_PROFILE_MAX_DEPTH || state.skippedDepth > 0) {
    if (!state.warnedTooDeep) {
      state.warnedTooDeep = true;
      MeWarning(0, "MeProfileStartSection: sections nested deeper than %d are not timed", ME_PROFILE_MAX_DEPTH);
    }
    ++state.skippedDepth;
    return;
  }
  const int index = findOrAddSection(state, name);
  if (index < 0) return;  // rejected name (warned once); its EndSection is ignored too
  state.stack[state.depth++] = OpenSection{index, profileNow(state)};
  ++state.sections[index].openCount;
}

MEPUBLIC void MEAPI MeProfileEndSection(const char *name) {
  ProfilerState &state = profiler();
  if (!state.enabled || !state.frameOpen) return;
  ME_REQUIRE_ARG(name != nullptr, "MeProfileEndSection", "section name is NULL");
  if (state.skippedDepth > 0) {
    --state.skippedDepth;  // ends one of the untimed deep starts
    return;
  }
  const int index = findSection(state, name);
  if (index < 0 && (state.sectionCount == ME_PROFILE_MAX_SECTIONS || std::strlen(name) >= ME_PROFILE_MAX_NAME))
    return;  // a rejected name: its start was ignored (and warned about)
  if (state.depth == 0 || state.stack[state.depth - 1].section != index) {
    MeWarning(0,
              "MeProfileEndSection: \"%s\" is not the innermost open section (%s%s%s); "
              "ignored",
              name, state.depth > 0 ? "that is \"" : "none is open",
              state.depth > 0 ? state.sections[state.stack[state.depth - 1].section].name : "",
              state.depth > 0 ? "\"" : "");
    return;
  }
  popSection(state, profileNow(state));
}

MEPUBLIC void MEAPI MeProfileReset(void) { resetProfiler(profiler()); }

}  // extern "C"
