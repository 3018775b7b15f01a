// Hand-made contacts: support, friction models, restitution, slip, slide.
#include <cmath>
#include <set>

#include "mdt_test_support.h"

using namespace mdt_test;

namespace {

const MeReal g = (MeReal)9.81;

// A stand-alone contact between `b` and the world at `at`, normal +y.
MdtContactID groundContact(MdtWorldID w, MdtBodyID b, const MeVector3 at) {
  MdtContactID c = MdtContactCreate(w);
  MdtContactSetBodies(c, b, nullptr);
  MdtContactSetPosition(c, at[0], at[1], at[2]);
  MdtContactSetNormal(c, 0, 1, 0);
  MdtContactSetPenetration(c, 0);
  MdtContactEnable(c);
  return c;
}

// A body of mass m at the origin with one contact at its own origin (so
// friction exerts no torque), normal +y.
struct Puck {
  MdtBodyID body;
  MdtContactID contact;
  Puck(MdtWorldID w, MeReal m) {
    body = MdtBodyCreate(w);
    MdtBodySetMass(body, m);
    MdtBodyEnable(body);
    const MeVector3 at = {0, 0, 0};
    contact = groundContact(w, body, at);
  }
};

// The creep velocity of a stuck friction row carrying force f: eps * f * h
// (h = 0.01 throughout).
double creep(MdtWorldID w, double f) { return (double)MdtWorldGetEpsilon(w) * f * 0.01; }

}  // namespace

TEST(Contact, BoxOnFourContactsCarriesItsWeight) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID box = MdtBodyCreate(w);
  MdtBodySetMass(box, 2);
  MdtBodySetPosition(box, 0, (MeReal)0.5, 0);
  MdtBodyEnable(box);
  MdtContactID c[4];
  for (int i = 0; i < 4; ++i) {
    const MeVector3 at = {(i & 1) ? (MeReal)0.5 : -(MeReal)0.5, 0, (i & 2) ? (MeReal)0.5 : -(MeReal)0.5};
    c[i] = groundContact(w, box, at);
  }
  for (int s = 0; s < 200; ++s) MdtWorldStep(w, (MeReal)0.01);
  double total = 0;
  for (MdtContactID k : c) {
    MeVector3 f;
    MdtContactGetForce(k, 0, f);
    total += f[1];
    EXPECT_GE(f[1], 0);
    EXPECT_NEAR(MdtContactGetNormalForce(k), f[1], 1e-4);
  }
  EXPECT_NEAR(total, 2 * g, 2 * g * 0.005);
  MeVector3 x;
  MdtBodyGetPosition(box, x);
  EXPECT_NEAR(x[1], 0.5, 1e-3);  // it does not sink
}

TEST(Contact, BoxFrictionHoldsBelowItsLimitAndSlidesAbove) {
  for (const MeReal push : {(MeReal)3, (MeReal)8}) {
    World w;
    MdtWorldSetGravity(w, 0, -g, 0);
    MdtWorldSetAutoDisable(w, FALSE);
    Puck p(w, 1);
    MdtContactParamsID prm = MdtContactGetParams(p.contact);
    MdtContactParamsSetType(prm, MdtContactTypeFriction2D);
    MdtContactParamsSetFriction(prm, 5);
    MdtContactSetDirection(p.contact, 1, 0, 0);
    const int steps = 100;
    for (int s = 0; s < steps; ++s) {
      MdtBodyAddForce(p.body, push, 0, 0);
      MdtWorldStep(w, (MeReal)0.01);
    }
    MeVector3 v;
    MdtBodyGetLinearVelocity(p.body, v);
    if (push < 5) {
      // Stuck, up to the creep that epsilon allows every rigid row: the row
      // gives way by eps * impulse, i.e. velocity eps * F * h.
      EXPECT_LE(std::fabs(v[0]), 1.01 * creep(w, push)) << "push " << push;
    } else {
      const double a = (push - 5) / 1.0;  // (F - friction) / m
      EXPECT_NEAR(v[0], a * steps * 0.01, a * steps * 0.01 * 0.01) << "push " << push;
    }
  }
}

