/* c_api_order.c: the Mdt headers first, then the Mcd ones: MdtBodyID is
 * declared once by each and both orders compile as C11. */
#include "Mdt.h"
#include "Mcd.h"

int mcd_c_api_order(void);

int mcd_c_api_order(void) {
  MdtBodyID body = 0;
  McdModelID model = 0;
  return McdModelGetBody(model) == body;
}
