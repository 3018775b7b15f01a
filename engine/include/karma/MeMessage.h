/* MeMessage.h: Karma's four message channels and their redirectable handlers.
 *
 *   MeInfo        progress and facts worth telling the user (always delivered)
 *   MeWarning     something was wrong but Karma carried on with a defined result
 *   MeFatalError  Karma cannot continue; the program ends unless the handler
 *                 leaves by other means (see MeFatalError below)
 *   MeDebug       developer tracing, dropped unless MeSetDebugLevel asks for it
 *
 * Every function takes a `level` (an integer the handler receives unchanged;
 * for MeDebug it is also the verbosity filter) and a printf-style format.
 * The text is formatted into a fixed buffer of ME_MESSAGE_MAX_LENGTH bytes:
 * longer messages are cut short and end in "...", never overflow. A trailing
 * newline in the format is removed, so handlers always get one bare line.
 *
 * Handlers are plain function pointers. Each MeSet...Handler installs a new
 * one and returns the previous one (which is never NULL: the defaults are
 * returned as ordinary function pointers, so a handler can chain to them).
 * Installing NULL restores the default, which writes one line to stderr with
 * a prefix: "Karma info: ", "Karma warning: ", "Karma fatal error: ",
 * "Karma debug: ".
 *
 * Threads: emitting a message is safe from any thread (no shared buffer);
 * installing handlers should happen during set-up.
 *
 * The check-build validation macros (ME_CHECK_ARG, MEASSERT, ...) live in
 * MeAssert.h, which this header includes. */
#ifndef KARMA_MEMESSAGE_H
#define KARMA_MEMESSAGE_H

#include "MeCall.h"
#include "MePrecision.h"

/* Longest formatted message, in bytes including the terminating zero. */
#define ME_MESSAGE_MAX_LENGTH 1024

/* ME_PRINTF_FORMAT(f, a): lets GCC/Clang check a printf-style call whose
 * format is parameter f and whose variable arguments start at parameter a. */
#if defined(__GNUC__) || defined(__clang__)
#  define ME_PRINTF_FORMAT(f, a) __attribute__((format(printf, f, a)))
#  define ME_NORETURN __attribute__((noreturn))
#else
#  define ME_PRINTF_FORMAT(f, a)
#  define ME_NORETURN
#endif

ME_EXTERN_C_BEGIN

/* A message handler: `level` as passed by the caller, `message` the formatted
 * text (no trailing newline). The text lives only for the duration of the
 * call; copy it to keep it. */
typedef void(MEAPI *MeMessageHandler)(int level, const char *message);

/* Reports information. Always delivered to the info handler. */
MEPUBLIC void MEAPI MeInfo(int level, const char *format, ...) ME_PRINTF_FORMAT(2, 3);

/* Reports a recoverable problem. Always delivered to the warning handler. */
MEPUBLIC void MEAPI MeWarning(int level, const char *format, ...) ME_PRINTF_FORMAT(2, 3);

/* Reports an unrecoverable problem: calls the fatal-error handler and, if the
 * handler returns, ends the program with abort(). A C++ application that
 * wants to regain control can throw an exception from its handler; Karma's
 * library code lets it pass (only C frames compiled without unwind tables
 * would stop it). */
MEPUBLIC void MEAPI MeFatalError(int level, const char *format, ...) ME_PRINTF_FORMAT(2, 3) ME_NORETURN;

/* Developer tracing: delivered to the debug handler only when
 * level <= MeGetDebugLevel(). Levels below 1 count as 1, and the debug level
 * starts at 0, so by default every MeDebug is dropped (after one compare,
 * before any formatting). */
MEPUBLIC void MEAPI MeDebug(int level, const char *format, ...) ME_PRINTF_FORMAT(2, 3);

/* Sets the verbosity threshold for MeDebug (0 = off, the default; 1 = coarse
 * tracing; higher values let through ever finer detail). */
MEPUBLIC void MEAPI MeSetDebugLevel(int level);

/* The current MeDebug threshold. */
MEPUBLIC int MEAPI MeGetDebugLevel(void);

/* Install a handler for one channel; NULL restores the default. Each returns
 * the handler that was installed before (never NULL). */
MEPUBLIC MeMessageHandler MEAPI MeSetInfoHandler(MeMessageHandler handler);
MEPUBLIC MeMessageHandler MEAPI MeSetWarningHandler(MeMessageHandler handler);
MEPUBLIC MeMessageHandler MEAPI MeSetFatalErrorHandler(MeMessageHandler handler);
MEPUBLIC MeMessageHandler MEAPI MeSetDebugHandler(MeMessageHandler handler);

/* Emits the warning "<function>: <formatted text>" (level 0). This is what
 * the ME_CHECK_* / ME_REQUIRE_* macros of MeAssert.h call; it is public so
 * those macros work in every Karma library and in user code. */
MEPUBLIC void MEAPI MeArgumentWarning(const char *function, const char *format, ...) ME_PRINTF_FORMAT(2, 3);

ME_EXTERN_C_END

#include "MeAssert.h"

#endif /* KARMA_MEMESSAGE_H */
