/* viewer.h: Appendix B's RainbowChain excerpts: the program's variables
 * (render context, graphics, the chain's collision models) and its
 * callbacks. */
#include "guide.h"
#define NBALLS 10
extern RRender *rc;
int argc;
const char **argv;
int i;
float color[4];
MeReal ballRadius = (MeReal)0.5;
McdModelID ball[NBALLS];
RGraphic *planeG;
RGraphic *sphereG[NBALLS];
void MEAPI Reset(RRender *rc, void *userData);
void MEAPI tick(RRender *rc, void *userData);
void MEAPI_CDECL cleanup(void);
