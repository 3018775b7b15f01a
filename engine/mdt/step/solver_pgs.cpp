// solver_pgs.cpp: projected Gauss-Seidel in body space (sequential
// impulses), the partition solver the world uses with MdtKeaMethodPGS.
//
// It never forms A. Each body keeps the velocity change the impulses have
// made so far, dv = M^-1 J^T lambda; row i's slack is then
//     w_i = J_i dv + softness_i lambda_i - rhs_i,
// and one Gauss-Seidel update of row i is
//     lambda_i <- clamp(lambda_i - w_i (1 / d_i), lo_i, hi_i),
//     d_i = J_i M^-1 J_i^T + softness_i,
// followed by dv += M^-1 J_i^T (change of lambda_i). A friction row's bounds
// are +-mu_i times its normal row's current impulse. This is Gauss-Seidel on
// A lambda = rhs with projection, the same iteration as Kea's PGS, at O(12)
// per row instead of a pass over the row's matrix entries.
//
// Contact blocks: the normal rows of one contact group (up to kMaxBlock of
// them, sharing their two bodies) are updated together, exactly, as one
// small LCP, so the corners of a face share the load symmetrically instead
// of the first corner in the sweep taking it all (which tips a stack).
// A persistent face's step is over-relaxed (block projected SOR): when
// every row of the block was warm-started with a nonzero impulse (the face
// carried load last step), with x the block's exact answer given the
// current dv,
//     lambda_b <- max(lo_b, lambda_b + kFaceRelaxation (x - lambda_b)).
// In a resting stack the load travels one face per sweep, and each face
// takes only the load it sees so far; stepping past it anticipates the
// load still coming (for a symmetric positive definite A, projected SOR
// converges for 0 < omega < 2 row by row: Cryer 1971; for whole faces,
// clamped row by row and coupled to friction, omega was chosen by
// measurement, below). A new face (an impact) keeps
// the plain step, as do point contacts, friction and joints: over-relaxing
// those made the rag doll and the car take more sweeps (docs/NOTES.md,
// "Over-relaxed faces").
//
// Joint block: the equality rows (unbounded, not friction: the rows of
// joints and other bilateral constraints) are updated together, exactly,
// as one visit of each sweep: with w_E their slacks at the current dv,
//     K delta = -w_E,   K = J_E M^-1 J_E^T + diag(softness_E),
//     lambda_E += delta,   dv += M^-1 J_E^T delta,
// after which every equality row's slack is zero. K is factorised once per
// solve by Cholesky in its envelope (envelope_cholesky.h; row e starts at
// the earliest equality row sharing a body with it), so a chain in
// constraint order costs time linear in its rows. This is block
// Gauss-Seidel, which converges like Gauss-Seidel on A, but a chain of
// joints is solved in one visit whatever its mass ratios: row by row, a
// 1000:1 chain of stiff rows needs thousands of sweeps, and warm-started
// from an unconverged answer it diverges from step to step. The block is
// skipped (rows updated one by one) when there are fewer than two equality
// rows, when its envelope would hold more than kMaxEnvelopePerRow entries
// per row on average (a body shared by many joints: a car's chassis, a rag
// doll's torso), or when K is not numerically positive definite (a pivot
// below 64 eps of its diagonal entry: rigid redundant rows). Within that
// bound the block's solve costs a sweep about what the row updates it
// replaces cost, and its factorisation a few sweeps; a visit whose slacks
// are all within the tolerance changes nothing.
//
// Warm start: lambda starts from the problem's warm impulses (clamped), and
// dv from them. Sweeps alternate forward and backward through the rows
// (symmetric Gauss-Seidel), so the order of the rows biases no direction
// from one step to the next; the last sweep of the cap always runs
// backward (an odd count starts backward), because a solve that ends on a
// forward sweep leaves the same one-sided error every step and a resting
// stack creeps with it. It stops after the settings' sweep count
// (default 50) or once a sweep changes no row's velocity by more than the
// tolerance times (1 + max |rhs|); it returns the last iterate (its natural-
// map residual, as in kea_lcp.h, is reported).
//
// Arithmetic for speed: a sweep is one chain of dependent updates (each
// row reads the dv the previous one wrote), so its time is the latency of
// one update and the instructions it issues. Each side of a row and each
// body's dv is a lin, ang pair of four-lane vectors ({x, y, z, 0}), so J_i dv
// is four lane products, two lane sums and one sum of four lanes, and a
// push four lane multiply-adds; a static side reads and writes a zero slot
// instead of being tested for. The update multiplies by 1 / d_i, kept per
// row, instead of dividing; the part of the slack that does not depend on
// dv (softness_i lambda_i - rhs_i) is added to J_i dv last. A contact's two
// friction rows and a face's normal rows compute their slacks from the
// same dv, side by side (FrictionPair, updateBlock).
#include <algorithm>
#include <climits>
#include <cmath>

