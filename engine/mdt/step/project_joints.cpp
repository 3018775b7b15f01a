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
// universal's angular rows) get position impulses P_a at their anchors that
// close every anchor pair to first order, all joints at once:
//     C_a = p1_a - p0_a,
//     sum_b K_ab P_b = C_a,
//     K_ab = sum over bodies B of both a and b:  s_a(B) s_b(B) (m_B^-1 1 - [r_a]x W_B [r_b]x)
// with s_a(B) = +1 if B is joint a's body 0 and -1 if its body 1, r the
// anchors' levers from B's centre of mass and W_B the inverse of the
// inertia the projection sees (below). Each body then moves by
// (m^-1 sum s P, W sum s r x P). K is J diag(m^-1, W) J^T of the joints'
// point rows, symmetric positive semi-definite and nonzero only between
// joints that share a body, factorised by Cholesky in its envelope
// (envelope_cholesky.h; row 3a starts at the earliest joint in constraint
// order that shares a body with a), so a chain in order costs time linear in
// its joints. A diagonal of 64 ulps of K's largest entry keeps redundant
// joints solvable. Solving the joints together matters: joint by joint
// (Gauss-Seidel) the drift of a turning chain, the same way at every joint,
// needs tens of sweeps to leave.
//
// The metric. With W = I^-1 (the body's own inertia) the correction of a
// long chain of light links carries a large tension P along the chain, and
// a lever slightly out of line with it turns a light link by a large angle,
// which the linear model does not follow (a 70-link chain: one step leaves
// 85% of the gap). The second derivative of sum P . C with respect to the
// turns, the geometric stiffness of the tension, is what Newton's method on
// the projection's Lagrangian adds to the inertia; its positive part is
// |P| |r| (1 - r^ r^T) per anchor (as in stabilize.cpp, after Andrews,
// Teichmann and Kry 2017). So each iteration solves twice: once with
// W = I^-1 for the tension, then with W = (I + sum |P| |r| (1 - r^ r^T))^-1
// for the move. The move is taken whole, or halved up to twice until the
// largest gap shrinks; up to `iterations` iterations, stopping once every
// anchor pair is within the slop (1e-4 m times the world's length scale)
// or a move cannot shrink it.
//
// Velocities are not changed: the joints keep the velocity step's impulses,
// and positions move by at most the drift the step made.
//
// What it costs in behaviour (docs/STABILITY.md): the correction turns the
// bodies it moves, so a fast spinner on a ball joint (a top) has its axis
// tilted, and a body held both by a projected joint and by a soft row (a
// suspension) settles at another equilibrium. Hence off by default, and
// switched on by the programs whose joints whip (RainbowChain, Ballman).
#include <algorithm>
#include <cmath>

#include "envelope_cholesky.h"
#include "rows.h"
#include "step.h"

