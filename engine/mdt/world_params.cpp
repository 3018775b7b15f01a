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
  world->params.gamma = gamma;
}

MeReal MEAPI MdtWorldGetGamma(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, (MeReal)0, "MdtWorldGetGamma", "world is NULL");
  return world->params.gamma;
}

}  // extern "C"
