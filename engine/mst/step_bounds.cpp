// step_bounds.cpp: what MstUniverseStep tells the collision space about the
// bodies before it updates the space (PrepareModelsForStep).
//
// Bounds padding (McdModelSetBoundsPadding; Mcd adds the framework's contact
// tolerance itself). For a model whose body is enabled, with h the step, v
// and w the body's linear and angular velocity, g the world's gravity and r
// the model's radius about the body's centre of mass:
//   margin = min(h |v| + h^2 |g| + h |w| r,  2 max(r, L))
// The first term bounds how far any point of the model moves in the coming
// step if the velocities change only by gravity (x' = x + h (v + h g) for
// the centre of mass; a point at distance <= r from it moves h |w| r more to
// first order). The cap, twice the larger of the model's radius and the
// universe's length scale L, keeps a very fast body from pairing with the
// whole scene; beyond it McdSafeTime is the tool. r is taken from the
// model's AABB at its last update: the distance from the centre of mass to
// the box's centre plus the box's half diagonal (>= the distance to any
// point of the shape); a non-finite r (an unbounded shape) counts as 0.
// Models without a body, and models of disabled bodies, get margin 0 (the
// tolerance only): they do not move. Only unfrozen models are visited.
//
// Sort keys: each model with a body inherits its body's sort key
// (McdModelSetInheritedSortKey), which orders its pairs unless the model's
// own key was set with McdModelSetSortKey. The guide keeps the two keys
// apart (collision keys in [0, 2^15 - 1], dynamics keys in [0, 2^31 - 1])
// and says nothing of one deriving from the other; inheriting makes keys set
// on bodies alone order the collision pairs too, and changes nothing for a
// user who sets both. A frozen model (its body asleep) takes the key when
// its body wakes (model_body.cpp).
#include "mst_internal.h"
#include "space/space_internal.h"

#include <algorithm>
#include <cmath>

namespace karma::mst {

namespace {

MeReal Norm(const MeVector3 a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The model's radius about the point c (see the top of the file).
MeReal RadiusAbout(McdModelID model, const MeVector3 c) {
  MeVector3 mn, mx, centre, half;
  McdModelGetAABB(model, mn, mx);
  for (int k = 0; k < 3; ++k) {
    centre[k] = (MeReal)0.5 * (mn[k] + mx[k]) - c[k];
    half[k] = (MeReal)0.5 * (mx[k] - mn[k]);
  }
  const MeReal r = Norm(centre) + Norm(half);
  return std::isfinite(r) ? r : 0;
}

MeReal StepMargin(McdModelID model, MdtBodyID body, MeReal h, MeReal gravity, MeReal lengthScale) {
  MeVector3 v, w, com;
  MdtBodyGetLinearVelocity(body, v);
  MdtBodyGetAngularVelocity(body, w);
  MdtBodyGetCenterOfMassPosition(body, com);
  const MeReal r = RadiusAbout(model, com);
  const MeReal motion = h * Norm(v) + h * h * gravity + h * Norm(w) * r;
  const MeReal cap = 2 * std::max(r, lengthScale);
  return std::isfinite(motion) ? std::min(motion, cap) : cap;
}

}  // namespace

void PrepareModelsForStep(MstUniverseID u, MeReal h) {
  MeVector3 g = {0, 0, 0};  // left unwritten on a bad world
  MdtWorldGetGravity(u->world, g);
  const MeReal gravity = Norm(g);
  const MeReal stepSize = h > 0 ? h : 0;
  // Unfrozen models only, in slot order: a frozen model's box is not
  // updated, so its padding is unused until it is unfrozen (and a model
  // freezes with padding 0, model_body.cpp); its body's sort key reaches it
  // when the body wakes.
  static_cast<McdSpace *>(u->space)->core->ForEachUnfrozen([&](int, void *user) {
    auto model = static_cast<McdModelID>(user);
    MdtBodyID body = McdModelGetBody(model);
    if (body) McdModelSetInheritedSortKey(model, MdtBodyGetSortKey(body));
    const bool moving = body && MdtBodyIsEnabled(body);
    McdModelSetBoundsPadding(model, moving ? StepMargin(model, body, stepSize, gravity, u->sizes.lengthScale) : 0);
  });
}

}  // namespace karma::mst
