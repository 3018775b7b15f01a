/* guide.h: what every fragment of the guide may assume: the C library
 * headers a Karma program includes, and Karma's own (Mst.h brings Mdt.h and
 * Mcd.h). The fragments' own names come from the other preludes. */
#ifndef GUIDE_FRAGMENT_GUIDE_H
#define GUIDE_FRAGMENT_GUIDE_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "Mst.h"
#include "MeViewer.h"
#endif
