// anchor_scene_trace.cpp: what the solver did at each step of an anchor
// scene (MdtWorldGetStepStats), one line per step, for reading a scene's
// cost rather than timing it:
//   build/bench/bench/anchor_scene_trace stack21 [FIRST [LAST]]   (also pile10k, not an anchor scene)
// prints steps FIRST..LAST-1 (default: the whole run), after a comment line
// naming the platform backend the scene's world steps on (KARMA_PLATFORM
// chooses it). `--iterative-rows N` (anywhere after the scene) sets the
// world's MdtWorldSetKeaIterativeRows (1: every partition iterative); the
// solves column then counts the iterative solver's sweeps too. `--sleep`
// turns the world's auto-disable on at its default thresholds (the anchor
// scenes turn it off); the bodies column counts the bodies stepped.
// `--epsilon E` (>= 0) and `--joint-projection N` set the world's softness
// and joint projection sweeps, as peer_bench's options of the same names.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "anchor_scene.h"

int main(int argc, char **argv) {
  using namespace karma::scenes;
  std::vector<char *> args;
  int iterativeRows = -1;
  bool sleep = false;
  double epsilon = -1;       // < 0: the world's default
  int jointProjection = -1;  // < 0: the world's default (off)
  for (int i = 0; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--iterative-rows") && i + 1 < argc)
      iterativeRows = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--sleep"))
      sleep = true;
    else if (!std::strcmp(argv[i], "--epsilon") && i + 1 < argc)
      epsilon = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--joint-projection") && i + 1 < argc)
      jointProjection = std::atoi(argv[++i]);
    else
      args.push_back(argv[i]);
  }
  argc = (int)args.size();
  argv = args.data();
  const char *name = argc > 1 ? argv[1] : "";
  std::unique_ptr<AnchorScene> scene = !std::strcmp(name, "car")        ? MakeCar()
                                       : !std::strcmp(name, "topple")   ? MakeTopple()
                                       : !std::strcmp(name, "stack21")  ? MakeStack21()
                                       : !std::strcmp(name, "ragdoll")  ? MakeRagdoll()
                                       : !std::strcmp(name, "pile1000") ? MakePile1000()
                                       : !std::strcmp(name, "pile10k")  ? MakePile10k()
                                                                        : nullptr;
  if (!scene) {
    std::fprintf(stderr,
                 "usage: %s car|topple|stack21|ragdoll|pile1000|pile10k [FIRST [LAST]] [--iterative-rows N] [--sleep] "
                 "[--epsilon E] [--joint-projection N]\n",
                 argv[0]);
    return 2;
  }
  if (iterativeRows >= 0) MdtWorldSetKeaIterativeRows(scene->world(), iterativeRows);
  if (sleep) MdtWorldSetAutoDisable(scene->world(), 1);
  if (epsilon >= 0) MdtWorldSetEpsilon(scene->world(), (MeReal)epsilon);
  if (jointProjection >= 0) MdtWorldSetJointProjection(scene->world(), jointProjection);
  const int first = argc > 2 ? std::atoi(argv[2]) : 0;
  const int last = argc > 3 ? std::atoi(argv[3]) : scene->steps();
  std::printf("# platform backend: %s\n", MdtWorldGetPlatformName(scene->world()));
  std::printf(
      "step partitions rows solves factorizations stale_solves friction_rounds unsolved cycles residual "
      "iterative_partitions warm_starts bodies factor_updates\n");
  for (int i = 0; i < last; ++i) {
    scene->step();
    if (i < first) continue;
    MdtWorldStepStats s;
    MdtWorldGetStepStats(scene->world(), &s);
    std::printf("%d %d %d %d %d %d %d %d %d %.3g %d %d %d %d\n", i, s.partitions, s.rows, s.keaIterations,
                s.keaFactorizations, s.keaStaleSolves, s.keaFrictionRounds, s.keaUnsolved, s.keaCycles,
                (double)s.keaResidual, s.iterativePartitions, s.keaWarmStarts, s.bodies, s.keaFactorUpdates);
  }
  return 0;
}
