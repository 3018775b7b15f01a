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
#include "MeDiagnostics.h"
#include <stddef.h>

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
 *   keaMethod                        MdtKeaMethodActiveSet
 *   keaMaxIterations                 0 = Kea's default
 *   keaTolerance                     0 = Kea's default
 *   keaAcceptWarmStart               1 (0 = off)
 *   geometricStiffness               1 (0 = off)
 *
 * epsilon is added to the diagonal of the constraint matrix: every rigid
 * constraint row gives way by epsilon times its impulse. gamma is the
 * fraction of a constraint's position error corrected in one step. The
 * auto-disable thresholds are magnitudes of linear/angular velocity and
 * acceleration below which a body counts as resting; a partition whose
 * bodies have all rested for aliveWindow seconds is disabled. */
typedef enum MdtKeaMethod {
  MdtKeaMethodActiveSet, /* exact: Cholesky factorisation, candidate active sets */
  MdtKeaMethodPGS        /* projected Gauss-Seidel, keaMaxIterations sweeps */
} MdtKeaMethod;

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
  MdtKeaMethod keaMethod;
  int keaMaxIterations;
  MeReal keaTolerance;
  MeReal geometricStiffness;
  int keaIterativeRows; /* see MdtWorldSetKeaIterativeRows; 0 = never, default 300 */
  int jointProjection;  /* see MdtWorldSetJointProjection; 0 = off (the default) */
  MeBool keaAcceptWarmStart; /* see MdtWorldSetKeaAcceptWarmStart; default 1 */
} MdtWorldParams;

/* What the last MdtWorldStep did. */
typedef struct MdtWorldStepStats {
  int partitions;          /* partitions stepped, one-body ones included */
  int sleeping;            /* of those, put to sleep at the end of the step */
  int bodies;              /* enabled bodies stepped */
  int constraints;         /* constraints simulated */
  int rows;                /* constraint rows solved (after capping) */
  int rowsRemoved;         /* rows removed by matrix capping */
  int keaIterations;       /* Kea iterations summed over partitions */
  int keaUnsolved;         /* partitions Kea did not solve to tolerance */
  MeReal keaResidual;      /* largest Kea residual (impulse units) */
  int keaSolved;           /* partitions solved to tolerance */
  int keaFactorizations;   /* factorisations of a free block (exact solver) */
  int keaStaleSolves;      /* linear solves preconditioned by last step's factor */
  int keaFrictionRounds;   /* friction fixed-point rounds beyond the first */
  int keaCycles;           /* partitions stopped by a detected cycle */
  int iterativePartitions; /* partitions solved by the iterative solver */
  int budgetLevel;         /* least accurate step-budget level used: 0 exact,
                              1 exact:8, 2 iterative; -1 after a step without
                              a budget */
  int budgetSweeps;        /* fewest iterative sweeps the budget gave, 0 if none */
  MeReal budgetPredicted;  /* step budget: predicted solve time (microseconds) */
  MeReal budgetMeasured;   /* step budget: measured step time (microseconds) */
  const char *platform;    /* the platform backend the step ran on (before
                              the first step: the world's current one) */
  int keaWarmStarts;       /* partitions whose last-step impulses met a
                              sixteenth of the tolerance as they were, kept
                              with no linear solve
                              (MdtWorldSetKeaAcceptWarmStart) */
  int keaFactorUpdates;    /* pivots of the exact solver served by a
                              Schur-complement update of a factor instead
                              of a factorisation */
} MdtWorldStepStats;

/* The world's private state (body pool, step order, counters). */
struct MdtWorldPrivate;

struct MdtWorld {
  MdtWorldParams params;        /* public, see above */
  struct MdtWorldPrivate *priv; /* opaque */
};

/* Creates a world that can hold up to maxBodies bodies and, to begin with,
 * maxConstraints constraints: when more constraints (contacts included) are
 * made, the world grows its constraint storage, doubling it, and warns once
 * (an extension: Karma 1.2 refused them). lengthScale and massScale must be
 * positive and finite; they scale the defaults. Returns NULL with a warning
 * on bad arguments or when memory runs out. */
