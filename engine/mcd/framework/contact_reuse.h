// contact_reuse.h: McdIntersect's memory of a pair's last contacts (not
// installed).
//
// A resting pair's two shapes hardly move relative to each other from one
// step to the next, yet a full nearfield test (box-box: 15 axes and a
// clipping) runs every step. With a reuse distance d > 0
// (McdFrameworkSetContactReuseDistance), McdIntersect keeps the contacts of
// a pair's last full test, taken in each model's own frame, and serves a
// later call from them while the pair's relative pose has moved no surface
// point by more than d. d is the framework's distance, at most a
// thousandth of the smaller shape's reach (kShapeFraction).
//
// =============================================================================
// THE REUSE RULE
// =============================================================================
// Poses. Model k's frame has origin o_k and axes a_k,i (the rows of its
// TM). Model 1's pose seen from model 2 is Q = (R, p):
//     R_ji = a_1,i . a_2,j,   p_j = (o_1 - o_2) . a_2,j.
// A point y of model 1 (its own coordinates) is at R y + p in model 2's.
//
// Drift. Between the pose Q0 of the full test and the present Q, a point y
// of model 1 moves, in model 2's frame, by
//     |(R - R0) y + (p - p0)| <= |R - R0|_F r_1 + |p - p0| = D_1,
// r_1 the largest distance from model 1's origin to its surface (from its
// geometry's bounds). Seen from model 1 the same motion moves model 2's
// points by at most D_2 (the inverse pose, r_2); the drift is
//     D = min(D_1, D_2),
// the most any gap between the shapes can have changed (a shape whose
// bounds are infinite takes the other side's bound).
//
// Slack. A full test runs at the caller's tolerance t plus d. When every
// contact it reports is within t, those are the call's answer and they are
// remembered: every feature within t + d was considered, and none beyond t
// took the place of one within it when the interaction reduced its points
// to the cap (then the answer has at least as many contacts as a test at t
// alone). Otherwise the pair is tested again at t and nothing is
// remembered. A later call at tolerance t' is served from memory iff
//     D <= d  and  D + t' <= t + d:
// a feature within t' now was within t' + D <= t + d at the full test, so
// the full test considered it (kept it, or reduced it away as a test now
// could). Nothing within t' is missed, and nothing remembered is left out:
// a served call reports every remembered contact, moved (up to t + d
// apart: a speculative contact, positive separation, is harmless). The
// memory is also ignored (and overwritten by the next full test) when the
// effective contact cap, either model's geometry, or any shape's size (the
// framework's shape revision) has changed. A call with room for no contact
// is always tested: its answer is the interaction's touch alone.
//
// Contacts served from memory. Each remembered contact keeps its point
// in both models' coordinates (y_1, y_2: the same world point then), its
// normal in model 2's, its separation s0 and its other fields (feature,
// dims, elements). Now, with x_k = model k's TM applied to y_k and n =
// model 2's axes applied to the normal:
//     position = (x_1 + x_2) / 2,   separation = s0 + (x_1 - x_2) . n
// (n points from model 2 towards model 1: model 1 moving along n opens the
// gap). This is the first-order update: it is exact for a motion along n,
// and otherwise off a full test by terms of the drift's size, D <= d: a
// clipped point that would slide along an edge moves with the bodies
// instead, and a normal that belongs to model 1's face turns with model 2.
// touch and the representative normal are the full test's (the normal
// turned with model 2).
//
// Pairs served. Those whose two shapes are each a box, a cylinder, a
// sphyl or a convex mesh, tested by the engine's own interaction
// (McdInteractions::m_builtIn): it depends on the two shapes and poses
// alone, and costs more than the memory. Spheres and planes (closed
// forms), triangle lists (a user's generator), aggregates and an
// application's interactions are always tested.
//
// Memory. Per pair, in McdModelPair::m_contactMemory, from MeMemoryAPI: made
// at the first full test, grown only when a test finds more contacts than
// it holds, freed at McdGoodbye. A settled scene's step allocates nothing.
// =============================================================================
#pragma once

#include "mcd_internal.h"

namespace karma::mcd {

// The default reuse distance, in units of the framework's length scale.
inline constexpr MeReal kDefaultContactReuse = (MeReal)1e-4;
// A pair's reuse distance is at most this fraction of the smaller shape's
// reach: a served contact is then off a full test by at most a thousandth
// of the smaller shape (1 cm cubes: 8.7 micrometres, not 0.1 mm).
inline constexpr MeReal kShapeFraction = (MeReal)1e-3;

// Model 1's pose seen from model 2 (see "Poses" above).
struct RelativePose {
  MeReal R[3][3];
  MeReal p[3];
};
RelativePose PoseOf(const McdModel *m1, const McdModel *m2);

// The reuse distance d of the pair: the framework's, at most kShapeFraction
// of the smaller shape's reach, when both geometry types are served by the
// engine's own interaction (see above); else 0.
MeReal ReuseDistance(const McdModelPair *pair);

// Fills `result` from the pair's memory when the rule allows it at
// tolerance `tolerance`, cap `cap` and distance `distance` (ReuseDistance),
// the pair's pose being `now`; false (result untouched) otherwise.
bool ServeFromMemory(McdModelPair *pair, McdIntersectResult *result, MeReal tolerance, int cap, MeReal distance,
                     const RelativePose &now);

// Remembers a full test's result (contacts in the caller's order) made at
// tolerance `tested` (t + d) with cap `cap` at the pose `now`. Allocation
// failure forgets.
void Remember(McdModelPair *pair, const McdIntersectResult *result, MeReal tested, int cap, const RelativePose &now);

// Whether every contact of `result` is at most `tolerance` apart.
bool AllWithin(const McdIntersectResult *result, MeReal tolerance);

// Frees the pair's memory.
void Forget(McdModelPair *pair);

}  // namespace karma::mcd
