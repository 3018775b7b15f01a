/* Mst.h: the Karma bridge between collision and dynamics, and the universe
 * (a framework, space, world and bridge together). Includes Mdt.h and
 * Mcd.h. McdModelSetBody (McdModel.h) is defined in this library too. */
#ifndef KARMA_MST_H
#define KARMA_MST_H
#include "Mdt.h"
#include "Mcd.h"
#include "MstBridge.h"
#include "MstUniverse.h"
#endif
