// ProfileResults.cpp: reading the profiler's results (milliseconds).
#include "ProfilerState.h"

using namespace karma::me;

namespace {

MeReal averageOf(double total, int frames) noexcept {
  return frames > 0 ? static_cast<MeReal>(total / frames) : MeReal(0);
}

}  // namespace

extern "C" {

MEPUBLIC MeReal MEAPI MeProfileGetSectionTime(const char *name) {
  const ProfilerState &state = profiler();
  const int index = name != nullptr ? findSection(state, name) : -1;
  return index >= 0 ? static_cast<MeReal>(state.sections[index].last) : MeReal(0);
}

MEPUBLIC MeReal MEAPI MeProfileGetSectionAverage(const char *name) {
  const ProfilerState &state = profiler();
  const int index = name != nullptr ? findSection(state, name) : -1;
  return index >= 0 ? averageOf(state.sections[index].total, state.frameCount) : MeReal(0);
}

MEPUBLIC MeReal MEAPI MeProfileGetFrameTime(void) { return static_cast<MeReal>(profiler().lastFrame); }

MEPUBLIC MeReal MEAPI MeProfileGetFrameAverage(void) {
  const ProfilerState &state = profiler();
  return averageOf(state.totalFrames, state.frameCount);
}

MEPUBLIC int MEAPI MeProfileGetFrameCount(void) { return profiler().frameCount; }

MEPUBLIC int MEAPI MeProfileGetSectionCount(void) { return profiler().sectionCount; }

MEPUBLIC const char *MEAPI MeProfileGetSectionName(int i) {
  const ProfilerState &state = profiler();
  return i >= 0 && i < state.sectionCount ? state.sections[i].name : nullptr;
}

}  // extern "C"
