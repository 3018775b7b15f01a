// world_solver_choice.cpp: the world's per-partition choice of solver by
// size (MdtWorldSetKeaIterativeRows; the choice itself is made in
// step/solve.cpp), and whether the exact solver keeps a warm start that
// already meets the tolerance (MdtWorldSetKeaAcceptWarmStart).
#include "MeMessage.h"
#include "mdt_internal.h"

extern "C" {

void MEAPI MdtWorldSetKeaIterativeRows(const MdtWorldID world, const int rows) {
  static const char *fn = "MdtWorldSetKeaIterativeRows";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(rows >= 0, fn, "row threshold must be >= 0 (0 = never), got %d; ignored", rows);
  world->params.keaIterativeRows = world->priv->checked.keaIterativeRows = rows;
}

int MEAPI MdtWorldGetKeaIterativeRows(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetKeaIterativeRows", "world is NULL");
  return world->params.keaIterativeRows;
}

void MEAPI MdtWorldSetKeaAcceptWarmStart(const MdtWorldID world, const MeBool on) {
  ME_REQUIRE_ARG(world != nullptr, "MdtWorldSetKeaAcceptWarmStart", "world is NULL");
  world->params.keaAcceptWarmStart = world->priv->checked.keaAcceptWarmStart = on ? 1 : 0;
}

MeBool MEAPI MdtWorldGetKeaAcceptWarmStart(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetKeaAcceptWarmStart", "world is NULL");
  return world->params.keaAcceptWarmStart ? 1 : 0;
}

}  // extern "C"
