// check_macros_probe_impl.h: the probe bodies. Include once per translation
// unit, after choosing ME_CHECK_ENABLED (or leaving it to MeConfig.h), with
// PROBE_NAME set to the CheckProbe object to define.
#include "MeAssert.h"
#include "check_macros_probe.h"

namespace {

int evaluations = 0;

bool counted(bool condition) {
  ++evaluations;
  return condition;
}

void checkArg(int x, int *reached) {
  ME_CHECK_ARG(counted(x > 0), "checkArg", "x must be positive, got %d", x);
  *reached = 1;
}

int checkArgRet(int x) {
  ME_CHECK_ARG_RET(counted(x > 0), -1, "checkArgRet", "x must be positive, got %d", x);
  return 2 * x;
}

int checkWarn(int x) {
  if (x != 0)
    ME_CHECK_WARN(counted(x < 10), "checkWarn", "x=%d is large", x);
  else
    ME_CHECK_WARN(counted(true), "checkWarn", "unreachable");
  return x;
}

void assertPositive(int x) { MEASSERT(counted(x > 0)); }

void requireArg(int x, int *reached) {
  ME_REQUIRE_ARG(x != 0, "requireArg", "x is zero");
  *reached = 1;
}

int requireArgRet(int x) {
  ME_REQUIRE_ARG_RET(x != 0, -1, "requireArgRet", "x is zero");
  return x;
}

}  // namespace

const CheckProbe PROBE_NAME = {PROBE_MODE, ME_CHECK_ENABLED != 0, &evaluations, &checkArg,     &checkArgRet,
                               &checkWarn, &assertPositive,       &requireArg,  &requireArgRet};
