/* reference.cpp: the reference scalar backend of the platform kernels
 * (kernels.h). Plain C++, operation order spelled out: this is the
 * definition every other backend's results must match bit for bit. The
 * build disables floating-point contraction (no fused multiply-add), so each
 * product and each sum is rounded on its own. */
#include "kernels.h"
#include "reference_inline.h"

namespace karma::platform {
namespace {

void RefBodyMinvJt(MeReal invMass, const MeReal invInertiaWorld[3][3], const MeReal jl[3], const MeReal ja[3],
                   MeReal outLin[3], MeReal outAng[3]) {
  reference::BodyMinvJt(invMass, invInertiaWorld, jl, ja, outLin, outAng);
}

MeReal RefRowPairEntry(const MeReal jl_i[3], const MeReal ja_i[3], const MeReal minvJtLin_j[3],
                       const MeReal minvJtAng_j[3]) {
  return reference::RowPairEntry(jl_i, ja_i, minvJtLin_j, minvJtAng_j);
}

constexpr Kernels kReference = {"reference", RefBodyMinvJt, RefRowPairEntry};

}  // namespace

const Kernels &ReferenceKernels() { return kReference; }

const Kernels &ActiveKernels() { return kReference; }

}  // namespace karma::platform
