// The validation macros with the checks forced off in this translation unit.
#define ME_CHECK_ENABLED 0
#define PROBE_NAME forcedOffProbe
#define PROBE_MODE "forced off"
#include "check_macros_probe_impl.h"