namespace karma::mdt {

namespace {

struct Mat3 {
  MeMatrix3 m;
};

// The partition's point joints, their anchors, and per body of the step
// (by MdtBody::index) the metric W and the move.
struct Projection {
  std::span<MdtConstraint *const> joints;
  std::span<Anchors> anchors;
  std::span<MdtBody *const> bodies;
  std::span<Mat3> W;
  std::span<MeVector3> dx, turn;
  std::span<MeVector3> savedPosition;  // per partition body, for a step back
  std::span<MeVector4> savedQ;
  EnvelopeMatrix K;
  std::span<MeReal> P;  // C on entry to a solve, the impulses after
};

// The sign of body B in joint c's anchor equation: +1 body 0, -1 body 1,
// 0 neither (the world is no body).
MeReal sideOf(const MdtConstraint *c, const MdtBody *B) {
  if (!B) return 0;
  return c->body[0] == B ? 1 : (c->body[1] == B ? -1 : 0);
}

// W = I^-1 for every body.
void plainMetric(Projection &p) {
  for (MdtBody *B : p.bodies) bodyTensorInWorld(p.W[(size_t)B->index].m, B, B->invInertia);
}

// W = (I + sum over its anchors |P| |r| (1 - r^ r^T))^-1, from the
// impulses in p.P.
void stiffMetric(Projection &p) {
  for (MdtBody *B : p.bodies) bodyTensorInWorld(p.W[(size_t)B->index].m, B, B->inertia);
  for (size_t a = 0; a < p.joints.size(); ++a) {
    const MeVector3 Pa = {p.P[3 * a], p.P[3 * a + 1], p.P[3 * a + 2]};
    const MeReal force = MeVector3Magnitude(Pa);
    for (int i = 0; i < 2; ++i) {
      MdtBody *B = p.joints[a]->body[i];
      const MeReal len = MeVector3Magnitude(p.anchors[a].r[i]);
      if (!B || !(len > 0)) continue;
      MeVector3 u;
      MeVector3MultiplyScalar(u, p.anchors[a].r[i], 1 / len);
      MeMatrix3 &I = p.W[(size_t)B->index].m;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) I[r][c] += force * len * ((r == c ? (MeReal)1 : (MeReal)0) - u[r] * u[c]);
    }
  }
  for (MdtBody *B : p.bodies) {
    MeMatrix3 inverse;
    if (MeMatrix3Inverse(inverse, p.W[(size_t)B->index].m))
      MeMatrix3Copy(p.W[(size_t)B->index].m, inverse);
    else
      bodyTensorInWorld(p.W[(size_t)B->index].m, B, B->invInertia);
  }
}

// K += sign (m^-1 1 - [ra]x W [rb]x) for one body, column by column: how
// the point at lever ra moves when the impulse e_j acts at lever rb,
// m^-1 e_j + (W (rb x e_j)) x ra.
void addPointMass(MeMatrix3 K, const MdtBody *b, MECONSTMATRIX MeMatrix3 W, const MeVector3 ra, const MeVector3 rb,
                  MeReal sign) {
  for (int j = 0; j < 3; ++j) {
    MeVector3 e = {0, 0, 0}, rxe, turn, col;
    e[j] = 1;
    MeVector3Cross(rxe, rb, e);
    MeMatrix3MultiplyVector(turn, W, rxe);
    MeVector3Cross(col, turn, ra);
    for (int i = 0; i < 3; ++i) K[i][j] += sign * (col[i] + (i == j ? b->invMass : 0));
  }
}

// K's envelope for the joints (see the top).
EnvelopeMatrix layOut(StepArena &arena, std::span<MdtConstraint *const> joints) {
  const int m = (int)joints.size(), n = 3 * m;
  EnvelopeMatrix e{arena.take<int>((size_t)n), arena.take<int>((size_t)n + 1), {}};
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

// The anchors and C (into P) as the joints stand; the largest gap.
MeReal measure(Projection &p) {
  MeReal worst = 0;
  for (size_t a = 0; a < p.joints.size(); ++a) {
    p.anchors[a] = anchorsOf(p.joints[a]);
    MeVector3 gap;
    MeVector3Subtract(gap, p.anchors[a].p[1], p.anchors[a].p[0]);
    for (int k = 0; k < 3; ++k) p.P[3 * a + (size_t)k] = gap[k];
    worst = std::fmax(worst, MeVector3Magnitude(gap));
  }
  return worst;
}

// K from the anchors and the metric.
void assemble(Projection &p) {
  const int m = (int)p.joints.size();
  for (MeReal &x : p.K.value) x = 0;
  MeReal largest = 0;
  for (int a = 0; a < m; ++a)
    for (int b = p.K.first[(size_t)(3 * a)] / 3; b <= a; ++b) {
      MeMatrix3 block = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      for (int i = 0; i < 2; ++i) {
        const MdtBody *B = p.joints[(size_t)a]->body[i];
        const MeReal sb = sideOf(p.joints[(size_t)b], B);
        if (sb == 0) continue;
        const int ib = p.joints[(size_t)b]->body[0] == B ? 0 : 1;
        addPointMass(block, B, p.W[(size_t)B->index].m, p.anchors[(size_t)a].r[i], p.anchors[(size_t)b].r[ib],
                     (i == 0 ? 1 : -1) * sb);
      }
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3 && (b < a || c <= r); ++c) {
          p.K.at(3 * a + r, 3 * b + c) = block[r][c];
          largest = std::fmax(largest, std::fabs(block[r][c]));
        }
    }
  const MeReal floor = largest * 64 * ME_REAL_EPSILON;
  for (int i = 0; i < 3 * m; ++i) p.K.at(i, i) += floor;
}

// P = K^-1 C for the current metric; false if K cannot be factorised.
bool solve(Projection &p, std::span<const MeReal> C) {
  std::copy(C.begin(), C.end(), p.P.begin());
  assemble(p);
  if (!envelopeCholesky(p.K)) return false;
  envelopeCholeskySolve(p.K, p.P);
  return true;
}

// Moves every body by alpha times the joints' impulses, summed per body
// first: the centre by m^-1 sum s P, the orientation by W sum s (r x P).
void move(Projection &p, MeReal alpha) {
  for (MdtBody *B : p.bodies) {
    MeVector3Set(p.dx[(size_t)B->index], 0, 0, 0);
    MeVector3Set(p.turn[(size_t)B->index], 0, 0, 0);
  }
  for (size_t a = 0; a < p.joints.size(); ++a) {
    const MeVector3 Pa = {alpha * p.P[3 * a], alpha * p.P[3 * a + 1], alpha * p.P[3 * a + 2]};
    for (int i = 0; i < 2; ++i) {
      MdtBody *B = p.joints[a]->body[i];
      if (!B) continue;
      const MeReal sign = i == 0 ? 1 : -1;
      MeVector3 rxP, turn;
      MeVector3Cross(rxP, p.anchors[a].r[i], Pa);
      MeMatrix3MultiplyVector(turn, p.W[(size_t)B->index].m, rxP);
      MeVector3MultiplyAdd(p.dx[(size_t)B->index], sign * B->invMass, Pa);
      MeVector3MultiplyAdd(p.turn[(size_t)B->index], sign, turn);
    }
  }
  for (MdtBody *B : p.bodies) {
    const MeReal *dx = p.dx[(size_t)B->index], *turn = p.turn[(size_t)B->index];
    if (MeVector3MagnitudeSqr(dx) == 0 && MeVector3MagnitudeSqr(turn) == 0) continue;
    MeVector3 com, c, rc;
    bodyCom(B, com);
    MeVector3Add(com, com, dx);
    MeQuaternionFiniteRotation(B->q, turn, 1);
    MeMatrix4TMGetPosition(c, B->comTM);
    MeQuaternionRotateVector(rc, B->q, c);
    MeVector3Subtract(B->position, com, rc);
    updateTransform(B);
  }
}

MeReal worstGap(const Projection &p) {
  MeReal worst = 0;
  for (MdtConstraint *c : p.joints) {
    const Anchors a = anchorsOf(c);
    worst = std::fmax(worst, MeVector3Distance(a.p[0], a.p[1]));
  }
  return worst;
}

void savePoses(Projection &p) {
  for (size_t i = 0; i < p.bodies.size(); ++i) {
    MeVector3Copy(p.savedPosition[i], p.bodies[i]->position);
    MeVector4Copy(p.savedQ[i], p.bodies[i]->q);
  }
}

void restorePoses(Projection &p) {
  for (size_t i = 0; i < p.bodies.size(); ++i) {
    MeVector3Copy(p.bodies[i]->position, p.savedPosition[i]);
    MeVector4Copy(p.bodies[i]->q, p.savedQ[i]);
    updateTransform(p.bodies[i]);
  }
}

// One iteration (see the top): false if the gaps are within the slop, K
// cannot be factorised, or no move shrinks the largest gap (poses then
// as before the iteration).
bool iterate(Projection &p, std::span<MeReal> C, MeReal slop) {
  const MeReal worst = measure(p);
  if (worst <= slop) return false;
  std::copy(p.P.begin(), p.P.end(), C.begin());
  plainMetric(p);
  if (!solve(p, C)) return false;
  stiffMetric(p);
  if (!solve(p, C)) return false;
  savePoses(p);
  for (MeReal alpha = 1; alpha >= (MeReal)0.25; alpha *= (MeReal)0.5) {
    move(p, alpha);
    if (worstGap(p) < worst) return true;
    restorePoses(p);
  }
  return false;
}

}  // namespace

