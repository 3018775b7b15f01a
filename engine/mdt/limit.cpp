// limit.cpp: the MdtLimit / MdtSingleLimit API (the rows are in rows.cpp).
#include <cmath>

#include "MeMessage.h"
#include "MdtLimit.h"
#include "mdt_internal.h"

using karma::mdt::realFinite;

extern "C" {

void MEAPI MdtSingleLimitReset(const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG(sl != nullptr, "MdtSingleLimitReset", "limit is NULL");
  sl->stop = 0;
  sl->stiffness = MEINFINITY;
  sl->damping = 0;
  sl->restitution = 1;
}

MeReal MEAPI MdtSingleLimitGetStop(const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG_RET(sl != nullptr, 0, "MdtSingleLimitGetStop", "limit is NULL");
  return sl->stop;
}
MeReal MEAPI MdtSingleLimitGetStiffness(const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG_RET(sl != nullptr, 0, "MdtSingleLimitGetStiffness", "limit is NULL");
  return sl->stiffness;
}
MeReal MEAPI MdtSingleLimitGetDamping(const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG_RET(sl != nullptr, 0, "MdtSingleLimitGetDamping", "limit is NULL");
  return sl->damping;
}
MeReal MEAPI MdtSingleLimitGetRestitution(const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG_RET(sl != nullptr, 0, "MdtSingleLimitGetRestitution", "limit is NULL");
  return sl->restitution;
}

void MEAPI MdtSingleLimitSetStop(const MdtSingleLimitID sl, const MeReal stop) {
  static const char *fn = "MdtSingleLimitSetStop";
  ME_REQUIRE_ARG(sl != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(realFinite(stop), fn, "stop is not finite; ignored");
  sl->stop = stop;
}
void MEAPI MdtSingleLimitSetStiffness(const MdtSingleLimitID sl, const MeReal k) {
  static const char *fn = "MdtSingleLimitSetStiffness";
  ME_REQUIRE_ARG(sl != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(k >= 0, fn, "stiffness %g must be >= 0; ignored", (double)k);
  sl->stiffness = k > MEINFINITY ? MEINFINITY : k;
}
void MEAPI MdtSingleLimitSetDamping(const MdtSingleLimitID sl, const MeReal d) {
  static const char *fn = "MdtSingleLimitSetDamping";
  ME_REQUIRE_ARG(sl != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(d >= 0 && realFinite(d), fn, "damping %g must be finite and >= 0; ignored", (double)d);
  sl->damping = d;
}
void MEAPI MdtSingleLimitSetRestitution(const MdtSingleLimitID sl, const MeReal e) {
  static const char *fn = "MdtSingleLimitSetRestitution";
  ME_REQUIRE_ARG(sl != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(e >= 0 && e <= 1, fn, "restitution %g must be in [0, 1]; ignored", (double)e);
  sl->restitution = e;
}

void MEAPI MdtLimitReset(const MdtLimitID limit) {
  ME_REQUIRE_ARG(limit != nullptr, "MdtLimitReset", "limit is NULL");
  MdtSingleLimitReset(&limit->limit[0]);
  MdtSingleLimitReset(&limit->limit[1]);
  limit->stiffnessThreshold = MEINFINITY;
  limit->motorDesiredVelocity = 0;
  limit->motorMaxForce = 0;
  limit->limited = FALSE;
  limit->motorized = FALSE;
  limit->calculatePosition = FALSE;
  limit->offset = 0;
  limit->position = 0;
  limit->velocity = 0;
  limit->rawPrevious = 0;
  limit->turns = 0;
  limit->rawValid = FALSE;
}

MdtSingleLimitID MEAPI MdtLimitGetLowerLimit(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, nullptr, "MdtLimitGetLowerLimit", "limit is NULL");
  return &limit->limit[0];
}
MdtSingleLimitID MEAPI MdtLimitGetUpperLimit(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, nullptr, "MdtLimitGetUpperLimit", "limit is NULL");
  return &limit->limit[1];
}

void MEAPI MdtLimitSetLowerLimit(const MdtLimitID limit, const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG(limit != nullptr && sl != nullptr, "MdtLimitSetLowerLimit", "NULL argument");
  limit->limit[0] = *sl;
  if (limit->limit[1].stop < sl->stop) limit->limit[1].stop = sl->stop;
}
void MEAPI MdtLimitSetUpperLimit(const MdtLimitID limit, const MdtSingleLimitID sl) {
  ME_REQUIRE_ARG(limit != nullptr && sl != nullptr, "MdtLimitSetUpperLimit", "NULL argument");
  limit->limit[1] = *sl;
  if (limit->limit[0].stop > sl->stop) limit->limit[0].stop = sl->stop;
}

MeReal MEAPI MdtLimitGetPosition(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, 0, "MdtLimitGetPosition", "limit is NULL");
  return limit->position;
}
MeReal MEAPI MdtLimitGetVelocity(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, 0, "MdtLimitGetVelocity", "limit is NULL");
  return limit->velocity;
}
void MEAPI MdtLimitSetPosition(const MdtLimitID limit, const MeReal position) {
  static const char *fn = "MdtLimitSetPosition";
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(realFinite(position), fn, "position is not finite; ignored");
  // position = measured + offset, with measured = position - old offset.
  const MeReal measured = limit->position - limit->offset;
  limit->offset = position - measured;
  limit->position = position;
}

MeReal MEAPI MdtLimitGetStiffnessThreshold(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, 0, "MdtLimitGetStiffnessThreshold", "limit is NULL");
  return limit->stiffnessThreshold;
}
void MEAPI MdtLimitSetStiffnessThreshold(const MdtLimitID limit, const MeReal t) {
  static const char *fn = "MdtLimitSetStiffnessThreshold";
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(t >= 0, fn, "threshold %g must be >= 0; ignored", (double)t);
  limit->stiffnessThreshold = t > MEINFINITY ? MEINFINITY : t;
}

