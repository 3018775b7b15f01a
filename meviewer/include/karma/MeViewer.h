/* MeViewer.h: the Karma demo renderer (Appendix B of the guide).
 * The API arrives with the viewer issue. */
#ifndef KARMA_MEVIEWER_H
#define KARMA_MEVIEWER_H
#include "MeGlobals.h"
#endif