TEST(Contact, NormalForceFrictionOnAnIncline) {
  // Gravity tilted by theta stands in for an incline; mu = 0.5, so the block
  // sticks below theta = atan(0.5) = 26.6 degrees and slides above it with
  // a = g (sin theta - mu cos theta).
  const double mu = 0.5;
  for (const double deg : {20.0, 35.0}) {
    const double th = deg * M_PI / 180;
    World w;
    MdtWorldSetGravity(w, (MeReal)(g * std::sin(th)), (MeReal)(-g * std::cos(th)), 0);
    MdtWorldSetAutoDisable(w, FALSE);
    Puck p(w, 1);
    MdtContactParamsID prm = MdtContactGetParams(p.contact);
    MdtContactParamsSetType(prm, MdtContactTypeFriction2D);
    MdtContactParamsSetPrimaryFrictionModel(prm, MdtFrictionModelNormalForce);
    MdtContactParamsSetSecondaryFrictionModel(prm, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoefficient(prm, (MeReal)mu);
    MdtContactSetDirection(p.contact, 1, 0, 0);
    const int steps = 100;
    for (int s = 0; s < steps; ++s) MdtWorldStep(w, (MeReal)0.01);
    MeVector3 v;
    MdtBodyGetLinearVelocity(p.body, v);
    const double a = g * (std::sin(th) - mu * std::cos(th));
    if (a < 0) {
      EXPECT_LE(std::fabs(v[0]), 1.01 * creep(w, g * std::sin(th))) << deg;
    } else {
      EXPECT_NEAR(v[0], a * steps * 0.01, a * steps * 0.01 * 0.03) << deg;
    }
  }
}

TEST(Contact, RestitutionReboundsAtESpeed) {
  // One step of an impact at v = 2 on a contact of restitution e. The normal
  // row asks for separation speed e v; epsilon softens it like every rigid
  // row: (1/m + eps) lambda = (1 + e) v, so v' = -v + (1 + e) v / (1 + eps m).
  // With eps = 0.001 that is e v within 2%; the default eps = 0.01 is checked
  // against the formula.
  for (const MeReal eps : {(MeReal)0.001, (MeReal)0.01}) {
    for (const MeReal e : {(MeReal)0, (MeReal)0.5, (MeReal)1}) {
      World w;
      MdtWorldSetAutoDisable(w, FALSE);
      MdtWorldSetEpsilon(w, eps);
      Puck p(w, 1);
      MdtContactParamsSetRestitution(MdtContactGetParams(p.contact), e);
      MdtBodySetLinearVelocity(p.body, 0, -2, 0);
      MdtWorldStep(w, (MeReal)0.01);
      MeVector3 v;
      MdtBodyGetLinearVelocity(p.body, v);
      const double predicted = -2 + (1 + e) * 2 / (1 + eps);
      EXPECT_NEAR(v[1], predicted, 1e-4) << "e " << e << " eps " << eps;
      if (eps <= (MeReal)0.001) {
        EXPECT_NEAR(v[1], 2 * e, 0.02 * 2) << "e " << e;
      }
    }
  }
}

TEST(Contact, SlipGivesVelocityProportionalToForce) {
  World w;
  MdtWorldSetAutoDisable(w, FALSE);
  Puck p(w, 1);
  MdtContactParamsID prm = MdtContactGetParams(p.contact);
  MdtContactParamsSetType(prm, MdtContactTypeFriction1D);
  MdtContactParamsSetPrimarySlip(prm, (MeReal)0.02);
  MdtContactSetDirection(p.contact, 1, 0, 0);
  for (int s = 0; s < 50; ++s) {
    MdtBodyAddForce(p.body, 10, 0, 0);
    MdtWorldStep(w, (MeReal)0.01);
  }
  MeVector3 v;
  MdtBodyGetLinearVelocity(p.body, v);
  EXPECT_NEAR(v[0], 0.02 * 10, 0.2 * 0.01);
}

TEST(Contact, SlideCarriesTheBodyLikeAConveyor) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  Puck p(w, 1);
  MdtContactParamsID prm = MdtContactGetParams(p.contact);
  MdtContactParamsSetType(prm, MdtContactTypeFriction2D);
  MdtContactParamsSetPrimarySlide(prm, (MeReal)0.5);
  MdtContactSetDirection(p.contact, 0, 0, 1);
  for (int s = 0; s < 20; ++s) MdtWorldStep(w, (MeReal)0.01);
  MeVector3 v;
  MdtBodyGetLinearVelocity(p.body, v);
  EXPECT_NEAR(v[2], 0.5, 1e-3);
  EXPECT_NEAR(v[0], 0, 1e-4);
}

