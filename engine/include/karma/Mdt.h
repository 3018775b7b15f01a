/* Mdt.h: Karma Dynamics -- the world, bodies, constraints and contacts.
 * Includes MeGlobals so programs written against the guide need only this. */
#ifndef KARMA_MDT_H
#define KARMA_MDT_H
#include "MeGlobals.h"
#include "MdtWorld.h"
#include "MdtBody.h"
#include "MdtConstraint.h"
#include "MdtLimit.h"
#include "MdtBSJoint.h"
#include "MdtHinge.h"
#include "MdtContact.h"
#endif
