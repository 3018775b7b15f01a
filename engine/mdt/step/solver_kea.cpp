// solver_kea.cpp: the exact partition solver, through Kea (kea_lcp.h): it
// assembles A = J M^-1 J^T + diag(softness) in compressed sparse rows and
// hands the LCP to KeaSolveSparse's active-set method.
//
// Assembly. Two rows interact when they share a body b, through
//     A_ij += J_i,b . (M_b^-1 J_j,b^T)
// (reference_inline.h computes M^-1 J^T per row and side, and each share of
// an entry). Per row, the columns are found by walking the rows of its (at
// most two) bodies and stored in ascending order, diagonal always present;
// the lower triangle is computed and mirrored, so A is exactly symmetric.
#include <algorithm>
#include <cstdint>
#include <limits>

#include "kea_lcp.h"
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
void rowsByBody(const BodySpaceProblem &p, StepArena &arena, std::span<int> &start, std::span<int> &rows) {
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
  std::span<MeReal> mj = arena.filled<MeReal>((size_t)p.rowCount * 12, 0);
  for (int k = 0; k < p.rowCount; ++k) {
    const MeReal *J = &p.J[(size_t)k * 12];
    MeReal *out = &mj[(size_t)k * 12];
    const int bodies[2] = {p.body0[(size_t)k], p.body1[(size_t)k]};
    for (int side = 0; side < 2; ++side) {
      const int b = bodies[side];
      if (b < 0) continue;
      const auto *inertia = reinterpret_cast<const MeReal(*)[3]>(&p.invInertia[(size_t)b * 9]);
      platform::reference::BodyMinvJt(p.invMass[(size_t)b], inertia, J + side * 6, J + side * 6 + 3, out + side * 6,
                                      out + side * 6 + 3);
    }
  }
  return mj;
}

// The columns of every row: row i's are the union of its bodies' row lists,
// each ascending, so a merge gives them in order. Fills a.rowStart and
// a.col (room for `bound` entries) and diagonal[i], the index of (i, i).
void layoutColumns(const BodySpaceProblem &p, std::span<const int> bodyRowStart, std::span<const int> bodyRows, Csr &a,
                   std::span<int> diagonal) {
  constexpr int kEnd = std::numeric_limits<int>::max();
  int nnz = 0;
  a.rowStart[0] = 0;
  for (int i = 0; i < p.rowCount; ++i) {
    int at[2], end[2];
    for (int side = 0; side < 2; ++side) {
      const int b = side == 0 ? p.body0[(size_t)i] : p.body1[(size_t)i];
      at[side] = b >= 0 ? bodyRowStart[(size_t)b] : 0;
      end[side] = b >= 0 ? bodyRowStart[(size_t)b + 1] : 0;
    }
    diagonal[(size_t)i] = -1;
    int previous = -1;
    while (at[0] < end[0] || at[1] < end[1]) {
      const int j0 = at[0] < end[0] ? bodyRows[(size_t)at[0]] : kEnd;
      const int j1 = at[1] < end[1] ? bodyRows[(size_t)at[1]] : kEnd;
      const int j = std::min(j0, j1);
      at[0] += j0 == j;
      at[1] += j1 == j;
      if (j == previous) continue;  // a row on both bodies of row i
      previous = j;
      if (j == i) diagonal[(size_t)i] = nnz;
      a.col[(size_t)nnz++] = j;
    }
    if (diagonal[(size_t)i] < 0) {  // a row with no enabled body (cannot happen) keeps its diagonal
      diagonal[(size_t)i] = nnz;
      a.col[(size_t)nnz++] = i;
    }
    a.rowStart[(size_t)i + 1] = nnz;
  }
}

// How the lower-triangle entries (i, j), j <= i, are summed, once per
// sparsity: share[k] tells, for each side of row i, which side of row j
// acts on the same body (2 bits a side: 0 none, 1 body 0, 2 body 1), and
// mirror[k] is the index of (j, i). Rows are visited in ascending order, so
// the entries above row j's diagonal are reached in ascending column order:
// next[j] walks them.
void layoutShares(const BodySpaceProblem &p, std::span<const int> rowStart, std::span<const int> col,
                  std::span<const int> diagonal, std::span<int> next, std::span<unsigned char> share,
                  std::span<int> mirror) {
  for (int i = 0; i < p.rowCount; ++i) next[(size_t)i] = diagonal[(size_t)i] + 1;
  for (int i = 0; i < p.rowCount; ++i) {
    const int bodies[2] = {p.body0[(size_t)i], p.body1[(size_t)i]};
    for (int k = rowStart[(size_t)i]; k <= diagonal[(size_t)i]; ++k) {
      const int j = col[(size_t)k];
      unsigned code = 0;
      for (int side = 0; side < 2; ++side) {
        const int bi = bodies[side];
        if (bi < 0) continue;
        const unsigned sideJ = p.body0[(size_t)j] == bi ? 1u : p.body1[(size_t)j] == bi ? 2u : 0u;
        code |= sideJ << (2 * side);
      }
      share[(size_t)k] = (unsigned char)code;
      mirror[(size_t)k] = j == i ? k : next[(size_t)j]++;
    }
  }
}

