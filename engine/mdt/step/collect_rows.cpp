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

#include "MeMessage.h"
#include "row_scan.h"
#include "step.h"

namespace karma::mdt {

namespace {

int rowCapacity(const MdtConstraint *c) { return c->type->rowCapacity ? c->type->rowCapacity(c) : c->type->maxRows; }

// Whether every row is finite; adds the rows that ask for a bounce to
// out->bounceRows and raises out->largestJ and out->largestSoftness to the
// rows' largest |J| value and |softness| (row_scan.h).
bool scanRows(const Row *rows, int n, PartitionRows *out) {
  const RowScan scan = scanRowValues(rows, n);
  if (!scan.finite) return false;
  out->bounceRows += scan.asking;
  out->largestJ = std::max(out->largestJ, scan.largestJ);
  out->largestSoftness = std::max(out->largestSoftness, scan.largestSoftness);
  return true;
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
