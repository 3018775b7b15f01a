// joint_input.h: argument checks and the stiffness/damping convention shared
// by the joint types of this library (Prismatic, Universal, Angular3,
// ConeLimit, Linear1/2, FixedPath). Not installed.
#pragma once

#include "MeMessage.h"
#include "constraint.h"
#include "rows.h"

namespace karma::mdt {

// Normalises a world direction; false (with a warning naming `fn`) when it is
// not finite or (nearly) zero.
inline bool unitDirection(MeVector3 v, const char *fn, const char *what) {
  if (!MeVector3AllFinite(v)) {
    MeWarning(0, "%s: %s is not finite; ignored", fn, what);
    return false;
  }
  const MeReal n = MeVector3Magnitude(v);
  if (!(n > (MeReal)1e-6)) {
    MeWarning(0, "%s: %s has zero length; ignored", fn, what);
    return false;
  }
  MeVector3Scale(v, 1 / n);
  return true;
}

// A primary and a secondary world axis: both normalised, the secondary made
// exactly orthogonal; false (with a warning naming `fn`) when either is not
// finite or zero, or they are not orthogonal within a cosine of 1e-3.
inline bool orthogonalAxes(MeVector3 p, MeVector3 o, const char *fn) {
  if (!unitDirection(p, fn, "the primary axis") || !unitDirection(o, fn, "the secondary axis")) return false;
  const MeReal cosine = MeVector3Dot(p, o);
  if (cosine > (MeReal)1e-3 || cosine < -(MeReal)1e-3) {
    MeWarning(0, "%s: the axes are not orthogonal (cosine %g); ignored", fn, (double)cosine);
    return false;
  }
  MeVector3MultiplyAdd(o, -cosine, p);
  MeVector3Normalize(o);
  return true;
}

inline bool bodyIndexOk(unsigned i, const char *fn) {
  if (i > 1) {
    MeWarning(0, "%s: body index %u is not 0 or 1; ignored", fn, i);
    return false;
  }
  return true;
}

// A stiffness (>= 0, MEINFINITY allowed) or damping argument; false with a
// warning when negative or NaN.
inline bool nonNegative(MeReal x, const char *fn, const char *what) {
  if (!(x >= 0)) {
    MeWarning(0, "%s: %s %g must be >= 0; ignored", fn, what, (double)x);
    return false;
  }
  return true;
}

// The spring convention of these joints: stiffness k and damping c, both
// >= 0, defaults MEINFINITY.
//   k = MEINFINITY           rigid row (world softness, gamma correction)
//   k finite, c = MEINFINITY the damping is read as zero: a pure spring
//   otherwise                damped spring (springRow), force k * error
// k = 0 with no (or infinite) damping means the row exerts nothing:
// isInert() tells the caller to leave it out.
inline bool isRigid(MeReal k) { return k >= MEINFINITY; }
inline bool isInert(MeReal k, MeReal c) { return k <= 0 && (c <= 0 || c >= MEINFINITY); }
inline void makeSpring(Row &row, const StepContext &ctx, MeReal k, MeReal c, MeReal error) {
  springRow(row, ctx, k, c >= MEINFINITY ? 0 : c, error);
}

}  // namespace karma::mdt
