// collect_rows.cpp: stage 3 of the step (step.h). Every constraint of the
// partition writes its rows through the row protocol (constraint.h) into
// one array, constraint after constraint. A constraint whose rows are not
// all finite is dropped for this step (with a warning), so one bad joint
// cannot poison the partition; the same scan counts the rows that ask for
// a bounce and keeps the largest |J| and |softness|, which spare the
// body-space operator a pass of its own (problem.h). Then matrix capping
// (capping.cpp) marks the rows to leave out, and each kept row gets its
// index in the solve.
#include <algorithm>
#include <cmath>

#include "MeMessage.h"
#include "step.h"

namespace karma::mdt {

namespace {

int rowCapacity(const MdtConstraint *c) { return c->type->rowCapacity ? c->type->rowCapacity(c) : c->type->maxRows; }

// The largest |J| value of a row, its twelve values reduced as a tree of
// depth four, so that the rows' running maximum waits on one comparison a
// row. (The maximum of values that are not NaN is the same in any order; a
// row with a NaN fails the finiteness test, which discards the result.)
MeReal largestAbsJ(const Row &row) {
  MeReal block[4];
  for (int k = 0; k < 4; ++k)
    block[k] = std::max(std::max(std::fabs(row.J[k][0]), std::fabs(row.J[k][1])), std::fabs(row.J[k][2]));
  return std::max(std::max(block[0], block[1]), std::max(block[2], block[3]));
}

// Whether every row is finite; adds the rows that ask for a bounce
// (bounceAfter > 0) to out->bounceRows and raises out->largestJ and
// out->largestSoftness to the largest |J| value and |softness| of the rows.
bool scanRows(const Row *rows, int n, PartitionRows *out) {
  bool finite = true;
  int asking = 0;
  MeReal largestJ = 0, largestSoftness = 0;
  for (int r = 0; r < n; ++r) {
    const Row &row = rows[r];
    for (int k = 0; k < 4; ++k) finite = finite && MeVector3AllFinite(row.J[k]);
    finite = finite && std::isfinite(row.speed) && std::isfinite(row.softness);
    largestJ = std::max(largestJ, largestAbsJ(row));
    largestSoftness = std::max(largestSoftness, std::fabs(row.softness));
    asking += row.bounceAfter > 0 ? 1 : 0;
  }
  if (finite) {
    out->bounceRows += asking;
    out->largestJ = std::max(out->largestJ, largestJ);
    out->largestSoftness = std::max(out->largestSoftness, largestSoftness);
  }
  return finite;
}

// Writes constraint c's rows at rows[n...]; returns how many it kept and
// notes them in *out (scanRows).
int writeRows(MdtConstraint *c, Row *rows, const StepContext &ctx, PartitionRows *out) {
  RowSink sink(rows, rowCapacity(c));
  c->type->addRows(c, sink, ctx);
  if (sink.overflowed())
    MeWarning(0, "MdtWorldStep: a %s wrote more rows than it declared; extra rows dropped", c->type->name);
  if (!scanRows(sink.rows(), sink.count(), out)) {
    MeWarning(0, "MdtWorldStep: a %s produced non-finite rows; it was skipped this step", c->type->name);
    return 0;
  }
  return sink.count();
}

}  // namespace

PartitionRows collectRows(MdtWorldID world, StepScratch &s, const Partition &part, const StepContext &ctx) {
  const int nc = part.constraintCount;
  MdtConstraint *const *cons = s.partConstraints.data() + part.constraintStart;
  int capacity = 0;
  for (int i = 0; i < nc; ++i) capacity += rowCapacity(cons[i]);
  PartitionRows out;
  out.largestJ = out.largestSoftness = 0;  // raised by each constraint's scan
  out.rows = s.arena.take<Row>((size_t)capacity);
  out.constraintRowStart = s.arena.take<int>((size_t)nc + 1);
  int n = 0;
  out.constraintRowStart[0] = 0;
  for (int i = 0; i < nc; ++i) {
    if (i + 1 < nc && cons[i + 1]->type->prefetch) cons[i + 1]->type->prefetch(cons[i + 1]);
    n += writeRows(cons[i], out.rows.data() + n, ctx, &out);
    out.constraintRowStart[(size_t)i + 1] = n;
  }
  out.count = n;
  out.rows = out.rows.first((size_t)n);
  out.keep = s.arena.filled<char>((size_t)n, 1);
  const int maxRows = world->params.maxMatrixSize;
  if (maxRows > 0 && n > maxRows) capRows(world, out.rows, out.keep, maxRows);
  out.solveIndex = s.arena.take<int>((size_t)n);
  int m = 0;
  for (int r = 0; r < n; ++r) out.solveIndex[(size_t)r] = out.keep[(size_t)r] ? m++ : -1;
  out.kept = m;
  return out;
}

}  // namespace karma::mdt
