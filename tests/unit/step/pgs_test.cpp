// Projected Gauss-Seidel in body space (engine/mdt/step/solver_pgs.cpp),
// the solver of MdtKeaMethodPGS.
#include <cmath>

#include "step_scene.h"

namespace {

using step_test::Contacts;
using step_test::kG;
using step_test::kH;
using step_test::Scene;

TEST(Pgs, ARestingBoxSharesItsWeightEquallyOverItsFourCorners) {
  // The four corner contacts are one block, solved together: each carries
  // a quarter of m g h, not the first corner of the sweep the most.
  Scene s;
  MdtWorldSetKeaMethod(s.u->world, MdtKeaMethodPGS);
  McdModelID b = s.box(1, 1, 1, 0, (MeReal)0.5, 0, 10);
  s.step(60);
  MdtContactID c[8];
  ASSERT_EQ(Contacts(b, c, 8), 4);
  const MeReal quarter = 10 * kG * kH / 4;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(MdtContactGetImpulse(c[k], nullptr), quarter, 1e-3 * quarter);
}

TEST(Pgs, AgreesWithTheExactSolverOnAResolvedContact) {
  // A ball resting on the ground: one contact, no coupling; both methods
  // give the same impulse and the same rest height.
  MeReal height[2], impulse[2];
  for (int method = 0; method < 2; ++method) {
    Scene s;
    MdtWorldSetKeaMethod(s.u->world, method ? MdtKeaMethodPGS : MdtKeaMethodActiveSet);
    McdModelID ball = s.ball((MeReal)0.25, 0, (MeReal)0.25, 0);
    s.step(120);
    MeVector3 p;
    Scene::position(ball, p);
    height[method] = p[1];
    MdtContactID c[2];
    ASSERT_EQ(Contacts(ball, c, 2), 1);
    impulse[method] = MdtContactGetImpulse(c[0], nullptr);
  }
  EXPECT_NEAR(height[1], height[0], 1e-5);
  EXPECT_NEAR(impulse[1], impulse[0], 1e-4 * impulse[0]);
}

TEST(Pgs, TheSweepCountCapsTheWorkAndIsReported) {
  Scene s;
  MdtWorldSetKeaMethod(s.u->world, MdtKeaMethodPGS);
  MdtWorldSetKeaMaxIterations(s.u->world, 3);
  for (int i = 0; i < 4; ++i) s.box(1, 1, 1, 0, (MeReal)0.5 + i, 0);  // a touching tower
  s.step(1);
  MdtWorldStepStats st;
  MdtWorldGetStepStats(s.u->world, &st);
  EXPECT_EQ(st.partitions, 1);
  EXPECT_LE(st.keaIterations, 3);
  EXPECT_GE(st.keaIterations, 1);
}

}  // namespace
