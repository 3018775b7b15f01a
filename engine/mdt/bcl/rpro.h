// rpro.h: the RPRO joint's private layout, shared by rpro.cpp (rows) and
// rpro_api.cpp. Not installed.
#pragma once

#include "MdtRPROJoint.h"
#include "bcl_type.h"

struct MdtRPROJoint : MdtConstraint {
  MeVector4 relativeQ;  // target: F1 = F0 turned by relativeQ (F0 axes)
  MeVector3 relativeW;  // target w1 - w0 in F0 axes
  MeVector3 linearStrength;
  MeVector3 angularStrength;
};

namespace karma::mdt {
extern const ConstraintType kRPROJointType;
}
