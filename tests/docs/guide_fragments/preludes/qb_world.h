/* qb_world.h: QuadBike's InitialiseMEWorld() (main.c): the tutorial's
 * globals and the function's local `sizes`. */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD MstUniverseSizes sizes;
