/* MdtPlatform.h: the platform backends, the sets of numeric kernels the
 * dynamics step can run on, and the process-wide default (an extension: the
 * guide's Karma chose its C, x86 or SSE kernels when it was built).
 *
 * The backends are "reference" (portable scalar code, the definition of
 * every result), "sse4" (SSE4.2), "avx2" (AVX2) and "avx512" (AVX-512F).
 * All of them give the same results to the bit; they differ in speed only,
 * and in which CPUs can run them. A world takes the process default when
 * it is created; MdtWorldSetPlatform (MdtWorld.h) changes one world.
 *
 * The process default starts as the backend named by the environment
 * variable KARMA_PLATFORM when it is set (read once, at the first world or
 * the first call here), else the best backend this CPU supports. Programs
 * that draw with MeViewer, and the tutorials, also take `-platform NAME`
 * on their command line, which sets it. */
#ifndef KARMA_MDTPLATFORM_H
#define KARMA_MDTPLATFORM_H
#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/* Makes the backend called `name` the default of worlds created from now
 * on (worlds that exist keep theirs). An unknown name, NULL, or a backend
 * this CPU cannot run gives a warning and selects the best supported
 * backend instead. Safe to call from any thread. */
MEPUBLIC void MEAPI MdtPlatformSetDefault(const char *name);
/* The name of the process default backend. */
MEPUBLIC const char *MEAPI MdtPlatformGetDefaultName(void);
/* The name of the best backend this CPU supports (what an unusable name
 * falls back to). */
MEPUBLIC const char *MEAPI MdtPlatformGetBestName(void);
/* Whether `name` is a backend and this CPU (and its operating system) can
 * run it; FALSE for NULL and unknown names. */
MEPUBLIC MeBool MEAPI MdtPlatformIsSupported(const char *name);
/* The backends, supported or not: MdtPlatformName(i) for 0 <= i <
 * MdtPlatformCount(), "reference" first, then in increasing order of
 * preference (the last supported one is the best). Out of range: NULL with
 * a warning. */
MEPUBLIC int MEAPI MdtPlatformCount(void);
MEPUBLIC const char *MEAPI MdtPlatformName(const int i);

ME_EXTERN_C_END

#endif
