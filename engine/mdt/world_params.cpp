// world_params.cpp: accessors of the public world parameters.
#include "MeMessage.h"
#include "mdt_internal.h"

using namespace karma::mdt;

extern "C" {

void MEAPI MdtWorldSetGravity(const MdtWorldID world, const MeReal gx, const MeReal gy,
                              const MeReal gz) {
  static const char *fn = "MdtWorldSetGravity";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite3(gx, gy, gz), fn, "gravity (%g, %g, %g) is not finite; ignored",
                 (double)gx, (double)gy, (double)gz);
  MeVector3Set(world->params.gravity, gx, gy, gz);
}

void MEAPI MdtWorldGetGravity(const MdtWorldID world, MeVector3 g) {
  ME_REQUIRE_ARG(world != nullptr && g != nullptr, "MdtWorldGetGravity", "NULL argument");
  MeVector3Copy(g, world->params.gravity);
}

void MEAPI MdtWorldSetEpsilon(const MdtWorldID world, const MeReal epsilon) {
  static const char *fn = "MdtWorldSetEpsilon";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(epsilon) && epsilon >= 0, fn,
                 "epsilon must be finite and >= 0, got %g; ignored", (double)epsilon);
  world->params.epsilon = epsilon;
}

MeReal MEAPI MdtWorldGetEpsilon(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, (MeReal)0, "MdtWorldGetEpsilon", "world is NULL");
  return world->params.epsilon;
}

void MEAPI MdtWorldSetGamma(const MdtWorldID world, const MeReal gamma) {
  static const char *fn = "MdtWorldSetGamma";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(gamma) && gamma >= 0, fn,
                 "gamma must be finite and >= 0, got %g; ignored", (double)gamma);
  if (gamma > 1)
    MeWarning(0,
              "%s: gamma %g > 1 over-corrects every step (gamma is the fraction of the error "
              "corrected per step; a rate r in 1/s is gamma = r * h)",
              fn, (double)gamma);
  world->params.gamma = gamma;
}

MeReal MEAPI MdtWorldGetGamma(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, (MeReal)0, "MdtWorldGetGamma", "world is NULL");
  return world->params.gamma;
}

void MEAPI MdtWorldSetAutoDisable(const MdtWorldID world, const MeBool on) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetAutoDisable", "world is NULL");
  world->params.autoDisable = on ? TRUE : FALSE;
}

MeBool MEAPI MdtWorldGetAutoDisable(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, FALSE, "MdtWorldGetAutoDisable", "world is NULL");
  return world->params.autoDisable;
}

namespace {
void setNonNegative(MdtWorldID world, MeReal v, MeReal MdtWorldParams::*field, const char *fn) {
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(realFinite(v) && v >= 0, fn, "value must be finite and >= 0, got %g; ignored",
                 (double)v);
  world->params.*field = v;
}
}  // namespace

void MEAPI MdtWorldSetAutoDisableVelocityThreshold(const MdtWorldID world, const MeReal v) {
  setNonNegative(world, v, &MdtWorldParams::velocityThreshold,
                 "MdtWorldSetAutoDisableVelocityThreshold");
}
void MEAPI MdtWorldSetAutoDisableAngularVelocityThreshold(const MdtWorldID world,
                                                          const MeReal w) {
  setNonNegative(world, w, &MdtWorldParams::angularVelocityThreshold,
                 "MdtWorldSetAutoDisableAngularVelocityThreshold");
}
void MEAPI MdtWorldSetAutoDisableAccelerationThreshold(const MdtWorldID world, const MeReal a) {
  setNonNegative(world, a, &MdtWorldParams::accelerationThreshold,
                 "MdtWorldSetAutoDisableAccelerationThreshold");
}
void MEAPI MdtWorldSetAutoDisableAngularAccelerationThreshold(const MdtWorldID world,
                                                              const MeReal a) {
  setNonNegative(world, a, &MdtWorldParams::angularAccelerationThreshold,
                 "MdtWorldSetAutoDisableAngularAccelerationThreshold");
}
void MEAPI MdtWorldSetAutoDisableAliveWindow(const MdtWorldID world, const MeReal t) {
  setNonNegative(world, t, &MdtWorldParams::aliveWindow, "MdtWorldSetAutoDisableAliveWindow");
}

void MEAPI MdtWorldSetMaxMatrixSize(const MdtWorldID world, const int size) {
  static const char *fn = "MdtWorldSetMaxMatrixSize";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(size >= 0, fn, "size must be >= 0 (0 = no cap), got %d; ignored", size);
  world->params.maxMatrixSize = size;
}

void MEAPI MdtWorldSetContactImportanceCB(const MdtWorldID world, MdtContactImportanceCBPtr cb) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetContactImportanceCB", "world is NULL");
  world->priv->importance = cb;
}

void MEAPI MdtWorldSetKeaMethod(const MdtWorldID world, const MdtKeaMethod method) {
  static const char *fn = "MdtWorldSetKeaMethod";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(method == MdtKeaMethodActiveSet || method == MdtKeaMethodPGS, fn,
                 "unknown method %d; ignored", (int)method);
  world->params.keaMethod = method;
}

void MEAPI MdtWorldSetKeaMaxIterations(const MdtWorldID world, const int n) {
  static const char *fn = "MdtWorldSetKeaMaxIterations";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(n >= 0, fn, "iteration cap must be >= 0 (0 = default), got %d; ignored", n);
  world->params.keaMaxIterations = n;
}

void MEAPI MdtWorldSetGeometricStiffness(const MdtWorldID world, const MeReal factor) {
  setNonNegative(world, factor, &MdtWorldParams::geometricStiffness,
                 "MdtWorldSetGeometricStiffness");
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
