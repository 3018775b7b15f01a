/* universe_step.h: the step of a universe `u` (the guide's MstUniverseStep). */
#include "guide.h"
MstUniverseID u;
MeReal stepSize = (MeReal)0.01;