void projectJoints(MdtWorldID world, StepScratch &s, const Partition &part) {
  const int iterations = world->params.jointProjection;
  if (iterations <= 0) return;
  std::span<MdtConstraint *> found = s.arena.take<MdtConstraint *>((size_t)part.constraintCount);
  size_t m = 0;
  for (int i = 0; i < part.constraintCount; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    if (isPointJoint(c)) found[m++] = c;
  }
  if (m == 0) return;
  const size_t nb = (size_t)part.bodyCount, all = s.bodies.size();
  Projection p{found.first(m),
               s.arena.take<Anchors>(m),
               std::span<MdtBody *const>(&s.partBodies[(size_t)part.bodyStart], nb),
               s.arena.take<Mat3>(all),
               s.arena.take<MeVector3>(all),
               s.arena.take<MeVector3>(all),
               s.arena.take<MeVector3>(nb),
               s.arena.take<MeVector4>(nb),
               layOut(s.arena, found.first(m)),
               s.arena.take<MeReal>(3 * m)};
  const std::span<MeReal> C = s.arena.take<MeReal>(3 * m);
  const MeReal slop = (MeReal)1e-4 * world->priv->lengthScale;
  for (int it = 0; it < iterations && iterate(p, C, slop); ++it) {
  }
}

}  // namespace karma::mdt
