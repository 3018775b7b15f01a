/* avx2.cpp: the AVX2 backend (kernels.h), on the reductions of
 * avx2_inline.h. Every result is the reference's to the bit. */
#include "avx2_inline.h"
#include "backends.h"

namespace karma::platform {
namespace {

KARMA_AVX2 MeReal Avx2Dot(const MeReal *a, const MeReal *b, int n) { return avx2::Dot(a, b, n); }

KARMA_AVX2 MeReal Avx2GatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  return avx2::GatherDot(value, index, x, n);
}

#define KARMA_ROUTINE_TARGET KARMA_AVX2
#define KARMA_ROUTINE_GATHER_DOT avx2::GatherDot
#include "routines.inc"

}  // namespace

const Kernels kAvx2Kernels = {"avx2", Avx2Dot, Avx2GatherDot, RoutineSparseRowsTimes};

}  // namespace karma::platform
