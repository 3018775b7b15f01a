/* Mcd.h: Karma Collision (framework, geometries, spaces, queries).
 * The API arrives with the collision issue. */
#ifndef KARMA_MCD_H
#define KARMA_MCD_H
#include "MeGlobals.h"
#endif
