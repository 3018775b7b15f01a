/* chain.h: the simulation half of RainbowChain (no drawing).
 *
 * A chain of RC_NBALLS balls, all sharing ONE sphere collision geometry,
 * joined by ball-and-socket joints (MdtBSJoint) at the midpoints between
 * neighbours. Ball 0 is held to the world by one more ball-and-socket joint
 * at its centre, so the chain swings from it; the chain starts straight and
 * level and falls onto a ground plane (y = 0). The viewer (rainbowchain.c)
 * draws it; the behaviour test (tests/unit/tutorial_chain_ballman) runs it
 * without MeViewer. Units: metres, kilograms, seconds; y up. */
#ifndef RAINBOWCHAIN_CHAIN_H
#define RAINBOWCHAIN_CHAIN_H

#include "Mst.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RC_NBALLS 10

typedef struct RainbowChain {
  MstUniverseID universe;
  McdGeometryID ballGeometry; /* the one sphere every ball uses */
  McdModelID ball[RC_NBALLS];
  /* joint[0] holds ball 0 to the world; joint[i] joins ball i-1 and ball i. */
  MdtBSJointID joint[RC_NBALLS];
  McdModelID ground;
  MeMatrix4 groundTM;
  MeVector3 endForce; /* applied to the last ball every step (the mouse) */
} RainbowChain;

extern const MeReal kChainBallRadius; /* 0.5 m */
extern const MeReal kChainLink;       /* 1.1 m between neighbouring centres */
extern const MeReal kChainStep;       /* 1/60 s: one frame, one world step */
extern const int kChainProjection;    /* joint projection sweeps per step */

/* Builds the universe, the ground and the chain in its starting pose.
 * Returns NULL if the universe cannot be made. */
RainbowChain *RainbowChainCreate(void);
void RainbowChainDestroy(RainbowChain *chain);
/* Back to the starting pose, at rest, no end force. */
void RainbowChainReset(RainbowChain *chain);
/* The force on the last ball until changed (N). */
void RainbowChainSetEndForce(RainbowChain *chain, MeReal fx, MeReal fy, MeReal fz);
/* A frame is one step of kChainStep in two halves, so that the viewer can
 * time them apart: collision (farfield, nearfield, contacts) then dynamics
 * (forces, solve, integration, joint projection). RainbowChainStep runs a
 * whole frame. */
void RainbowChainCollide(RainbowChain *chain);
void RainbowChainDynamics(RainbowChain *chain);
void RainbowChainStep(RainbowChain *chain);
/* The largest joint error now: the distance between a joint's point as
 * carried by its two bodies (m). */
MeReal RainbowChainJointError(const RainbowChain *chain);

#ifdef __cplusplus
}
#endif

#endif
