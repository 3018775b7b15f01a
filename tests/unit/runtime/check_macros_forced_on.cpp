// The validation macros with the checks forced on in this translation unit.
#define ME_CHECK_ENABLED 1
#define PROBE_NAME forcedOnProbe
#define PROBE_MODE "forced on"
#include "check_macros_probe_impl.h"
