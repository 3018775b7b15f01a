// solver_kea.cpp: the exact partition solver, through Kea (kea_lcp.h): it
// assembles A = J M^-1 J^T + diag(softness) in compressed sparse rows and
// hands the LCP to KeaSolveSparse's active-set method.
//
// Assembly. Two rows interact when they share a body b, through
//     A_ij += J_i,b . (M_b^-1 J_j,b^T)
// (the platform kernels compute M^-1 J^T per row and side, and each share of
// an entry). Per row, the columns are found by walking the rows of its (at
// most two) bodies; a row's entries are summed over both shared bodies and
// stored in ascending column order, diagonal always present.
#include <algorithm>
#include <limits>

#include "kea_lcp.h"
#include "kernels.h"
#include "reference_inline.h"
#include "partition_solver.h"

namespace karma::mdt {

namespace {

// A in CSR, spans into the arena.
struct Csr {
  std::span<int> rowStart, col;
  std::span<MeReal> val;
};

// bodyRowStart/bodyRows: for each body, the rows that act on it.
void rowsByBody(const BodySpaceProblem &p, StepArena &arena, std::span<int> &start,
                std::span<int> &rows) {
  const int m = p.rowCount;
  start = arena.filled<int>((size_t)p.bodyCount + 1, 0);
  for (int k = 0; k < m; ++k) {
    if (p.body0[(size_t)k] >= 0) ++start[(size_t)p.body0[(size_t)k] + 1];
    if (p.body1[(size_t)k] >= 0) ++start[(size_t)p.body1[(size_t)k] + 1];
  }
  for (int i = 0; i < p.bodyCount; ++i) start[(size_t)i + 1] += start[(size_t)i];
  rows = arena.take<int>((size_t)start[(size_t)p.bodyCount]);
  std::span<int> fill = arena.take<int>((size_t)p.bodyCount);
  std::copy(start.begin(), start.end() - 1, fill.begin());
  for (int k = 0; k < m; ++k) {
    if (p.body0[(size_t)k] >= 0) rows[(size_t)fill[(size_t)p.body0[(size_t)k]]++] = k;
    if (p.body1[(size_t)k] >= 0) rows[(size_t)fill[(size_t)p.body1[(size_t)k]]++] = k;
  }
}

// M^-1 J^T of every row, per side: 12 values a row (lin0 ang0 lin1 ang1).
std::span<MeReal> minvJt(const BodySpaceProblem &p, StepArena &arena) {
  const platform::Kernels &kern = platform::ActiveKernels();
  std::span<MeReal> mj = arena.filled<MeReal>((size_t)p.rowCount * 12, 0);
  for (int k = 0; k < p.rowCount; ++k) {
    const MeReal *J = &p.J[(size_t)k * 12];
    MeReal *out = &mj[(size_t)k * 12];
    const int bodies[2] = {p.body0[(size_t)k], p.body1[(size_t)k]};
    for (int side = 0; side < 2; ++side) {
      const int b = bodies[side];
      if (b < 0) continue;
      const auto *inertia = reinterpret_cast<const MeReal(*)[3]>(&p.invInertia[(size_t)b * 9]);
      kern.bodyMinvJt(p.invMass[(size_t)b], inertia, J + side * 6, J + side * 6 + 3,
                      out + side * 6, out + side * 6 + 3);
    }
  }
  return mj;
}

// `entry` is one body's share of an entry (the platform's rowPairEntry).
// Row i's columns are the union of its bodies' row lists, each ascending,
// so a merge gives them in order; an entry shared through both bodies is
// (0 + share through body 0) + share through body 1, and the diagonal then
// gets the softness.
template <class Entry>
Csr assemble(const BodySpaceProblem &p, StepArena &arena, Entry entry) {
  const int m = p.rowCount;
  std::span<int> bodyRowStart, bodyRows;
  rowsByBody(p, arena, bodyRowStart, bodyRows);
  std::span<MeReal> mj = minvJt(p, arena);
  // Entries of row i: at most the rows of its two bodies.
  size_t bound = 0;
  for (int i = 0; i < m; ++i)
    for (int b : {p.body0[(size_t)i], p.body1[(size_t)i]})
      if (b >= 0) bound += (size_t)(bodyRowStart[(size_t)b + 1] - bodyRowStart[(size_t)b]);
  bound += (size_t)m;  // a row with no body keeps its diagonal
  Csr a;
  a.rowStart = arena.take<int>((size_t)m + 1);
  a.col = arena.take<int>(bound);
  a.val = arena.take<MeReal>(bound);
  int nnz = 0;
  a.rowStart[0] = 0;
  constexpr int kEnd = std::numeric_limits<int>::max();
  for (int i = 0; i < m; ++i) {
    const MeReal *Ji = &p.J[(size_t)i * 12];
    const int bodies[2] = {p.body0[(size_t)i], p.body1[(size_t)i]};
    int at[2], end[2];
    for (int side = 0; side < 2; ++side) {
      at[side] = bodies[side] >= 0 ? bodyRowStart[(size_t)bodies[side]] : 0;
      end[side] = bodies[side] >= 0 ? bodyRowStart[(size_t)bodies[side] + 1] : 0;
    }
    // Body bi's share of entry (i, j): row j's M^-1 J^T half for bi.
    auto share = [&](int side, int j) {
      const int bi = bodies[side];
      const int sideJ = p.body0[(size_t)j] == bi ? 0 : 1;
      const MeReal *mjj = &mj[(size_t)j * 12 + (size_t)(sideJ * 6)];
      return entry(Ji + side * 6, Ji + side * 6 + 3, mjj, mjj + 3);
    };
    bool diagonal = false;
    while (at[0] < end[0] || at[1] < end[1]) {
      const int j0 = at[0] < end[0] ? bodyRows[(size_t)at[0]] : kEnd;
      const int j1 = at[1] < end[1] ? bodyRows[(size_t)at[1]] : kEnd;
      const int j = std::min(j0, j1);
      MeReal v = 0;
      for (int side = 0; side < 2; ++side)
        while (at[side] < end[side] && bodyRows[(size_t)at[side]] == j) {
          v += share(side, j);
          ++at[side];
        }
      if (j == i) {
        v += p.softness[(size_t)i];
        diagonal = true;
      }
      a.col[(size_t)nnz] = j;
      a.val[(size_t)nnz++] = v;
    }
    if (!diagonal) {  // a row with no enabled body (cannot happen) keeps its diagonal
      a.col[(size_t)nnz] = i;
      a.val[(size_t)nnz++] = 0 + p.softness[(size_t)i];
    }
    a.rowStart[(size_t)i + 1] = nnz;
  }
  a.col = a.col.first((size_t)nnz);
  a.val = a.val.first((size_t)nnz);
  return a;
}

class KeaSolver final : public PartitionSolver {
 public:
  KeaSolver() : workspace_(kea::KeaWorkspaceCreate()) {}
  ~KeaSolver() override { kea::KeaWorkspaceDestroy(workspace_); }
  KeaSolver(const KeaSolver &) = delete;
  KeaSolver &operator=(const KeaSolver &) = delete;

