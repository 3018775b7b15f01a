// world_params.cpp: accessors of the public world parameters, and the
// check of values written into world->params directly.
//
// Direct writes. The guide's programs write world->params.gamma and
// .epsilon themselves, past the setters. The world keeps `checked`, the
// parameters as last validated; every setter stores into both. At the start
// of each MdtWorldStep, checkDirectParamWrites compares the two field by
// field: a field that differs went in directly and gets the setter's rule
// and message now, once (afterwards the two agree again): a value the setter
// would reject is replaced by the last valid one, a value the setter accepts
// with a warning (gamma > 1) is kept with that warning.
#include <cstring>

#include "MeMessage.h"
#include "mdt_internal.h"

using namespace karma::mdt;

namespace {

void warnGammaOverOne(MeReal gamma, const char *fn) {
  if (gamma > 1)
    MeWarning(0,
              "%s: gamma %g > 1 over-corrects every step (gamma is the fraction of the error "
              "corrected per step; a rate r in 1/s is gamma = r * h)",
              fn, (double)gamma);
}

}  // namespace

extern "C" {

void MEAPI MdtWorldSetGravity(const MdtWorldID world, const MeReal gx, const MeReal gy, const MeReal gz) {
  static const char *fn = "MdtWorldSetGravity";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite3(gx, gy, gz), fn, "gravity (%g, %g, %g) is not finite; ignored", (double)gx, (double)gy,
                 (double)gz);
  MeVector3Set(world->params.gravity, gx, gy, gz);
  MeVector3Copy(world->priv->checked.gravity, world->params.gravity);
}

void MEAPI MdtWorldGetGravity(const MdtWorldID world, MeVector3 g) {
  ME_REQUIRE_ARG(world != nullptr && g != nullptr, "MdtWorldGetGravity", "NULL argument");
  MeVector3Copy(g, world->params.gravity);
}

void MEAPI MdtWorldSetEpsilon(const MdtWorldID world, const MeReal epsilon) {
  static const char *fn = "MdtWorldSetEpsilon";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(epsilon) && epsilon >= 0, fn, "epsilon must be finite and >= 0, got %g; ignored",
                 (double)epsilon);
  world->params.epsilon = world->priv->checked.epsilon = epsilon;
}

MeReal MEAPI MdtWorldGetEpsilon(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, (MeReal)0, "MdtWorldGetEpsilon", "world is NULL");
  return world->params.epsilon;
}

void MEAPI MdtWorldSetGamma(const MdtWorldID world, const MeReal gamma) {
  static const char *fn = "MdtWorldSetGamma";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(gamma) && gamma >= 0, fn, "gamma must be finite and >= 0, got %g; ignored", (double)gamma);
  warnGammaOverOne(gamma, fn);
  world->params.gamma = world->priv->checked.gamma = gamma;
}

MeReal MEAPI MdtWorldGetGamma(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, (MeReal)0, "MdtWorldGetGamma", "world is NULL");
  return world->params.gamma;
}

void MEAPI MdtWorldSetAutoDisable(const MdtWorldID world, const MeBool on) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetAutoDisable", "world is NULL");
  world->params.autoDisable = world->priv->checked.autoDisable = on ? TRUE : FALSE;
}

MeBool MEAPI MdtWorldGetAutoDisable(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, FALSE, "MdtWorldGetAutoDisable", "world is NULL");
  return world->params.autoDisable;
}

namespace {
void setNonNegative(MdtWorldID world, MeReal v, MeReal MdtWorldParams::*field, const char *fn) {
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(v) && v >= 0, fn, "value must be finite and >= 0, got %g; ignored", (double)v);
  world->params.*field = world->priv->checked.*field = v;
}
}  // namespace

void MEAPI MdtWorldSetAutoDisableVelocityThreshold(const MdtWorldID world, const MeReal v) {
  setNonNegative(world, v, &MdtWorldParams::velocityThreshold, "MdtWorldSetAutoDisableVelocityThreshold");
}
void MEAPI MdtWorldSetAutoDisableAngularVelocityThreshold(const MdtWorldID world, const MeReal w) {
  setNonNegative(world, w, &MdtWorldParams::angularVelocityThreshold, "MdtWorldSetAutoDisableAngularVelocityThreshold");
}
void MEAPI MdtWorldSetAutoDisableAccelerationThreshold(const MdtWorldID world, const MeReal a) {
  setNonNegative(world, a, &MdtWorldParams::accelerationThreshold, "MdtWorldSetAutoDisableAccelerationThreshold");
}
void MEAPI MdtWorldSetAutoDisableAngularAccelerationThreshold(const MdtWorldID world, const MeReal a) {
  setNonNegative(world, a, &MdtWorldParams::angularAccelerationThreshold,
                 "MdtWorldSetAutoDisableAngularAccelerationThreshold");
}
void MEAPI MdtWorldSetAutoDisableAliveWindow(const MdtWorldID world, const MeReal t) {
  setNonNegative(world, t, &MdtWorldParams::aliveWindow, "MdtWorldSetAutoDisableAliveWindow");
}