TEST(ContactGroup, CarriesWeightAndReportsNormalForce) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  MdtBodyID box = MdtBodyCreate(w);
  MdtBodySetMass(box, 3);
  MdtBodySetPosition(box, 0, (MeReal)0.5, 0);
  MdtBodyEnable(box);
  MdtContactGroupID grp = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(grp, box, nullptr);
  for (int i = 0; i < 4; ++i) {
    MdtContactID c = MdtContactGroupCreateContact(grp);
    ASSERT_NE(c, nullptr);
    MdtContactSetPosition(c, (i & 1) ? (MeReal)0.5 : -(MeReal)0.5, 0, (i & 2) ? (MeReal)0.5 : -(MeReal)0.5);
    MdtContactSetNormal(c, 0, 1, 0);
  }
  MdtContactGroupEnable(grp);
  EXPECT_EQ(MdtContactGroupGetCount(grp), 4);
  for (int s = 0; s < 100; ++s) MdtWorldStep(w, (MeReal)0.01);
  EXPECT_NEAR(MdtContactGroupGetNormalForce(grp), 3 * g, 3 * g * 0.005);
  int n = 0;
  for (MdtContactID c = MdtContactGroupGetFirstContact(grp); c; c = MdtContactGroupGetNextContact(grp, c)) ++n;
  EXPECT_EQ(n, 4);
  // The body sees the group's contacts.
  n = 0;
  for (MdtContactID c = MdtBodyGetFirstContact(box); c; c = MdtBodyGetNextContact(box, c)) ++n;
  EXPECT_EQ(n, 4);
  MdtContactGroupDestroyContact(grp, MdtContactGroupGetFirstContact(grp));
  EXPECT_EQ(MdtContactGroupGetCount(grp), 3);
  MdtContactGroupDestroy(grp);
  EXPECT_EQ(MdtWorldGetConstraintCount(w), 0u);
}

