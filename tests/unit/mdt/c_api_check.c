/* c_api_check.c: the Mdt headers compile as C11 and the API links from C. */
#include "Mdt.h"

#include <string.h>

int mdt_c_api_check(void);

int mdt_c_api_check(void) {
  MdtWorldID world = MdtWorldCreate(2, 0, 1, 1);
  MdtBodyID body;
  MeVector3 p;
  int ok;
  if (!world) return 0;
  MdtWorldSetPlatform(world, MdtPlatformName(0));
  if (strcmp(MdtWorldGetPlatformName(world), "reference") != 0 || !MdtPlatformIsSupported(MdtPlatformGetDefaultName()))
    return 0;
  world->params.gravity[1] = -(MeReal)9.81;
  world->params.epsilon = (MeReal)0.005;
  body = MdtBodyCreate(world);
  MdtBodyEnable(body);
  MdtWorldStep(world, (MeReal)0.01);
  MdtBodyGetPosition(body, p);
  ok = p[1] < 0 && MdtBodyGetTransformPtr(body)[3][1] == p[1];
  MdtBodyDestroy(body);
  MdtWorldDestroy(world);
  return ok;
}
