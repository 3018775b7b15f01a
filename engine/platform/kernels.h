/* kernels.h: the platform's table of hot numeric kernels, one table per
 * backend, and the choice of backend.
 *
 * INTERNAL header (namespace karma::platform), not installed.
 *
 * Backends. `reference` is portable scalar C++ and defines every kernel's
 * result; `sse4` (SSE4.2), `avx2` (AVX2) and `avx512` (AVX-512F) compute
 * the same operations in the same order, several independent lanes at a
 * time, with per-function target attributes, so one library holds them all
 * and the CPU decides at run time which can run. No backend contracts a
 * multiply and an add into one rounding (no FMA): every backend's results
 * are bit-identical to the reference's, which is what the conformance test
 * (platform_test) checks and why the goldens and state hashes are shared by
 * all backends.
 *
 * Reductions. A sum of products is defined over kLanes interleaved partial
 * sums: term k goes to partial sum k mod kLanes (each partial sum adds its
 * terms in ascending k, starting from 0), and the partial sums combine as
 *     ((s0 + s4) + (s2 + s6)) + ((s1 + s5) + (s3 + s7))
 * (LaneSum in reference_inline.h, kLanes = 8). That order is what an
 * 8-lane vector accumulator gives, so a SIMD backend keeps one accumulator
 * per lane.
 *
 * Calls. Callers go through Dot and GatherDot below: an array shorter than
 * kLanes has nothing to vectorise, and is done by the inline reference code
 * (the same bits) instead of an indirect call. A loop of many short
 * reductions (a sparse product) is a whole routine in the table, so the
 * indirect call is paid once per loop.
 *
 * What is here: the array kernels of Kea's sparse path (its sparse
 * products, the conjugate-gradient dots of its stale solves, the sparse PGS
 * sweep). What is not: the per-row three-vector operations of the assembly
 * (reference_inline.h), called inline, as a table entry would cost an
 * indirect call per six flops; and the envelope LDL^T and its triangular
 * solves (kea_envelope_ldlt.h), recurrences whose speed is the latency from
 * one result to the next, which vector reductions lengthen
 * (docs/NOTES.md, "Envelope recurrences").
 * Counts n may be 0. */
#ifndef KARMA_PLATFORM_KERNELS_H
#define KARMA_PLATFORM_KERNELS_H

#include "MePrecision.h"
#include "reference_inline.h"

#include <span>

namespace karma::platform {

struct Kernels {
  /* The backend's name: "reference", "sse4", "avx2" or "avx512". */
  const char *name;

  /* sum_{k < n} a[k] b[k], in the lane order above. */
  MeReal (*dot)(const MeReal *a, const MeReal *b, int n);

  /* sum_{k < n} value[k] x[index[k]] (a sparse row times a dense vector),
   * in the lane order above. */
  MeReal (*gatherDot)(const MeReal *value, const int *index, const MeReal *x, int n);

  /* A whole routine (routines.inc): y[a] = sum_{rowStart[i] <= k <
   * rowStart[i+1]} val[k] x[col[k]] with i = rows[a] (i = a when rows is
   * null), for a < count: CSR rows times a dense vector, each row a
   * gatherDot (y must not overlap x). */
  void (*sparseRowsTimes)(const int *rowStart, const int *col, const MeReal *val, const int *rows, int count,
                          const MeReal *x, MeReal *y);
};

/* Every backend, reference first, then in order of preference (the last
 * one the CPU supports is the best). */
std::span<const Kernels *const> AllKernels();

/* The backend called `name`, or nullptr when there is none by that name
 * (whether or not the CPU supports it). */
const Kernels *FindKernels(const char *name);

/* Whether this CPU (and its operating system) can run the backend. */
bool Supported(const Kernels &kernels);

/* The most capable backend this CPU supports. */
const Kernels &BestSupported();

/* The reference scalar backend. */
const Kernels &ReferenceKernels();

/* The process default, the backend a new world starts with. Until
 * SetDefaultKernels changes it: the one named by the environment variable
 * KARMA_PLATFORM when it is set, known and supported; else the best
 * supported one. The variable is read once, at the first call of either
 * function; an unknown or unsupported name then gives one warning
 * (MeWarning), naming the backend used instead. */
const Kernels &DefaultKernels();

/* Makes `kernels` the process default for worlds created from now on
 * (worlds already made keep theirs). The caller checks Supported first.
 * Safe to call while other threads read the default. */
void SetDefaultKernels(const Kernels &kernels);

/* The backend for a request by name: the named one when known and
 * supported; else `fallback` (typically the best supported one), with a
 * warning saying why. */
const Kernels &KernelsForRequest(const char *name, const Kernels &fallback);

/* The kernels through `kernels`, arrays shorter than kLanes inline. */
inline MeReal Dot(const Kernels &kernels, const MeReal *a, const MeReal *b, int n) {
  return n < kLanes ? reference::Dot(a, b, n) : kernels.dot(a, b, n);
}
inline MeReal GatherDot(const Kernels &kernels, const MeReal *value, const int *index, const MeReal *x, int n) {
  return n < kLanes ? reference::GatherDot(value, index, x, n) : kernels.gatherDot(value, index, x, n);
}
}  // namespace karma::platform

#endif
