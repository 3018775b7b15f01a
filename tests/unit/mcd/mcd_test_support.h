// mcd_test_support.h: warning capture, a framework fixture and small
// helpers for the Mcd tests.
#pragma once

#include "support/warning_capture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "Mcd.h"

namespace mcd_test {

using karma_test::WarningCapture;  // warnings recorded while alive

// A framework with every built-in type and interaction, terminated at the
// end of the test.
struct Framework {
  McdFrameworkID id;
  explicit Framework(int models = 32, int instances = 64, MeReal scale = 1, bool primitives = true)
      : id(McdInit(0, models, instances, scale)) {
    if (primitives) {
      McdPrimitivesRegisterTypes(id);
      McdPrimitivesRegisterInteractions(id);
    }
  }
  ~Framework() { McdTerm(id); }
  Framework(const Framework &) = delete;
  Framework &operator=(const Framework &) = delete;
  operator McdFrameworkID() const { return id; }
};

// Relative tolerance: `ulps` MeReal epsilons times max(1, scale).
inline double tol(double scale, double ulps = 64) { return ulps * (double)ME_REAL_EPSILON * (scale < 1 ? 1 : scale); }

// A heap TM (the API keeps pointers) at position p, rotated by R (or identity).
struct TM {
  MeMatrix4 m;
  TM(MeReal x = 0, MeReal y = 0, MeReal z = 0) {
    MeMatrix4TMMakeIdentity(m);
    MeMatrix4TMSetPosition(m, x, y, z);
  }
  void rotate(const MeVector3 axis, MeReal angle) {
    MeMatrix3 R;
    MeVector3 a = {axis[0], axis[1], axis[2]};
    MeVector3Normalize(a);
    MeMatrix3FromAxisAngle(R, a, angle);
    MeMatrix4TMSetRotation(m, R);
  }
  operator MeMatrix4Ptr() { return m; }
};

inline void expectMatrixNear(MECONSTMATRIX MeMatrix3 a, const double (&b)[3][3], double eps) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR((double)a[i][j], b[i][j], eps) << "entry " << i << j;
}

inline void expectDiagonal(MECONSTMATRIX MeMatrix3 a, double xx, double yy, double zz, double eps) {
  const double d[3][3] = {{xx, 0, 0}, {0, yy, 0}, {0, 0, zz}};
  expectMatrixNear(a, d, eps);
}

}  // namespace mcd_test
