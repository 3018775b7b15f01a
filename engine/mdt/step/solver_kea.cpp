// solver_kea.cpp: the exact partition solver, through Kea (kea_lcp.h): it
// hands the LCP with A = J M^-1 J^T + diag(softness) to KeaSolveSparse's
// active-set method as A's layout in compressed sparse rows and an
// operator (PartitionMatrix). A solve that starts on the partition's kept
// factor applies A through the bodies (body_space_operator.h) and has A's
// values assembled only if it factorises: a partition at rest whose solve
// ends on the kept factor (a stale solve) is never assembled. Any other
// solve has A assembled first and works on the stored values (kea_lcp.h).
//
// Assembly. Two rows interact when they share a body b, through
//     A_ij += J_i,b . (M_b^-1 J_j,b^T)
// Per row, the columns are found by walking the rows of its (at most two)
// bodies and stored in ascending order, diagonal always present. The values
// are summed body by body: for each body, its rows' M^-1 J^T (problem.h's
// SideMinvJt) are laid out side by side, and every pair of its
// rows (j <= i) gets its share S_ij = J_i,b . (M_b^-1 J_j,b^T) as one small
// block product. Each share is added at (i, j) and, off the diagonal, at
// (j, i), so A is exactly symmetric. The places are kept with the layout as
// runs: S's row i lands in consecutive entries of A's row i wherever b's
// rows are consecutive columns there (a contact group's rows always are),
// and S's column j in consecutive entries of A's row j; a run is one
// vector add.
//
// Bits. An entry has at most two shares (two rows share at most two
// bodies); each is the six products summed as RowPairEntry sums them, and
// the entry is 0 + one share + the other, then + softness on the diagonal.
// Floating-point addition is commutative, so the order in which the bodies
// are visited does not change a bit, and (i, j) and (j, i) are equal.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>

#include "body_space_operator.h"
#include "kea_lcp.h"
#include "partition_solver.h"
#include "warm_keep_rule.h"

