/* Mst.h: the Karma bridge between collision and dynamics.
 * The API arrives with the collision issue. */
#ifndef KARMA_MST_H
#define KARMA_MST_H
#include "Mdt.h"
#include "Mcd.h"
#endif
