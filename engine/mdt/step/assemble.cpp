// assemble.cpp: stage 4 of the step (step.h): the body-space problem
// (problem.h) of a partition's kept rows.
//
//   body side   invMass and the world-frame inverse inertia of each body;
//   row side    J (problem.h's layout), softness, and
//     rhs   = speed - J v*            (v*: the predicted velocities),
//     lo/hi = force bounds * h        (+-MEINFINITY stay unbounded),
//     friction: the kept index of its normal row; if capping dropped the
//               normal row, the friction row is pinned at zero instead;
//     warm  = the row's own warm value (Row::warmSet: contacts), else the
//             constraint's row-by-row memory when it wrote as many rows
//             last step, else 0;
//   blocks    each constraint's kept contact normal rows.
#include <cstring>

#include "reference_inline.h"
#include "step.h"

namespace karma::mdt {

namespace {

int bodyIndex(const MdtBody *b) { return b && b->enabled ? b->index : -1; }

void fillBodies(StepScratch &s, const Partition &part, BodySpaceProblem &p) {
  std::span<MeReal> invMass = s.arena.take<MeReal>((size_t)part.bodyCount);
  std::span<MeReal> invInertia = s.arena.take<MeReal>((size_t)part.bodyCount * 9);
  for (int i = 0; i < part.bodyCount; ++i) {
    const MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    invMass[(size_t)i] = b->invMass;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) invInertia[(size_t)(i * 9 + r * 3 + c)] = b->invInertiaWorld[r][c];
  }
  p.bodyCount = part.bodyCount;
  p.identity = part.bodyCount > 0 ? reinterpret_cast<std::uintptr_t>(s.partBodies[(size_t)part.bodyStart]) : 0;
  p.invMass = invMass;
  p.invInertia = invInertia;
}

// J v* of one row, on the constraint's bodies with an index (body[side] >= 0).
MeReal rowVelocityPredicted(const Row &row, const MdtConstraint *c, const int body[2]) {
  MeReal jv = 0;
  if (body[0] >= 0) jv += platform::reference::RowPairEntry(row.J[0], row.J[1], c->body[0]->vPred, c->body[0]->wPred);
  if (body[1] >= 0) jv += platform::reference::RowPairEntry(row.J[2], row.J[3], c->body[1]->vPred, c->body[1]->wPred);
  return jv;
}

// Row k's J in problem.h's layout: as the row gave it, both sides.
static_assert(sizeof(Row::J) == 12 * sizeof(MeReal), "a side's lin and ang are six consecutive values");
void fillRowSides(const Row &row, size_t k, MeReal *J) {
  for (int side = 0; side < 2; ++side) {
    MeReal *j = J + k * kRowValues + (size_t)side * kSideValues;
    std::memcpy(j, row.J[2 * side], 6 * sizeof(MeReal));
    for (size_t e = 6; e < kSideValues; ++e) j[e] = 0;
  }
}

}  // namespace

BodySpaceProblem assembleProblem(StepScratch &s, const Partition &part, const PartitionRows &rows,
                                 const StepContext &ctx) {
  BodySpaceProblem p;
  fillBodies(s, part, p);
  const size_t m = (size_t)rows.kept;
  p.rowCount = rows.kept;
  std::span<int> body0 = s.arena.take<int>(m), body1 = s.arena.take<int>(m);
  std::span<int> friction = s.arena.take<int>(m);
  std::span<MeReal> J = s.arena.take<MeReal>(m * kRowValues);
  std::span<MeReal> rhs = s.arena.take<MeReal>(m), softness = s.arena.take<MeReal>(m);
  std::span<MeReal> lo = s.arena.take<MeReal>(m), hi = s.arena.take<MeReal>(m);
  std::span<MeReal> mu = s.arena.take<MeReal>(m), warm = s.arena.take<MeReal>(m);
  std::span<int> blockStart = s.arena.take<int>((size_t)part.constraintCount + 1);
  std::span<int> blockRows = s.arena.take<int>(m);
  int blocks = 0, blockRowCount = 0;
  blockStart[0] = 0;
  for (int i = 0; i < part.constraintCount; ++i) {
    const MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    const int r0 = rows.constraintRowStart[(size_t)i], r1 = rows.constraintRowStart[(size_t)i + 1];
    const bool memoryFits = c->warmRows == r1 - r0;
    const int body[2] = {bodyIndex(c->body[0]), bodyIndex(c->body[1])};
    for (int r = r0; r < r1; ++r) {
      const int k = rows.solveIndex[(size_t)r];
      if (k < 0) continue;
      const size_t kk = (size_t)k;
      const Row &row = rows.rows[(size_t)r];
      body0[kk] = body[0];
      body1[kk] = body[1];
      fillRowSides(row, kk, J.data());
      rhs[kk] = row.speed - rowVelocityPredicted(row, c, body);
      softness[kk] = row.softness;
      lo[kk] = row.lo <= -MEINFINITY ? -MEINFINITY : row.lo * ctx.h;
      hi[kk] = row.hi >= MEINFINITY ? MEINFINITY : row.hi * ctx.h;
      friction[kk] = -1;
      mu[kk] = 0;
      if (row.friction >= 0) {
        const int normal = rows.solveIndex[(size_t)(r0 + row.friction)];
        if (normal >= 0) {
          friction[kk] = normal;
          mu[kk] = row.mu;
          p.anyFriction = true;
        } else {
          lo[kk] = hi[kk] = 0;  // its normal row was capped away
        }
      }
      if (row.warmSet)
        warm[kk] = row.warm;
      else
        warm[kk] = memoryFits && r - r0 < kMaxWarmRows ? c->warm[r - r0] : 0;
      p.anyWarm = p.anyWarm || warm[kk] != 0;
      if (row.role == RowRole::ContactNormal) blockRows[(size_t)blockRowCount++] = k;
    }
    if (blockRowCount > blockStart[(size_t)blocks]) blockStart[(size_t)++blocks] = blockRowCount;
  }
  p.normalBlock = blockStart.first((size_t)blocks + 1);
  p.normalRows = blockRows.first((size_t)blockRowCount);
  p.blockCount = blocks;
  p.body0 = body0;
  p.body1 = body1;
  p.J = J;
  p.rhs = rhs;
  p.softness = softness;
  p.lo = lo;
  p.hi = hi;
  p.friction = friction;
  p.mu = mu;
  p.warm = warm;
  p.largestJ = rows.largestJ;  // over every row written: at least over the kept ones
  p.largestSoftness = rows.largestSoftness;
  return p;
}

}  // namespace karma::mdt
