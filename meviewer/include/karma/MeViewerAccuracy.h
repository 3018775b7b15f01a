/* MeViewerAccuracy.h: the figures of MeViewer's accuracy overlay computed
 * from a dynamics world (library Karma::MeViewerAccuracy, which links Mdt;
 * MeViewer itself knows no physics).
 *
 *   RRender *rc = RRenderContextCreate(options, 0, 1);
 *   ... build the world ...
 *   RAccuracyProbe *probe = RAccuracyProbeCreate(rc, world);
 *   RAccuracyProbeAddJoint(probe, MdtBSJointQuaConstraint(joint));  (each joint to watch)
 *   RRun(rc, tick, 0);      run with -accuracy (overlay) or -profile (table)
 *
 * Per frame, after the tick:
 *   joint error   the largest distance between a watched joint's point as
 *                 carried by its two bodies (MdtConstraintBodyGetPosition)
 *   penetration   the deepest penetration of the contacts of the bodies
 *                 the last step solved (MdtBodyGetFirstContact)
 *   energy drift  sum over the bodies seen so far of 1/2 m v.v +
 *                 1/2 w.I w - m g.x, minus its value at the first frame
 *                 (a body first seen later joins at its then energy)
 *   residual      MdtWorldGetStepStats' keaResidual of the last step
 * Bodies are found through the last step's partitions (the enabled
 * bodies), so a world that never steps shows zeros. */
#ifndef KARMA_MEVIEWER_ACCURACY_H
#define KARMA_MEVIEWER_ACCURACY_H

#include "MeViewer.h"
#include "Mdt.h"

ME_EXTERN_C_BEGIN

typedef struct RAccuracyProbe RAccuracyProbe;

/* Watches `world` and makes itself rc's accuracy source. NULL (with a
 * warning) when rc or world is NULL. */
MEPUBLIC RAccuracyProbe *MEAPI RAccuracyProbeCreate(RRender *rc, MdtWorldID world);
/* Adds a joint whose gap counts as joint error. */
MEPUBLIC void MEAPI RAccuracyProbeAddJoint(RAccuracyProbe *probe, MdtConstraintID joint);
/* The figures now (what the overlay shows after a tick). */
MEPUBLIC void MEAPI RAccuracyProbeRead(RAccuracyProbe *probe, RAccuracyFigures *figures);
/* Stops being rc's source and frees the probe. NULL is ignored. */
MEPUBLIC void MEAPI RAccuracyProbeDestroy(RAccuracyProbe *probe);

ME_EXTERN_C_END

#endif
