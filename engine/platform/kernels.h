/* kernels.h: the platform's table of hot numeric kernels (per body, per
 * constraint row) used by the dynamics step.
 *
 * INTERNAL header (namespace karma::platform), not installed. The step calls
 * the kernels through the table that ActiveKernels() returns, so a SIMD
 * backend can replace the reference scalar one without touching the callers.
 * Every backend must give results bit-identical to the reference backend's
 * (the same operations in the same order, no contraction), since the step's
 * determinism is tested by hash; a backend that cannot must not be selected
 * by default.
 *
 * Conventions: vectors are MeReal[3]; the inertia is a row-major 3x3
 * (MeMatrix3); a row's Jacobian for one body is its linear part jl and
 * angular part ja. */
#ifndef KARMA_PLATFORM_KERNELS_H
#define KARMA_PLATFORM_KERNELS_H

#include "MePrecision.h"

namespace karma::platform {

struct Kernels {
  /* The backend's name ("reference", ...), for logs and benchmarks. */
  const char *name;

  /* M^-1 J^T of one row for one body:
   *     outLin = invMass * jl                 (componentwise, jl[k] * invMass)
   *     outAng = invInertiaWorld * ja          (row r: I[r][0]*ja[0] + I[r][1]*ja[1] + I[r][2]*ja[2])
   * out may not alias the inputs. */
  void (*bodyMinvJt)(MeReal invMass, const MeReal invInertiaWorld[3][3], const MeReal jl[3], const MeReal ja[3],
                     MeReal outLin[3], MeReal outAng[3]);

  /* One body's contribution to the entry A_ij of A = J M^-1 J^T: row i's
   * Jacobian (jl_i, ja_i) for the body dotted with row j's M^-1 J^T for it:
   *     (jl_i . lin_j) + (ja_i . ang_j),
   * each dot summed left to right. Also gives J v for a body velocity
   * (lin_j, ang_j) = (v, w). */
  MeReal (*rowPairEntry)(const MeReal jl_i[3], const MeReal ja_i[3], const MeReal minvJtLin_j[3],
                         const MeReal minvJtAng_j[3]);
};

/* The reference scalar backend (reference.cpp). */
const Kernels &ReferenceKernels();

/* The backend the step uses. For now always the reference backend. */
const Kernels &ActiveKernels();

}  // namespace karma::platform

#endif