MEPUBLIC MdtWorldID MEAPI MdtWorldCreate(const unsigned int maxBodies, const unsigned int maxConstraints,
                                         const MeReal lengthScale, const MeReal massScale);
/* Destroys the world and every body still in it. NULL is ignored. */
MEPUBLIC void MEAPI MdtWorldDestroy(const MdtWorldID world);

/* Advances every enabled body by stepSize seconds (> 0, finite). */
MEPUBLIC void MEAPI MdtWorldStep(const MdtWorldID world, const MeReal stepSize);
/* The stepSize of the last MdtWorldStep, 0 before the first (an extension:
 * the collision bridge sizes its speculative contacts with it). */
MEPUBLIC MeReal MEAPI MdtWorldGetLastStepSize(const MdtWorldID world);

MEPUBLIC void MEAPI MdtWorldSetGravity(const MdtWorldID world, const MeReal gx, const MeReal gy, const MeReal gz);
MEPUBLIC void MEAPI MdtWorldGetGravity(const MdtWorldID world, MeVector3 g);
/* Epsilon must be >= 0, gamma >= 0.
 * Gamma is the fraction of each constraint's error corrected per step (the
 * correcting velocity is gamma * error / h; default 0.2; 0.1 to 0.8 works
 * well). A rate in 1/s converts as gamma = rate * h, as QuadBike's
 * MdtWorldSetGamma(world, timeStep * 10) does. Above 1 every step
 * over-corrects: accepted, with a warning. */
MEPUBLIC void MEAPI MdtWorldSetEpsilon(const MdtWorldID world, const MeReal epsilon);
MEPUBLIC MeReal MEAPI MdtWorldGetEpsilon(const MdtWorldID world);
MEPUBLIC void MEAPI MdtWorldSetGamma(const MdtWorldID world, const MeReal gamma);
MEPUBLIC MeReal MEAPI MdtWorldGetGamma(const MdtWorldID world);

/* Statistics of the last step. */
MEPUBLIC void MEAPI MdtWorldGetStepStats(const MdtWorldID world, MdtWorldStepStats *stats);

/* The platform backend of the world's steps (MdtPlatform.h lists them): a
 * world starts with the process default and keeps it until this is called.
 * Every backend gives the same results to the bit, so switching changes
 * speed only. An unknown name, NULL, or a backend this CPU cannot run gives
 * a warning and the best supported backend. An extension. */
MEPUBLIC void MEAPI MdtWorldSetPlatform(const MdtWorldID world, const char *name);
/* The name of the world's backend ("reference", "sse4", "avx2", "avx512");
 * NULL, with a warning, for a NULL world. */
MEPUBLIC const char *MEAPI MdtWorldGetPlatformName(const MdtWorldID world);
/* The world's accuracy figures now (MeDiagnostics.h: largest point-joint
 * gap, deepest contact penetration, energy drift since the first read,
 * last step's solver residual). Every world is also listed as a diagnostic
 * source from creation to destruction, which is how MeViewer's -accuracy
 * and -profile find it. An extension. */
MEPUBLIC void MEAPI MdtWorldGetDiagnostics(const MdtWorldID world, MeDiagnosticFigures *figures);

/* The partitions of the last step: how many, and the bodies and solved row
 * count of partition i. Partitions are numbered in the order they are
 * found, each from its first body in (sort key, creation) order, and their
 * bodies are listed in breadth-first order from that body. A body joined to
 * nothing is a partition of its own with 0 rows; such partitions are
 * stepped together in one batch after the others, which changes no result
 * (they share nothing). The others are solved in numbering order. */
MEPUBLIC int MEAPI MdtWorldGetPartitionCount(const MdtWorldID world);
MEPUBLIC int MEAPI MdtWorldGetPartitionBodyCount(const MdtWorldID world, const int partition);
MEPUBLIC MdtBodyID MEAPI MdtWorldGetPartitionBody(const MdtWorldID world, const int partition, const int i);
MEPUBLIC int MEAPI MdtWorldGetPartitionRowCount(const MdtWorldID world, const int partition);

