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
 * Per frame, after the tick, the world's own figures (MdtWorldGetDiagnostics:
 * largest point-joint gap, deepest contact penetration, energy drift, last
 * step's residual), except that once joints are added the joint error is
 * the largest gap of those joints alone (MdtConstraintBodyGetPosition). A
 * program that makes no probe still gets the overlay: MeViewer then reads
 * every world through MeGlobals' diagnostic sources (MeDiagnostics.h). A
 * probe is for naming the joints to watch.
 */
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
