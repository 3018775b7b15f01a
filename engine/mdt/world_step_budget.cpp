// world_step_budget.cpp: MdtWorldSetStepBudget and its level names (the
// controller is step/step_budget.h).
#include <cmath>

#include "MeMessage.h"
#include "mdt_internal.h"
#include "step.h"

extern "C" {

void MEAPI MdtWorldSetStepBudget(const MdtWorldID world, const MeReal microseconds) {
  static const char *fn = "MdtWorldSetStepBudget";
  ME_REQUIRE_ARG(world != nullptr, fn, "world is NULL");
  ME_REQUIRE_ARG(std::isfinite((double)microseconds) && microseconds >= 0, fn,
                 "budget must be >= 0 microseconds (0 = off) and finite, got %g; ignored", (double)microseconds);
  world->priv->scratch->budget.setBudget(microseconds);
}

MeReal MEAPI MdtWorldGetStepBudget(const MdtWorldID world) {
  ME_REQUIRE_ARG_RET(world != nullptr, 0, "MdtWorldGetStepBudget", "world is NULL");
  return world->priv->scratch->budget.budget();
}

const char *MEAPI MdtWorldGetStepBudgetLevelName(const int level) { return karma::mdt::StepBudget::levelName(level); }

}  // extern "C"
