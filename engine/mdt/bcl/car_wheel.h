// car_wheel.h: the car wheel's private layout and geometry, shared by
// car_wheel.cpp (rows) and car_wheel_api.cpp (accessors). Not installed.
//
// Frames. Body 0 (chassis) frame a0, o0, n0 = a0 x o0; body 1 (wheel)
// frame a1, o1, n1 = a1 x o1 (attachment axes, world). Then
//   s  = n0   steering axis, fixed in the chassis
//   o0        the chassis's steering reference (the hinge axis at set-up)
//   h  = o1   hinge axis, fixed in the wheel
//   n1        the wheel's spin reference (the steering axis at set-up)
// so the guide's defaults (chassis z, wheel y) are the frames that
// MdtConstraintSetBodies gives (world x and y: n = z, o = y).
//   steering angle phi   = angle from o0 to h about s; d(phi)/dt = s . (w1 - w0)
//   hinge angle theta    = angle from s to n1 about h; d(theta)/dt = h . (w1 - w0)
//   height z             = s . (p1 - p0), p0 the joint point in the chassis,
//                          p1 the wheel's centre of mass;
//   dz/dt = s.(v1 - v0) - (s x r0).w0 ... written out in heightJacobian.
#pragma once

#include "MdtCarWheel.h"
#include "bcl_type.h"

struct MdtCarWheel : MdtConstraint {
  MdtLimit steer;       // steering motor only (no stops)
  MdtLimit hinge;       // hinge motor only
  MdtLimit suspension;  // the hard (or softened) stops on the height
  MeBool steeringLocked;
  MeReal kp, kd;         // suspension spring
  MeReal limitSoftness;  // row softness of the stops (0: the world's epsilon)
  MeReal reference;      // height the spring relaxes to
};

namespace karma::mdt {

struct WheelGeometry {
  MeVector3 s, h;        // steering and hinge axes (world, unit)
  Anchors a;             // p[0] joint point, p[1] wheel centre; r[0] = p1 - x0
  MeReal height;         // s . (p1 - p0)
  MeReal jHeight[4][3];  // row Jacobian whose J v is d(height)/dt
};

WheelGeometry wheelGeometry(const MdtCarWheel *j);
MeReal wheelSteeringAngle(const MdtCarWheel *j);  // (-pi, pi]
// The steering angle given the steering axis s (wheelGeometry's).
MeReal steeringAngleAbout(const MdtCarWheel *j, const MeVector3 s);
MeReal wheelHingeAngle(const MdtCarWheel *j);     // [0, 2 pi)
// Rate of an angle whose Jacobian is {0, -e, 0, e}: e . (w1 - w0).
MeReal wheelRelativeRate(const MdtCarWheel *j, const MeVector3 e);

extern const ConstraintType kCarWheelType;

}  // namespace karma::mdt
