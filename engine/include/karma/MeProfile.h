/* MeProfile.h: named wall-clock timers per frame, for the viewer's
 * performance bar and its -profile report.
 *
 * Use:
 *   MeProfileStartFrame();
 *     MeProfileStartSection("collision"); ...; MeProfileEndSection("collision");
 *     MeProfileStartSection("dynamics");  ...; MeProfileEndSection("dynamics");
 *   MeProfileEndFrame();
 *   ms = MeProfileGetSectionTime("dynamics");
 *
 * Sections. The built-in sections "collision", "dynamics", "render" and
 * "user" always exist (indices 0..3); any other name becomes a new section
 * on first use, up to ME_PROFILE_MAX_SECTIONS in all, names up to
 * ME_PROFILE_MAX_NAME - 1 characters (copied). A name beyond either limit is
 * ignored, with a single warning until MeProfileReset. Sections nest; a
 * section's time includes the sections nested in it. A section that is
 * started while already open (recursion) is timed only by its outermost
 * start/end pair. A section may run several times per frame: its times add
 * up. Sections are timed only inside a frame; outside one, Start/End
 * warn and are ignored. EndSection must name the innermost open section;
 * otherwise it warns and is ignored.
 *
 * Results, all in milliseconds: values of the last completed frame, and
 * averages over all frames completed since the last reset (a frame in which
 * a section did not run counts as 0 for it). Before the first completed
 * frame everything reads 0. Unknown section names read 0.
 *
 * Clock. By default a monotonic system clock (std::chrono::steady_clock).
 * MeProfileSetClock installs another one, which tests use to get exact
 * results.
 *
 * State. The profiler is one global object inside the MeGlobals library
 * (engine/me/profile), like Karma's. It is not thread-safe: time one thread,
 * or serialise the calls. MeProfileSetEnabled(FALSE) makes every Start/End
 * call return after one test. Profiling starts enabled. */
#ifndef KARMA_MEPROFILE_H
#define KARMA_MEPROFILE_H

#include "MeCall.h"
#include "MePrecision.h"

#define ME_PROFILE_MAX_SECTIONS 32
#define ME_PROFILE_MAX_NAME 32
#define ME_PROFILE_MAX_DEPTH 16

ME_EXTERN_C_BEGIN

/* A clock: returns the current time in milliseconds from any fixed origin.
 * It must never go backwards. `user` is the pointer given to SetClock. */
typedef double(MEAPI *MeProfileClock)(void *user);

/* Installs `clock` (called with `user`); NULL restores the default clock.
 * Drops any frame and sections in progress (their start times belong to the
 * old clock); results already recorded are kept. */
MEPUBLIC void MEAPI MeProfileSetClock(MeProfileClock clock, void *user);

/* Turns profiling on or off. Turning it off drops any frame and sections in
 * progress; results already recorded are kept and can still be read. */
MEPUBLIC void MEAPI MeProfileSetEnabled(MeBool enabled);
MEPUBLIC MeBool MEAPI MeProfileIsEnabled(void);

/* Begins a frame. If a frame is already open, it warns and ends that frame
 * first. */
MEPUBLIC void MEAPI MeProfileStartFrame(void);

/* Ends the frame: its section times become the "last frame" results and
 * join the averages. Sections still open are closed at this moment, with a
 * warning. Without an open frame it warns and does nothing. */
MEPUBLIC void MEAPI MeProfileEndFrame(void);

/* Starts / ends timing the named section (see the header comment). */
MEPUBLIC void MEAPI MeProfileStartSection(const char *name);
MEPUBLIC void MEAPI MeProfileEndSection(const char *name);

/* Time spent in the section during the last completed frame. */
MEPUBLIC MeReal MEAPI MeProfileGetSectionTime(const char *name);

/* Mean time per frame spent in the section since the last reset. */
MEPUBLIC MeReal MEAPI MeProfileGetSectionAverage(const char *name);

/* Length of the last completed frame / mean frame length since reset. */
MEPUBLIC MeReal MEAPI MeProfileGetFrameTime(void);
MEPUBLIC MeReal MEAPI MeProfileGetFrameAverage(void);

/* Frames completed since the last reset. */
MEPUBLIC int MEAPI MeProfileGetFrameCount(void);

/* Number of sections (built-in ones included) and the name of section i
 * (NULL if out of range). Indices are stable until MeProfileReset. */
MEPUBLIC int MEAPI MeProfileGetSectionCount(void);
MEPUBLIC const char *MEAPI MeProfileGetSectionName(int i);

/* Forgets all results and user sections and drops any frame in progress.
 * The clock and the enabled state are kept. */
MEPUBLIC void MEAPI MeProfileReset(void);

ME_EXTERN_C_END

#endif /* KARMA_MEPROFILE_H */