// A's values. Entry (i, j) is summed over the bodies the two rows share,
//     A_ij = sum_b J_i,b . (M_b^-1 J_j,b^T)   (+ softness_i when j = i),
// body 0 of row i first; `entry` is one body's share (the reference
// RowPairEntry). Only j <= i is computed: A is symmetric, and (i, j) is
// copied to (j, i).
template <class Entry>
void fillValues(const BodySpaceProblem &p, std::span<const MeReal> mj, std::span<const int> diagonal,
                std::span<const unsigned char> share, std::span<const int> mirror, Csr &a, Entry entry) {
  for (int i = 0; i < p.rowCount; ++i) {
    const MeReal *Ji = &p.J[(size_t)i * 12];
    for (int k = a.rowStart[(size_t)i]; k <= diagonal[(size_t)i]; ++k) {
      const MeReal *mjj = &mj[(size_t)a.col[(size_t)k] * 12];
      const unsigned code = share[(size_t)k];
      MeReal v = 0;
      if (const unsigned sideJ = code & 3u; sideJ != 0) {
        const MeReal *m = mjj + (sideJ - 1) * 6;
        v += entry(Ji, Ji + 3, m, m + 3);
      }
      if (const unsigned sideJ = code >> 2; sideJ != 0) {
        const MeReal *m = mjj + (sideJ - 1) * 6;
        v += entry(Ji + 6, Ji + 9, m, m + 3);
      }
      a.val[(size_t)k] = v;
      a.val[(size_t)mirror[(size_t)k]] = v;
    }
    a.val[(size_t)diagonal[(size_t)i]] += p.softness[(size_t)i];
  }
}

// What the solver keeps of one partition from step to step: the Kea
// workspace (with its factorisation) and A's sparsity, which depends only
// on which bodies the rows act on (body0, body1: kept to check it).
struct PartitionMemory {
  std::uintptr_t identity = 0;
  std::uint64_t lastUse = 0;
  kea::KeaWorkspace *workspace = nullptr;
  std::vector<int> body0, body1, rowStart, col, diagonal, mirror;
  std::vector<unsigned char> share;

  bool sameBodies(const BodySpaceProblem &p) const {
    return body0.size() == p.body0.size() && std::equal(body0.begin(), body0.end(), p.body0.begin()) &&
           std::equal(body1.begin(), body1.end(), p.body1.begin());
  }
};

// A's sparsity in `memory`, computed when the rows act on other bodies than
// last step's (layoutColumns), else kept.
void updateSparsity(const BodySpaceProblem &p, StepArena &arena, PartitionMemory &memory) {
  if (memory.sameBodies(p)) return;
  const int m = p.rowCount;
  std::span<int> bodyRowStart, bodyRows;
  rowsByBody(p, arena, bodyRowStart, bodyRows);
  // Entries of row i: at most the rows of its two bodies.
  size_t bound = 0;
  for (int i = 0; i < m; ++i)
    for (int b : {p.body0[(size_t)i], p.body1[(size_t)i]})
      if (b >= 0) bound += (size_t)(bodyRowStart[(size_t)b + 1] - bodyRowStart[(size_t)b]);
  bound += (size_t)m;  // a row with no body keeps its diagonal
  memory.rowStart.resize((size_t)m + 1);
  memory.col.resize(bound);
  memory.diagonal.resize((size_t)m);
  Csr a{memory.rowStart, memory.col, {}};
  layoutColumns(p, bodyRowStart, bodyRows, a, memory.diagonal);
  const size_t nnz = (size_t)memory.rowStart[(size_t)m];
  memory.col.resize(nnz);
  memory.share.resize(nnz);
  memory.mirror.resize(nnz);
  layoutShares(p, memory.rowStart, memory.col, memory.diagonal, arena.take<int>((size_t)m), memory.share,
               memory.mirror);
  memory.body0.assign(p.body0.begin(), p.body0.end());
  memory.body1.assign(p.body1.begin(), p.body1.end());
}

