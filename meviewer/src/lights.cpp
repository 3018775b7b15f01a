/* lights.cpp: switching the context's four lights on and off.
 *
 * A switch takes effect next frame: it sets the light's m_bUseLight (or
 * m_bUseAmbientLight) and raises the matching m_bForce...Update flag, as a
 * program changing the structure itself would. */
#include "viewer_internal.h"

namespace {

void Switch(RRender *rc, RRenderLight light, int on, const char *fn) {
  ME_REQUIRE_ARG(rc, fn, "rc is NULL");
  switch (light) {
    case kRAmbient:
      rc->m_bUseAmbientLight = on;
      break;
    case kRDirect1:
      rc->m_DirectLight1.m_bUseLight = on, rc->m_bForceDirectLight1Update = 1;
      break;
    case kRDirect2:
      rc->m_DirectLight2.m_bUseLight = on, rc->m_bForceDirectLight2Update = 1;
      break;
    case kRPoint:
      rc->m_PointLight.m_bUseLight = on, rc->m_bForcePointLightUpdate = 1;
      break;
    default:
      MeWarning(0, "%s: %d is not a light (kRAmbient, kRDirect1, kRDirect2, kRPoint)", fn, int(light));
  }
}

}  // namespace

void MEAPI RLightSwitchOn(RRender *rc, RRenderLight light) { Switch(rc, light, 1, "RLightSwitchOn"); }
void MEAPI RLightSwitchOff(RRender *rc, RRenderLight light) { Switch(rc, light, 0, "RLightSwitchOff"); }
void MEAPI RSwitchLightOn(RRender *rc, RRenderLight light) { Switch(rc, light, 1, "RSwitchLightOn"); }
void MEAPI RSwitchLightOff(RRender *rc, RRenderLight light) { Switch(rc, light, 0, "RSwitchLightOff"); }
