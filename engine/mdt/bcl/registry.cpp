// registry.cpp: the list of every constraint type, for names and for the
// size of the world's constraint slots (the largest type).
#include "constraint.h"

namespace karma::mdt {

extern const ConstraintType kBSJointType;
extern const ConstraintType kHingeType;
extern const ConstraintType kPrismaticType;
extern const ConstraintType kUniversalType;
extern const ConstraintType kAngular3Type;
extern const ConstraintType kConeLimitType;
extern const ConstraintType kLinear1Type;
extern const ConstraintType kLinear2Type;
extern const ConstraintType kFixedPathType;
extern const ConstraintType kCarWheelType;
extern const ConstraintType kSpringType;
extern const ConstraintType kSkeletalType;
extern const ConstraintType kSpring6Type;
extern const ConstraintType kRPROJointType;
extern const ConstraintType kContactType;
extern const ConstraintType kContactGroupType;

const ConstraintType *const *allConstraintTypes() {
  static const ConstraintType *const all[] = {
      &kBSJointType, &kHingeType,     &kPrismaticType, &kUniversalType,    &kAngular3Type, &kConeLimitType,
      &kLinear1Type, &kLinear2Type,   &kFixedPathType, &kCarWheelType,     &kSpringType,   &kSkeletalType,
      &kSpring6Type, &kRPROJointType, &kContactType,   &kContactGroupType, nullptr};
  return all;
}

unsigned largestConstraintSize() {
  unsigned size = 0;
  for (const ConstraintType *const *t = allConstraintTypes(); *t; ++t)
    if ((*t)->size > size) size = (*t)->size;
  return size;
}

}  // namespace karma::mdt
