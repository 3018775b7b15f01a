// project_joints.cpp: stage 7c of the step (step.h), optional: the point
// joints' position error removed after integration
// (MdtWorldSetJointProjection; off by default).
//
// Why. The velocity step holds a joint's anchors together to first order:
// it makes their velocities agree, but the centres move on straight lines
// while the bodies turn, so two bodies whipping round a joint at angular
// speed w drift apart by about h^2 w^2 d / 2 per step (d the distance
// between their centres), and gamma only removes a fraction of that a step
// later. A chain falling from the horizontal or a rag doll whose limbs swing
// at 20 rad/s opens by centimetres at 1/60 s.
//
// What. The partition's enabled ball-and-socket, hinge, universal and
// skeletal joints (m of them; only their common point, not a hinge's or a
// universal's angular rows) get position impulses P_a at their anchors such
// that every anchor pair closes to first order, all joints at once:
//     C_a = p1_a - p0_a,
//     sum_b K_ab P_b = C_a,
//     K_ab = sum over bodies B of both a and b:  s_a(B) s_b(B) (m_B^-1 1 - [r_a]x I_B^-1 [r_b]x)
// with s_a(B) = +1 if B is joint a's body 0 and -1 if its body 1, r the
// anchors' levers from B's centre of mass. Each body then moves by
// (m^-1 sum s P, I^-1 sum s r x P). K is J W J^T of the joints' point rows
// (W the inverse masses), symmetric positive semi-definite, and nonzero only
// between joints that share a body; it is factorised by Cholesky in its
// envelope (row 3a starts at joint first(a), the earliest joint in
// constraint order sharing a body with a; the factor fills nothing outside
// that), so a chain in order costs time linear in its joints. A diagonal of
// 64 ulps of K's largest entry keeps redundant joints solvable. One such
// solve is one Newton iteration of the non-linear anchor equations, taken
// whole, or halved up to twice until the largest gap shrinks (light links
// on long levers make the linear step overshoot: the turns it asks for are
// not small); up to `iterations` of them, stopping once every anchor pair
// is within the slop (1e-4 m times the world's length scale) or a step
// cannot shrink it. Solving the joints together
// matters: joint by joint (Gauss-Seidel) the drift of a turning chain, the
// same way at every joint, needs tens of sweeps to leave. Velocities are
// not changed: the joints keep the velocity step's impulses, and positions
// move by at most the drift the step made.
//
// What it costs in behaviour (docs/STABILITY.md): the correction turns the
// bodies it moves, so a fast spinner on a ball joint (a top) has its axis
// tilted, and a body held both by a projected joint and by a soft row (a
// suspension) settles at another equilibrium. Hence off by default, and
// switched on by the programs whose joints whip (RainbowChain, Ballman).
#include <algorithm>
#include <cmath>

#include "rows.h"
#include "step.h"

