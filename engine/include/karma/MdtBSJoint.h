/* MdtBSJoint.h: the ball-and-socket joint. A point fixed in each body is
 * kept at the same place in the world: three linear degrees of freedom are
 * removed, all rotations about the common point stay free.
 * Reset: the joint point at body 0's origin in both bodies. */
#ifndef KARMA_MDTBSJOINT_H
#define KARMA_MDTBSJOINT_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(BSJoint, MdtBSJointID)
MDT_CONSTRAINT_COMMON_API(BSJoint, MdtBSJointID)
MDT_CONSTRAINT_POSITION_API(BSJoint, MdtBSJointID)
ME_EXTERN_C_END

#endif
