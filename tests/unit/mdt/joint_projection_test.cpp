// The point joints' projection after the step (MdtWorldSetJointProjection,
// engine/mdt/step/project_joints.cpp): off by default, it moves positions
// only, and it holds a whipping chain at 1/60 s where the velocity step
// alone lets it open by centimetres.
#include <cmath>
#include <cstring>
#include <vector>

#include "mdt_test_support.h"

using namespace mdt_test;

namespace {

constexpr int kLinks = 6;
constexpr int kLongChain = 70;
constexpr MeReal kLink = (MeReal)0.5;  // m between neighbouring centres
constexpr MeReal kMass = 1, kInertia = (MeReal)0.01;
constexpr MeReal kStep = (MeReal)1 / 60;

// A chain of `links` bodies along +x from a world pivot at the origin, each
// joined to the one before at the midpoint between them, turning as one
// about the pivot's z axis at `spin` rad/s (the velocities of a rigid turn).
struct Chain {
  World world;
  std::vector<MdtBodyID> link;
  std::vector<MdtBSJointID> joint;

  Chain(MeReal spin, int sweeps, int links = kLinks)
      : world((unsigned)links + 2, 1, 1, (unsigned)links + 2), link((size_t)links), joint((size_t)links) {
    MdtWorldSetGravity(world, 0, -(MeReal)9.81, 0);
    MdtWorldSetJointProjection(world, sweeps);
    const MeReal I[3][3] = {{kInertia, 0, 0}, {0, kInertia, 0}, {0, 0, kInertia}};
    for (int i = 0; i < links; ++i) {
      link[i] = MdtBodyCreate(world);
      MdtBodySetMass(link[i], kMass);
      MdtBodySetInertiaTensor(link[i], I);
      const MeReal x = kLink * (MeReal)(i + 1);
      MdtBodySetPosition(link[i], x, 0, 0);
      MdtBodySetLinearVelocity(link[i], 0, spin * x, 0);
      MdtBodySetAngularVelocity(link[i], 0, 0, spin);
      MdtBodyEnable(link[i]);
      joint[i] = MdtBSJointCreate(world);
      MdtBSJointSetBodies(joint[i], link[i], i == 0 ? nullptr : link[i - 1]);
      MdtBSJointSetPosition(joint[i], x - kLink / 2 - (i == 0 ? kLink / 2 : 0), 0, 0);
      MdtBSJointEnable(joint[i]);
    }
  }

  double worstGap() const {
    double worst = 0;
    for (MdtBSJointID j : joint) worst = std::fmax(worst, anchorGap(MdtBSJointQuaConstraint(j)));
    return worst;
  }

  // Kinetic plus potential energy (J).
  double energy() const {
    double e = 0;
    for (MdtBodyID b : link) {
      MeVector3 x, v, w;
      MdtBodyGetPosition(b, x);
      MdtBodyGetLinearVelocity(b, v);
      MdtBodyGetAngularVelocity(b, w);
      e += 0.5 * (double)kMass * (double)MeVector3MagnitudeSqr(v) +
           0.5 * (double)kInertia * (double)MeVector3MagnitudeSqr(w) + (double)kMass * 9.81 * (double)x[1];
    }
    return e;
  }
};

bool sameBits(const MeVector3 a, const MeVector3 b) { return std::memcmp(a, b, sizeof(MeVector3)) == 0; }

}  // namespace

TEST(JointProjection, OffByDefaultAndRefusesANegativeCount) {
  World w;
  EXPECT_EQ(MdtWorldGetJointProjection(w), 0);
  MdtWorldSetJointProjection(w, 4);
  EXPECT_EQ(MdtWorldGetJointProjection(w), 4);
  WarningCapture cap;
  MdtWorldSetJointProjection(w, -1);
  EXPECT_EQ(cap.count(), 1u);
  EXPECT_EQ(MdtWorldGetJointProjection(w), 4);
}

TEST(JointProjection, MovesPositionsAndLeavesTheStepsVelocities) {
  // One step of a chain turning at 6 rad/s: the same velocities to the
  // bit with and without the projection, and far smaller gaps with it.
  Chain plain(6, 0), projected(6, 2);
  MdtWorldStep(plain.world, kStep);
  MdtWorldStep(projected.world, kStep);
  bool moved = false;
  for (int i = 0; i < kLinks; ++i) {
    MeVector3 v0, v1, w0, w1, x0, x1;
    MdtBodyGetLinearVelocity(plain.link[i], v0);
    MdtBodyGetLinearVelocity(projected.link[i], v1);
    MdtBodyGetAngularVelocity(plain.link[i], w0);
    MdtBodyGetAngularVelocity(projected.link[i], w1);
    EXPECT_TRUE(sameBits(v0, v1)) << "link " << i;
    EXPECT_TRUE(sameBits(w0, w1)) << "link " << i;
    MdtBodyGetPosition(plain.link[i], x0);
    MdtBodyGetPosition(projected.link[i], x1);
    moved = moved || !sameBits(x0, x1);
  }
  EXPECT_TRUE(moved);
  std::printf("one step at 6 rad/s: worst gap %.3f mm plain, %.4f mm projected\n", plain.worstGap() * 1e3,
              projected.worstGap() * 1e3);
  // The drift of a rigid turn: about h^2 w^2 d / 2 per joint (d the link),
  // 2.5 mm at the far end here.
  EXPECT_GT(plain.worstGap(), 1e-3);
  EXPECT_LT(projected.worstGap(), 1e-4 + 1e-6);
}