/* Auto-disable on or off (on by default). */
MEPUBLIC void MEAPI MdtWorldSetAutoDisable(const MdtWorldID world, const MeBool on);
MEPUBLIC MeBool MEAPI MdtWorldGetAutoDisable(const MdtWorldID world);
/* The four thresholds (>= 0) and the alive window (>= 0, seconds). */
MEPUBLIC void MEAPI MdtWorldSetAutoDisableVelocityThreshold(const MdtWorldID world, const MeReal v);
MEPUBLIC void MEAPI MdtWorldSetAutoDisableAngularVelocityThreshold(const MdtWorldID world, const MeReal w);
MEPUBLIC void MEAPI MdtWorldSetAutoDisableAccelerationThreshold(const MdtWorldID world, const MeReal a);
MEPUBLIC void MEAPI MdtWorldSetAutoDisableAngularAccelerationThreshold(const MdtWorldID world, const MeReal a);
MEPUBLIC void MEAPI MdtWorldSetAutoDisableAliveWindow(const MdtWorldID world, const MeReal t);

/* Waking by force (the guide's "Automatic Enabling and Disabling of Bodies"):
 * at the start of each MdtWorldStep a disabled body is enabled when what was
 * applied to it since the last step would move it past a threshold:
 *   |force| / mass                      > accelerationThreshold, or
 *   |inverse inertia (torque)|          > angularAccelerationThreshold, or
 *   |impulse| / mass                    > velocityThreshold, or
 *   |inverse inertia (angular impulse)| > angularVelocityThreshold
 * (gravity is not an applied force). Smaller forces on a disabled body are
 * dropped at that step, as a disabled body is not stepped. The thresholds
 * are those of the auto-disable test, so a force that wakes a body also
 * keeps it from being disabled while it acts. Waking by force happens with
 * auto-disable on or off, as does waking by a constraint.
 *
 * The guide also says the opposite: its question-and-answer section ("I have
 * dropped an object onto a surface...") has an explicit force NOT wake a
 * disabled body; the force accumulates until a touch or MdtBodyEnable
 * enables the body. MdtWorldSetWakeByForce(world, 0) selects that reading
 * (nothing is woken or dropped); the default, 1, is the chapter's.
 *
 * The alive window. The guide gives it two ways: its chapter text as "the
 * number of evolve steps before an object can be disabled again, after it
 * has been awakened", its Appendix A as 0.2 (a time: MdtWorldSetAutoDisableAliveWindow
 * takes a real and the other defaults there are in seconds). The mode picks
 * the reading:
 *   MdtAliveWindowIdleSeconds   (default) a partition is disabled once each
 *                               of its bodies has stayed below every
 *                               threshold for aliveWindow seconds; enabling
 *                               a body (waking) restarts its count. So a
 *                               woken body is never disabled within the
 *                               window, and neither is a body that is at
 *                               rest for a single step.
 *   MdtAliveWindowAwakeSeconds  the chapter's reading in seconds: a body
 *                               enabled (by MdtBodyEnable or by waking)
 *                               less than aliveWindow seconds ago is never
 *                               disabled;
 *                               after that, its partition is disabled at the
 *                               first step where every body is below every
 *                               threshold.
 *   MdtAliveWindowAwakeSteps    the same, aliveWindow read as a number of
 *                               steps (the chapter's words). */
MEPUBLIC void MEAPI MdtWorldSetWakeByForce(const MdtWorldID world, const MeBool on);
MEPUBLIC MeBool MEAPI MdtWorldGetWakeByForce(const MdtWorldID world);

typedef enum MdtAliveWindowMode {
  MdtAliveWindowIdleSeconds,
  MdtAliveWindowAwakeSeconds,
  MdtAliveWindowAwakeSteps
} MdtAliveWindowMode;
MEPUBLIC void MEAPI MdtWorldSetAutoDisableAliveWindowMode(const MdtWorldID world, const MdtAliveWindowMode mode);
MEPUBLIC MdtAliveWindowMode MEAPI MdtWorldGetAutoDisableAliveWindowMode(const MdtWorldID world);

/* Appendix A's DebugDrawOptions (default 0): a bit set the application keeps
 * for its own debug drawing of the world. The guide gives no bits and this
 * library draws nothing itself; the value is only stored. */
