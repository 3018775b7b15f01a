// joints_b_support.h: helpers for the CarWheel, Spring, Spring6, RPRO and
// Skeletal tests.
#pragma once

#include "joints_a_support.h"

namespace mdt_test {

// Holds a body fixed to the world (position and orientation).
inline void pinToWorld(MdtWorldID w, MdtBodyID b) {
  MdtBSJointID bs = MdtBSJointCreate(w);
  MdtBSJointSetBodies(bs, b, nullptr);
  MdtBSJointEnable(bs);
  MdtAngular3ID a = MdtAngular3Create(w);
  MdtAngular3SetBodies(a, b, nullptr);
  MdtAngular3Enable(a);
}

inline void setDiagonalInertia(MdtBodyID b, MeReal x, MeReal y, MeReal z) {
  const MeMatrix3 I = {{x, 0, 0}, {0, y, 0}, {0, 0, z}};
  MdtBodySetInertiaTensor(b, I);
}

// A body-frame direction of `b` written in another body's frame.
inline void directionIn(MdtBodyID b, MdtBodyID frame, MeReal x, MeReal y, MeReal z, MeVector3 out) {
  MeVector3 world;
  bodyDirection(b, x, y, z, world);
  MeMatrix4 tm;
  MdtBodyGetTransform(frame, tm);
  MeMatrix4TMInverseRotate(out, tm, world);
}

}  // namespace mdt_test
