/* qb_terrain.h: QuadBike's InitialiseTerrain() (terrain.c). The guide's
 * section defines TRI_LIST_SIZE and then uses TRILIST_SIZE (README: both
 * are 50). */
#include "quadbike.h"
#define TRILIST_SIZE 50