MEPUBLIC void MEAPI MdtWorldSetDebugDrawOptions(const MdtWorldID world, const int options);
MEPUBLIC int MEAPI MdtWorldGetDebugDrawOptions(const MdtWorldID world);

/* Matrix capping: at most `size` rows per partition (0 = no cap). Rows are
 * removed in this order: friction rows, then contacts between two bodies,
 * then contacts with the world, shallowest first (or least important first
 * when an importance callback is set); joint rows never, and every contact
 * group keeps at least one contact. */
MEPUBLIC void MEAPI MdtWorldSetMaxMatrixSize(const MdtWorldID world, const int size);
/* Importance of a contact for capping: higher is kept longer. NULL restores
 * the penetration depth order. */
struct MdtContact;
typedef MeReal(MEAPI *MdtContactImportanceCBPtr)(struct MdtContact *contact);
MEPUBLIC void MEAPI MdtWorldSetContactImportanceCB(const MdtWorldID world, MdtContactImportanceCBPtr cb);

/* Called whenever a body of the world changes between enabled and disabled:
 * MdtBodyEnable / MdtBodyDisable by the program, waking by a constraint in
 * a step, auto-disable, an overflowing body (not MdtBodyDestroy). The bridge
 * (MstSetWorldHandlers) uses it to unfreeze and freeze the body's collision
 * model. One callback per world; NULL removes it.
 * Within MdtWorldStep:
 *   - enabled TRUE comes while the step finds what it will move, before
 *     anything moves (a body woken by its forces or by an enabled
 *     constraint to an awake body). The callback may then disable or
 *     destroy the body it is told about, destroy other bodies and
 *     constraints, and create bodies and constraints; the step moves what
 *     it leaves. (Disabling or destroying another awake body may leave a
 *     sleeper joined to an awake body unwoken, and so held still, for this
 *     step.)
 *   - enabled FALSE comes while the step moves the bodies (auto-disable, an
 *     overflowing body). The callback must then not create, destroy, enable
 *     or disable bodies or constraints: note the body and act once
 *     MdtWorldStep has returned. */
typedef void(MEAPI *MdtBodyEnableCallbackPtr)(MdtBodyID body, MeBool enabled, void *data);
MEPUBLIC void MEAPI MdtWorldSetBodyEnableCallback(const MdtWorldID world, MdtBodyEnableCallbackPtr cb, void *data);
/* The callback set (NULL if none) and, when data is not NULL, its data. */
MEPUBLIC MdtBodyEnableCallbackPtr MEAPI MdtWorldGetBodyEnableCallback(const MdtWorldID world, void **data);

/* Stabilisation of light bodies between large constraint forces (a light
 * link holding a heavy load): the constraint response sees each body's
 * inertia increased by h^2 times its geometric stiffness, factor times
 * |force| |lever| from last step's constraint forces, for turns that move
 * an attachment point. It damps the fast link modes that otherwise make
 * large mass ratios unstable, and leaves bodies driven through their centre
 * of mass (wheels on axles) untouched. factor >= 0; 0 switches it off. */
MEPUBLIC void MEAPI MdtWorldSetGeometricStiffness(const MdtWorldID world, const MeReal factor);

/* Projection of the point joints (ball-and-socket, hinge, universal,
 * skeletal) after each step: up to `sweeps` rounds of position impulses,
 * joint by joint, that bring each joint's two anchors back together (to
 * 1e-4 m times the world's length scale); velocities are left as the step
 * made them. For chains and rag dolls whose links whip round faster than
 * the step can follow (a joint drifts open by about h^2 w^2 d / 2 a step),
 * so they hold at 1/60 s without sub-steps. It turns the bodies it moves:
 * do not use it where a fast spinner hangs from a joint (a top) or where a
 * body is also held by a soft row (a suspension). sweeps >= 0; 0, the
 * default, switches it off. */
MEPUBLIC void MEAPI MdtWorldSetJointProjection(const MdtWorldID world, const int sweeps);
MEPUBLIC int MEAPI MdtWorldGetJointProjection(const MdtWorldID world);