namespace karma::mdt {

namespace {

bool isPointJoint(const MdtConstraint *c) {
  switch (c->type->id) {
    case MdtConstraintTypeBSJoint:
    case MdtConstraintTypeHinge:
    case MdtConstraintTypeUniversal:
    case MdtConstraintTypeSkeletal:
      return true;
    default:
      return false;
  }
}

// K += sign (m^-1 1 - [ra]x I^-1 [rb]x) for one body, column by column:
// how the point at lever ra moves when the impulse e_j acts at lever rb,
// m^-1 e_j + (I^-1 (rb x e_j)) x ra.
void addPointMass(MeMatrix3 K, const MdtBody *b, const MeVector3 ra, const MeVector3 rb, MeReal sign) {
  for (int j = 0; j < 3; ++j) {
    MeVector3 e = {0, 0, 0}, rxe, turn, col;
    e[j] = 1;
    MeVector3Cross(rxe, rb, e);
    applyBodyTensor(turn, b, b->invInertia, rxe);
    MeVector3Cross(col, turn, ra);
    for (int i = 0; i < 3; ++i) K[i][j] += sign * (col[i] + (i == j ? b->invMass : 0));
  }
}

// Moves body b by the position impulse `sign` P applied at lever r from its
// centre of mass: the centre by m^-1 P, the orientation by I^-1 (r x P).
void moveBody(MdtBody *b, const MeVector3 r, const MeVector3 P, MeReal sign) {
  MeVector3 com, rxP, turn, c, rc;
  bodyCom(b, com);
  MeVector3MultiplyAdd(com, sign * b->invMass, P);
  MeVector3Cross(rxP, r, P);
  applyBodyTensor(turn, b, b->invInertia, rxP);
  MeQuaternionFiniteRotation(b->q, turn, sign);
  MeMatrix4TMGetPosition(c, b->comTM);
  MeQuaternionRotateVector(rc, b->q, c);
  MeVector3Subtract(b->position, com, rc);
  updateTransform(b);
}

// The sign of body B in joint c's anchor equation: +1 body 0, -1 body 1,
// 0 neither (the world is no body).
MeReal sideOf(const MdtConstraint *c, const MdtBody *B) {
  if (!B) return 0;
  return c->body[0] == B ? 1 : (c->body[1] == B ? -1 : 0);
}

// K in its envelope: row i holds columns first[i] .. i, at start[i].
struct Envelope {
  std::span<int> first, start;
  std::span<MeReal> value;
  MeReal &at(int i, int j) { return value[(size_t)(start[(size_t)i] + j - first[(size_t)i])]; }
};

// The envelope of the joints' K (see the top), zeroed.
Envelope layOut(StepArena &arena, std::span<MdtConstraint *const> joints) {
  const int m = (int)joints.size(), n = 3 * m;
  Envelope e{arena.take<int>((size_t)n), arena.take<int>((size_t)n + 1), {}};
  e.start[0] = 0;
  for (int a = 0; a < m; ++a) {
    int first = a;
    for (int b = 0; b < a && first == a; ++b)
      for (int i = 0; i < 2; ++i)
        if (sideOf(joints[(size_t)b], joints[(size_t)a]->body[i]) != 0) first = b;
    for (int r = 0; r < 3; ++r) {
      const int row = 3 * a + r;
      e.first[(size_t)row] = 3 * first;
      e.start[(size_t)row + 1] = e.start[(size_t)row] + row - 3 * first + 1;
    }
  }
  e.value = arena.take<MeReal>((size_t)e.start[(size_t)n]);
  return e;
}

// In-place Cholesky of K in its envelope (lower triangle) and the solve
// K x = b into b. False if a pivot is not positive.
bool choleskySolve(Envelope &K, std::span<MeReal> b) {
  const int n = (int)b.size();
  for (int i = 0; i < n; ++i) {
    const int fi = K.first[(size_t)i];
    for (int j = fi; j <= i; ++j) {
      MeReal s = K.at(i, j);
      for (int k = std::max(fi, K.first[(size_t)j]); k < j; ++k) s -= K.at(i, k) * K.at(j, k);
      if (j < i) {
        K.at(i, j) = s / K.at(j, j);
      } else {
        if (!(s > 0) || !std::isfinite(s)) return false;
        K.at(i, i) = std::sqrt(s);
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    MeReal s = b[(size_t)i];
    for (int k = K.first[(size_t)i]; k < i; ++k) s -= K.at(i, k) * b[(size_t)k];
    b[(size_t)i] = s / K.at(i, i);
  }
  for (int i = n - 1; i >= 0; --i) {
    b[(size_t)i] /= K.at(i, i);
    for (int k = K.first[(size_t)i]; k < i; ++k) b[(size_t)k] -= K.at(i, k) * b[(size_t)i];
  }
  return true;
}

// Fills K and C (3m) for the joints as they stand; returns the largest
// anchor distance.
MeReal assemble(std::span<MdtConstraint *const> joints, std::span<Anchors> anchors, Envelope &K, std::span<MeReal> C) {
  const int m = (int)joints.size();
  MeReal worst = 0;
  for (int a = 0; a < m; ++a) {
    anchors[(size_t)a] = anchorsOf(joints[(size_t)a]);
    MeVector3 gap;
    MeVector3Subtract(gap, anchors[(size_t)a].p[1], anchors[(size_t)a].p[0]);
    for (int k = 0; k < 3; ++k) C[(size_t)(3 * a + k)] = gap[k];
    worst = std::fmax(worst, MeVector3Magnitude(gap));
  }
  for (MeReal &x : K.value) x = 0;
  MeReal largest = 0;
  for (int a = 0; a < m; ++a)
    for (int b = K.first[(size_t)(3 * a)] / 3; b <= a; ++b) {
      MeMatrix3 block = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      for (int i = 0; i < 2; ++i) {
        const MdtBody *B = joints[(size_t)a]->body[i];
        const MeReal sb = sideOf(joints[(size_t)b], B);
        if (sb == 0) continue;
        const int ib = joints[(size_t)b]->body[0] == B ? 0 : 1;
        addPointMass(block, B, anchors[(size_t)a].r[i], anchors[(size_t)b].r[ib], (i == 0 ? 1 : -1) * sb);
      }
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3 && (b < a || c <= r); ++c) {
          K.at(3 * a + r, 3 * b + c) = block[r][c];
          largest = std::fmax(largest, std::fabs(block[r][c]));
        }
    }
  const MeReal floor = largest * 64 * ME_REAL_EPSILON;
  for (int i = 0; i < 3 * m; ++i) K.at(i, i) += floor;
  return worst;
}

// Moves every body by the joints' impulses alpha P (3 per joint).
void apply(std::span<MdtConstraint *const> joints, std::span<const Anchors> anchors, std::span<const MeReal> P,
           MeReal alpha) {
  for (size_t a = 0; a < joints.size(); ++a) {
    const MeVector3 Pa = {alpha * P[3 * a], alpha * P[3 * a + 1], alpha * P[3 * a + 2]};
    for (int i = 0; i < 2; ++i)
      if (MdtBody *B = joints[a]->body[i]) moveBody(B, anchors[a].r[i], Pa, i == 0 ? 1 : -1);
  }
}

MeReal worstGap(std::span<MdtConstraint *const> joints) {
  MeReal worst = 0;
  for (MdtConstraint *c : joints) {
    const Anchors a = anchorsOf(c);
    worst = std::fmax(worst, MeVector3Distance(a.p[0], a.p[1]));
  }
  return worst;
}

// The partition's bodies' poses, to take a step back.
struct Poses {
  std::span<MdtBody *const> bodies;
  std::span<MeVector3> position;
  std::span<MeVector4> q;
  void save() {
    for (size_t i = 0; i < bodies.size(); ++i) {
      MeVector3Copy(position[i], bodies[i]->position);
      MeVector4Copy(q[i], bodies[i]->q);
    }
  }
  void restore() {
    for (size_t i = 0; i < bodies.size(); ++i) {
      MeVector3Copy(bodies[i]->position, position[i]);
      MeVector4Copy(bodies[i]->q, q[i]);
      updateTransform(bodies[i]);
    }
  }
};

// One Newton iteration with a step back: the full step, else half of it,
// else a quarter, whichever first leaves the largest gap below `worst`;
// false (poses unchanged) if none does or K cannot be factorised.
bool newtonStep(std::span<MdtConstraint *const> joints, std::span<const Anchors> anchors, Envelope &K,
                std::span<MeReal> P, MeReal worst, Poses &poses) {
  if (!choleskySolve(K, P)) return false;
  poses.save();
  for (MeReal alpha = 1; alpha >= (MeReal)0.25; alpha *= (MeReal)0.5) {
    apply(joints, anchors, P, alpha);
    if (worstGap(joints) < worst) return true;
    poses.restore();
  }
  return false;
}

}  // namespace

void projectJoints(MdtWorldID world, StepScratch &s, const Partition &part) {
  const int iterations = world->params.jointProjection;
  if (iterations <= 0) return;
  const MeReal slop = (MeReal)1e-4 * world->priv->lengthScale;
  std::span<MdtConstraint *> all = s.arena.take<MdtConstraint *>((size_t)part.constraintCount);
  size_t m = 0;
  for (int i = 0; i < part.constraintCount; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    if (isPointJoint(c)) all[m++] = c;
  }
  if (m == 0) return;
  const std::span<MdtConstraint *const> joints = all.first(m);
  const std::span<Anchors> anchors = s.arena.take<Anchors>(m);
  const std::span<MeReal> P = s.arena.take<MeReal>(3 * m);
  Envelope K = layOut(s.arena, joints);
  const std::span<MdtBody *const> bodies(&s.partBodies[(size_t)part.bodyStart], (size_t)part.bodyCount);
  Poses poses{bodies, s.arena.take<MeVector3>(bodies.size()), s.arena.take<MeVector4>(bodies.size())};
  for (int it = 0; it < iterations; ++it) {
    const MeReal worst = assemble(joints, anchors, K, P);
    if (worst <= slop || !newtonStep(joints, anchors, K, P, worst, poses)) return;
  }
}

}  // namespace karma::mdt
