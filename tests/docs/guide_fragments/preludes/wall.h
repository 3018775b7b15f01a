/* wall.h: the per-pair callback sample's names: the universe and the two
 * materials, and the callback the fragment registers. */
#include "guide.h"
MstUniverseID universe;
MstMaterialID mat_Wall, mat_Ball;
MeBool MEAPI WallCollisionCB(McdIntersectResult *c, MdtContactGroupID cg);
