// mdt_test_support.h: warning capture and small helpers for the Mdt tests.
#pragma once

#include "support/warning_capture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "Mdt.h"

namespace mdt_test {

using karma_test::WarningCapture;  // warnings recorded while alive

// A world destroyed at the end of the test.
struct World {
  MdtWorldID id;
  explicit World(unsigned bodies = 8, MeReal l = 1, MeReal m = 1, unsigned constraints = 64)
      : id(MdtWorldCreate(bodies, constraints, l, m)) {}
  ~World() { MdtWorldDestroy(id); }
  World(const World &) = delete;
  World &operator=(const World &) = delete;
  operator MdtWorldID() const { return id; }
};

// Relative tolerance of a few MeReal ulps times `ulps`.
inline double tol(double scale, double ulps = 8) { return ulps * (double)ME_REAL_EPSILON * (scale < 1 ? 1 : scale); }

// Distance between a constraint's two attachment points (world frame).
inline double anchorGap(MdtConstraintID c) {
  MeVector3 p0, p1;
  MdtConstraintBodyGetPosition(c, 0, p0);
  MdtConstraintBodyGetPosition(c, 1, p1);
  return (double)MeVector3Distance(p0, p1);
}

// True if every component of the body's state is finite.
inline bool bodyFinite(MdtBodyID b) {
  MeVector3 x, v, w;
  MeVector4 q;
  MdtBodyGetPosition(b, x);
  MdtBodyGetLinearVelocity(b, v);
  MdtBodyGetAngularVelocity(b, w);
  MdtBodyGetQuaternion(b, q);
  return MeVector3AllFinite(x) && MeVector3AllFinite(v) && MeVector3AllFinite(w) && std::isfinite(q[0]) &&
         std::isfinite(q[1]) && std::isfinite(q[2]) && std::isfinite(q[3]);
}

}  // namespace mdt_test
