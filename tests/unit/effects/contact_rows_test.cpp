// Issue 17: contacts write rows only for the effects that act. A friction
// direction whose bound is zero (NormalForce model with coefficient 0, Box
// model with friction 0) writes no row, so a contact with zero friction
// costs what the frictionless contact type costs and moves the same; a
// contact without restitution does no bounce work (engine/mdt/bcl/contact.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "step/step_scene.h"

namespace {

using step_test::Contacts;
using step_test::Scene;

// The friction set-ups of the tests, applied to the universe's default
// material pair.
enum class Friction {
  TypeZero,      // MdtContactTypeFrictionZero: the reference
  MuZero,        // Friction2D, NormalForce model, mu = 0 in both directions
  MuOne,         // Friction2D, NormalForce model, mu = 1 in both directions
  BoxZero,       // Friction2D, Box model, limit 0 in both directions
  BoxPrimary,    // Friction2D, Box model, limit 1 along the primary, 0 along the secondary
  BoxSecondary,  // Friction2D, Box model, limit 0 along the primary, 1 along the secondary
  OneDMuZero,    // Friction1D, NormalForce model, mu = 0
  OneDMuOne,     // Friction1D, NormalForce model, mu = 1
};

void setFriction(MstUniverseID u, Friction f) {
  MdtContactParamsID p = MstBridgeGetContactParams(u->bridge, 0, 0);
  MdtContactParamsReset(p);
  switch (f) {
    case Friction::TypeZero:
      MdtContactParamsSetType(p, MdtContactTypeFrictionZero);
      return;
    case Friction::MuZero:
    case Friction::MuOne:
      MdtContactParamsSetType(p, MdtContactTypeFriction2D);
      MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
      MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
      MdtContactParamsSetFrictionCoefficient(p, f == Friction::MuOne ? 1 : 0);
      return;
    case Friction::BoxZero:
      MdtContactParamsSetType(p, MdtContactTypeFriction2D);
      MdtContactParamsSetFriction(p, 0);
      return;
    case Friction::BoxPrimary:
    case Friction::BoxSecondary:
      MdtContactParamsSetType(p, MdtContactTypeFriction2D);
      MdtContactParamsSetPrimaryFriction(p, f == Friction::BoxPrimary ? 1 : 0);
      MdtContactParamsSetSecondaryFriction(p, f == Friction::BoxPrimary ? 0 : 1);
      return;
    case Friction::OneDMuZero:
    case Friction::OneDMuOne:
      MdtContactParamsSetType(p, MdtContactTypeFriction1D);
      MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
      MdtContactParamsSetPrimaryFrictionCoefficient(p, f == Friction::OneDMuOne ? 1 : 0);
      return;
  }
}

struct BoxRun {
  int contacts = 0;  // of the box, after the last step
  int rows = 0;      // solved in the last step
  MeVector3 x{}, v{};
  MeVector4 q{};
};

// A 1 m box resting flat on the ground (4 corner contacts), pushed along x
// at `speed`, stepped `steps` times.
BoxRun slideBox(Friction f, MeReal speed, int steps) {
  Scene s;
  setFriction(s.u, f);
  McdModelID box = s.box(1, 1, 1, 0, (MeReal)0.5, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(box), speed, 0, 0);
  s.step(steps);
  BoxRun r;
  MdtContactID c[16];
  r.contacts = Contacts(box, c, 16);
  MdtWorldStepStats st;
  MdtWorldGetStepStats(s.u->world, &st);
  r.rows = st.rows;
  MdtBodyID b = McdModelGetBody(box);
  MdtBodyGetPosition(b, r.x);
  MdtBodyGetLinearVelocity(b, r.v);
  MdtBodyGetQuaternion(b, r.q);
  return r;
}

}  // namespace

TEST(ContactRows, ZeroFrictionWritesOnlyTheNormalRows) {
  const BoxRun zero = slideBox(Friction::TypeZero, 0, 30);
  const BoxRun muZero = slideBox(Friction::MuZero, 0, 30);
  const BoxRun muOne = slideBox(Friction::MuOne, 0, 30);
  const BoxRun boxZero = slideBox(Friction::BoxZero, 0, 30);
  std::printf("box at rest, 4 contacts: rows frictionless %d, mu = 0 %d, mu = 1 %d, box limit 0 %d\n", zero.rows,
              muZero.rows, muOne.rows, boxZero.rows);
  ASSERT_EQ(zero.contacts, 4);
  ASSERT_EQ(muOne.contacts, 4);
  EXPECT_EQ(zero.rows, 4);
  EXPECT_EQ(muZero.rows, 4);   // as the frictionless type
  EXPECT_EQ(boxZero.rows, 4);  // as the frictionless type
  EXPECT_EQ(muOne.rows, 12);   // normal + two friction rows per contact
}