void MEAPI MdtWorldSetAutoDisableAliveWindowMode(const MdtWorldID world, const MdtAliveWindowMode mode) {
  static const char *fn = "MdtWorldSetAutoDisableAliveWindowMode";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(
      mode == MdtAliveWindowIdleSeconds || mode == MdtAliveWindowAwakeSeconds || mode == MdtAliveWindowAwakeSteps, fn,
      "unknown mode %d; ignored", (int)mode);
  world->priv->aliveWindowMode = mode;
}

MdtAliveWindowMode MEAPI MdtWorldGetAutoDisableAliveWindowMode(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, MdtAliveWindowIdleSeconds, "MdtWorldGetAutoDisableAliveWindowMode",
                     "world is NULL");
  return world->priv->aliveWindowMode;
}

void MEAPI MdtWorldSetWakeByForce(const MdtWorldID world, const MeBool on) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetWakeByForce", "world is NULL");
  world->priv->forcesDoNotWake = on ? FALSE : TRUE;
}

MeBool MEAPI MdtWorldGetWakeByForce(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, TRUE, "MdtWorldGetWakeByForce", "world is NULL");
  return world->priv->forcesDoNotWake ? FALSE : TRUE;
}

void MEAPI MdtWorldSetDebugDrawOptions(const MdtWorldID world, const int options) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetDebugDrawOptions", "world is NULL");
  world->priv->debugDrawOptions = options;
}

int MEAPI MdtWorldGetDebugDrawOptions(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetDebugDrawOptions", "world is NULL");
  return world->priv->debugDrawOptions;
}

void MEAPI MdtWorldSetMaxMatrixSize(const MdtWorldID world, const int size) {
  static const char *fn = "MdtWorldSetMaxMatrixSize";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(size >= 0, fn, "size must be >= 0 (0 = no cap), got %d; ignored", size);
  world->params.maxMatrixSize = world->priv->checked.maxMatrixSize = size;
}

void MEAPI MdtWorldSetContactImportanceCB(const MdtWorldID world, MdtContactImportanceCBPtr cb) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetContactImportanceCB", "world is NULL");
  world->priv->importance = cb;
}

void MEAPI MdtWorldSetKeaMethod(const MdtWorldID world, const MdtKeaMethod method) {
  static const char *fn = "MdtWorldSetKeaMethod";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(method == MdtKeaMethodActiveSet || method == MdtKeaMethodPGS, fn, "unknown method %d; ignored",
                 (int)method);
  world->params.keaMethod = world->priv->checked.keaMethod = method;
}

void MEAPI MdtWorldSetKeaMaxIterations(const MdtWorldID world, const int n) {
  static const char *fn = "MdtWorldSetKeaMaxIterations";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(n >= 0, fn, "iteration cap must be >= 0 (0 = default), got %d; ignored", n);
  world->params.keaMaxIterations = world->priv->checked.keaMaxIterations = n;
}

void MEAPI MdtWorldSetJointProjection(const MdtWorldID world, const int sweeps) {
  static const char *fn = "MdtWorldSetJointProjection";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(sweeps >= 0, fn, "sweeps must be >= 0 (0 = off), got %d; ignored", sweeps);
  world->params.jointProjection = world->priv->checked.jointProjection = sweeps;
}

int MEAPI MdtWorldGetJointProjection(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetJointProjection", "world is NULL");
  return world->params.jointProjection;
}

void MEAPI MdtWorldSetGeometricStiffness(const MdtWorldID world, const MeReal factor) {
  setNonNegative(world, factor, &MdtWorldParams::geometricStiffness, "MdtWorldSetGeometricStiffness");
}

void MEAPI MdtWorldSetKeaTolerance(const MdtWorldID world, const MeReal tol) {
  setNonNegative(world, tol, &MdtWorldParams::keaTolerance, "MdtWorldSetKeaTolerance");
}

size_t MEAPI MdtKeaMemoryRequired(const int rows, const int bodies) {
  if (rows <= 0) return 0;
  const size_t n = (size_t)rows;
  const size_t nb = bodies > 0 ? (size_t)bodies : 0;
  // Matrix and factor (n^2 each), 8 row vectors, the Jacobian (12 per row),
  // M^-1 J^T (12 per row), body data (velocities and inverse inertia).
  return sizeof(MeReal) * (2 * n * n + 8 * n + 24 * n + 24 * nb) + sizeof(int) * 6 * n;
}

}  // extern "C"

