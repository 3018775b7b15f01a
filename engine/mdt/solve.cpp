// solve.cpp: one partition through the solver (step stage 4 and 5).
//
// With v* the predicted velocities (forces applied, constraints not yet),
// the rows give the boxed LCP in the constraint impulses lambda:
//   A = J M^-1 J^T + diag(softness),  b = speed - J v*,
//   lo*h <= lambda <= hi*h  (friction rows: |lambda| <= mu * lambda_normal),
// then v' = v* + M^-1 J^T lambda and each constraint's force is J^T lambda/h.
#include <algorithm>
#include <cmath>

#include "MeMessage.h"
#include "kernels.h"
#include "step.h"

namespace karma::mdt {

namespace {

int rowCapacity(const MdtConstraint *c);

}  // namespace

void solvePartition(MdtWorldID world, StepScratch &s, const Partition &part,
                    const StepContext &ctx) {
  MdtWorldPrivate *p = world->priv;
  const MdtWorldParams &params = world->params;
  // The per-row kernels: M^-1 J^T of a row for one body, and one body's
  // share of a J M^-1 J^T entry (also J v).
  const platform::Kernels &kern = platform::ActiveKernels();
  accumulateGeometricStiffness(world, s, part);
  for (int i = 0; i < part.bodyCount; ++i) {
    MdtBody *b = s.partBodies[(size_t)(part.bodyStart + i)];
    b->index = i;
    predictVelocities(b, params.gravity, ctx.h);
  }

  // Collect rows.
  const int nc = part.constraintCount;
  int capacity = 0;
  for (int i = 0; i < nc; ++i)
    capacity += rowCapacity(s.partConstraints[(size_t)(part.constraintStart + i)]);
  s.rows.resize((size_t)capacity);
  s.constraintRowStart.assign((size_t)nc + 1, 0);
  int n = 0;
  for (int i = 0; i < nc; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    RowSink sink(s.rows.data() + n, rowCapacity(c));
    c->type->addRows(c, sink, ctx);
    if (sink.overflowed())
      MeWarning(0, "MdtWorldStep: a %s wrote more rows than it declared; extra rows dropped",
                c->type->name);
    // A row that is not finite would poison the whole partition: drop the
    // constraint's rows for this step instead.
    bool finite = true;
    for (int r = 0; r < sink.count(); ++r) {
      const Row &row = sink.rows()[r];
      for (int k = 0; k < 4; ++k) finite = finite && MeVector3AllFinite(row.J[k]);
      finite = finite && std::isfinite(row.speed) && std::isfinite(row.softness);
    }
    if (!finite) {
      MeWarning(0, "MdtWorldStep: a %s produced non-finite rows; it was skipped this step",
                c->type->name);
      s.constraintRowStart[(size_t)i + 1] = n;
      continue;
    }
    n += sink.count();
    s.constraintRowStart[(size_t)i + 1] = n;
  }

  // Matrix capping.
  s.keep.assign((size_t)n, 1);
  if (params.maxMatrixSize > 0 && n > params.maxMatrixSize) capRows(world, s, n, params.maxMatrixSize);

  // Kept rows, their bodies and the problem vectors.
  std::vector<int> map((size_t)n, -1);
  int m = 0;
  for (int r = 0; r < n; ++r)
    if (s.keep[(size_t)r]) map[(size_t)r] = m++;
  s.partitionRows.push_back(m);
  s.stats.rows += m;
  s.stats.rowsRemoved += n - m;
  std::vector<int> body0((size_t)m), body1((size_t)m), findex((size_t)m, -1);
  std::vector<MeReal> b((size_t)m), lo((size_t)m), hi((size_t)m), mu((size_t)m, 0),
      warm((size_t)m, 0), soft((size_t)m);
  std::vector<const Row *> kept((size_t)m);
  bool anyFriction = false, warmAny = false;
  for (int i = 0; i < nc; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    const int r0 = s.constraintRowStart[(size_t)i], r1 = s.constraintRowStart[(size_t)i + 1];
    const bool warmOk = c->warmRows == r1 - r0;
    for (int r = r0; r < r1; ++r) {
      const int k = map[(size_t)r];
      if (k < 0) continue;
      const Row &row = s.rows[(size_t)r];
      kept[(size_t)k] = &row;
      body0[(size_t)k] = c->body[0] && c->body[0]->enabled ? c->body[0]->index : -1;
      body1[(size_t)k] = c->body[1] && c->body[1]->enabled ? c->body[1]->index : -1;
      MeReal jv = 0;
      if (body0[(size_t)k] >= 0)
        jv += kern.rowPairEntry(row.J[0], row.J[1], c->body[0]->vPred, c->body[0]->wPred);
      if (body1[(size_t)k] >= 0)
        jv += kern.rowPairEntry(row.J[2], row.J[3], c->body[1]->vPred, c->body[1]->wPred);
      b[(size_t)k] = row.speed - jv;
      lo[(size_t)k] = row.lo <= -MEINFINITY ? -MEINFINITY : row.lo * ctx.h;
      hi[(size_t)k] = row.hi >= MEINFINITY ? MEINFINITY : row.hi * ctx.h;
      soft[(size_t)k] = row.softness;
      if (row.friction >= 0) {
        const int nk = map[(size_t)(r0 + row.friction)];
        if (nk >= 0) {
          findex[(size_t)k] = nk;
          mu[(size_t)k] = row.mu;
          anyFriction = true;
        } else {
          lo[(size_t)k] = hi[(size_t)k] = 0;  // its normal row was capped away
        }
      }
      if (warmOk && r - r0 < kMaxWarmRows) {
        warm[(size_t)k] = c->warm[r - r0];
        warmAny = true;
      }
    }
  }

  // A = J M^-1 J^T + diag(softness), CSR. Rows interact through shared bodies.
  std::vector<int> bodyRowStart((size_t)part.bodyCount + 1, 0), bodyRows;
  for (int k = 0; k < m; ++k) {
    if (body0[(size_t)k] >= 0) ++bodyRowStart[(size_t)body0[(size_t)k] + 1];
    if (body1[(size_t)k] >= 0) ++bodyRowStart[(size_t)body1[(size_t)k] + 1];
  }
  for (int i = 0; i < part.bodyCount; ++i) bodyRowStart[(size_t)i + 1] += bodyRowStart[(size_t)i];
  bodyRows.resize((size_t)bodyRowStart[(size_t)part.bodyCount]);
  {
    std::vector<int> fill(bodyRowStart.begin(), bodyRowStart.end() - 1);
    for (int k = 0; k < m; ++k) {
      if (body0[(size_t)k] >= 0) bodyRows[(size_t)fill[(size_t)body0[(size_t)k]]++] = k;
      if (body1[(size_t)k] >= 0) bodyRows[(size_t)fill[(size_t)body1[(size_t)k]]++] = k;
    }
  }
  // M^-1 J^T per row and side.
  std::vector<MeReal> mj((size_t)m * 12, 0);
  for (int k = 0; k < m; ++k) {
    const Row &row = *kept[(size_t)k];
    MeReal *out = &mj[(size_t)k * 12];
    if (body0[(size_t)k] >= 0) {
      const MdtBody *bk = s.partBodies[(size_t)(part.bodyStart + body0[(size_t)k])];
      kern.bodyMinvJt(bk->invMass, bk->invInertiaWorld, row.J[0], row.J[1], out, out + 3);
    }
    if (body1[(size_t)k] >= 0) {
      const MdtBody *bk = s.partBodies[(size_t)(part.bodyStart + body1[(size_t)k])];
      kern.bodyMinvJt(bk->invMass, bk->invInertiaWorld, row.J[2], row.J[3], out + 6, out + 9);
    }
  }
  std::vector<int> rowStart((size_t)m + 1, 0), col;
  std::vector<MeReal> val;
  std::vector<MeReal> acc((size_t)m, 0);
  std::vector<int> seen((size_t)m, -1), cols;
  for (int i = 0; i < m; ++i) {
    cols.clear();
    const Row &ri = *kept[(size_t)i];
    for (int side = 0; side < 2; ++side) {
      const int bi = side == 0 ? body0[(size_t)i] : body1[(size_t)i];
      if (bi < 0) continue;
      for (int t = bodyRowStart[(size_t)bi]; t < bodyRowStart[(size_t)bi + 1]; ++t) {
        const int j = bodyRows[(size_t)t];
        // Row j's M^-1 J^T half that belongs to body bi.
        const int sideJ = body0[(size_t)j] == bi ? 0 : 1;
        const MeReal *mjj = &mj[(size_t)j * 12 + (size_t)(sideJ * 6)];
        const MeReal v = kern.rowPairEntry(ri.J[2 * side], ri.J[2 * side + 1], mjj, mjj + 3);
        if (seen[(size_t)j] != i) {
          seen[(size_t)j] = i;
          acc[(size_t)j] = 0;
          cols.push_back(j);
        }
        acc[(size_t)j] += v;
      }
    }
    if (seen[(size_t)i] != i) {  // a row with no enabled body (cannot happen) keeps its diagonal
      seen[(size_t)i] = i;
      acc[(size_t)i] = 0;
      cols.push_back(i);
    }
    acc[(size_t)i] += soft[(size_t)i];
    std::sort(cols.begin(), cols.end());
    for (int j : cols) {
      col.push_back(j);
      val.push_back(acc[(size_t)j]);
    }
    rowStart[(size_t)i + 1] = (int)col.size();
  }

  kea::SparseLcpProblem prob;
  prob.n = m;
  prob.rowStart = rowStart;
  prob.col = col;
  prob.val = val;
  prob.b = b;
  prob.lo = lo;
  prob.hi = hi;
  if (anyFriction) {
    prob.findex = findex;
    prob.mu = mu;
  }
  kea::KeaOptions opt;
  opt.method = params.keaMethod == MdtKeaMethodPGS ? kea::KeaMethod::PGS : kea::KeaMethod::ActiveSet;
  opt.maxIterations = params.keaMaxIterations;
  opt.tolerance = params.keaTolerance;
  opt.epsilon = 0;  // softness is already on the diagonal
  if (warmAny) opt.warmStart = warm;
  kea::KeaResult res;
  if (m > 0) {
    res = kea::KeaSolveSparse(prob, opt);
    s.stats.keaIterations += res.iterations;
    if (res.status != kea::KeaStatus::Solved) ++s.stats.keaUnsolved;
    if (res.residual > s.stats.keaResidual) s.stats.keaResidual = res.residual;
  }
  const bool good = m == 0 || res.status != kea::KeaStatus::BadInput;

  // Apply impulses, store forces and warm starts.
  s.lambdaAll.assign((size_t)n, 0);
  for (int r = 0; r < n; ++r)
    if (good && map[(size_t)r] >= 0) s.lambdaAll[(size_t)r] = res.lambda[(size_t)map[(size_t)r]];
  for (int i = 0; i < nc; ++i) {
    MdtConstraint *c = s.partConstraints[(size_t)(part.constraintStart + i)];
    const int r0 = s.constraintRowStart[(size_t)i], r1 = s.constraintRowStart[(size_t)i + 1];
    MeVector3 imp[4] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int r = r0; r < r1; ++r) {
      const MeReal l = s.lambdaAll[(size_t)r];
      for (int q = 0; q < 4; ++q) MeVector3MultiplyAdd(imp[q], l, s.rows[(size_t)r].J[q]);
    }
    for (int k = 0; k < 2; ++k) {
      MeVector3MultiplyScalar(c->force[k], imp[2 * k], ctx.invH);
      MeVector3MultiplyScalar(c->torque[k], imp[2 * k + 1], ctx.invH);
      MdtBody *bk = c->body[k];
      if (bk && bk->enabled) applyImpulse(bk, imp[2 * k], imp[2 * k + 1]);
    }
    c->warmRows = r1 - r0 <= kMaxWarmRows ? r1 - r0 : 0;
    for (int r = r0; r < r0 + c->warmRows; ++r) c->warm[r - r0] = s.lambdaAll[(size_t)r];
    if (c->type->afterSolve) c->type->afterSolve(c, s.lambdaAll.data() + r0, r1 - r0, ctx);
  }
  (void)p;

  for (int i = 0; i < part.bodyCount; ++i)
    advanceBody(s.partBodies[(size_t)(part.bodyStart + i)], ctx.h);
}

namespace {
int rowCapacity(const MdtConstraint *c) {
  return c->type->rowCapacity ? c->type->rowCapacity(c) : c->type->maxRows;
}
}  // namespace

}  // namespace karma::mdt