TEST(ContactRows, ADirectionWithZeroBoundWritesNoRow) {
  const BoxRun primaryOnly = slideBox(Friction::BoxPrimary, 0, 30);
  const BoxRun oneDZero = slideBox(Friction::OneDMuZero, 0, 30);
  const BoxRun oneDOne = slideBox(Friction::OneDMuOne, 0, 30);
  ASSERT_EQ(primaryOnly.contacts, 4);
  EXPECT_EQ(primaryOnly.rows, 8);  // the secondary direction (limit 0) has none
  EXPECT_EQ(oneDZero.rows, 4);
  EXPECT_EQ(oneDOne.rows, 8);
}

TEST(ContactRows, TheMemoryOfAContactKeepsEachImpulseOnItsOwnDirection) {
  // Primary limit 0, secondary 1: the one friction row written is the
  // secondary's, and the contact remembers its impulse along d2, never d1.
  Scene s;
  setFriction(s.u, Friction::BoxSecondary);
  McdModelID box = s.box(1, 1, 1, 0, (MeReal)0.5, 0);
  MdtBodySetLinearVelocity(McdModelGetBody(box), 1, 0, 1);
  s.step(5);
  MdtWorldStepStats st;
  MdtWorldGetStepStats(s.u->world, &st);
  MdtContactID c[16];
  const int n = Contacts(box, c, 16);
  ASSERT_EQ(n, 4);
  EXPECT_EQ(st.rows, 8);
  double carried = 0;
  for (int i = 0; i < n; ++i) {
    MeVector3 friction, d1, normal, d2;
    MdtContactGetImpulse(c[i], friction);
    MdtContactGetDirection(c[i], d1);
    MdtContactGetNormal(c[i], normal);
    MeVector3Cross(d2, normal, d1);
    EXPECT_NEAR(MeVector3Dot(friction, d1), 0, 1e-6) << "contact " << i;
    carried += std::fabs((double)MeVector3Dot(friction, d2));
  }
  EXPECT_GT(carried, 1e-3);  // the secondary row did act
}

TEST(ContactRows, ZeroFrictionMovesAsTheFrictionlessType) {
  // Sliding at 2 m/s for 1 s: with a zero friction bound the rows left out
  // would have carried no impulse, so the motion is the frictionless type's
  // (here bit for bit: the solver sees the same rows).
  const BoxRun zero = slideBox(Friction::TypeZero, 2, 60);
  for (Friction f : {Friction::MuZero, Friction::BoxZero, Friction::OneDMuZero}) {
    const BoxRun r = slideBox(f, 2, 60);
    EXPECT_EQ(r.rows, zero.rows);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(r.x[k], zero.x[k]) << "axis " << k;
      EXPECT_EQ(r.v[k], zero.v[k]) << "axis " << k;
    }
    for (int k = 0; k < 4; ++k) EXPECT_EQ(r.q[k], zero.q[k]);
  }
  EXPECT_NEAR(zero.v[0], 2, 1e-3);  // nothing slows it
  // With mu = 1 it stops within 1 s (2 m/s against mu g = 9.81 m/s^2).
  const BoxRun one = slideBox(Friction::MuOne, 2, 60);
  EXPECT_NEAR(one.v[0], 0, 1e-2);
}

TEST(ContactRows, RestitutionAddsNoRowsAndStillBounces) {
  // A ball dropped from 1 m: the bounce work happens only for contacts with
  // restitution, and adds no rows (the bounce is asked within the normal
  // row, then given after the positions move).
  double topAfter[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    Scene s;
    MdtContactParamsID p = MstBridgeGetContactParams(s.u->bridge, 0, 0);
    MdtContactParamsSetRestitution(p, i == 0 ? 0 : (MeReal)0.5);
    MdtContactParamsSetRestitutionThreshold(p, (MeReal)0.1);
    McdModelID ball = s.ball((MeReal)0.1, 0, (MeReal)1.1, 0);
    int maxRows = 0;
    bool landed = false;
    for (int k = 0; k < 120; ++k) {
      s.step();
      MdtWorldStepStats st;
      MdtWorldGetStepStats(s.u->world, &st);
      maxRows = std::max(maxRows, st.rows);
      MeVector3 x, v;
      Scene::position(ball, x);
      Scene::velocity(ball, v);
      landed = landed || v[1] > 0;
      if (landed) topAfter[i] = std::max(topAfter[i], (double)x[1] - 0.1);
    }
    EXPECT_EQ(maxRows, 1) << "restitution " << (i == 0 ? 0 : 0.5);
  }
  std::printf("ball from 1 m: highest after the impact %.4f m (e = 0), %.4f m (e = 0.5)\n", topAfter[0], topAfter[1]);
  EXPECT_LT(topAfter[0], 0.01);          // no rebound
  EXPECT_NEAR(topAfter[1], 0.25, 0.05);  // e^2 h = 0.25 m
}
