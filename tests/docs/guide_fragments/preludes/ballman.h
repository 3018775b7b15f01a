/* ballman.h: Ballman's cheap-material fragments: a bridge and two materials. */
#include "guide.h"
MstBridgeID bridge;
MstMaterialID material1, material2;
MdtContactParamsID p;