TEST(JointProjection, HoldsAChainFallingFromTheHorizontalAt60Hz) {
  // 3 s from horizontal and at rest: the chain whips down past the
  // vertical and back. The velocity step alone opens it by centimetres;
  // projected, every joint stays within a millimetre and no energy is
  // gained.
  Chain plain(0, 0), projected(0, 2);
  const double e0 = projected.energy();
  double plainWorst = 0, projectedWorst = 0, highest = e0;
  for (int s = 0; s < 180; ++s) {
    MdtWorldStep(plain.world, kStep);
    MdtWorldStep(projected.world, kStep);
    plainWorst = std::fmax(plainWorst, plain.worstGap());
    projectedWorst = std::fmax(projectedWorst, projected.worstGap());
    highest = std::fmax(highest, projected.energy());
  }
  std::printf(
      "falling chain, 3 s at 1/60 s: worst gap %.2f mm plain, %.3f mm projected; energy from %.3f J to %.3f J "
      "plain, %.3f J projected\n",
      plainWorst * 1e3, projectedWorst * 1e3, e0, plain.energy(), projected.energy());
  for (MdtBodyID b : projected.link) EXPECT_TRUE(bodyFinite(b));
  EXPECT_GT(plainWorst, 0.01);
  EXPECT_LT(projectedWorst, 0.001);
  EXPECT_LE(highest, e0 + 1e-3 * std::fabs(e0) + 1e-3);
}

TEST(JointProjection, ClosesAHingesAnchor) {
  // A body on a hinge to the world, knocked 2 cm off its anchor, at rest,
  // no gravity: one step closes the anchor to the slop (1e-4 m).
  World w(4, 1, 1, 8);
  MdtWorldSetGravity(w, 0, 0, 0);
  MdtWorldSetJointProjection(w, 4);
  MdtBodyID b = MdtBodyCreate(w);
  MdtBodySetPosition(b, 1, 0, 0);
  MdtBodyEnable(b);
  MdtHingeID hinge = MdtHingeCreate(w);
  MdtHingeSetBodies(hinge, b, nullptr);
  MdtHingeSetPosition(hinge, 0, 0, 0);
  MdtHingeSetAxis(hinge, 0, 0, 1);
  MdtHingeEnable(hinge);
  MdtBodySetPosition(b, 1, (MeReal)0.02, 0);
  EXPECT_NEAR(anchorGap(MdtHingeQuaConstraint(hinge)), 0.02, 1e-6);
  MdtWorldStep(w, kStep);
  EXPECT_LE(anchorGap(MdtHingeQuaConstraint(hinge)), 1e-4 + 1e-6);
}

TEST(JointProjection, ALongChainClosesToTheSlop) {
  // 70 light links in one partition, solved together in K's envelope: the
  // turning chain's gaps close to the slop (1e-4 m) in one iteration,
  // velocities kept. (Without the tension's geometric stiffness in the
  // metric, a step closed 15% of the gap.)
  Chain plain(2, 0, kLongChain), projected(2, 1, kLongChain);
  MdtWorldStep(plain.world, kStep);
  MdtWorldStep(projected.world, kStep);
  std::printf("one step of a 70-link chain at 2 rad/s: worst gap %.3f mm plain, %.3f mm projected\n",
              plain.worstGap() * 1e3, projected.worstGap() * 1e3);
  for (int i = 0; i < kLongChain; ++i) {
    MeVector3 v0, v1;
    MdtBodyGetLinearVelocity(plain.link[(size_t)i], v0);
    MdtBodyGetLinearVelocity(projected.link[(size_t)i], v1);
    EXPECT_TRUE(sameBits(v0, v1)) << "link " << i;
    EXPECT_TRUE(bodyFinite(projected.link[(size_t)i]));
  }
  EXPECT_GT(plain.worstGap(), 2e-4);
  EXPECT_LE(projected.worstGap(), 1e-4 + 1e-6);
}

TEST(JointProjection, HoldsALongLightChainFallingAt60Hz) {
  // 70 links, each with a small moment of inertia for its lever (I = 0.01,
  // lever 0.25 m), 3 s from the horizontal: the velocity step alone opens
  // it by a quarter of a metre; four iterations hold every joint near the
  // slop.
  Chain plain(0, 0, kLongChain), projected(0, 4, kLongChain);
  double plainWorst = 0, projectedWorst = 0;
  for (int s = 0; s < 180; ++s) {
    MdtWorldStep(plain.world, kStep);
    MdtWorldStep(projected.world, kStep);
    plainWorst = std::fmax(plainWorst, plain.worstGap());
    projectedWorst = std::fmax(projectedWorst, projected.worstGap());
  }
  std::printf("falling 70-link chain, 3 s at 1/60 s: worst gap %.1f mm plain, %.3f mm projected\n", plainWorst * 1e3,
              projectedWorst * 1e3);
  for (MdtBodyID b : projected.link) EXPECT_TRUE(bodyFinite(b));
  EXPECT_GT(plainWorst, 0.1);
  EXPECT_LT(projectedWorst, 0.0005);
}
