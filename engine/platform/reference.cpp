/* reference.cpp: the reference scalar backend of the platform kernels
 * (kernels.h). Plain C++, operation order spelled out in
 * reference_inline.h: this is the definition every other backend's results
 * match bit for bit. The build disables floating-point contraction (no fused
 * multiply-add), so each product and each sum is rounded on its own. */
#include "backends.h"
#include "reference_inline.h"

namespace karma::platform {

namespace {

MeReal RefDot(const MeReal *a, const MeReal *b, int n) { return reference::Dot(a, b, n); }

MeReal RefGatherDot(const MeReal *value, const int *index, const MeReal *x, int n) {
  return reference::GatherDot(value, index, x, n);
}

#define KARMA_ROUTINE_TARGET
#define KARMA_ROUTINE_GATHER_DOT reference::GatherDot
#include "routines.inc"

}  // namespace

const Kernels kReferenceKernels = {"reference", RefDot, RefGatherDot, RoutineSparseRowsTimes};

const Kernels &ReferenceKernels() { return kReferenceKernels; }

}  // namespace karma::platform
