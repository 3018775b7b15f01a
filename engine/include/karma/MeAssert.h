/* MeAssert.h: argument validation and invariant checks for Karma API code.
 *
 * The check build (configured with KARMA_CHECK=ON, so MeConfig.h says
 * `#define KARMA_CHECK 1`) validates every API call and explains what was
 * wrong; the normal build compiles those checks away. Checks that protect
 * against crashes on any build (NULL handles, impossible sizes) use the
 * always-on ME_REQUIRE_* forms instead.
 *
 *   ME_CHECK_ARG(cond, fn, fmt, ...)           check build: if !cond, warn
 *                                              "fn: <fmt...>" and `return;`
 *   ME_CHECK_ARG_RET(cond, ret, fn, fmt, ...)  same, but `return ret;`
 *   ME_CHECK_WARN(cond, fn, fmt, ...)          check build: if !cond, warn
 *                                              and carry on
 *   MEASSERT(cond)                             check build: if !cond,
 *                                              MeFatalError with the
 *                                              expression, file and line
 *   ME_REQUIRE_ARG(cond, fn, fmt, ...)         every build: warn and return
 *   ME_REQUIRE_ARG_RET(cond, ret, fn, fmt, ...) every build: warn and return ret
 *
 * `fn` is the name of the API function being checked (a string; `__func__`
 * works). The format part is mandatory and printf-style. When checks are off
 * the condition is not evaluated (so it must have no side effects), but it
 * is still compiled inside sizeof, which keeps it type-checked and keeps
 * variables used only in checks from triggering unused warnings.
 *
 * Example:
 *
 *   void MEAPI MdtBodySetMass(MdtBodyID b, const MeReal mass)
 *   {
 *       ME_REQUIRE_ARG(b != NULL, "MdtBodySetMass", "body is NULL");
 *       ME_CHECK_ARG(mass > 0, "MdtBodySetMass",
 *                    "mass must be positive, got %g", (double)mass);
 *       MEASSERT(b->world != NULL);
 *       ...
 *   }
 *
 * Each macro is a single statement (safe after `if` without braces) and must
 * be used with a trailing semicolon.
 *
 * ME_CHECK_ENABLED selects the mode. It defaults to KARMA_CHECK; a
 * translation unit may define it to 0 or 1 before including any Karma header
 * to force the checks of its own code off or on (the unit tests do this to
 * exercise both modes in one build). */
#ifndef KARMA_MEASSERT_H
#define KARMA_MEASSERT_H

#include "MeConfig.h"
#include "MeMessage.h"

#ifndef ME_CHECK_ENABLED
#  define ME_CHECK_ENABLED KARMA_CHECK
#endif

/* Always-on forms. */
#define ME_REQUIRE_ARG(cond, fn, ...)       \
  do {                                      \
    if (!(cond)) {                          \
      MeArgumentWarning((fn), __VA_ARGS__); \
      return;                               \
    }                                       \
  } while (0)

#define ME_REQUIRE_ARG_RET(cond, ret, fn, ...) \
  do {                                         \
    if (!(cond)) {                             \
      MeArgumentWarning((fn), __VA_ARGS__);    \
      return (ret);                            \
    }                                          \
  } while (0)

/* Not-evaluated reference to a condition (see the header comment). */
#define ME_CHECK_UNEVALUATED_(cond) ((void)sizeof(!(cond)))

#if ME_CHECK_ENABLED

#  define ME_CHECK_ARG(cond, fn, ...) ME_REQUIRE_ARG(cond, fn, __VA_ARGS__)
#  define ME_CHECK_ARG_RET(cond, ret, fn, ...) ME_REQUIRE_ARG_RET(cond, ret, fn, __VA_ARGS__)
#  define ME_CHECK_WARN(cond, fn, ...)                   \
    do {                                                 \
      if (!(cond)) MeArgumentWarning((fn), __VA_ARGS__); \
    } while (0)
#  define MEASSERT(cond)                                                                       \
    do {                                                                                       \
      if (!(cond)) MeFatalError(0, "assertion failed: %s (%s:%d)", #cond, __FILE__, __LINE__); \
    } while (0)

#else

#  define ME_CHECK_ARG(cond, fn, ...) ME_CHECK_UNEVALUATED_(cond)
#  define ME_CHECK_ARG_RET(cond, ret, fn, ...) ME_CHECK_UNEVALUATED_(cond)
#  define ME_CHECK_WARN(cond, fn, ...) ME_CHECK_UNEVALUATED_(cond)
#  define MEASSERT(cond) ME_CHECK_UNEVALUATED_(cond)

#endif

#endif /* KARMA_MEASSERT_H */