template <class Entry>
Csr assemble(const BodySpaceProblem &p, StepArena &arena, PartitionMemory &memory, Entry entry) {
  updateSparsity(p, arena, memory);
  Csr a{memory.rowStart, memory.col, arena.take<MeReal>(memory.col.size())};
  fillValues(p, minvJt(p, arena), memory.diagonal, memory.share, memory.mirror, a, entry);
  return a;
}

// The partitions' memories, found by partition identity (problem.h). A
// new identity takes the memory used longest ago when that one was not
// used in the last round (as many takes as there are memories: every
// partition of a step takes one); otherwise the memories grow, so a scene
// of many partitions keeps one per partition (pile1000 settles into about
// a hundred columns) instead of handing each one's memory to the next, up
// to kMaxPartitions. A memory given to another partition only costs work
// (the sparsity is checked here, the factor's in Kea), never accuracy.
// The search is linear: a step's cost in it is partitions x memories
// comparisons, small beside a solve.
class PartitionMemories {
 public:
  static constexpr std::size_t kMaxPartitions = 4096;
  PartitionMemories() { slots_.reserve(kInitialSlots); }
  ~PartitionMemories() {
    for (PartitionMemory &slot : slots_) kea::KeaWorkspaceDestroy(slot.workspace);
  }
  PartitionMemories(const PartitionMemories &) = delete;
  PartitionMemories &operator=(const PartitionMemories &) = delete;

  PartitionMemory &take(std::uintptr_t identity) {
    ++clock_;
    PartitionMemory *oldest = nullptr;
    for (PartitionMemory &slot : slots_) {
      if (slot.identity == identity) return use(slot);
      if (!oldest || slot.lastUse < oldest->lastUse) oldest = &slot;
    }
    const bool oldestInUse = oldest && clock_ - oldest->lastUse <= slots_.size();
    if (!oldest || (oldestInUse && slots_.size() < kMaxPartitions)) {
      slots_.emplace_back();
      slots_.back().identity = identity;
      slots_.back().workspace = kea::KeaWorkspaceCreate();
      return use(slots_.back());
    }
    oldest->identity = identity;
    return use(*oldest);
  }

 private:
  static constexpr std::size_t kInitialSlots = 32;
  PartitionMemory &use(PartitionMemory &slot) {
    slot.lastUse = clock_;
    return slot;
  }
  std::vector<PartitionMemory> slots_;
  std::uint64_t clock_ = 0;
};

class KeaSolver final : public PartitionSolver {
 public:
  KeaSolver() = default;
  KeaSolver(const KeaSolver &) = delete;
  KeaSolver &operator=(const KeaSolver &) = delete;

  const char *name() const override { return "kea-active-set"; }

  SolveReport solve(const BodySpaceProblem &p, const SolverSettings &settings, StepArena &arena,
                    std::span<MeReal> lambda) override {
    SolveReport report;
    std::fill(lambda.begin(), lambda.end(), MeReal(0));
    if (p.rowCount == 0) return report;
    PartitionMemory &memory = memories_.take(p.identity);
    const Csr a =
        assemble(p, arena, memory, [](const MeReal *jl, const MeReal *ja, const MeReal *ml, const MeReal *ma) {
          return platform::reference::RowPairEntry(jl, ja, ml, ma);
        });
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
    opt.kernels = settings.kernels;
    opt.epsilon = 0;  // softness is already on the diagonal
    if (p.anyWarm) opt.warmStart = p.warm;
    opt.factorMemory = kea::KeaFactorMemory::WhenCheaper;
    opt.trustedStructure = true;  // layoutColumns: ascending columns, every diagonal present
    opt.warnings = false;         // the step reports, rate-limited (solve_warnings.h)
    kea::KeaSolveSparse(prob, opt, *memory.workspace, result_);
    report.iterations = result_.iterations;
    report.residual = result_.residual;
    report.factorizations = result_.factorizations;
    report.staleSolves = result_.staleSolves;
    report.frictionRounds = result_.frictionRounds;
    report.solved = result_.status == kea::KeaStatus::Solved;
    report.cycle = result_.status == kea::KeaStatus::CycleDetected;
    report.badInput = result_.status == kea::KeaStatus::BadInput;
    if (!report.badInput) std::copy(result_.lambda.begin(), result_.lambda.begin() + p.rowCount, lambda.begin());
    return report;
  }

 private:
  PartitionMemories memories_;
  kea::KeaResult result_;
};

}  // namespace

PartitionSolver *CreateKeaActiveSetSolver() { return new KeaSolver; }

}  // namespace karma::mdt
