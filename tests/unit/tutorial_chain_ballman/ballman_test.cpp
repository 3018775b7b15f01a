// Ballman's behaviour, without MeViewer: the rag doll falls down the stairs
// in one piece with either friction model, the push sends it into the
// boxes, and the two friction models are what the guide describes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ballman_sim.h"

namespace {

struct DollRun {
  double worstError = 0;  // m, largest joint error over every frame
  bool finite = true;
  MeVector3 torsoEnd = {0, 0, 0};
  double boxMoved = 0;  // m, the largest distance a box ended from its start
};

bool Finite(const MeVector3 v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// `frames` frames (one world step each) with the given
// friction model; the push at frame `propelAt` (< 0: none).
DollRun RunDoll(bool highQuality, int frames, int propelAt = -1) {
  Ballman *b = BallmanCreate();
  EXPECT_NE(b, nullptr);
  BallmanSetHighQualityFriction(b, highQuality);
  MeVector3 boxStart[BALLMAN_BOXES];
  for (int i = 0; i < BALLMAN_BOXES; ++i) MdtBodyGetPosition(McdModelGetBody(b->box[i]), boxStart[i]);
  DollRun r;
  for (int f = 0; f < frames; ++f) {
    if (f == propelAt) BallmanPropel(b);
    BallmanStep(b);
    r.worstError = std::fmax(r.worstError, (double)BallmanJointError(b));
    for (McdModelID m : b->part) {
      MeVector3 x, v, w;
      MdtBodyGetPosition(McdModelGetBody(m), x);
      MdtBodyGetLinearVelocity(McdModelGetBody(m), v);
      MdtBodyGetAngularVelocity(McdModelGetBody(m), w);
      if (!Finite(x) || !Finite(v) || !Finite(w)) r.finite = false;
    }
  }
  BallmanTorsoPosition(b, r.torsoEnd);
  for (int i = 0; i < BALLMAN_BOXES; ++i) {
    MeVector3 x;
    MdtBodyGetPosition(McdModelGetBody(b->box[i]), x);
    r.boxMoved = std::fmax(r.boxMoved, (double)MeVector3Distance(x, boxStart[i]));
  }
  BallmanDestroy(b);
  return r;
}

TEST(Ballman, TenBodiesNineJointsConnectedAtTheStart) {
  Ballman *b = BallmanCreate();
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(MdtWorldGetBodyCount(b->universe->world), (unsigned)(BALLMAN_PARTS + BALLMAN_BOXES));
  EXPECT_LT(BallmanJointError(b), 1e-5);
  MeVector3 torso;
  BallmanTorsoPosition(b, torso);
  EXPECT_GT(torso[1], 2.3);  // standing on the 1.5 m landing
  BallmanDestroy(b);
}

TEST(Ballman, FallsDownTheStairsInOnePieceWithEitherFrictionModel) {
  // 4 s: off the landing, down the five steps (and onto the floor).
  const DollRun cheap = RunDoll(false, 240), hq = RunDoll(true, 240);
  std::printf("ballman cheap: joint error max %.2f mm; torso ends at (%.2f, %.2f, %.2f)\n", cheap.worstError * 1e3,
              cheap.torsoEnd[0], cheap.torsoEnd[1], cheap.torsoEnd[2]);
  std::printf("ballman high quality: joint error max %.2f mm; torso ends at (%.2f, %.2f, %.2f)\n", hq.worstError * 1e3,
              hq.torsoEnd[0], hq.torsoEnd[1], hq.torsoEnd[2]);
  for (const DollRun *r : {&cheap, &hq}) {
    EXPECT_TRUE(r->finite);
    EXPECT_LT(r->worstError, 0.005);
  }
  // Cheap: down on the floor (the torso started at 2.6 m), past the foot
  // of the stairs.
  EXPECT_LT(cheap.torsoEnd[1], 0.5);
  EXPECT_GT(cheap.torsoEnd[0], 2.5);
  // High quality: well down from the landing, and off it.
  EXPECT_LT(hq.torsoEnd[1], 1.5);
  EXPECT_GT(hq.torsoEnd[0], 0.5);
  // Viscous friction (the cheap model) cannot hold a body still: it slides
  // at slip x force. Coulomb friction stops the doll on the steps.
  EXPECT_GT(cheap.torsoEnd[0], hq.torsoEnd[0] + 0.5);
}

TEST(Ballman, PushSendsTheDollIntoTheBoxesAndItStaysWhole) {
  for (bool highQuality : {false, true}) {
    // The golden tests' script: the push at frame 100, 4 s in all.
    const DollRun r = RunDoll(highQuality, 240, 100);
    std::printf("ballman %s, pushed: joint error max %.2f mm; a box moved %.2f m\n",
                highQuality ? "high quality" : "cheap", r.worstError * 1e3, r.boxMoved);
    EXPECT_TRUE(r.finite);
    EXPECT_LT(r.worstError, 0.005);
    if (!highQuality) {
      EXPECT_GT(r.boxMoved, 0.3);  // the stack is knocked over
    }
  }
}

TEST(Ballman, FrictionModelsAreTheGuides) {
  Ballman *b = BallmanCreate();
  MdtContactParamsID p = MstBridgeGetContactParams(b->universe->bridge, b->dollMaterial, b->stairMaterial);
  // Cheap (the default): infinite friction, slip VISCOCITY, infinitely adhesive.
  EXPECT_EQ(MdtContactParamsGetType(p), MdtContactTypeFriction2D);
  EXPECT_EQ(MdtContactParamsGetPrimaryFrictionModel(p), MdtFrictionModelBox);
  EXPECT_GE(MdtContactParamsGetPrimaryFriction(p), MEINFINITY);
  EXPECT_GE(MdtContactParamsGetSecondaryFriction(p), MEINFINITY);
  EXPECT_EQ(MdtContactParamsGetPrimarySlip(p), kBallmanViscosity);
  EXPECT_GE(MdtContactParamsGetMaxAdhesiveForce(p), MEINFINITY);
  // High quality: normal-force (Coulomb) friction, no slip, no adhesion.
  BallmanSetHighQualityFriction(b, 1);
  EXPECT_EQ(MdtContactParamsGetPrimaryFrictionModel(p), MdtFrictionModelNormalForce);
  EXPECT_EQ(MdtContactParamsGetSecondaryFrictionModel(p), MdtFrictionModelNormalForce);
  EXPECT_NEAR(MdtContactParamsGetPrimaryFrictionCoefficient(p), 0.8, 1e-6);
  EXPECT_EQ(MdtContactParamsGetPrimarySlip(p), 0);
  EXPECT_EQ(MdtContactParamsGetMaxAdhesiveForce(p), 0);
  // And back.
  BallmanSetHighQualityFriction(b, 0);
  EXPECT_EQ(MdtContactParamsGetPrimaryFrictionModel(p), MdtFrictionModelBox);
  BallmanDestroy(b);
}

TEST(Ballman, ResetRestoresTheStart) {
  Ballman *a = BallmanCreate(), *b = BallmanCreate();
  for (int f = 0; f < 90; ++f) BallmanStep(b);
  BallmanReset(b);
  for (int i = 0; i < BALLMAN_PARTS; ++i) {
    MeVector3 xa, xb;
    MdtBodyGetPosition(McdModelGetBody(a->part[i]), xa);
    MdtBodyGetPosition(McdModelGetBody(b->part[i]), xb);
    EXPECT_EQ(MeVector3Distance(xa, xb), 0) << "part " << i;
  }
  EXPECT_LT(BallmanJointError(b), 1e-5);
  BallmanDestroy(a);
  BallmanDestroy(b);
}

}  // namespace
