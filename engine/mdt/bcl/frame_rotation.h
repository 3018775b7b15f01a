// frame_rotation.h: the relative rotation of a constraint's two attachment
// frames, exactly (not the small-angle frameRotationError of rows.h), for the
// types that hold or limit finite angles (Spring6, RPROJoint, Skeletal).
// Not installed.
//
// F_i is body i's attachment frame in the world as the rows of a MeMatrix3:
// (a_i, o_i, n_i = a_i x o_i). The relative rotation Rrel = F1 F0^T, i.e.
// Rrel[r][k] = f1_r . f0_k, carries frame 0's axes onto frame 1's and is
// written in frame 0's coordinates.
#pragma once

#include "constraint.h"

namespace karma::mdt {

// Rows a, o, n of body i's attachment frame in world coordinates.
void frameRows(const MdtConstraint *c, int i, MeMatrix3 F);
// The unit quaternion (w >= 0) of Rrel.
void relativeQuaternion(const MdtConstraint *c, MeVector4 q);
// The rotation vector (unit axis times angle in [0, pi]) of a unit
// quaternion q = (cos(t/2), sin(t/2) n): t n, in q's own coordinates.
void rotationVector(const MeVector4 q, MeVector3 out);
// Frame coordinates -> world: out = sum_k local[k] F[k].
void frameToWorld(MECONSTMATRIX MeMatrix3 F, const MeVector3 local, MeVector3 out);
// The relative angular velocity w1 - w0 (world; a missing body is at rest).
void relativeAngularVelocity(const MdtConstraint *c, MeVector3 out);

}  // namespace karma::mdt