// The walk of a body's contacts reaches exactly the contacts that act on it
// -- enabled stand-alone contacts and the contacts of enabled groups --
// each once, whatever else the world holds: disabled contacts and groups,
// contacts between other bodies, a contact that stood alone (and was
// linked) before it joined a group, joints.
TEST(Contact, ABodysWalkReachesEachContactActingOnItOnce) {
  World w(8, 1, 1, 64);
  MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w), c = MdtBodyCreate(w);
  std::multiset<MdtContactID> expected;
  auto alone = [&](MdtBodyID x, MdtBodyID y, bool enable) {
    MdtContactID k = MdtContactCreate(w);
    MdtContactSetBodies(k, x, y);
    if (enable) MdtContactEnable(k);
    return k;
  };
  expected.insert(alone(a, b, true));
  expected.insert(alone(b, a, true));
  const MdtContactID onGround = alone(a, nullptr, true);
  expected.insert(onGround);
  alone(a, b, false);
  alone(b, c, true);
  MdtBSJointID joint = MdtBSJointCreate(w);
  MdtBSJointSetBodies(joint, a, c);
  MdtBSJointEnable(joint);
  MdtContactGroupID live = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(live, c, a);
  std::set<MdtContactID> ofLive;
  for (int i = 0; i < 3; ++i) ofLive.insert(MdtContactGroupCreateContact(live));
  expected.insert(ofLive.begin(), ofLive.end());
  MdtContactID joined = alone(c, a, true);  // linked while alone
  MdtContactDisable(joined);
  MdtContactGroupAppendContact(live, joined);
  expected.insert(joined);
  ofLive.insert(joined);
  MdtContactGroupEnable(live);
  MdtContactGroupID off = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(off, a, b);
  MdtContactGroupCreateContact(off);
  MdtContactGroupID empty = MdtContactGroupCreate(w);
  MdtContactGroupSetBodies(empty, a, nullptr);
  MdtContactGroupEnable(empty);
  std::multiset<MdtContactID> found;
  for (MdtContactID k = MdtBodyGetFirstContact(a); k; k = MdtBodyGetNextContact(a, k)) found.insert(k);
  EXPECT_EQ(found, expected);
  // Body c: the live group's four and the stand-alone one with b.
  int atC = 0;
  for (MdtContactID k = MdtBodyGetFirstContact(c); k; k = MdtBodyGetNextContact(c, k)) ++atC;
  EXPECT_EQ(atC, 5);
  // A group disabled in the middle of a walk: the rest of it is not reached.
  MdtContactID k = MdtBodyGetFirstContact(c);
  while (k && !ofLive.count(k)) k = MdtBodyGetNextContact(c, k);
  ASSERT_NE(k, nullptr);
  MdtContactGroupDisable(live);
  for (k = MdtBodyGetNextContact(c, k); k; k = MdtBodyGetNextContact(c, k)) EXPECT_EQ(ofLive.count(k), 0u);
  MdtContactGroupEnable(live);
  // A contact asked for from a body it does not act on ends the walk, with a warning.
  WarningCapture cap;
  EXPECT_EQ(MdtBodyGetNextContact(c, onGround), nullptr);
  EXPECT_EQ(cap.count(), 1u);
}