namespace karma::mdt {

namespace {

// A in CSR, spans into the arena.
struct Csr {
  std::span<int> rowStart, col;
  std::span<MeReal> val;
};

// start/rows: for each body, the rows that act on it, ascending.
void rowsByBody(const BodySpaceProblem &p, StepArena &arena, std::vector<int> &start, std::vector<int> &rows) {
  const int m = p.rowCount;
  start.assign((size_t)p.bodyCount + 1, 0);
  for (int k = 0; k < m; ++k) {
    if (p.body0[(size_t)k] >= 0) ++start[(size_t)p.body0[(size_t)k] + 1];
    if (p.body1[(size_t)k] >= 0) ++start[(size_t)p.body1[(size_t)k] + 1];
  }
  for (int i = 0; i < p.bodyCount; ++i) start[(size_t)i + 1] += start[(size_t)i];
  rows.resize((size_t)start[(size_t)p.bodyCount]);
  std::span<int> fill = arena.take<int>((size_t)p.bodyCount);
  std::copy(start.begin(), start.end() - 1, fill.begin());
  for (int k = 0; k < m; ++k) {
    if (p.body0[(size_t)k] >= 0) rows[(size_t)fill[(size_t)p.body0[(size_t)k]]++] = k;
    if (p.body1[(size_t)k] >= 0) rows[(size_t)fill[(size_t)p.body1[(size_t)k]]++] = k;
  }
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

// A run of shares added to consecutive entries of A: val[dst + t] +=
// S[src + t * step], t < length, where S is one body's share block
// (row-major, stride = the most rows on one body). Lower runs read a row of
// S (step 1), upper runs a column (step = stride).
struct ShareRun {
  int dst, src, length;
};

// Appends to `runs` the runs of the places `place[0..count)` (entries of
// A) of the shares at S[src0 + t * step]: a run ends where the next place
// is not the next entry.
void appendRuns(const int *place, int count, int src0, int step, std::vector<ShareRun> &runs) {
  for (int t = 0; t < count; ++t) {
    if (t > 0 && place[t] == place[t - 1] + 1) {
      ++runs.back().length;
      continue;
    }
    runs.push_back({place[t], src0 + t * step, 1});
  }
}

// The share runs of every body: for body b, whose rows are R =
// bodyRows[bodyRowStart[b] ..] (ascending, r of them), its lower runs
// (shares (R[p], R[q]), q <= p, into row R[p]) then its upper runs (shares
// (R[p], R[q]), p > q, into row R[q] at column R[p]) are runs[runStart[b]
// ..runStart[b + 1]), upper ones from upperStart[b]. R[0..p] are all
// columns of row R[p] (they share b), so one walk of its columns up to the
// diagonal finds the lower places and one walk on from the diagonal the
// upper ones.
void layoutShareRuns(int bodyCount, std::span<const int> bodyRowStart, std::span<const int> bodyRows,
                     std::span<const int> rowStart, std::span<const int> col, int stride, std::span<int> place,
                     std::vector<int> &runStart, std::vector<int> &upperStart, std::vector<ShareRun> &runs) {
  runStart.resize((size_t)bodyCount + 1);
  upperStart.resize((size_t)bodyCount);
  runs.clear();
  for (int b = 0; b < bodyCount; ++b) {
    runStart[(size_t)b] = (int)runs.size();
    const int *R = &bodyRows[(size_t)bodyRowStart[(size_t)b]];
    const int r = bodyRowStart[(size_t)b + 1] - bodyRowStart[(size_t)b];
    for (int p = 0; p < r; ++p) {
      int k = rowStart[(size_t)R[p]];
      for (int q = 0; q <= p; ++q) {
        while (col[(size_t)k] != R[q]) ++k;
        place[(size_t)q] = k++;
      }
      appendRuns(place.data(), p + 1, p * stride, 1, runs);
    }
    upperStart[(size_t)b] = (int)runs.size();
    for (int q = 0; q + 1 < r; ++q) {
      int k = rowStart[(size_t)R[q]];
      for (int p = q + 1; p < r; ++p) {
        while (col[(size_t)k] != R[p]) ++k;
        place[(size_t)(p - q - 1)] = k++;
      }
      appendRuns(place.data(), r - q - 1, (q + 1) * stride + q, stride, runs);
    }
  }
  runStart[(size_t)bodyCount] = (int)runs.size();
}

// What the solver keeps of one partition from step to step: the Kea
// workspace (with its factorisation) and A's layout, which depends only on
// which bodies the rows act on (body0, body1: kept to check it).
struct PartitionMemory {
  std::uintptr_t identity = 0;
  std::uint64_t lastUse = 0;
  kea::KeaWorkspace *workspace = nullptr;
  std::vector<int> body0, body1;
  std::vector<int> rowStart, col, diagonal;  // A's CSR layout
  std::vector<int> bodyRowStart, bodyRows;   // the rows on each body (rowsByBody)
  std::vector<int> runStart, upperStart;     // layoutShareRuns
  std::vector<ShareRun> runs;                // layoutShareRuns
  int widestBody = 0;                        // the most rows on one body
  // How the last answer came, which decides how the next warm start is
  // checked (warm_keep_rule.h), and the step it came at: an answer older
  // than last step's is taken as Unknown (the partition slept, or went to
  // the iterative solver, in between).
  LastAnswer lastAnswer = LastAnswer::Unknown;
  std::uint64_t lastAnswerStep = 0;
  // Numbers the layouts this memory has held (1, 2, ...): Kea's name for
  // A's sparsity (SparseLcpProblem::sparsityStamp). The workspace is this
  // memory's alone, so the number needs to be unique only here.
  std::uint64_t layoutStamp = 0;

  // The layout is indexed by body as well as by row: the body count counts.
  bool sameBodies(const BodySpaceProblem &p) const {
    return bodyRowStart.size() == (size_t)p.bodyCount + 1 && body0.size() == p.body0.size() &&
           std::equal(body0.begin(), body0.end(), p.body0.begin()) &&
           std::equal(body1.begin(), body1.end(), p.body1.begin());
  }
};

// Room in v for n elements rounded up to a power of two, when it has less
// than n (as Kea's ReserveRoom, kea_internal.h): a partition that gains a
// few rows each step (a column under landing boxes) reallocates its layout
// about log2 n times, not at every size.
template <class T>
void reserveRoom(std::vector<T> &v, size_t n) {
  if (v.capacity() < n) v.reserve(std::bit_ceil(n));
}

// Room in memory's per-row and per-body arrays for p's sizes.
void reserveLayoutRoom(const BodySpaceProblem &p, PartitionMemory &memory) {
  const size_t m = (size_t)p.rowCount, bodies = (size_t)p.bodyCount;
  for (std::vector<int> *v : {&memory.body0, &memory.body1, &memory.diagonal}) reserveRoom(*v, m);
  reserveRoom(memory.rowStart, m + 1);
  reserveRoom(memory.bodyRows, 2 * m);  // a row acts on at most two bodies
  reserveRoom(memory.bodyRowStart, bodies + 1);
  reserveRoom(memory.runStart, bodies + 1);
  reserveRoom(memory.upperStart, bodies);
}

// A's layout in `memory`, computed when the rows act on other bodies than
// last step's, else kept.
void updateLayout(const BodySpaceProblem &p, StepArena &arena, PartitionMemory &memory) {
  if (memory.sameBodies(p)) return;
  reserveLayoutRoom(p, memory);
  const int m = p.rowCount;
  rowsByBody(p, arena, memory.bodyRowStart, memory.bodyRows);
  const std::span<const int> bodyRowStart = memory.bodyRowStart, bodyRows = memory.bodyRows;
  // Entries of row i: at most the rows of its two bodies.
  size_t bound = 0;
  for (int i = 0; i < m; ++i)
    for (int b : {p.body0[(size_t)i], p.body1[(size_t)i]})
      if (b >= 0) bound += (size_t)(bodyRowStart[(size_t)b + 1] - bodyRowStart[(size_t)b]);
  bound += (size_t)m;  // a row with no body keeps its diagonal
  memory.rowStart.resize((size_t)m + 1);
  reserveRoom(memory.col, bound);
  memory.col.resize(bound);
  memory.diagonal.resize((size_t)m);
  Csr a{memory.rowStart, memory.col, {}};
  layoutColumns(p, bodyRowStart, bodyRows, a, memory.diagonal);
  memory.col.resize((size_t)memory.rowStart[(size_t)m]);
  memory.widestBody = 0;
  for (int b = 0; b < p.bodyCount; ++b)
    memory.widestBody = std::max(memory.widestBody, bodyRowStart[(size_t)b + 1] - bodyRowStart[(size_t)b]);
  layoutShareRuns(p.bodyCount, bodyRowStart, bodyRows, memory.rowStart, memory.col, memory.widestBody,
                  arena.take<int>((size_t)memory.widestBody), memory.runStart, memory.upperStart, memory.runs);
  memory.body0.assign(p.body0.begin(), p.body0.end());
  memory.body1.assign(p.body1.begin(), p.body1.end());
  ++memory.layoutStamp;
}

// Body b's rows' M_b^-1 J^T (problem.h's SideMinvJt), one row of `mj` per
// component (lin xyz, ang xyz) and one column per row of b:
// mj[c * stride + q].
void bodyMinvJt(const BodySpaceProblem &p, int b, std::span<const int> rows, MeReal *mj, int stride) {
  const MeReal invMass = p.invMass[(size_t)b], *invInertia = &p.invInertia[(size_t)b * 9];
  for (size_t q = 0; q < rows.size(); ++q) {
    const int row = rows[q];
    MeReal side[6];
    SideMinvJt(invMass, invInertia, sideJ(p, row, p.body0[(size_t)row] == b ? 0 : 1), side);
    for (int c = 0; c < 6; ++c) mj[(size_t)c * (size_t)stride + q] = side[c];
  }
}

// Body b's shares into `share` (row-major, `stride` per row): for its rows
// R and each q <= p, share[p * stride + q] = J_R[p],b . (M_b^-1 J_R[q],b^T),
// summed in RowPairEntry's order. The block is stride^2 values of step
// scratch: quadratic in the rows on the widest body, as its pairs are.
void bodyShares(const BodySpaceProblem &p, int b, std::span<const int> rows, const MeReal *mj, int stride,
                MeReal *share) {
  const MeReal *m0 = mj, *m1 = mj + stride, *m2 = mj + 2 * stride;
  const MeReal *m3 = mj + 3 * stride, *m4 = mj + 4 * stride, *m5 = mj + 5 * stride;
  for (size_t i = 0; i < rows.size(); ++i) {
    const int row = rows[i];
    const MeReal *J = sideJ(p, row, p.body0[(size_t)row] == b ? 0 : 1);
    const MeReal j0 = J[0], j1 = J[1], j2 = J[2], j3 = J[3], j4 = J[4], j5 = J[5];
    MeReal *out = share + i * (size_t)stride;
    for (size_t q = 0; q <= i; ++q)
      out[q] = (j0 * m0[q] + j1 * m1[q] + j2 * m2[q]) + (j3 * m3[q] + j4 * m4[q] + j5 * m5[q]);
  }
}

// Adds the shares along lower runs (each a row of `share`).
void addLowerRuns(std::span<const ShareRun> runs, const MeReal *share, MeReal *__restrict val) {
  for (const ShareRun &run : runs) {
    MeReal *to = val + run.dst;
    const MeReal *from = share + run.src;
    for (int t = 0; t < run.length; ++t) to[t] += from[t];
  }
}

// Adds the shares along upper runs (each a column of `share`, `stride`
// apart).
void addUpperRuns(std::span<const ShareRun> runs, int stride, const MeReal *share, MeReal *__restrict val) {
  for (const ShareRun &run : runs) {
    MeReal *to = val + run.dst;
    const MeReal *from = share + run.src;
    for (int t = 0; t < run.length; ++t) to[t] += from[(size_t)t * (size_t)stride];
  }
}

// A's values into `val` (memory's layout, made by updateLayout).
void fillValues(const BodySpaceProblem &p, StepArena &arena, const PartitionMemory &memory, std::span<MeReal> val) {
  std::fill(val.begin(), val.end(), MeReal(0));
  const int stride = memory.widestBody;
  MeReal *mj = arena.take<MeReal>((size_t)stride * 6).data();
  MeReal *share = arena.take<MeReal>((size_t)stride * (size_t)stride).data();
  const std::span<const ShareRun> runs = memory.runs;
  for (int b = 0; b < p.bodyCount; ++b) {
    const std::span<const int> rows(&memory.bodyRows[(size_t)memory.bodyRowStart[(size_t)b]],
                                    (size_t)(memory.bodyRowStart[(size_t)b + 1] - memory.bodyRowStart[(size_t)b]));
    if (rows.empty()) continue;
    bodyMinvJt(p, b, rows, mj, stride);
    bodyShares(p, b, rows, mj, stride, share);
    const size_t lower = (size_t)memory.runStart[(size_t)b], upper = (size_t)memory.upperStart[(size_t)b];
    const size_t end = (size_t)memory.runStart[(size_t)b + 1];
    addLowerRuns(runs.subspan(lower, upper - lower), share, val.data());
    addUpperRuns(runs.subspan(upper, end - upper), stride, share, val.data());
  }
  for (int i = 0; i < p.rowCount; ++i) val[(size_t)memory.diagonal[(size_t)i]] += p.softness[(size_t)i];
}

// The partition's A for Kea: applied through the bodies
// (body_space_operator.h), its values filled only when Kea asks for them
// (a factorisation), at most once per solve.
class PartitionMatrix final : public BodySpaceOperator {
 public:
  PartitionMatrix(const BodySpaceProblem &p, StepArena &arena, const PartitionMemory &memory)
      : BodySpaceOperator(p, arena),
        problem_(p),
        scratch_(arena),
        memory_(memory),
        val_(arena.take<MeReal>(memory.col.size())) {}
  ~PartitionMatrix() = default;
  PartitionMatrix(const PartitionMatrix &) = delete;
  PartitionMatrix &operator=(const PartitionMatrix &) = delete;

  // Where assemble() puts A's values: unfilled until then.
  std::span<const MeReal> storage() const { return val_; }
  void assemble() const override {
    if (assembled_) return;
    fillValues(problem_, scratch_, memory_, val_);
    assembled_ = true;
  }

 private:
  const BodySpaceProblem &problem_;
  StepArena &scratch_;
  const PartitionMemory &memory_;
  std::span<MeReal> val_;
  mutable bool assembled_ = false;
};

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
    oldest->lastAnswer = LastAnswer::Unknown;
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
    updateLayout(p, arena, memory);
    const PartitionMatrix a(p, arena, memory);
    kea::SparseLcpProblem prob;
    prob.n = p.rowCount;
    prob.rowStart = memory.rowStart;
    prob.col = memory.col;
    prob.val = a.storage();
    prob.op = &a;
    prob.b = p.rhs;
    prob.lo = p.lo;
    prob.hi = p.hi;
    prob.sparsityStamp = memory.layoutStamp;
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
    if (memory.lastAnswerStep + 1 != settings.step) memory.lastAnswer = LastAnswer::Unknown;
    const WarmKeep keep = warmKeepAfter(memory.lastAnswer);
    opt.acceptWarmStart = settings.acceptWarmStart && keep.check;
    opt.warmAcceptDivisor = keep.divisor;
    opt.factorMemory = kea::KeaFactorMemory::WhenCheaper;
    opt.trustedStructure = true;  // layoutColumns: ascending columns, every diagonal present
    opt.warnings = false;         // the step reports, rate-limited (solve_warnings.h)
    kea::KeaSolveSparse(prob, opt, *memory.workspace, result_);
    memory.lastAnswer = lastAnswerOf(result_, memory.lastAnswer);
    memory.lastAnswerStep = settings.step;
    report.iterations = result_.iterations;
    report.residual = result_.residual;
    report.factorizations = result_.factorizations;
    report.staleSolves = result_.staleSolves;
    report.factorUpdates = result_.factorUpdates;
    report.warmStartAccepted = result_.warmStartAccepted;
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
