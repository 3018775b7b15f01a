// joints_a_support.h: small helpers for the Prismatic, Universal, Angular3,
// ConeLimit, Linear and FixedPath tests.
#pragma once

#include <cmath>

#include "mdt_test_support.h"

namespace mdt_test {

constexpr double kG = 9.81;

// A unit-mass body at (x, y, z), enabled (default inertia 0.4 I).
inline MdtBodyID makeBody(MdtWorldID w, MeReal x, MeReal y, MeReal z) {
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, x, y, z);
  MdtBodyEnable(b);
  return b;
}

// Rotation angle of a body's orientation away from the identity (rad).
inline double rotationAngle(MdtBodyID b) {
  MeVector4 q;
  MdtBodyGetQuaternion(b, q);
  const double v = std::sqrt((double)q[1] * q[1] + (double)q[2] * q[2] + (double)q[3] * q[3]);
  return 2 * std::atan2(v, std::fabs((double)q[0]));
}

// Angle of the relative rotation between two bodies' orientations (rad).
inline double relativeAngle(MdtBodyID a, MdtBodyID b) {
  MeVector4 p, q;
  MdtBodyGetQuaternion(a, p);
  MdtBodyGetQuaternion(b, q);
  const double dot = std::fabs((double)p[0] * q[0] + (double)p[1] * q[1] + (double)p[2] * q[2] + (double)p[3] * q[3]);
  return 2 * std::acos(dot > 1 ? 1 : dot);
}

// A body-frame direction in world coordinates.
inline void bodyDirection(MdtBodyID b, MeReal x, MeReal y, MeReal z, MeVector3 out) {
  MeMatrix4 tm;
  MdtBodyGetTransform(b, tm);
  const MeVector3 d = {x, y, z};
  MeMatrix4TMRotate(out, tm, d);
}

inline double angleBetween(const MeVector3 a, const MeVector3 b) {
  MeVector3 x;
  MeVector3Cross(x, a, b);
  return std::atan2((double)MeVector3Magnitude(x), (double)MeVector3Dot(a, b));
}

}  // namespace mdt_test
