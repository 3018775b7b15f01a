/* Mdt.h: Karma Dynamics (world, bodies; constraints and contacts to come).
 * Includes MeGlobals so programs written against the guide need only this. */
#ifndef KARMA_MDT_H
#define KARMA_MDT_H
#include "MeGlobals.h"
#include "MdtWorld.h"
#include "MdtBody.h"
#endif
