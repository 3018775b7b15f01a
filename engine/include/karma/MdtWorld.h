/* MdtWorld.h: the dynamics world, the container of bodies (and, later,
 * constraints, partitions and the auto-disable machinery).
 *
 * Units: a world is created with a length scale l and a mass scale m (typical
 * size and mass of its objects). The defaults that have units are scaled by
 * them when the world is created (see MdtWorldParams), so a world of
 * centimetre-sized, gram-weight objects starts from sensible values.
 *
 * The parameter block `world->params` is public: programs written against
 * the guide read and write `world->params.gravity[1]` or
 * `world->params.epsilon` directly. Everything else of a world is private. */
#ifndef KARMA_MDTWORLD_H
#define KARMA_MDTWORLD_H
#include "MeCall.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct MdtWorld *MdtWorldID;
typedef struct MdtBody *MdtBodyID;

/* World-wide simulation parameters. Defaults (Appendix A of the guide), with
 * l = lengthScale and m = massScale given to MdtWorldCreate:
 *   gravity                          (0, 0, 0)
 *   epsilon (constraint softness)    0.01 / m
 *   gamma (constraint relaxation)    0.2
 *   autoDisable                      1 (on)
 *   velocityThreshold                0.02 * l
 *   angularVelocityThreshold         0.001
 *   accelerationThreshold            0.5 * l
 *   angularAccelerationThreshold     0.002
 *   aliveWindow                      0.2
 *   minSafeTime                      0.001
 *   maxMatrixSize                    0 = unlimited
 * Only gravity is used by the current step; epsilon, gamma and the
 * auto-disable fields are stored for the solver and auto-disable to come. */
typedef struct MdtWorldParams {
    MeVector3 gravity;
    MeReal epsilon;
    MeReal gamma;
    MeBool autoDisable;
    MeReal velocityThreshold;
    MeReal angularVelocityThreshold;
    MeReal accelerationThreshold;
    MeReal angularAccelerationThreshold;
    MeReal aliveWindow;
    MeReal minSafeTime;
    int maxMatrixSize;
} MdtWorldParams;

/* The world's private state (body pool, step order, counters). */
struct MdtWorldPrivate;

struct MdtWorld {
    MdtWorldParams params;          /* public, see above */
    struct MdtWorldPrivate *priv;   /* opaque */
};

/* Creates a world that can hold up to maxBodies bodies and maxConstraints
 * constraints. lengthScale and massScale must be positive and finite; they
 * scale the defaults. Returns NULL with a warning on bad arguments or when
 * memory runs out. */
MEPUBLIC MdtWorldID MEAPI MdtWorldCreate(const unsigned int maxBodies,
                                         const unsigned int maxConstraints,
                                         const MeReal lengthScale, const MeReal massScale);
/* Destroys the world and every body still in it. NULL is ignored. */
MEPUBLIC void MEAPI MdtWorldDestroy(const MdtWorldID world);

/* Advances every enabled body by stepSize seconds (> 0, finite). */
MEPUBLIC void MEAPI MdtWorldStep(const MdtWorldID world, const MeReal stepSize);

MEPUBLIC void MEAPI MdtWorldSetGravity(const MdtWorldID world, const MeReal gx, const MeReal gy,
                                       const MeReal gz);
MEPUBLIC void MEAPI MdtWorldGetGravity(const MdtWorldID world, MeVector3 g);
/* Epsilon must be >= 0, gamma >= 0. */
MEPUBLIC void MEAPI MdtWorldSetEpsilon(const MdtWorldID world, const MeReal epsilon);
MEPUBLIC MeReal MEAPI MdtWorldGetEpsilon(const MdtWorldID world);
MEPUBLIC void MEAPI MdtWorldSetGamma(const MdtWorldID world, const MeReal gamma);
MEPUBLIC MeReal MEAPI MdtWorldGetGamma(const MdtWorldID world);

/* Bodies in the world: enabled ones / all / the capacity. */
MEPUBLIC unsigned int MEAPI MdtWorldGetEnabledBodyCount(const MdtWorldID world);
MEPUBLIC unsigned int MEAPI MdtWorldGetBodyCount(const MdtWorldID world);
MEPUBLIC unsigned int MEAPI MdtWorldGetMaxBodies(const MdtWorldID world);

ME_EXTERN_C_END

#endif /* KARMA_MDTWORLD_H */
