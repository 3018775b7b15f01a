// hard_support.h: helpers shared by the hard-cases suite (issue 15).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "Mdt.h"
#include "mdt/mdt_test_support.h"

namespace hard {

constexpr double kG = 9.81;

// Every solver the engine offers, for parameterised cases.
inline const MdtKeaMethod kSolvers[] = {MdtKeaMethodActiveSet, MdtKeaMethodPGS};

inline const char *solverName(MdtKeaMethod m) { return m == MdtKeaMethodPGS ? "PGS" : "ActiveSet"; }

// A world destroyed at the end of the test.
struct World {
  MdtWorldID id;
  explicit World(unsigned bodies = 16, unsigned constraints = 64, MeReal l = 1, MeReal m = 1)
      : id(MdtWorldCreate(bodies, constraints, l, m)) {}
  ~World() { MdtWorldDestroy(id); }
  World(const World &) = delete;
  World &operator=(const World &) = delete;
  operator MdtWorldID() const { return id; }
};

// Body-frame vector -> world, world -> body-frame (rows of R are the body axes).
inline void toWorld(MdtBodyID b, const double in[3], double out[3]) {
  MeMatrix4 tm;
  MdtBodyGetTransform(b, tm);
  for (int j = 0; j < 3; ++j) out[j] = in[0] * tm[0][j] + in[1] * tm[1][j] + in[2] * tm[2][j];
}
inline void toBody(MdtBodyID b, const double in[3], double out[3]) {
  MeMatrix4 tm;
  MdtBodyGetTransform(b, tm);
  for (int i = 0; i < 3; ++i) out[i] = in[0] * tm[i][0] + in[1] * tm[i][1] + in[2] * tm[i][2];
}

// World angular momentum about the centre of mass, R^T Ib R w, for a body
// with a diagonal body-frame inertia `I`.
inline void angularMomentum(MdtBodyID b, const double I[3], double L[3]) {
  MeVector3 w;
  MdtBodyGetAngularVelocity(b, w);
  const double ww[3] = {w[0], w[1], w[2]};
  double wb[3];
  toBody(b, ww, wb);
  const double Lb[3] = {I[0] * wb[0], I[1] * wb[1], I[2] * wb[2]};
  toWorld(b, Lb, L);
}

inline double rotationalEnergy(MdtBodyID b, const double I[3]) {
  MeVector3 w;
  MdtBodyGetAngularVelocity(b, w);
  const double ww[3] = {w[0], w[1], w[2]};
  double wb[3];
  toBody(b, ww, wb);
  return 0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
}

inline double norm(const double v[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// True if every component of the body's state is finite.
using mdt_test::bodyFinite;

inline void setDiagonalInertia(MdtBodyID b, double a, double c, double d) {
  const MeMatrix3 I = {{(MeReal)a, 0, 0}, {0, (MeReal)c, 0}, {0, 0, (MeReal)d}};
  MdtBodySetInertiaTensor(b, I);
}

}  // namespace hard
