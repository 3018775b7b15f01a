/* dynamics.h: the names the dynamics chapters' fragments use without
 * declaring them (a world, bodies, joints). The guide is not consistent
 * with its names (world and world_, doorBody and doorBody_): both are
 * declared. */
#include "guide.h"
#define NO_BOXES 21
MdtWorldID world, world_, _world;
MdtBodyID doorBody, doorBody_, _body, boxOne, boxTwo;
MdtHingeID hinge;
MdtUniversalID _univJoint;
MdtConeLimitID _coneLimit;
MdtSpringID spring;
MeVector3 doorPosition;
MeReal r = 2, step = (MeReal)0.01;
MdtContactParamsID box_ground, box_box;
