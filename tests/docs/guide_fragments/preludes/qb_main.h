/* qb_main.h: QuadBike's main.c at function scope (tick). */
#include "quadbike.h"
