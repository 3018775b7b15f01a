/* materials.h: the materials fragment sets the materials of a ball and a
 * floor model it does not declare; as locals (a global `floor` would clash
 * with the C library's). */
#include "guide.h"
MstUniverseID universe;
#define GUIDE_FRAGMENT_LEAD McdModelID ball = 0, floor = 0;