/* Solver knobs (see kea_lcp.h's contract): the method, its iteration cap
 * (0 = default) and relative tolerance (0 = default). */
MEPUBLIC void MEAPI MdtWorldSetKeaMethod(const MdtWorldID world, const MdtKeaMethod method);
MEPUBLIC void MEAPI MdtWorldSetKeaMaxIterations(const MdtWorldID world, const int n);
MEPUBLIC void MEAPI MdtWorldSetKeaTolerance(const MdtWorldID world, const MeReal tol);

/* Whether the exact method first checks each partition's warm start (its
 * contacts' and joints' impulses of the last step) and keeps it, with no
 * linear solve, when its residual is already within a sixteenth of the
 * tolerance (MdtWorldSetKeaTolerance): one product with the constraint
 * matrix instead of a factorisation or a solve. A resting stack then often
 * costs a check a step. Such impulses meet the tolerance with room to
 * spare, where a solve usually ends near rounding. On by default; off (0),
 * every partition is solved and the warm start only chooses where the
 * pivoting begins. The step stats count the partitions kept this way
 * (keaWarmStarts). */
MEPUBLIC void MEAPI MdtWorldSetKeaAcceptWarmStart(const MdtWorldID world, const MeBool on);
MEPUBLIC MeBool MEAPI MdtWorldGetKeaAcceptWarmStart(const MdtWorldID world);

/* Each partition's solver by its size: with the exact method selected, a
 * partition of more than `rows` constraint rows (after capping) is solved
 * by the iterative method (projected Gauss-Seidel, with the same iteration
 * cap and tolerance knobs) and one of at most `rows` exactly, so a car or a
 * rag doll stays exact beside a large heap. rows >= 0; 0 solves every
 * partition by the selected method. The default is 300 rows: the exact
 * method pivots one row at a time, and a partition that large can cost it
 * thousands of linear solves in a step where many contacts change. The
 * step stats count the partitions solved iteratively. */
MEPUBLIC void MEAPI MdtWorldSetKeaIterativeRows(const MdtWorldID world, const int rows);
MEPUBLIC int MEAPI MdtWorldGetKeaIterativeRows(const MdtWorldID world);

/* A time budget for each MdtWorldStep, in microseconds (> 0; 0 turns it off,
 * the default). With a budget the engine picks, per partition and per step,
 * the most accurate solver settings whose predicted cost fits what is left
 * of the budget: exact (level 0), exact capped at 8 solves (1), or the
 * iterative solver with as many sweeps as fit, 10 to 50 (2); below 10
 * sweeps a stack no longer stands, so a budget too small for 10 is
 * exceeded rather than obeyed. It predicts costs from what it measures as
 * it runs, so a budgeted world is not bit-identical from run to run. The
 * method, iteration cap and MdtWorldSetKeaIterativeRows are set aside while
 * a budget is on; the step stats report the level and sweeps used and the
 * predicted and measured times. The budget covers MdtWorldStep, not
 * collision. Negative or non-finite values warn and are ignored. */
MEPUBLIC void MEAPI MdtWorldSetStepBudget(const MdtWorldID world, const MeReal microseconds);
MEPUBLIC MeReal MEAPI MdtWorldGetStepBudget(const MdtWorldID world);
/* "exact", "exact:8", "iterative" for levels 0-2, "off" otherwise. */
MEPUBLIC const char *MEAPI MdtWorldGetStepBudgetLevelName(const int level);

/* Bytes of solver workspace a partition of `rows` rows and `bodies` bodies
 * needs at most (dense worst case: the matrix, its factor and the row
 * vectors). */
MEPUBLIC size_t MEAPI MdtKeaMemoryRequired(const int rows, const int bodies);

/* Bodies in the world: enabled ones / all / the capacity. */
MEPUBLIC unsigned int MEAPI MdtWorldGetEnabledBodyCount(const MdtWorldID world);
MEPUBLIC unsigned int MEAPI MdtWorldGetBodyCount(const MdtWorldID world);
MEPUBLIC unsigned int MEAPI MdtWorldGetMaxBodies(const MdtWorldID world);

ME_EXTERN_C_END

#endif /* KARMA_MDTWORLD_H */
