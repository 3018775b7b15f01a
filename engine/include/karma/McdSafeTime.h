/* McdSafeTime.h: an estimate of the time of impact of a pair of models.
 *
 * McdSafeTime(pair, maxTime, result) moves both models along their
 * velocities (the linear and angular velocity pointers of McdModel.h,
 * usually the body's; no pointer means at rest) for up to maxTime and
 * reports in result->time the last time at which they are known not to
 * touch: 0 when they touch now, maxTime when they stay apart. It is an
 * approximation (the guide says so too): the motion is sampled in steps
 * short enough that neither model moves by more than half the smaller
 * model's thickness, the first touching sample is refined by bisection,
 * and rotation is about each model's origin.
 *
 * Supported pairs, as the guide lists: {sphere, box, cylinder} against
 * each other, and the plane against the sphere and the box, when the
 * framework has an interaction for them. It returns 1 for those; for any
 * other pair it sets result->time = maxTime and returns 0. The pair must
 * be between McdHello and McdGoodbye. */
#ifndef KARMA_MCDSAFETIME_H
#define KARMA_MCDSAFETIME_H
#include "MeCall.h"
#include "MePrecision.h"
#include "McdModelPair.h"

ME_EXTERN_C_BEGIN

typedef struct McdSafeTimeResult {
  McdModelPair *pair;
  MeReal time; /* in [0, maxTime] */
} McdSafeTimeResult;

MEPUBLIC MeBool MEAPI McdSafeTime(McdModelPair *pair, MeReal maxTime, McdSafeTimeResult *result);

ME_EXTERN_C_END
#endif