#include "envelope_cholesky.h"
#include "partition_solver.h"
#include "small_lcp.h"

namespace karma::mdt {

namespace {

constexpr int kDefaultSweeps = 50;

MeReal defaultTolerance() { return sizeof(MeReal) == 4 ? (MeReal)1e-4 : (MeReal)1e-10; }

// Contact normal blocks of at most this many rows are solved as one unit.
constexpr int kMaxBlock = kSmallLcpMax;

// The over-relaxation of a persistent face's step (see the top). Mean
// sweeps per step with the iterative solver forced (anchor_scene_trace
// --iterative-rows 1, every face over-relaxed): stack21 21.0 at 1.0, 12.4
// at 1.4, 11.3 at 1.5, 9.8 at 1.6; topple 42.2, 34.0, 34.2, 35.9 (six
// partitions); beyond 1.6 topple's sweeps grow again. Persistent faces
// only, at 1.5: stack21 11.1, topple 33.8.
constexpr MeReal kFaceRelaxation = (MeReal)1.5;

// The joint block's envelope may hold at most this many entries per row
// on average: a chain of ball joints holds about 5, of hinges about 8; a
// car's 20 joint rows on one chassis 10.5, a rag doll's 27 rows 9.3.
constexpr int kMaxEnvelopePerRow = 8;

// w.block's mark for a row of the joint block, and the schedule's visit
// of the block.
constexpr int kJointBlockRow = -2;
constexpr int kJointBlockVisit = INT_MIN;

// Four lanes: one side's linear or angular part of a row, or one body's
// dv, as {x, y, z, 0}. A row's J dv and its push run in lanes; the lanes
// of a sum are added as (l0 + l2) + (l1 + l3) (sum4), the same bits on
// every machine (element-wise operations, no contraction).
using Lane4 = MeReal __attribute__((vector_size(4 * sizeof(MeReal))));

MeReal sum4(Lane4 v) { return (v[0] + v[2]) + (v[1] + v[3]); }

// What one row's update reads, in one record (the problem's arrays are
// one per field): its Jacobian and M^-1 J^T per side (lin, ang: J[2 s],
// J[2 s + 1]), where its bodies' dv are (dv0, dv1: Lane4 offsets in
// Workspace::dv; a static side has the zero slot, and zero M^-1 J^T, so
// that the update needs no test), the bodies themselves (-1: static), d_i,
// and its bounds or its normal row.
struct PgsRow {
  Lane4 J[4];
  Lane4 mj[4];
  int dv0, dv1;
  int body0, body1;
  MeReal diag, invDiag, softness, rhs, lo, hi, mu;  // invDiag = 1 / diag, 0 for a null row
  int normal;                                       // a friction row's normal row, else -1
};

// J_side . (M^-1 J^T)_side of two rows' sides (a and m point at a lin, ang
// pair).
MeReal sideDot(const Lane4 *a, const Lane4 *m) { return sum4(a[0] * m[0] + a[1] * m[1]); }

// The equality rows and their factorised K (see the top).
struct JointBlock {
  std::span<int> rows;      // problem rows, ascending
  EnvelopeMatrix L;         // K's Cholesky factor
  std::span<MeReal> delta;  // scratch: -w_E, then the change of lambda_E
  MeReal tolerance = 0;     // the solve's: slacks all within it need no update
};

// The two friction rows of one contact (rows `first` and first + 1, the
// same bodies, both bounded by +-mu times the same normal impulse), updated
// together: with s their slacks at the current dv and
//     K = [d_1 k; k d_2],   k = J_1 M^-1 J_2^T,
// the pair's exact step is x = lambda - K^-1 s. When x lies inside both
// rows' boxes (static friction, the common case at rest) it is taken: a
// block Gauss-Seidel step, whose two slacks are computed from the same dv
// and so run side by side instead of one after the other. Otherwise the
// two rows are updated one by one, as without the pair, which projects
// each onto its box. invK holds K^-1 = [k22 -k; -k k11] / det.
struct FrictionPair {
  int first;
  MeReal invK11, invK12, invK22;
};

struct Workspace {
  std::span<PgsRow> row;                  // per row
  std::span<Lane4> dv;                    // 2 per body (linear, angular), then the zero slot
  std::span<int> block;                   // per row: its normal block, kJointBlockRow, or -1
  std::span<MeReal> blockA;               // per block: its kMaxBlock^2 matrix A_bb (row-major, k x k used)
  std::span<SmallLcpFullSet> blockFull;   // per qualifying block: A_bb's elimination with every row free
  std::span<unsigned char> blockRelaxed;  // per qualifying block: a persistent face, over-relaxed (see the top)
  JointBlock joints;
  std::span<FrictionPair> pairs;  // the friction pairs (see FrictionPair)
  std::span<int> pair;            // per row: its friction pair, or -1
  // The sweeps' visits, forward and backward: a row alone (>= 0), a normal
  // block b (encoded -1 - b) or friction pair f (encoded -1 - blockCount -
  // f) at the first of its rows the sweep meets, or the joint block.
  std::span<int> forward, backward;
};

MeReal dot6(const MeReal *a, const MeReal *b) {
  return ((a[0] * b[0] + a[1] * b[1]) + (a[2] * b[2] + a[3] * b[3])) + (a[4] * b[4] + a[5] * b[5]);
}

// A block qualifies when its rows share both bodies (a contact group's do)
// and are bounded below only.
bool blockable(const BodySpaceProblem &p, int b) {
  const int first = p.normalBlock[(size_t)b], last = p.normalBlock[(size_t)b + 1];
  if (last - first < 2 || last - first > kMaxBlock) return false;
  const int r0 = p.normalRows[(size_t)first];
  for (int k = first; k < last; ++k) {
    const int r = p.normalRows[(size_t)k];
    if (p.body0[(size_t)r] != p.body0[(size_t)r0] || p.body1[(size_t)r] != p.body1[(size_t)r0]) return false;
    if (p.hi[(size_t)r] < MEINFINITY || p.friction[(size_t)r] >= 0) return false;
  }
  return true;
}

// Whether every row of block b carried an impulse last step (see the top).
bool persistentFace(const BodySpaceProblem &p, int b) {
  for (int k = p.normalBlock[(size_t)b]; k < p.normalBlock[(size_t)b + 1]; ++k)
    if (p.warm[(size_t)p.normalRows[(size_t)k]] == 0) return false;
  return true;
}

// Each qualifying block's matrix A_bb = J_b M^-1 J_b^T + diag(softness),
// and whether it is over-relaxed.
void prepareBlocks(const BodySpaceProblem &p, Workspace &w, StepArena &arena) {
  w.block = arena.filled<int>((size_t)p.rowCount, -1);
  w.blockA = arena.take<MeReal>((size_t)p.blockCount * kMaxBlock * kMaxBlock);
  w.blockFull = arena.take<SmallLcpFullSet>((size_t)p.blockCount);
  w.blockRelaxed = arena.take<unsigned char>((size_t)p.blockCount);
  for (int b = 0; b < p.blockCount; ++b) {
    if (!blockable(p, b)) continue;
    w.blockRelaxed[(size_t)b] = persistentFace(p, b);
    const int first = p.normalBlock[(size_t)b], k = p.normalBlock[(size_t)b + 1] - first;
    MeReal *A = &w.blockA[(size_t)b * kMaxBlock * kMaxBlock];
    for (int i = 0; i < k; ++i) {
      const int ri = p.normalRows[(size_t)(first + i)];
      w.block[(size_t)ri] = b;
      for (int j = 0; j < k; ++j) {
        const int rj = p.normalRows[(size_t)(first + j)];
        const PgsRow &a = w.row[(size_t)ri], &c = w.row[(size_t)rj];
        A[i * kMaxBlock + j] = (i == j ? a.softness : 0) + sideDot(a.J, c.mj) + sideDot(a.J + 2, c.mj + 2);
      }
    }
    EliminateSmallLcpFullSet(A, k, w.blockFull[(size_t)b]);
  }
}

bool isEquality(const PgsRow &r) { return r.normal < 0 && r.lo <= -MEINFINITY && r.hi >= MEINFINITY && r.diag > 0; }

// K_ac for rows a and c: J_a M^-1 J_c^T over the bodies they share.
MeReal coupling(const PgsRow &a, const PgsRow &c) {
  const int aBody[2] = {a.body0, a.body1}, cBody[2] = {c.body0, c.body1};
  MeReal k = 0;
  for (int s = 0; s < 2; ++s)
    for (int t = 0; t < 2; ++t)
      if (aBody[s] >= 0 && aBody[s] == cBody[t]) k += sideDot(a.J + 2 * s, c.mj + 2 * t);
  return k;
}

// The equality rows' envelope: row e starts at the earliest equality row
// that shares a body with it. Returns false (no block) when it would be
// too full.
bool layOutJointBlock(const BodySpaceProblem &p, Workspace &w, StepArena &arena) {
  JointBlock &jb = w.joints;
  const int m = (int)jb.rows.size();
  std::span<int> bodyFirst = arena.filled<int>((size_t)p.bodyCount, -1);
  jb.L.first = arena.take<int>((size_t)m);
  jb.L.start = arena.take<int>((size_t)m + 1);
  int total = 0;
  for (int e = 0; e < m; ++e) {
    const PgsRow &r = w.row[(size_t)jb.rows[(size_t)e]];
    int first = e;
    for (int body : {r.body0, r.body1}) {
      if (body < 0) continue;
      int &f = bodyFirst[(size_t)body];
      if (f < 0) f = e;
      first = std::min(first, f);
    }
    jb.L.first[(size_t)e] = first;
    jb.L.start[(size_t)e] = total;
    total += e - first + 1;
  }
  jb.L.start[(size_t)m] = total;
  return total <= kMaxEnvelopePerRow * m;
}

// The joint block (see the top), when it applies.
void prepareJointBlock(const BodySpaceProblem &p, Workspace &w, StepArena &arena) {
  int m = 0;
  for (const PgsRow &r : w.row) m += isEquality(r);
  if (m < 2) return;
  JointBlock &jb = w.joints;
  jb.rows = arena.take<int>((size_t)m);
  for (int i = 0, e = 0; i < p.rowCount; ++i)
    if (isEquality(w.row[(size_t)i])) jb.rows[(size_t)e++] = i;
  if (!layOutJointBlock(p, w, arena)) return;
  jb.L.value = arena.take<MeReal>((size_t)jb.L.start[(size_t)m]);
  for (int e = 0; e < m; ++e) {
    const PgsRow &re = w.row[(size_t)jb.rows[(size_t)e]];
    for (int c = jb.L.first[(size_t)e]; c < e; ++c) jb.L.at(e, c) = coupling(re, w.row[(size_t)jb.rows[(size_t)c]]);
    jb.L.at(e, e) = re.diag;
  }
  if (!envelopeCholesky(jb.L)) return;
  jb.delta = arena.take<MeReal>((size_t)m);
  for (int i : jb.rows) w.block[(size_t)i] = kJointBlockRow;
}

// The friction pairs (see FrictionPair): two adjacent friction rows of one
// normal row, on the same bodies, in no block, with K well conditioned
// (det K above 64 eps d_1 d_2; tangent directions are orthogonal, so K is
// nearly diagonal).
void prepareFrictionPairs(const BodySpaceProblem &p, Workspace &w, StepArena &arena) {
  w.pair = arena.filled<int>((size_t)p.rowCount, -1);
  w.pairs = arena.take<FrictionPair>((size_t)p.rowCount / 2);  // a pair takes two rows
  size_t count = 0;
  for (int i = 0; i + 1 < p.rowCount; ++i) {
    const PgsRow &a = w.row[(size_t)i], &c = w.row[(size_t)i + 1];
    if (a.normal < 0 || c.normal != a.normal || a.dv0 != c.dv0 || a.dv1 != c.dv1) continue;
    if (w.block[(size_t)i] != -1 || w.block[(size_t)i + 1] != -1 || !(a.diag > 0) || !(c.diag > 0)) continue;
    const MeReal k = coupling(a, c), det = a.diag * c.diag - k * k;
    if (!(det > 64 * ME_REAL_EPSILON * a.diag * c.diag)) continue;
    w.pairs[count] = {i, c.diag / det, -k / det, a.diag / det};
    w.pair[(size_t)i] = w.pair[(size_t)i + 1] = (int)count++;
    ++i;
  }
  w.pairs = w.pairs.first(count);
}

// The visits of one sweep through `rows` rows in the order `rowAt(n)`
// gives: each row alone, or its normal block, friction pair or the joint
// block, the first time the sweep meets one of its rows. Returns the
// visits written.
template <class RowAt>
int schedule(const Workspace &w, int rows, int blockCount, RowAt rowAt, std::span<int> out,
             std::span<unsigned char> seen) {
  std::fill(seen.begin(), seen.end(), (unsigned char)0);
  bool jointsSeen = false;
  int n = 0;
  for (int k = 0; k < rows; ++k) {
    const int i = rowAt(k), b = w.block[(size_t)i];
    if (b == kJointBlockRow) {
      if (!jointsSeen) out[(size_t)n++] = kJointBlockVisit;
      jointsSeen = true;
    } else if (w.pair[(size_t)i] >= 0) {
      const int code = -1 - blockCount - w.pair[(size_t)i];  // its two rows are adjacent in either order
      if (n == 0 || out[(size_t)n - 1] != code) out[(size_t)n++] = code;
    } else if (b < 0) {
      out[(size_t)n++] = i;
    } else if (!seen[(size_t)b]) {
      seen[(size_t)b] = 1;
      out[(size_t)n++] = -1 - b;
    }
  }
  return n;
}

void prepareSchedules(const BodySpaceProblem &p, Workspace &w, StepArena &arena) {
  std::span<unsigned char> seen = arena.take<unsigned char>((size_t)p.blockCount);
  const int rows = p.rowCount;
  w.forward = arena.take<int>((size_t)rows);
  w.backward = arena.take<int>((size_t)rows);
  w.forward = w.forward.first((size_t)schedule(
      w, rows, p.blockCount, [](int k) { return k; }, w.forward, seen));
  w.backward = w.backward.first((size_t)schedule(
      w, rows, p.blockCount, [&](int k) { return rows - 1 - k; }, w.backward, seen));
}

// Six values as a lin, ang pair of lanes.
void toLanes(const MeReal *six, Lane4 *out) {
  out[0] = Lane4{six[0], six[1], six[2], 0};
  out[1] = Lane4{six[3], six[4], six[5], 0};
}

PgsRow gatherRow(const BodySpaceProblem &p, int i) {
  PgsRow r{};
  const size_t k = (size_t)i;
  r.body0 = p.body0[k];
  r.body1 = p.body1[k];
  const int zeroSlot = 2 * p.bodyCount;
  r.dv0 = r.body0 >= 0 ? 2 * r.body0 : zeroSlot;
  r.dv1 = r.body1 >= 0 ? 2 * r.body1 : zeroSlot;
  MeReal d = p.softness[k];
  const int bodies[2] = {r.body0, r.body1};
  for (int side = 0; side < 2; ++side) {
    const MeReal *J = sideJ(p, i, side);
    toLanes(J, r.J + 2 * side);
    if (bodies[side] < 0) continue;  // mj stays zero
    MeReal mj[6];
    sideMinvJt(p, i, side, mj);
    toLanes(mj, r.mj + 2 * side);
    d += dot6(J, mj);
  }
  r.diag = d;
  r.invDiag = d > 0 ? 1 / d : 0;
  r.softness = p.softness[k];
  r.rhs = p.rhs[k];
  r.lo = p.lo[k];
  r.hi = p.hi[k];
  r.mu = p.mu[k];
  r.normal = p.friction[k];
  return r;
}

Workspace prepare(const BodySpaceProblem &p, StepArena &arena) {
  Workspace w;
  w.row = arena.take<PgsRow>((size_t)p.rowCount);
  w.dv = arena.filled<Lane4>((size_t)p.bodyCount * 2 + 2, Lane4{0, 0, 0, 0});
  for (int i = 0; i < p.rowCount; ++i) w.row[(size_t)i] = gatherRow(p, i);
  prepareBlocks(p, w, arena);
  prepareJointBlock(p, w, arena);
  prepareFrictionPairs(p, w, arena);
  prepareSchedules(p, w, arena);
  return w;
}

// The row's bounds for the current impulses.
void bounds(const PgsRow &r, std::span<const MeReal> lambda, MeReal &lo, MeReal &hi) {
  if (r.normal >= 0) {
    hi = r.mu * std::max(lambda[(size_t)r.normal], MeReal(0));
    lo = -hi;
  } else {
    lo = r.lo;
    hi = r.hi;
  }
}

// J_i dv.
[[gnu::always_inline]] inline MeReal rowVelocity(const PgsRow &r, const Lane4 *dv) {
  const Lane4 *a = dv + r.dv0, *b = dv + r.dv1;
  return sum4((r.J[0] * a[0] + r.J[1] * a[1]) + (r.J[2] * b[0] + r.J[3] * b[1]));
}

// w_i = J_i dv + (softness_i lambda_i - rhs_i).
[[gnu::always_inline]] inline MeReal rowSlack(const PgsRow &r, const Lane4 *dv, MeReal lambda) {
  return rowVelocity(r, dv) + (r.softness * lambda - r.rhs);
}

// dv += M^-1 J_i^T * delta (a static side adds zeros to the zero slot).
void push(const PgsRow &r, Lane4 *dv, MeReal delta) {
  Lane4 *a = dv + r.dv0, *b = dv + r.dv1;
  a[0] += r.mj[0] * delta;
  a[1] += r.mj[1] * delta;
  b[0] += r.mj[2] * delta;
  b[1] += r.mj[3] * delta;
}

// One Gauss-Seidel update of row i; returns the velocity change it made.
MeReal update(Workspace &w, std::span<MeReal> lambda, int i) {
  const PgsRow &r = w.row[(size_t)i];
  const MeReal d = r.diag;
  if (!(d > 0)) return 0;  // a null row: nothing to gain from it
  Lane4 *dv = w.dv.data();
  const MeReal slack = rowSlack(r, dv, lambda[(size_t)i]);
  MeReal lo, hi;
  bounds(r, lambda, lo, hi);
  const MeReal old = lambda[(size_t)i];
  const MeReal next = std::clamp(old - slack * r.invDiag, lo, hi);
  lambda[(size_t)i] = next;
  push(r, dv, next - old);
  return std::fabs(next - old) * d;
}

// One update of normal block b: the k rows' impulses x together solve the
// small LCP  w' = w + A_bb (x - lambda_b) = A_bb x - q >= 0, x >= lo,
// complementary: x = lambda - A_bb^-1 w when that is above lo (every row
// free), else by small_lcp.h; a persistent face then moves
// kFaceRelaxation times as far, kept above lo. Returns the largest
// velocity change, or -1 when no set fits (rounding): the caller then
// updates row by row.
MeReal updateBlock(const BodySpaceProblem &p, Workspace &w, std::span<MeReal> lambda, int b) {
  const int first = p.normalBlock[(size_t)b], k = p.normalBlock[(size_t)b + 1] - first;
  const MeReal *A = &w.blockA[(size_t)b * kMaxBlock * kMaxBlock];
  MeReal lam[kMaxBlock] = {}, lo[kMaxBlock] = {}, q[kMaxBlock] = {};
  int rows[kMaxBlock] = {};
  for (int i = 0; i < k; ++i) {
    rows[i] = p.normalRows[(size_t)(first + i)];
    lam[i] = lambda[(size_t)rows[i]];
    lo[i] = p.lo[(size_t)rows[i]];
  }
  MeReal slack[kMaxBlock] = {}, x[kMaxBlock] = {};
  for (int i = 0; i < k; ++i) slack[i] = rowSlack(w.row[(size_t)rows[i]], w.dv.data(), lam[i]);
  // Every row free (a face at rest): x = lambda - A_bb^-1 w, the slacks
  // multiplied by the kept inverse side by side, no chain of divisions.
  const SmallLcpFullSet &full = w.blockFull[(size_t)b];
  for (int i = 0; i < k; ++i) {
    MeReal step = 0;
    for (int j = 0; j < k; ++j) step += full.inverse[i][j] * slack[j];
    x[i] = lam[i] - step;
  }
  bool fits = full.ok;
  for (int i = 0; i < k; ++i) fits = fits && x[i] >= lo[i];
  if (!fits) {
    // w' = A x - q with q = A lambda - w; the rows the all-free step left
    // above their bound are the first guess of the free set.
    unsigned guess = 0;
    for (int i = 0; i < k; ++i) guess |= x[i] > lo[i] ? 1u << i : 0u;  // read only when full.ok
    for (int i = 0; i < k; ++i) {
      q[i] = -slack[i];
      for (int j = 0; j < k; ++j) q[i] += A[i * kMaxBlock + j] * lam[j];
    }
    if (!(full.ok ? SolveSmallLcpAfterFull(A, q, lo, k, guess, x) : SolveSmallLcp(A, full, q, lo, k, x))) return -1;
  }
  if (w.blockRelaxed[(size_t)b])
    for (int i = 0; i < k; ++i) x[i] = std::max(lo[i], lam[i] + kFaceRelaxation * (x[i] - lam[i]));
  MeReal biggest = 0;
  for (int i = 0; i < k; ++i) {
    lambda[(size_t)rows[i]] = x[i];
    push(w.row[(size_t)rows[i]], w.dv.data(), x[i] - lam[i]);
    biggest = std::max(biggest, std::fabs(x[i] - lam[i]) * w.row[(size_t)rows[i]].diag);
  }
  return biggest;
}

// One exact update of the joint block: delta = K^-1 (-w_E). Returns the
// largest slack it removes, max_e |w_e| (a row's update changes its
// velocity by its slack, unless clamped); when that is within the
// tolerance, the block is left as it is.
MeReal updateJointBlock(Workspace &w, std::span<MeReal> lambda) {
  JointBlock &jb = w.joints;
  const size_t m = jb.rows.size();
  MeReal biggest = 0;
  for (size_t e = 0; e < m; ++e) {
    const int i = jb.rows[e];
    jb.delta[e] = -rowSlack(w.row[(size_t)i], w.dv.data(), lambda[(size_t)i]);
    biggest = std::max(biggest, std::fabs(jb.delta[e]));
  }
  if (biggest <= jb.tolerance) return biggest;
  envelopeCholeskySolve(jb.L, jb.delta);
  for (size_t e = 0; e < m; ++e) {
    lambda[(size_t)jb.rows[e]] += jb.delta[e];
    push(w.row[(size_t)jb.rows[e]], w.dv.data(), jb.delta[e]);
  }
  return biggest;
}

// One visit of friction pair f (see FrictionPair). Returns the largest
// velocity change.
MeReal updatePair(Workspace &w, std::span<MeReal> lambda, int f) {
  const FrictionPair &pair = w.pairs[(size_t)f];
  const int i = pair.first;
  const PgsRow &a = w.row[(size_t)i], &c = w.row[(size_t)i + 1];
  Lane4 *dv = w.dv.data();
  const MeReal la = lambda[(size_t)i], lc = lambda[(size_t)i + 1];
  const MeReal sa = rowSlack(a, dv, la), sc = rowSlack(c, dv, lc);
  const MeReal xa = la - (pair.invK11 * sa + pair.invK12 * sc);
  const MeReal xc = lc - (pair.invK12 * sa + pair.invK22 * sc);
  const MeReal normal = std::max(lambda[(size_t)a.normal], MeReal(0));
  const MeReal ha = a.mu * normal, hc = c.mu * normal;
  if (!(std::fabs(xa) <= ha && std::fabs(xc) <= hc))
    return std::max(update(w, lambda, i), update(w, lambda, i + 1));  // a box binds: row by row
  lambda[(size_t)i] = xa;
  lambda[(size_t)i + 1] = xc;
  push(a, dv, xa - la);
  push(c, dv, xc - lc);
  return std::max(std::fabs(xa - la) * a.diag, std::fabs(xc - lc) * c.diag);
}

// One visit of a sweep's schedule: row i alone (i >= 0), the joint block
// (kJointBlockVisit), normal block -1 - i or friction pair -1 - i -
// blockCount.
MeReal visit(const BodySpaceProblem &p, Workspace &w, std::span<MeReal> lambda, int i) {
  if (i >= 0) return update(w, lambda, i);
  if (i == kJointBlockVisit) return updateJointBlock(w, lambda);
  if (-1 - i >= p.blockCount) return updatePair(w, lambda, -1 - i - p.blockCount);
  const int b = -1 - i;
  const MeReal change = updateBlock(p, w, lambda, b);
  if (change >= 0) return change;
  MeReal biggest = 0;  // no consistent set (rounding): row by row
  const int first = p.normalBlock[(size_t)b], last = p.normalBlock[(size_t)b + 1];
  for (int k = first; k < last; ++k) biggest = std::max(biggest, update(w, lambda, p.normalRows[(size_t)k]));
  return biggest;
}

// Brings every friction row inside +-mu times its normal row's final
// impulse (dv follows). A face's last visit in a sweep can lower its normal
// impulses after its contacts' friction had their last visit (the schedule
// meets a face at its first row, in either direction), so without this the
// returned friction could exceed Coulomb's bound, up to friction at a
// normal impulse of zero when few sweeps stop far from the answer.
void projectFriction(Workspace &w, std::span<MeReal> lambda) {
  for (size_t i = 0; i < w.row.size(); ++i) {
    const PgsRow &r = w.row[i];
    if (r.normal < 0) continue;
    MeReal lo, hi;
    bounds(r, lambda, lo, hi);
    const MeReal old = lambda[i], next = std::clamp(old, lo, hi);
    if (next == old) continue;
    lambda[i] = next;
    push(r, w.dv.data(), next - old);
  }
}

// The contract's residual max_i |lambda_i - clamp(lambda_i - w_i, lo, hi)|.
MeReal residual(const BodySpaceProblem &p, const Workspace &w, std::span<const MeReal> lambda) {
  MeReal worst = 0;
  for (int i = 0; i < p.rowCount; ++i) {
    const PgsRow &r = w.row[(size_t)i];
    const MeReal slack = rowSlack(r, w.dv.data(), lambda[(size_t)i]);
    MeReal lo, hi;
    bounds(r, lambda, lo, hi);
    const MeReal l = lambda[(size_t)i];
    worst = std::max(worst, std::fabs(l - std::clamp(l - slack, lo, hi)));
  }
  return worst;
}

class PgsSolver final : public PartitionSolver {
 public:
  const char *name() const override { return "pgs"; }