// A contact's friction directions turn with its normal. Near the vertical,
// where |n_x| and |n_z| are both small, anyOrthogonal's choice of axis
// switches with their order and a fresh choice would turn the friction rows
// by a quarter turn; the contact keeps last step's axis instead, projected
// onto the new tangent plane, until the normal has turned 60 degrees
// towards it. A direction set by the user comes first.
TEST(Contact, FrictionDirectionsTurnWithTheNormal) {
  World w;
  MdtWorldSetGravity(w, 0, -g, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  Puck p(w, 1);
  MdtContactParamsID prm = MdtContactGetParams(p.contact);
  MdtContactParamsSetType(prm, MdtContactTypeFriction2D);
  MdtContactParamsSetPrimaryFrictionModel(prm, MdtFrictionModelNormalForce);
  MdtContactParamsSetSecondaryFrictionModel(prm, MdtFrictionModelNormalForce);
  MdtContactParamsSetFrictionCoefficient(prm, 1);
  auto dot = [](const MeVector3 a, const MeVector3 b) { return (double)MeVector3Dot(a, b); };
  auto same = [](const MeVector3 a, const MeVector3 b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
  // The direction a contact without memory takes for normal (x, y, z).
  auto fresh = [&](MeReal x, MeReal y, MeReal z, MeVector3 d) {
    MdtContactID c = MdtContactCreate(w);
    MdtContactSetNormal(c, x, y, z);
    MdtContactGetDirection(c, d);
    MdtContactDestroy(c);
  };

  MdtContactSetNormal(p.contact, (MeReal)0.001, 1, (MeReal)0.002);
  MeVector3 before, start;
  MdtContactGetDirection(p.contact, before);
  fresh((MeReal)0.001, 1, (MeReal)0.002, start);
  EXPECT_TRUE(same(before, start));  // no memory yet: anyOrthogonal's choice
  MdtWorldStep(w, (MeReal)0.01);

  // |n_x| and |n_z| swap order: a fresh choice is a quarter turn away.
  MdtContactSetNormal(p.contact, (MeReal)0.002, 1, (MeReal)0.001);
  MeVector3 kept, jumped, n;
  MdtContactGetDirection(p.contact, kept);
  fresh((MeReal)0.002, 1, (MeReal)0.001, jumped);
  MdtContactGetNormal(p.contact, n);
  EXPECT_LT(std::fabs(dot(jumped, before)), 0.01);
  EXPECT_GT(dot(kept, before), 0.99999);
  EXPECT_NEAR(dot(kept, n), 0, 1e-6);
  EXPECT_NEAR(dot(kept, kept), 1, 1e-6);
  MdtWorldStep(w, (MeReal)0.01);

  // The normal tilted by a towards w, 20 degrees off the kept axis (so the
  // fresh choice and the carried axis differ): the carried axis is the kept
  // one projected while kept . normal = sin(a) cos(20 deg) stays below
  // cos(30 deg) (the normal turned less than 60 degrees towards it).
  MeVector3 side, toward;
  MeVector3Cross(side, n, kept);
  const double b = 20 * M_PI / 180;
  for (int i = 0; i < 3; ++i) toward[i] = (MeReal)(std::cos(b) * kept[i] + std::sin(b) * side[i]);
  auto tiltAndCompare = [&](double degrees, MeVector3 carried, MeVector3 projected, MeVector3 fromScratch) {
    const double a = degrees * M_PI / 180;
    MeVector3 tilted;
    for (int i = 0; i < 3; ++i) tilted[i] = (MeReal)(std::cos(a) * n[i] + std::sin(a) * toward[i]);
    MdtContactSetNormal(p.contact, tilted[0], tilted[1], tilted[2]);
    MeVector3 unit;
    MdtContactGetNormal(p.contact, unit);
    MdtContactGetDirection(p.contact, carried);
    fresh(tilted[0], tilted[1], tilted[2], fromScratch);
    MeVector3Copy(projected, kept);
    MeVector3MultiplyAdd(projected, -MeVector3Dot(kept, unit), unit);
    MeVector3Normalize(projected);
  };
  MeVector3 carried, projected, fromScratch;
  tiltAndCompare(50, carried, projected, fromScratch);  // kept . normal = 0.72
  EXPECT_GT(dot(carried, projected), 0.99999);
  EXPECT_LT(dot(fromScratch, projected), 0.99);
  tiltAndCompare(80, carried, projected, fromScratch);  // kept . normal = 0.93: given up
  EXPECT_TRUE(same(carried, fromScratch));
  EXPECT_LT(dot(carried, projected), 0.99);

  // A direction set by the user wins over the kept axis.
  MdtContactSetNormal(p.contact, 0, 1, 0);
  MdtWorldStep(w, (MeReal)0.01);
  MdtContactSetDirection(p.contact, 0, 0, 1);
  MeVector3 user;
  MdtContactGetDirection(p.contact, user);
  EXPECT_EQ(user[2], 1);
}

TEST(Contact, DefaultsAndBadInput) {
  World w;
  WarningCapture cap;
  MdtContactID c = MdtContactCreate(w);
  MdtContactParamsID p = MdtContactGetParams(c);
  EXPECT_EQ(MdtContactParamsGetType(p), MdtContactTypeFrictionZero);
  EXPECT_EQ(MdtContactParamsGetPrimaryFrictionModel(p), MdtFrictionModelBox);
  EXPECT_EQ(MdtContactParamsGetPrimaryFriction(p), MEINFINITY);
  EXPECT_EQ(MdtContactParamsGetRestitutionThreshold(p), (MeReal)0.001);
  EXPECT_EQ(MdtContactParamsGetRestitution(p), 0);
  MeVector3 n;
  MdtContactGetNormal(c, n);
  EXPECT_EQ(n[1], 1);
  EXPECT_EQ(cap.count(), 0u);
  MdtContactSetNormal(c, 0, 0, 0);
  MdtContactParamsSetRestitution(p, 2);
  MdtContactParamsSetFriction(p, -1);
  MdtContactEnable(c);  // no bodies yet
  EXPECT_EQ(cap.count(), 4u);
  EXPECT_FALSE(MdtContactIsEnabled(c));
  EXPECT_EQ(MdtConstraintDCastHinge(MdtContactQuaConstraint(c)), nullptr);
  EXPECT_EQ(MdtConstraintDCastContact(MdtContactQuaConstraint(c)), c);
}
