// contact_params.cpp: MdtContactParams accessors and mutators. Negative
// limits, coefficients, slips, softness or thresholds, restitution outside
// [0, 1] and non-finite numbers are rejected with a warning.
#include <cmath>

#include "MdtContact.h"
#include "MeMessage.h"

namespace {

bool validNonNegative(MdtContactParamsID p, MeReal v, const char *fn, bool allowInfinity) {
  if (!p) {
    MeWarning(0, "%s: params is NULL", fn);
    return false;
  }
  const bool ok = v >= 0 && (allowInfinity ? !std::isnan(v) : std::isfinite(v));
  if (!ok) MeWarning(0, "%s: value %g must be >= 0%s; ignored", fn, (double)v, allowInfinity ? "" : " and finite");
  return ok;
}

MeReal clampInf(MeReal v) { return v > MEINFINITY ? MEINFINITY : v; }

}  // namespace

extern "C" {

void MEAPI MdtContactParamsReset(const MdtContactParamsID p) {
  ME_REQUIRE_ARG(p != nullptr, "MdtContactParamsReset", "params is NULL");
  p->type = MdtContactTypeFrictionZero;
  p->model1 = p->model2 = MdtFrictionModelBox;
  p->options = 0;
  p->frictionCoefficient1 = p->frictionCoefficient2 = 0;
  p->restitution = 0;
  p->velThreshold = (MeReal)0.001;
  p->softness = 0;
  p->max_adhesive_force = 0;
  p->friction1 = p->friction2 = MEINFINITY;
  p->slip1 = p->slip2 = 0;
  p->slide1 = p->slide2 = 0;
}

void MEAPI MdtContactParamsSetType(const MdtContactParamsID p, const MdtContactType t) {
  static const char *fn = "MdtContactParamsSetType";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  ME_REQUIRE_ARG(t == MdtContactTypeFrictionZero || t == MdtContactTypeFriction1D || t == MdtContactTypeFriction2D, fn,
                 "unknown contact type %d; ignored", (int)t);
  p->type = t;
}
MdtContactType MEAPI MdtContactParamsGetType(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, MdtContactTypeFrictionZero, "MdtContactParamsGetType", "params is NULL");
  return p->type;
}

static bool validModel(MdtFrictionModel m, const char *fn) {
  if (m == MdtFrictionModelBox || m == MdtFrictionModelNormalForce) return true;
  MeWarning(0, "%s: unknown friction model %d; ignored", fn, (int)m);
  return false;
}
void MEAPI MdtContactParamsSetPrimaryFrictionModel(const MdtContactParamsID p, const MdtFrictionModel m) {
  static const char *fn = "MdtContactParamsSetPrimaryFrictionModel";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  if (validModel(m, fn)) p->model1 = m;
}
void MEAPI MdtContactParamsSetSecondaryFrictionModel(const MdtContactParamsID p, const MdtFrictionModel m) {
  static const char *fn = "MdtContactParamsSetSecondaryFrictionModel";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  if (validModel(m, fn)) p->model2 = m;
}
MdtFrictionModel MEAPI MdtContactParamsGetPrimaryFrictionModel(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, MdtFrictionModelBox, "MdtContactParamsGetPrimaryFrictionModel", "params is NULL");
  return p->model1;
}
MdtFrictionModel MEAPI MdtContactParamsGetSecondaryFrictionModel(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, MdtFrictionModelBox, "MdtContactParamsGetSecondaryFrictionModel", "params is NULL");
  return p->model2;
}

void MEAPI MdtContactParamsSetFriction(const MdtContactParamsID p, const MeReal f) {
  if (!validNonNegative(p, f, "MdtContactParamsSetFriction", true)) return;
  p->friction1 = p->friction2 = clampInf(f);
}
void MEAPI MdtContactParamsSetPrimaryFriction(const MdtContactParamsID p, const MeReal f) {
  if (!validNonNegative(p, f, "MdtContactParamsSetPrimaryFriction", true)) return;
  p->friction1 = clampInf(f);
}
void MEAPI MdtContactParamsSetSecondaryFriction(const MdtContactParamsID p, const MeReal f) {
  if (!validNonNegative(p, f, "MdtContactParamsSetSecondaryFriction", true)) return;
  p->friction2 = clampInf(f);
}
MeReal MEAPI MdtContactParamsGetPrimaryFriction(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetPrimaryFriction", "params is NULL");
  return p->friction1;
}
MeReal MEAPI MdtContactParamsGetSecondaryFriction(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetSecondaryFriction", "params is NULL");
  return p->friction2;
}

void MEAPI MdtContactParamsSetFrictionCoefficient(const MdtContactParamsID p, const MeReal mu) {
  if (!validNonNegative(p, mu, "MdtContactParamsSetFrictionCoefficient", false)) return;
  p->frictionCoefficient1 = p->frictionCoefficient2 = mu;
}
void MEAPI MdtContactParamsSetPrimaryFrictionCoefficient(const MdtContactParamsID p, const MeReal mu) {
  if (!validNonNegative(p, mu, "MdtContactParamsSetPrimaryFrictionCoefficient", false)) return;
  p->frictionCoefficient1 = mu;
}
void MEAPI MdtContactParamsSetSecondaryFrictionCoefficient(const MdtContactParamsID p, const MeReal mu) {
  if (!validNonNegative(p, mu, "MdtContactParamsSetSecondaryFrictionCoefficient", false)) return;
  p->frictionCoefficient2 = mu;
}
MeReal MEAPI MdtContactParamsGetPrimaryFrictionCoefficient(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetPrimaryFrictionCoefficient", "params is NULL");
  return p->frictionCoefficient1;
}
MeReal MEAPI MdtContactParamsGetSecondaryFrictionCoefficient(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetSecondaryFrictionCoefficient", "params is NULL");
  return p->frictionCoefficient2;
}

