/* qb_materials.h: QuadBike's InitialiseMaterials() (main.c). */
#include "quadbike.h"
#define GUIDE_FRAGMENT_LEAD MdtContactParamsID params;