  SolveReport solve(const BodySpaceProblem &p, const SolverSettings &settings, StepArena &arena,
                    std::span<MeReal> lambda) override {
    SolveReport report;
    if (p.rowCount == 0) return report;
    Workspace w = prepare(p, arena);
    MeReal rhsMax = 0;
    for (int i = 0; i < p.rowCount; ++i) rhsMax = std::max(rhsMax, std::fabs(p.rhs[(size_t)i]));
    const MeReal tol = (settings.tolerance > 0 ? settings.tolerance : defaultTolerance()) * (1 + rhsMax);
    w.joints.tolerance = tol;
    // Warm start: normal and bounded rows first, so friction bounds see
    // their normal impulse.
    for (int i = 0; i < p.rowCount; ++i) lambda[(size_t)i] = p.warm[(size_t)i];
    for (int i = 0; i < p.rowCount; ++i) {
      const PgsRow &r = w.row[(size_t)i];
      MeReal lo, hi;
      bounds(r, lambda, lo, hi);
      lambda[(size_t)i] = std::clamp(lambda[(size_t)i], lo, hi);
      push(r, w.dv.data(), lambda[(size_t)i]);
    }
    const int sweeps = settings.maxIterations > 0 ? settings.maxIterations : kDefaultSweeps;
    int done = 0;
    bool converged = false;
    while (done < sweeps && !converged) {
      MeReal biggest = 0;
      for (int i : (sweeps - done) % 2 == 0 ? w.forward : w.backward)
        biggest = std::max(biggest, visit(p, w, lambda, i));
      ++done;
      converged = biggest <= tol;
    }
    projectFriction(w, lambda);
    report.iterations = done;
    report.residual = residual(p, w, lambda);
    report.solved = converged;
    return report;
  }
};

}  // namespace

PartitionSolver *CreatePgsSolver() { return new PgsSolver; }

}  // namespace karma::mdt
