// check_macros_probe.h: functions that use each validation macro of
// MeAssert.h, compiled three times: with the configured mode and with the
// checks forced on and off (check_macros_probe_impl.h holds the bodies).
#ifndef KARMA_TESTS_CHECK_MACROS_PROBE_H
#define KARMA_TESTS_CHECK_MACROS_PROBE_H

struct CheckProbe {
  const char *mode;  // "configured", "forced on", "forced off"
  bool checksOn;     // what ME_CHECK_ENABLED was in that translation unit
  int *evaluations;  // how often a checked condition was evaluated
  // Sets *reached to 1 if it gets past ME_CHECK_ARG(x > 0, ...).
  void (*checkArg)(int x, int *reached);
  // ME_CHECK_ARG_RET(x > 0, -1, ...); then returns 2 * x.
  int (*checkArgRet)(int x);
  // ME_CHECK_WARN(x < 10, ...); then returns x.
  int (*checkWarn)(int x);
  // MEASSERT(x > 0).
  void (*assertPositive)(int x);
  // ME_REQUIRE_ARG(x != 0, ...); sets *reached.
  void (*requireArg)(int x, int *reached);
  // ME_REQUIRE_ARG_RET(x != 0, -1, ...); returns x.
  int (*requireArgRet)(int x);
};

extern const CheckProbe configuredProbe;
extern const CheckProbe forcedOnProbe;
extern const CheckProbe forcedOffProbe;

#endif
