/* Mdt.h: Karma Dynamics -- the world, bodies, constraints and contacts.
 * Includes MeGlobals so programs written against the guide need only this. */
#ifndef KARMA_MDT_H
#define KARMA_MDT_H
#include "MeGlobals.h"
#include "MdtWorld.h"
#include "MdtPlatform.h"
#include "MdtBody.h"
#include "MdtConstraint.h"
#include "MdtLimit.h"
#include "MdtBSJoint.h"
#include "MdtHinge.h"
#include "MdtPrismatic.h"
#include "MdtUniversal.h"
#include "MdtAngular3.h"
#include "MdtConeLimit.h"
#include "MdtLinear1.h"
#include "MdtLinear2.h"
#include "MdtFixedPath.h"
#include "MdtCarWheel.h"
#include "MdtSpring.h"
#include "MdtSkeletal.h"
#include "MdtSpring6.h"
#include "MdtRPROJoint.h"
#include "MdtContact.h"
#endif
