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

namespace {

// A 1 kg body hanging 0.5 m below the world by two ball joints at the same
// point (redundant rows), with the given epsilon and solver, after 2 s:
// the largest joint gap and the largest force either joint reported.
struct Redundant {
  MeReal gap = 0, force = 0;
  bool finite = true;
};

Redundant RedundantBallJoints(MeReal epsilon, MdtKeaMethod method) {
  Scene s(false);
  MdtWorldSetEpsilon(s.u->world, epsilon);
  MdtWorldSetKeaMethod(s.u->world, method);
  MdtBodyID b = MdtBodyCreate(s.u->world);
  MdtBodySetPosition(b, (MeReal)0.3, (MeReal)-0.4, 0);  // 0.5 m from the pivot, swinging
  MdtBodyEnable(b);
  MdtConstraintID joints[2];
  for (MdtConstraintID &j : joints) {
    MdtBSJointID bs = MdtBSJointCreate(s.u->world);
    MdtBSJointSetBodies(bs, b, nullptr);
    MdtBSJointSetPosition(bs, 0, 0, 0);
    MdtBSJointEnable(bs);
    j = MdtBSJointQuaConstraint(bs);
  }
  Redundant r;
  for (int i = 0; i < 120; ++i) {
    s.step();
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    r.finite = r.finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
    r.gap = std::fmax(r.gap, std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - (MeReal)0.5));
    for (MdtConstraintID j : joints) {
      MeVector3 f;
      MdtConstraintGetForce(j, 0, f);
      r.force = std::fmax(r.force, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
    }
  }
  return r;
}

}  // namespace

TEST(Pgs, RedundantRigidJointsStayFiniteAndHold) {
  // With epsilon 0 the two joints' rows are the same rows twice: K of the
  // joint block is singular, and its factorisation must be refused (the rows
  // then update one by one) rather than give impulses that cancel in huge
  // pairs. The pendulum's tension is about m g + m v^2 / r, under 30 N.
  for (MeReal epsilon : {(MeReal)0, (MeReal)0.01}) {
    const Redundant pgs = RedundantBallJoints(epsilon, MdtKeaMethodPGS);
    const Redundant exact = RedundantBallJoints(epsilon, MdtKeaMethodActiveSet);
    std::printf("epsilon %g: PGS gap %.3g m, force %.3g N; exact gap %.3g m, force %.3g N\n", (double)epsilon,
                (double)pgs.gap, (double)pgs.force, (double)exact.gap, (double)exact.force);
    EXPECT_TRUE(pgs.finite);
    EXPECT_LT(pgs.gap, 0.02) << "epsilon " << epsilon;
    EXPECT_LT(pgs.force, 100) << "epsilon " << epsilon;
  }
}

namespace {

// Pushes a 100 kg cube on the ground sideways with force F = push * m g
// for one second, with normal-force friction mu = 0.5 in both directions
// (each friction row within +-mu times its normal impulse: a box cone);
// returns the distance it moved along x.
MeReal Pushed(MdtKeaMethod method, MeReal push) {
  Scene s;
  MdtWorldSetKeaMethod(s.u->world, method);
  MdtWorldSetEpsilon(s.u->world, (MeReal)1e-5);  // the default's give lets a held cube creep 13 mm/s
  MstBridgeID bridge = s.u->bridge;
  const MstMaterialID mat = MstBridgeGetNewMaterial(bridge);
  McdModelSetMaterial(s.ground, mat);
  MdtContactParamsID cp = MstBridgeGetContactParams(bridge, mat, mat);
  MdtContactParamsSetType(cp, MdtContactTypeFriction2D);
  MdtContactParamsSetPrimaryFrictionModel(cp, MdtFrictionModelNormalForce);
  MdtContactParamsSetSecondaryFrictionModel(cp, MdtFrictionModelNormalForce);
  MdtContactParamsSetFrictionCoefficient(cp, (MeReal)0.5);
  McdModelID b = s.box(1, 1, 1, 0, (MeReal)0.5, 0, 100);
  McdModelSetMaterial(b, mat);
  s.step(30);  // settle
  MeVector3 p0, p1;
  Scene::position(b, p0);
  for (int i = 0; i < 60; ++i) {
    MdtBodyAddForce(McdModelGetBody(b), push * 100 * kG, 0, 0);
    s.step();
  }
  Scene::position(b, p1);
  return p1[0] - p0[0];
}

}  // namespace

TEST(Pgs, FrictionHoldsBelowItsBoundAndSlidesAboveIt) {
  // A contact's two friction rows are updated together while their step
  // stays inside both boxes (static friction) and row by row when a box
  // binds (sliding): both branches, against the exact solver and the
  // closed form. Below mu m g the cube stays. Above it the friction force
  // lies between mu m g (a tangent along the push) and sqrt(2) mu m g (the
  // box cone's corner); from rest, 60 steps of constant acceleration a
  // move the cube a h^2 (1 + ... + 60) = a (61 / 120) s^2.
  const MeReal held = Pushed(MdtKeaMethodPGS, (MeReal)0.3);
  const MeReal slid = Pushed(MdtKeaMethodPGS, (MeReal)0.9);
  const MeReal heldExact = Pushed(MdtKeaMethodActiveSet, (MeReal)0.3);
  const MeReal slidExact = Pushed(MdtKeaMethodActiveSet, (MeReal)0.9);
  std::printf("held %.3g m (exact %.3g), slid %.5f m (exact %.5f)\n", (double)held, (double)heldExact,
              (double)slid, (double)slidExact);
  EXPECT_LT(std::fabs(held), 1e-4);
  EXPECT_LT(std::fabs(held - heldExact), 1e-4);
  const double most = (0.9 - 0.5) * kG * 61 / 120, least = (0.9 - std::sqrt(2.0) * 0.5) * kG * 61 / 120;
  EXPECT_GT(slid, least * 0.999);
  EXPECT_LT(slid, most * 1.001);
  EXPECT_NEAR(slid, slidExact, 1e-3 * slid);
}