void MEAPI MdtLimitSetLimitedForceMotor(const MdtLimitID limit, const MeReal desiredVelocity, const MeReal forceLimit) {
  static const char *fn = "MdtLimitSetLimitedForceMotor";
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(realFinite(desiredVelocity), fn, "desired velocity is not finite; ignored");
  ME_REQUIRE_ARG(forceLimit >= 0 && realFinite(forceLimit), fn, "force limit %g must be finite and >= 0; ignored",
                 (double)forceLimit);
  limit->motorDesiredVelocity = desiredVelocity;
  limit->motorMaxForce = forceLimit;
  limit->motorized = forceLimit > 0 ? TRUE : FALSE;
  if (limit->motorized) limit->calculatePosition = TRUE;
}
MeReal MEAPI MdtLimitGetMotorDesiredVelocity(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, 0, "MdtLimitGetMotorDesiredVelocity", "limit is NULL");
  return limit->motorDesiredVelocity;
}
MeReal MEAPI MdtLimitGetMotorMaxForce(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, 0, "MdtLimitGetMotorMaxForce", "limit is NULL");
  return limit->motorMaxForce;
}

void MEAPI MdtLimitActivateLimits(const MdtLimitID limit, const MeBool on) {
  ME_REQUIRE_ARG(limit != nullptr, "MdtLimitActivateLimits", "limit is NULL");
  limit->limited = on ? TRUE : FALSE;
  if (on) limit->calculatePosition = TRUE;
}
void MEAPI MdtLimitActivateMotor(const MdtLimitID limit, const MeBool on) {
  ME_REQUIRE_ARG(limit != nullptr, "MdtLimitActivateMotor", "limit is NULL");
  limit->motorized = on ? TRUE : FALSE;
  if (on) limit->calculatePosition = TRUE;
}
void MEAPI MdtLimitCalculatePosition(const MdtLimitID limit, const MeBool on) {
  ME_REQUIRE_ARG(limit != nullptr, "MdtLimitCalculatePosition", "limit is NULL");
  limit->calculatePosition = (on || limit->limited || limit->motorized) ? TRUE : FALSE;
}
MeBool MEAPI MdtLimitIsActive(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, FALSE, "MdtLimitIsActive", "limit is NULL");
  return limit->limited;
}
MeBool MEAPI MdtLimitIsMotorized(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, FALSE, "MdtLimitIsMotorized", "limit is NULL");
  return limit->motorized;
}
MeBool MEAPI MdtLimitPositionIsCalculated(const MdtLimitID limit) {
  ME_REQUIRE_ARG_RET(limit != nullptr, FALSE, "MdtLimitPositionIsCalculated", "limit is NULL");
  return limit->calculatePosition;
}

void MEAPI MdtLimitController(const MdtLimitID limit, const MeReal desiredPosition, const MeReal gap,
                              const MeReal maxSpeed, const MeReal maxForce) {
  static const char *fn = "MdtLimitController";
  ME_REQUIRE_ARG(limit != nullptr, fn, "limit is NULL");
  ME_REQUIRE_ARG(realFinite(desiredPosition) && realFinite(maxSpeed), fn, "arguments are not finite; ignored");
  ME_REQUIRE_ARG(gap > 0 && realFinite(gap), fn, "gap %g must be positive; ignored", (double)gap);
  const MeReal e = desiredPosition - limit->position;
  MeReal v = maxSpeed * e / gap;
  const MeReal s = std::fabs(maxSpeed);
  if (v > s) v = s;
  if (v < -s) v = -s;
  MdtLimitSetLimitedForceMotor(limit, v, maxForce);
}

}  // extern "C"
