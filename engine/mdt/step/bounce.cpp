// bounce.cpp: stage 7b of the step (step.h), the bounces of impacts found
// apart. A speculative contact that the bodies reach within the step, with
// restitution, was solved for the velocity that ends the step where the
// bounce takes them (contact.cpp, Row::bounceAfter); once the positions
// have moved, those rows get the impulses dlambda >= 0 that bring each J v
// up to its bounce speed b:
//     w = J v + A dlambda - b >= 0,  dlambda >= 0,  complementary,
//     A = J M^-1 J^T,  then v += M^-1 J^T dlambda,
// solved exactly for the rows of one constraint together (up to
// kSmallLcpMax: a face's corners share the bounce, so a box dropped flat
// bounces flat), one constraint after another. A partition in which no row
// asked for a bounce (no restitution, or no impact found apart) is not
// walked at all.
#include "small_lcp.h"
#include "step.h"

namespace karma::mdt {

namespace {

// M^-1 J^T of kept row k (12 values) and its J v over the bodies' velocities.
MeReal rowResponse(const BodySpaceProblem &p, StepScratch &s, const Partition &part, int k, MeReal mj[12]) {
  const int bodies[2] = {p.body0[(size_t)k], p.body1[(size_t)k]};
  MeReal jv = 0;
  for (int side = 0; side < 2; ++side) {
    MeReal *out = mj + side * 6;
    for (int e = 0; e < 6; ++e) out[e] = 0;
    const int b = bodies[side];
    if (b < 0) continue;
    const MdtBody *body = s.partBodies[(size_t)(part.bodyStart + b)];
    const MeReal *lin = sideJ(p, k, side), *ang = lin + 3;
    jv += MeVector3Dot(lin, body->velocity) + MeVector3Dot(ang, body->angularVelocity);
    sideMinvJt(p, k, side, out);
  }
  return jv;
}

void push(const BodySpaceProblem &p, StepScratch &s, const Partition &part, int k, const MeReal mj[12], MeReal dl) {
  const int bodies[2] = {p.body0[(size_t)k], p.body1[(size_t)k]};
  for (int side = 0; side < 2; ++side) {
    if (bodies[side] < 0) continue;
    MdtBody *body = s.partBodies[(size_t)(part.bodyStart + bodies[side])];
    MeVector3MultiplyAdd(body->velocity, dl, mj + side * 6);
    MeVector3MultiplyAdd(body->angularVelocity, dl, mj + side * 6 + 3);
  }
}

// The bounce of up to kSmallLcpMax rows (kept indices `ks`, bounce speeds
// `b`) together; one row at a time if the small LCP finds no answer.
void bounceTogether(const BodySpaceProblem &p, StepScratch &s, const Partition &part, const int *ks, const MeReal *b,
                    int n) {
  MeReal mj[kSmallLcpMax][12] = {}, q[kSmallLcpMax] = {}, lo[kSmallLcpMax] = {}, x[kSmallLcpMax] = {};
  MeReal A[kSmallLcpMax * kSmallLcpMax] = {};
  for (int i = 0; i < n; ++i) q[i] = b[i] - rowResponse(p, s, part, ks[i], mj[i]);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      MeReal a = 0;
      for (int side = 0; side < 2; ++side) {
        const MeReal *J = sideJ(p, ks[i], side);
        for (int e = 0; e < 6; ++e) a += J[e] * mj[j][side * 6 + e];
      }
      A[i * kSmallLcpMax + j] = a;
    }
  if (SolveSmallLcp(A, q, lo, n, x)) {
    for (int i = 0; i < n; ++i)
      if (x[i] > 0) push(p, s, part, ks[i], mj[i], x[i]);
    return;
  }
  for (int i = 0; i < n; ++i) {
    const MeReal need = b[i] - rowResponse(p, s, part, ks[i], mj[i]);
    const MeReal d = A[i * kSmallLcpMax + i];
    if (need > 0 && d > 0) push(p, s, part, ks[i], mj[i], need / d);
  }
}

}  // namespace

void applyBounces(StepScratch &s, const Partition &part, const PartitionRows &rows, const BodySpaceProblem &p) {
  if (rows.bounceRows == 0) return;
  for (int c = 0; c < part.constraintCount; ++c) {
    int ks[kSmallLcpMax], n = 0;
    MeReal b[kSmallLcpMax];
    for (int r = rows.constraintRowStart[(size_t)c]; r < rows.constraintRowStart[(size_t)c + 1]; ++r) {
      const int k = rows.solveIndex[(size_t)r];
      if (!(rows.rows[(size_t)r].bounceAfter > 0) || k < 0) continue;
      ks[n] = k;
      b[n++] = rows.rows[(size_t)r].bounceAfter;
      if (n == kSmallLcpMax) {
        bounceTogether(p, s, part, ks, b, n);
        n = 0;
      }
    }
    if (n > 0) bounceTogether(p, s, part, ks, b, n);
  }
}

}  // namespace karma::mdt
