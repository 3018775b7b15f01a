// euler.cpp: rotation matrix from z-x-z Euler angles (yaw psi, pitch theta,
// roll phi), entry for entry the matrix of Karma's glossary. Its rows are
// the body axes in world coordinates, like every MeMatrix3 rotation, and it
// factors as R = Rz(psi) * Rx(theta) * Rz(phi), with Rz, Rx the matrices of
// MeMatrix3MakeRotationZ / X (the unit test checks this factorisation).
#include "math_detail.h"

extern "C" {

void MEAPI MeMatrix3FromEulerAngles(MeMatrix3 R, MeReal psi, MeReal theta, MeReal phi) {
  const MeReal cps = MeCos(psi), sps = MeSin(psi);
  const MeReal cth = MeCos(theta), sth = MeSin(theta);
  const MeReal cph = MeCos(phi), sph = MeSin(phi);
  MeVector3Set(R[0], cps * cph - cth * sph * sps, cps * sph + cth * cph * sps, sps * sth);
  MeVector3Set(R[1], -sps * cph - cth * sph * cps, -sps * sph + cth * cph * cps, cps * sth);
  MeVector3Set(R[2], sth * sph, -sth * cph, cth);
}

}  // extern "C"
