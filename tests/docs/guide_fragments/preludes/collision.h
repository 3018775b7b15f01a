/* collision.h: the names the collision chapters' fragments use without
 * declaring them. */
#include "guide.h"
#define NBALLS 10
MstUniverseSizes sizes;
MstUniverseID universe;
McdFrameworkID framework;
McdSpaceID space, s;
McdModelID model, myModel1, myModel2, m1, m2, groundCM, planeModel, boxModel, myModel, hitModel;
McdGeometryID planeGeom, boxGeom;
MdtBodyID boxBody;
MeMatrix4Ptr planeTM;
McdModelPairContainer *pairs;
McdContact contacts[10];
MdtWorldID world;
MeReal stepSize = (MeReal)0.01;
int i;
void move(void);
void handleCollision(McdModelPairContainer *p);
