/* Mdt.h: Karma Dynamics (world, bodies, constraints, contacts).
 * The API arrives with the dynamics issue; today this header only pulls in
 * MeGlobals so that programs written against the guide find it. */
#ifndef KARMA_MDT_H
#define KARMA_MDT_H
#include "MeGlobals.h"
#endif
