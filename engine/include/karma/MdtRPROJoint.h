/* MdtRPROJoint.h: the relative-position-relative-orientation joint. It
 * holds all six degrees of freedom between two attachment frames, driving
 * their relative orientation to a target quaternion and relative angular
 * velocity (an animation or user input, supplied every step), each axis
 * with a strength: the most force (torque) it may use. Below its strength
 * it holds; above it, it saturates and gives way ("breaks") until the load
 * drops again.
 *
 * Attachment frames: a point and orientation per body, in that body's frame
 * (MdtRPROJointSetAttachmentPosition / Quaternion; for the world, in world
 * coordinates). Frames F0, F1 (world).
 *   relative quaternion q: F1 = F0 turned by q, q written in F0's axes;
 *   relative angular velocity W: w1 - w0 = W written in F0's axes;
 *   position: the attachment points coincide (relative position zero:
 *   animated relative positions are not supported, as in the guide).
 * Strengths act along and about F0's axes; MEINFINITY (the default) is
 * unbreakable.
 *
 * Defaults (Reset): q = identity, W = 0, strengths MEINFINITY; the
 * attachment frames are the bodies' own axes at their centres of mass; when
 * body 1 is the world, its frame is where body 0's is when the bodies are set
 * (so the body is held where it is rather than pulled to the world origin). */
#ifndef KARMA_MDTRPROJOINT_H
#define KARMA_MDTRPROJOINT_H
#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN
MDT_CONSTRAINT_TYPE_DECL(RPROJoint, MdtRPROJointID)
MDT_CONSTRAINT_COMMON_API(RPROJoint, MdtRPROJointID)

/* The attachment point of body `bodyindex`, world coordinates. */
MEPUBLIC void MEAPI MdtRPROJointGetPosition(const MdtRPROJointID joint, const unsigned int bodyindex,
                                            MeVector3 position);
/* Unit quaternions (w, x, y, z); they are normalised, zero or non-finite is
 * rejected. */
MEPUBLIC void MEAPI MdtRPROJointSetRelativeQuaternion(const MdtRPROJointID joint, const MeVector4 quaternion);
MEPUBLIC void MEAPI MdtRPROJointGetRelativeQuaternion(const MdtRPROJointID joint, MeVector4 quaternion);
MEPUBLIC void MEAPI MdtRPROJointSetRelativeAngularVelocity(MdtRPROJointID joint, MeVector3 velocity);
MEPUBLIC void MEAPI MdtRPROJointGetRelativeAngularVelocity(const MdtRPROJointID joint, MeVector3 velocity);
/* Attachment frame of body `bodyindex`, in that body's frame. */
MEPUBLIC void MEAPI MdtRPROJointSetAttachmentPosition(const MdtRPROJointID joint, const MeReal x, const MeReal y,
                                                      const MeReal z, const unsigned int bodyindex);
MEPUBLIC void MEAPI MdtRPROJointGetAttachmentPosition(const MdtRPROJointID joint, const unsigned int bodyindex,
                                                      MeVector3 position);
MEPUBLIC void MEAPI MdtRPROJointSetAttachmentQuaternion(const MdtRPROJointID joint, const MeReal q0, const MeReal q1,
                                                        const MeReal q2, const MeReal q3, const unsigned int bodyindex);
MEPUBLIC void MEAPI MdtRPROJointGetAttachmentOrientation(const MdtRPROJointID joint, const unsigned int bodyindex,
                                                         MeVector4 quaternion);
/* Most torque (force) per axis of F0; > 0, MEINFINITY for unbreakable. */
MEPUBLIC void MEAPI MdtRPROJointSetAngularStrength(const MdtRPROJointID joint, const MeReal sX, const MeReal sY,
                                                   const MeReal sZ);
MEPUBLIC void MEAPI MdtRPROJointSetLinearStrength(const MdtRPROJointID joint, const MeReal sX, const MeReal sY,
                                                  const MeReal sZ);
MEPUBLIC void MEAPI MdtRPROJointGetAngularStrength(const MdtRPROJointID joint, MeVector3 s);
MEPUBLIC void MEAPI MdtRPROJointGetLinearStrength(const MdtRPROJointID joint, MeVector3 s);
ME_EXTERN_C_END

#endif
