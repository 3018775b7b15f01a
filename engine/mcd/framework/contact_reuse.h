// contact_reuse.h: McdIntersect's memory of a pair's last contacts (not
// installed).
//
// A resting pair's two shapes hardly move relative to each other from one
// step to the next, yet a full nearfield test (box-box: 15 axes and a
// clipping) runs every step. With a reuse distance d > 0
// (McdFrameworkSetContactReuseDistance), McdIntersect keeps the contacts of
// a pair's last full test, taken in each model's own frame, and serves a
// later call from them while the pair's relative pose has moved no surface
// point by more than d.
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
// the most any gap between the shapes can have changed (a plane, whose r
// is infinite, takes the other side's bound).
//
// Slack. The full test runs at the caller's tolerance t plus d, and
// remembers every contact it finds up to t + d apart; the call itself
// reports those up to t. A later call at tolerance t' is served from
// memory iff
//     D <= d  and  D + t' <= t + d,
// so a feature the full test did not find (farther than t + d then) is
// still farther than t' now: nothing within t' is missed. The memory is
// also dropped when the effective contact cap, either model's geometry,
// or any shape's size (the framework's shape revision) has changed.
//
// Contacts served from memory. Each remembered contact keeps its point
// in both models' coordinates (y_1, y_2: the same world point then), its
// normal in model 2's, its separation s0 and its other fields. Now, with
// x_k = model k's TM applied to y_k and n = model 2's axes applied to the
// normal:
//     position = (x_1 + x_2) / 2,   separation = s0 + (x_1 - x_2) . n
// (n points from model 2 towards model 1: model 1 moving along n opens the
// gap). Contacts farther apart than t' are left out; touch is 1 when any
// contact is reported.
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

// Model 1's pose seen from model 2 (see "Poses" above).
struct RelativePose {
  MeReal R[3][3];
  MeReal p[3];
};
RelativePose PoseOf(const McdModel *m1, const McdModel *m2);

// The reuse distance that applies to the pair: the framework's when both
// geometry types are served (see above), else 0.
MeReal ReuseDistance(const McdModelPair *pair);

// Fills `result` from the pair's memory when the rule allows it at
// tolerance `tolerance` and cap `cap`, the pair's pose being `now`; false
// (result untouched) otherwise.
bool ServeFromMemory(McdModelPair *pair, McdIntersectResult *result, MeReal tolerance, int cap,
                     const RelativePose &now);

// Remembers a full test's result (contacts in the caller's order) made at
// tolerance `tested` (t + d) with cap `cap` at the pose `now`. Allocation
// failure forgets.
void Remember(McdModelPair *pair, const McdIntersectResult *result, MeReal tested, int cap, const RelativePose &now);

// Leaves out of `result` the contacts farther apart than `tolerance`.
void DropBeyond(McdIntersectResult *result, MeReal tolerance);

// Frees the pair's memory.
void Forget(McdModelPair *pair);

}  // namespace karma::mcd
