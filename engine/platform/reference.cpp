/* reference.cpp: the reference scalar backend of the platform kernels
 * (kernels.h). Plain C++, operation order spelled out: this is the
 * definition every other backend's results must match bit for bit. The
 * build disables floating-point contraction (no fused multiply-add), so each
 * product and each sum is rounded on its own. */
#include "kernels.h"

namespace karma::platform {
namespace {

void RefBodyMinvJt(MeReal invMass, const MeReal invInertiaWorld[3][3], const MeReal jl[3], const MeReal ja[3],
                   MeReal outLin[3], MeReal outAng[3]) {
  outLin[0] = jl[0] * invMass;
  outLin[1] = jl[1] * invMass;
  outLin[2] = jl[2] * invMass;
  for (int r = 0; r < 3; ++r) {
    const MeReal *row = invInertiaWorld[r];
    outAng[r] = row[0] * ja[0] + row[1] * ja[1] + row[2] * ja[2];
  }
}

MeReal RefRowPairEntry(const MeReal jl_i[3], const MeReal ja_i[3], const MeReal minvJtLin_j[3],
                       const MeReal minvJtAng_j[3]) {
  const MeReal lin = jl_i[0] * minvJtLin_j[0] + jl_i[1] * minvJtLin_j[1] + jl_i[2] * minvJtLin_j[2];
  const MeReal ang = ja_i[0] * minvJtAng_j[0] + ja_i[1] * minvJtAng_j[1] + ja_i[2] * minvJtAng_j[2];
  return lin + ang;
}

constexpr Kernels kReference = {"reference", RefBodyMinvJt, RefRowPairEntry};

}  // namespace

const Kernels &ReferenceKernels() { return kReference; }

const Kernels &ActiveKernels() { return kReference; }

}  // namespace karma::platform