  const char *name() const override { return "kea-active-set"; }

  SolveReport solve(const BodySpaceProblem &p, const SolverSettings &settings, StepArena &arena,
                    std::span<MeReal> lambda) override {
    SolveReport report;
    std::fill(lambda.begin(), lambda.end(), MeReal(0));
    if (p.rowCount == 0) return report;
    // The reference backend's entry inline (the same bits, no indirect call
    // per entry); any other backend through its table.
    const platform::Kernels &kern = platform::ActiveKernels();
    const Csr a = &kern == &platform::ReferenceKernels()
                      ? assemble(p, arena,
                                 [](const MeReal *jl, const MeReal *ja, const MeReal *ml, const MeReal *ma) {
                                   return platform::reference::RowPairEntry(jl, ja, ml, ma);
                                 })
                      : assemble(p, arena, kern.rowPairEntry);
    kea::SparseLcpProblem prob;
    prob.n = p.rowCount;
    prob.rowStart = a.rowStart;
    prob.col = a.col;
    prob.val = a.val;
    prob.b = p.rhs;
    prob.lo = p.lo;
    prob.hi = p.hi;
    if (p.anyFriction) {
      prob.findex = p.friction;
      prob.mu = p.mu;
    }
    kea::KeaOptions opt;
    opt.method = kea::KeaMethod::ActiveSet;
    opt.maxIterations = settings.maxIterations;
    opt.tolerance = settings.tolerance;
    opt.epsilon = 0;  // softness is already on the diagonal
    if (p.anyWarm) opt.warmStart = p.warm;
    kea::KeaSolveSparse(prob, opt, *workspace_, result_);
    report.iterations = result_.iterations;
    report.residual = result_.residual;
    report.solved = result_.status == kea::KeaStatus::Solved;
    report.badInput = result_.status == kea::KeaStatus::BadInput;
    if (!report.badInput)
      std::copy(result_.lambda.begin(), result_.lambda.begin() + p.rowCount, lambda.begin());
    return report;
  }

 private:
  kea::KeaWorkspace *workspace_;
  kea::KeaResult result_;
};

}  // namespace

PartitionSolver *CreateKeaActiveSetSolver() { return new KeaSolver; }

}  // namespace karma::mdt
