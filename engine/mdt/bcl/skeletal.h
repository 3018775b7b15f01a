// skeletal.h: the skeletal joint's private layout, shared by skeletal.cpp
// (rows) and skeletal_api.cpp. Not installed.
#pragma once

#include "MdtSkeletal.h"
#include "bcl_type.h"

struct MdtSkeletal : MdtConstraint {
  MeReal primary, secondary, twist;  // half-angles P, S and twist limit T
  MeReal coneStiffness, coneDamping, twistStiffness, twistDamping;
};

namespace karma::mdt {

extern const ConstraintType kSkeletalType;

// Swing of a1 away from a0: theta in [0, pi] and direction psi (from o0
// towards n0); the twist in [-pi, pi] from the swing-twist split of the
// relative rotation (twist about a0 first, then the great-circle swing).
struct SkeletalAngles {
  MeReal theta, psi, twist;
};
SkeletalAngles skeletalAngles(const MdtSkeletal *j);

}  // namespace karma::mdt
