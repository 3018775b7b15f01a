/* C consumer: the guide's include style, plain C11, linked as a user would. */
#include "Mst.h"
#include "MeViewer.h"
#include <karma/Mdt.h>
#include <karma/MeGlobals.h>
#include <stdio.h>

int main(void) {
  MeVector3 a = {1, 2, 3}, b = {4, 5, 6}, c;
  MeVector3Cross(c, a, b); /* (-3, 6, -3) */
  if (c[0] != -3 || c[1] != 6 || c[2] != -3) return 1;
  { /* the viewer links (OSMesa comes with it) and runs without drawing */
    const float white[4] = {1, 1, 1, 1};
    MeCommandLineOptions *o = MeCommandLineOptionsCreateFromString("consumer -null");
    RRender *rc = RRenderContextCreate(o, 0, 1);
    MeCommandLineOptionsDestroy(o);
    if (!rc || !RGraphicSphereCreate(rc, 1, white, 0)) return 2;
    RRenderContextDestroy(rc);
  }
  printf("karma consumer ok (C, MeReal is %u bytes)\n", (unsigned)sizeof(MeReal));
  return 0;
}
