// ProfilerState.h: the data of Karma's one global profiler, and the
// operations on it that the API files share.
#ifndef KARMA_ME_PROFILE_PROFILERSTATE_H
#define KARMA_ME_PROFILE_PROFILERSTATE_H

#include "MeProfile.h"

namespace karma::me {

// The built-in sections, always present at these indices.
inline constexpr const char *builtinSectionNames[] = {"collision", "dynamics", "render", "user"};
inline constexpr int builtinSectionCount = 4;

struct ProfileSection {
  char name[ME_PROFILE_MAX_NAME] = {};  // zero-terminated copy
  double current = 0;                   // ms accumulated in the open frame
  double last = 0;                      // ms in the last completed frame
  double total = 0;                     // ms summed over completed frames since reset
  int openCount = 0;                    // entries for this section on the open stack
};

struct OpenSection {
  int section = 0;   // index into sections
  double start = 0;  // clock reading when it was started
};

// Invariants: builtinSectionCount <= sectionCount <= ME_PROFILE_MAX_SECTIONS;
// depth == 0 and every `current` == 0 while no frame is open; openCount of
// a section equals its number of entries in stack[0 .. depth-1].
struct ProfilerState {
  ProfileSection sections[ME_PROFILE_MAX_SECTIONS];
  int sectionCount = 0;
  OpenSection stack[ME_PROFILE_MAX_DEPTH];
  int depth = 0;
  int skippedDepth = 0;  // starts beyond ME_PROFILE_MAX_DEPTH not yet ended
  bool enabled = true;
  bool frameOpen = false;
  double frameStart = 0;
  double lastFrame = 0;
  double totalFrames = 0;
  int frameCount = 0;
  MeProfileClock clock = nullptr;
  void *clockUser = nullptr;
  bool warnedIgnoredName = false;  // one warning per reset for rejected names
  bool warnedTooDeep = false;      // one warning per reset for deep nesting
};

// The global profiler (defined in ProfilerState.cpp).
ProfilerState &profiler() noexcept;

// The steady_clock reading in milliseconds (the default clock).
double MEAPI steadyClockMilliseconds(void *user);

// Reads the installed clock.
inline double profileNow(const ProfilerState &state) noexcept { return state.clock(state.clockUser); }

// Index of the section called `name`, or -1.
int findSection(const ProfilerState &state, const char *name) noexcept;

// Index of the section called `name`, created if new; -1 (with one warning
// per reset) if the name is too long or the table is full.
int findOrAddSection(ProfilerState &state, const char *name) noexcept;

// Forgets results and user sections; keeps clock and enabled state.
void resetProfiler(ProfilerState &state) noexcept;

// Drops the frame and sections in progress, keeping recorded results.
void dropOpenFrame(ProfilerState &state) noexcept;

}  // namespace karma::me

#endif
