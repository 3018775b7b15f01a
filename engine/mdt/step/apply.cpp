// apply.cpp: stage 6 of the step (step.h). Each constraint's rows give the
// impulse J^T lambda on its two bodies: added to the bodies' velocities,
// stored as the constraint's force and torque (impulse / h), and kept as
// its warm-start memory for the next step (row by row, up to kMaxWarmRows;
// contacts keep theirs in their own frame through afterSolve). Rows that
// capping dropped count as zero impulse.
#include <cstring>

#include "lanes16.h"
#include "step.h"

namespace karma::mdt {

namespace {

using platform::Lanes16;
constexpr std::size_t kPer = platform::kPerLanes16;
static_assert(12 % kPer == 0);
constexpr std::size_t kImpulseLanes = 12 / kPer;

// A constraint's impulse sum(lambda_r J_r) over its rows r0..r1 (12 values:
// lin0, ang0, lin1, ang1), element by element in 16-byte lanes held in
// registers: each element starts at 0 and rounds as MeVector3MultiplyAdd's
// v + s a does, row after row. Read back element by element, so that no
// load spans the lanes' stores (a wider load than the stores that wrote
// its bytes waits for them to reach the cache).
void constraintImpulse(const Row *rows, const MeReal *lambda, int count, MeVector3 imp[4]) {
  Lanes16 sum[kImpulseLanes] = {};
  for (int r = 0; r < count; ++r) {
    const auto *J = reinterpret_cast<const unsigned char *>(&rows[r].J);  // J's object representation
    for (std::size_t l = 0; l < kImpulseLanes; ++l) {
      Lanes16 j;
      std::memcpy(&j, J + l * sizeof j, sizeof j);
      sum[l] = sum[l] + lambda[r] * j;
    }
  }
  for (std::size_t i = 0; i < 12; ++i) imp[i / 3][i % 3] = sum[i / kPer][i % kPer];
}

}  // namespace

void applyImpulses(StepScratch &s, const Partition &part, const PartitionRows &rows, std::span<const MeReal> lambda,
                   const StepContext &ctx) {
  std::span<MeReal> all = s.arena.take<MeReal>((size_t)rows.count);
  for (int r = 0; r < rows.count; ++r) {
    const int k = rows.solveIndex[(size_t)r];
    all[(size_t)r] = k >= 0 ? lambda[(size_t)k] : 0;
  }
  for (int i = 0; i < part.constraintCount; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    const int r0 = rows.constraintRowStart[(size_t)i], r1 = rows.constraintRowStart[(size_t)i + 1];
    MeVector3 imp[4];
    static_assert(sizeof imp == 12 * sizeof(MeReal) && sizeof(Row::J) == 12 * sizeof(MeReal));
    constraintImpulse(rows.rows.data() + r0, all.data() + r0, r1 - r0, imp);
    for (int k = 0; k < 2; ++k) {
      MeVector3MultiplyScalar(c->force[k], imp[2 * k], ctx.invH);
      MeVector3MultiplyScalar(c->torque[k], imp[2 * k + 1], ctx.invH);
      MdtBody *bk = c->body[k];
      if (bk && bk->enabled) applyImpulse(bk, imp[2 * k], imp[2 * k + 1]);
    }
    c->warmRows = r1 - r0 <= kMaxWarmRows ? r1 - r0 : 0;
    for (int r = r0; r < r0 + c->warmRows; ++r) c->warm[r - r0] = all[(size_t)r];
    if (c->type->afterSolve) c->type->afterSolve(c, rows.rows.data() + r0, all.data() + r0, r1 - r0, ctx);
  }
}

}  // namespace karma::mdt