namespace karma::mdt {

namespace {

// One real parameter whose setter accepts finite values >= 0.
struct NonNegativeField {
  MeReal MdtWorldParams::*field;
  const char *setter;
  const char *name;
};

constexpr NonNegativeField kNonNegativeFields[] = {
    {&MdtWorldParams::epsilon, "MdtWorldSetEpsilon", "epsilon"},
    {&MdtWorldParams::gamma, "MdtWorldSetGamma", "gamma"},
    {&MdtWorldParams::velocityThreshold, "MdtWorldSetAutoDisableVelocityThreshold", "velocityThreshold"},
    {&MdtWorldParams::angularVelocityThreshold, "MdtWorldSetAutoDisableAngularVelocityThreshold",
     "angularVelocityThreshold"},
    {&MdtWorldParams::accelerationThreshold, "MdtWorldSetAutoDisableAccelerationThreshold", "accelerationThreshold"},
    {&MdtWorldParams::angularAccelerationThreshold, "MdtWorldSetAutoDisableAngularAccelerationThreshold",
     "angularAccelerationThreshold"},
    {&MdtWorldParams::aliveWindow, "MdtWorldSetAutoDisableAliveWindow", "aliveWindow"},
    {&MdtWorldParams::minSafeTime, "MdtWorldStep", "minSafeTime"},
    {&MdtWorldParams::keaTolerance, "MdtWorldSetKeaTolerance", "keaTolerance"},
    {&MdtWorldParams::geometricStiffness, "MdtWorldSetGeometricStiffness", "geometricStiffness"},
};

// Bit patterns compared, so a NaN written directly counts as a change.
bool sameReal(MeReal a, MeReal b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void checkNonNegative(MdtWorldParams &p, MdtWorldParams &ok, const NonNegativeField &f) {
  MeReal &v = p.*f.field;
  MeReal &last = ok.*f.field;
  if (sameReal(v, last)) return;
  if (!realFinite(v) || v < 0) {
    MeArgumentWarning(f.setter,
                      "world->params.%s = %g (written directly) must be finite and >= 0; "
                      "ignored, %s stays %g",
                      f.name, (double)v, f.name, (double)last);
    v = last;
    return;
  }
  if (f.field == &MdtWorldParams::gamma) warnGammaOverOne(v, f.setter);
  last = v;
}

// An int parameter whose setter accepts values >= 0.
void checkCount(int &v, int &last, const char *setter, const char *name) {
  if (v == last) return;
  if (v < 0) {
    MeArgumentWarning(setter,
                      "world->params.%s = %d (written directly) must be >= 0; ignored, %s "
                      "stays %d",
                      name, v, name, last);
    v = last;
    return;
  }
  last = v;
}

// Component by component, as the guide writes them (params.gravity[1] = ...):
// a non-finite component goes back to its last valid value.
void checkGravity(MdtWorldParams &p, MdtWorldParams &ok) {
  for (int k = 0; k < 3; ++k) {
    MeReal &v = p.gravity[k];
    if (sameReal(v, ok.gravity[k])) continue;
    if (!realFinite(v)) {
      MeArgumentWarning("MdtWorldSetGravity",
                        "world->params.gravity[%d] = %g (written directly) is not finite; "
                        "ignored, it stays %g",
                        k, (double)v, (double)ok.gravity[k]);
      v = ok.gravity[k];
      continue;
    }
    ok.gravity[k] = v;
  }
}

void checkKeaMethod(MdtWorldParams &p, MdtWorldParams &ok) {
  if (p.keaMethod == ok.keaMethod) return;
  if (p.keaMethod != MdtKeaMethodActiveSet && p.keaMethod != MdtKeaMethodPGS) {
    MeArgumentWarning("MdtWorldSetKeaMethod", "world->params.keaMethod = %d (written directly) is unknown; ignored",
                      (int)p.keaMethod);
    p.keaMethod = ok.keaMethod;
    return;
  }
  ok.keaMethod = p.keaMethod;
}

}  // namespace

void rememberCheckedParams(MdtWorldID world) { world->priv->checked = world->params; }

void checkDirectParamWrites(MdtWorldID world) {
  MdtWorldParams &p = world->params;
  MdtWorldParams &ok = world->priv->checked;
  checkGravity(p, ok);
  for (const NonNegativeField &f : kNonNegativeFields) checkNonNegative(p, ok, f);
  p.autoDisable = ok.autoDisable = p.autoDisable ? TRUE : FALSE;
  checkCount(p.maxMatrixSize, ok.maxMatrixSize, "MdtWorldSetMaxMatrixSize", "maxMatrixSize");
  checkCount(p.keaMaxIterations, ok.keaMaxIterations, "MdtWorldSetKeaMaxIterations", "keaMaxIterations");
  checkCount(p.jointProjection, ok.jointProjection, "MdtWorldSetJointProjection", "jointProjection");
  checkCount(p.keaIterativeRows, ok.keaIterativeRows, "MdtWorldSetKeaIterativeRows", "keaIterativeRows");
  p.keaAcceptWarmStart = ok.keaAcceptWarmStart = p.keaAcceptWarmStart ? 1 : 0;
  checkKeaMethod(p, ok);
}

}  // namespace karma::mdt