void MEAPI MdtContactParamsSetRestitution(const MdtContactParamsID p, const MeReal e) {
  static const char *fn = "MdtContactParamsSetRestitution";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  ME_REQUIRE_ARG(e >= 0 && e <= 1, fn, "restitution %g must be in [0, 1]; ignored", (double)e);
  p->restitution = e;
  if (e > 0)
    p->options |= MdtContactOptionBounce;
  else
    p->options &= ~MdtContactOptionBounce;
}
MeReal MEAPI MdtContactParamsGetRestitution(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetRestitution", "params is NULL");
  return p->restitution;
}
void MEAPI MdtContactParamsSetRestitutionThreshold(const MdtContactParamsID p, const MeReal v) {
  if (!validNonNegative(p, v, "MdtContactParamsSetRestitutionThreshold", false)) return;
  p->velThreshold = v;
}
MeReal MEAPI MdtContactParamsGetRestitutionThreshold(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetRestitutionThreshold", "params is NULL");
  return p->velThreshold;
}

static void setFlag(MdtContactParamsID p, int flag, bool on) {
  if (on)
    p->options |= flag;
  else
    p->options &= ~flag;
}

void MEAPI MdtContactParamsSetSoftness(const MdtContactParamsID p, const MeReal s) {
  if (!validNonNegative(p, s, "MdtContactParamsSetSoftness", false)) return;
  p->softness = s;
  setFlag(p, MdtContactOptionSoft, s > 0);
}
MeReal MEAPI MdtContactParamsGetSoftness(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetSoftness", "params is NULL");
  return p->softness;
}
void MEAPI MdtContactParamsSetMaxAdhesiveForce(const MdtContactParamsID p, const MeReal f) {
  if (!validNonNegative(p, f, "MdtContactParamsSetMaxAdhesiveForce", true)) return;
  p->max_adhesive_force = clampInf(f);
  setFlag(p, MdtContactOptionAdhesive, f > 0);
}
MeReal MEAPI MdtContactParamsGetMaxAdhesiveForce(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetMaxAdhesiveForce", "params is NULL");
  return p->max_adhesive_force;
}

void MEAPI MdtContactParamsSetSlip(const MdtContactParamsID p, const MeReal s) {
  if (!validNonNegative(p, s, "MdtContactParamsSetSlip", false)) return;
  p->slip1 = p->slip2 = s;
  setFlag(p, MdtContactOptionSlip1 | MdtContactOptionSlip2, s > 0);
}
void MEAPI MdtContactParamsSetPrimarySlip(const MdtContactParamsID p, const MeReal s) {
  if (!validNonNegative(p, s, "MdtContactParamsSetPrimarySlip", false)) return;
  p->slip1 = s;
  setFlag(p, MdtContactOptionSlip1, s > 0);
}
void MEAPI MdtContactParamsSetSecondarySlip(const MdtContactParamsID p, const MeReal s) {
  if (!validNonNegative(p, s, "MdtContactParamsSetSecondarySlip", false)) return;
  p->slip2 = s;
  setFlag(p, MdtContactOptionSlip2, s > 0);
}
MeReal MEAPI MdtContactParamsGetPrimarySlip(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetPrimarySlip", "params is NULL");
  return p->slip1;
}
MeReal MEAPI MdtContactParamsGetSecondarySlip(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetSecondarySlip", "params is NULL");
  return p->slip2;
}

void MEAPI MdtContactParamsSetPrimarySlide(const MdtContactParamsID p, const MeReal v) {
  static const char *fn = "MdtContactParamsSetPrimarySlide";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  ME_REQUIRE_ARG(std::isfinite(v), fn, "slide is not finite; ignored");
  p->slide1 = v;
  setFlag(p, MdtContactOptionSlide1, v != 0);
}
void MEAPI MdtContactParamsSetSecondarySlide(const MdtContactParamsID p, const MeReal v) {
  static const char *fn = "MdtContactParamsSetSecondarySlide";
  ME_REQUIRE_ARG(p != nullptr, fn, "params is NULL");
  ME_REQUIRE_ARG(std::isfinite(v), fn, "slide is not finite; ignored");
  p->slide2 = v;
  setFlag(p, MdtContactOptionSlide2, v != 0);
}
MeReal MEAPI MdtContactParamsGetPrimarySlide(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetPrimarySlide", "params is NULL");
  return p->slide1;
}
MeReal MEAPI MdtContactParamsGetSecondarySlide(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetSecondarySlide", "params is NULL");
  return p->slide2;
}
int MEAPI MdtContactParamsGetOptions(const MdtContactParamsID p) {
  ME_REQUIRE_ARG_RET(p != nullptr, 0, "MdtContactParamsGetOptions", "params is NULL");
  return p->options;
}

}  // extern "C"
