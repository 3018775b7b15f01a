// stabilize.cpp: geometric-stiffness stabilisation of light bodies under
// large constraint forces.
//
// A constraint force f acting at lever r from a body's centre of mass exerts
// the torque r x f. When the body turns by a small angle d, r turns with it
// and the torque changes by K d, with K of size |f||r| for turns that move
// the attachment point (perpendicular to r) and zero for turns about r. The
// velocity-level step treats f implicitly but this change explicitly, so a
// light body between large forces (a light chain link holding a heavy load)
// oscillates at w^2 ~ |f||r| / I and goes unstable once w h > 2: the
// mass-ratio instability of the guide's "points to remember".
//
// The remedy (after Andrews, Teichmann and Kry, "Geometric stiffness for
// real-time constrained multibody dynamics", 2017) is to let the constraint
// response see the body's inertia plus h^2 K, with the PSD approximation
//     K = factor * sum over attachments |f| |r| (I - r^ r^T),
// from last step's forces. It only damps those fast link modes: a body
// driven at its centre of mass (a wheel on its axle), or free of
// constraints, is unaffected, and slow motion changes by O(h^2 K / I).
// factor = world->params.geometricStiffness (default 1; 0 switches it off).
#include <cmath>

#include "step.h"

namespace karma::mdt {

void accumulateGeometricStiffness(MdtWorldID world, StepScratch &s, const Partition &part) {
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) b->geomStiffness[r][c] = 0;
  }
  const MeReal factor = world->params.geometricStiffness;
  if (!(factor > 0)) return;
  for (int i = 0; i < part.constraintCount; ++i) {
    const MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    for (int k = 0; k < 2; ++k) {
      MdtBody *b = c->body[k];
      if (!b) continue;
      const MeReal f = MeVector3Magnitude(c->force[k]);
      if (!(f > 0)) continue;
      MeVector3 p, com, r;
      attachmentPoint(c, k, p);
      bodyCom(b, com);
      MeVector3Subtract(r, p, com);
      const MeReal len = MeVector3Magnitude(r);
      if (!(len > 0)) continue;
      const MeReal kappa = factor * f * len;
      MeVector3Scale(r, 1 / len);
      for (int a = 0; a < 3; ++a)
        for (int e = 0; e < 3; ++e) b->geomStiffness[a][e] += kappa * ((a == e ? (MeReal)1 : (MeReal)0) - r[a] * r[e]);
    }
  }
}

}  // namespace karma::mdt
