/* KarmaTradeoffScene.h: a user's own scene for karma-tradeoff.
 *
 * Build a shared library that exports one C function,
 *
 *   int KarmaTradeoffBuildScene(KarmaTradeoffScene *scene);
 *
 * and pass the library's path to `karma-tradeoff --scene ./libmyscene.so`.
 * The tool calls the function once per run (it builds a fresh scene for
 * the reference run and for every setting of the sweep), applies the
 * setting to `scene->world`, then steps the scene for `seconds` of
 * simulated time with the sweep's step size h:
 *
 *   for each step:  beforeStep(user, h) if set;
 *                   MstUniverseStep(universe, h)  if universe is set,
 *                   else MdtWorldStep(world, h)
 *
 * The function fills the struct and returns 1, or returns 0 when it cannot
 * build the scene. `bodies` (bodyCount of them) are the bodies the errors
 * are measured on, in a fixed order (the same in every build: the tool
 * compares body i of a run with body i of the reference run). `joints`
 * (jointCount, may be 0) are the joints whose gap is the joint error: the
 * distance between the joint's point as carried by each of its bodies.
 * `check`, when set, is the scene's own test of a run (1: it held), called
 * after the last step. `destroy` is called last and must free everything
 * the function made (the universe or world included). Arrays must stay
 * valid until then.
 *
 * The library is compiled against the same Karma headers and precision
 * (MeReal) as the tool; the tool refuses a library whose `realSize` is not
 * sizeof(MeReal). */
#ifndef KARMA_TRADEOFF_SCENE_H
#define KARMA_TRADEOFF_SCENE_H

#include "Mst.h"

#ifdef __cplusplus
extern "C" {
#endif

#define KARMA_TRADEOFF_SCENE_VERSION 1

typedef struct KarmaTradeoffScene {
  int version;            /* set to KARMA_TRADEOFF_SCENE_VERSION */
  int realSize;           /* set to sizeof(MeReal) */
  const char *name;       /* shown in the tables and plots */
  MstUniverseID universe; /* stepped by MstUniverseStep, or NULL ... */
  MdtWorldID world;       /* ... and this world stepped by MdtWorldStep (required) */
  double seconds;         /* simulated time of a run */
  MdtBodyID *bodies;
  int bodyCount;
  MdtConstraintID *joints;
  int jointCount;
  void *user;
  void (*beforeStep)(void *user, MeReal h);
  int (*check)(void *user);
  void (*destroy)(void *user);
} KarmaTradeoffScene;

typedef int (*KarmaTradeoffBuildSceneFn)(KarmaTradeoffScene *scene);

#define KARMA_TRADEOFF_BUILD_SCENE_SYMBOL "KarmaTradeoffBuildScene"

#ifdef __cplusplus
}
#endif

#endif
