/* Mcd.h: Karma Collision. Includes every collision header: the framework,
 * geometries, models, pairs, contacts and the nearfield interactions. */
#ifndef KARMA_MCD_H
#define KARMA_MCD_H
#include "MeGlobals.h"
#include "McdFrame.h"
#include "McdGeometry.h"
#include "McdSphere.h"
#include "McdBox.h"
#include "McdCylinder.h"
#include "McdPlane.h"
#include "McdSphyl.h"
#include "McdTriangleList.h"
#include "McdConvexMesh.h"
#include "McdAggregate.h"
#include "McdModel.h"
#include "McdContact.h"
#include "McdModelPair.h"
#include "McdSpace.h"
#include "McdInteraction.h"
#include "McdLineSegment.h"
#include "McdSafeTime.h"
#endif
