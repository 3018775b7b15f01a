// bcl_type.h: what every constraint type file shares: the definition of the
// four real functions each public header declares through
// MDT_CONSTRAINT_TYPE_DECL, and the cast from the base. Not installed.
#pragma once

#include "MeMessage.h"
#include "constraint.h"
#include "rows.h"

namespace karma::mdt {

template <class T>
T *as(MdtConstraint *c) {
  return static_cast<T *>(c);
}
template <class T>
const T *as(const MdtConstraint *c) {
  return static_cast<const T *>(c);
}

}  // namespace karma::mdt

// Defines MdtP Create / Reset / QuaConstraint and MdtConstraintDCastP for the
// struct MdtP (derived from MdtConstraint) whose type record is `kType`.
#define MDT_DEFINE_CONSTRAINT_TYPE(P, kType)                                           \
  extern "C" {                                                                         \
  MEPUBLIC Mdt##P *MEAPI Mdt##P##Create(const MdtWorldID world) {                      \
    ME_REQUIRE_ARG_RET(world != nullptr, nullptr, "Mdt" #P "Create", "world is NULL"); \
    return static_cast<Mdt##P *>(karma::mdt::createConstraint(world, kType));          \
  }                                                                                    \
  MEPUBLIC void MEAPI Mdt##P##Reset(Mdt##P *const j) {                                 \
    if (!karma::mdt::checkType(j, kType, "Mdt" #P "Reset")) return;                    \
    karma::mdt::resetKeepingBodies(j);                                                 \
  }                                                                                    \
  MEPUBLIC MdtConstraintID MEAPI Mdt##P##QuaConstraint(Mdt##P *const j) { return j; }  \
  MEPUBLIC Mdt##P *MEAPI MdtConstraintDCast##P(const MdtConstraintID c) {              \
    return static_cast<Mdt##P *>(karma::mdt::castTo(c, kType));                        \
  }                                                                                    \
  }
