// effects.cpp: does the cost of a step follow what moves and what is
// switched on, rather than the size of the scene? (issue 17). Every scene is
// built through Mst like a user's scene (a universe, a frozen McdPlane
// ground, models with bodies) and stepped at 60 Hz with MstUniverseStep
// (MdtWorldStep for the plain-world reference). Each rule compares a subject
// scene with a reference scene:
//
//   sleepers     a ball rolling on the ground beside N = 100, 1,000, 10,000
//                cubes that came to rest and fell asleep on the ground,
//                against the ball alone: subject / reference <= 1.2;
//   resting      the ball beside 50 stacks of 4 cubes at rest and asleep
//                (cube-cube and cube-ground contacts kept), against its
//                awake part, the ball alone: <= 1.2;
//   mu0          50 awake cubes resting on the ground, contacts of type
//                Friction2D with the normal-force model and mu = 0, against
//                the same with the frictionless contact type: <= 1.1;
//   statics      the ball beside 1,000 frozen fixed boxes (MstFixedModelCreate),
//                against the ball in an otherwise empty space: <= 1.2;
//   joints       a swinging chain of 10 bodies and ball-and-socket joints
//                without collision models in an Mst universe (MstUniverseStep),
//                against the same chain in a plain MdtWorld (MdtWorldStep):
//                <= 1.1 (no contacts, so collision should cost nothing).
//
// Two passes, both on the same scenes, built once:
//  - the Google Benchmark cases (one per scene, the rule in the label);
//  - then the ratio table: R rounds, each stepping every scene in turn for
//    a batch of at least 5 ms of this thread's CPU time; the median over the
//    rounds of each scene's microseconds per step, and the ratio of the
//    medians. Interleaving puts subject and reference under the same drift
//    of a shared machine.
// Run e.g.
//   build/release/bench/effects_bench --effects_rounds=15
//   build/release/bench/effects_bench --benchmark_filter=NONE   (the table only)
#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "Mst.h"

namespace {

constexpr MeReal kStep = (MeReal)1 / 60;

double CpuUs() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec * 1e6 + (double)t.tv_nsec * 1e-3;
}

// A scene that can be stepped, with what it is and how it is stepped.
class Scene {
 public:
  virtual ~Scene() = default;
  virtual void step() = 0;
  virtual MdtWorldID world() const = 0;
  int enabledBodies() const { return (int)MdtWorldGetEnabledBodyCount(world()); }
  int rows() const {
    MdtWorldStepStats s;
    MdtWorldGetStepStats(world(), &s);
    return s.rows;
  }
};

// What a universe scene holds beside its ground.
struct UniverseOptions {
  bool ball = true;           // the rolling ball
  int sleepingCubes = 0;      // single cubes on the ground, put to sleep
  int restingStacks = 0;      // stacks of 4 cubes, put to sleep
  int awakeCubes = 0;         // cubes on the ground, auto-disable off
  int frozenStatics = 0;      // fixed boxes
  int chainLinks = 0;         // bodies without models, joined in a chain
  bool frictionless = false;  // material 0: FrictionZero, else Friction2D
  MeReal mu = (MeReal)0.5;    // material 0's coefficient (normal-force model)
};

class UniverseScene : public Scene {
 public:
  explicit UniverseScene(const UniverseOptions &o);
  ~UniverseScene() override { MstUniverseDestroy(u_); }
  void step() override;
  MdtWorldID world() const override { return MstUniverseGetWorld(u_); }

 private:
  McdModelID cube(MeReal x, MeReal y, MeReal z);
  void settle();

  MstUniverseID u_ = nullptr;
  McdGeometryID cubeGeometry_ = nullptr;
  MdtBodyID ball_ = nullptr;
  MeMatrix4 groundTM_;
  std::unique_ptr<MeMatrix4[]> staticTMs_;  // the fixed boxes' transforms
};

// Grid cell i of a field of the given width, 2 m apart, behind z = -3 (the
// ball rolls along z = +5, so nothing there ever comes near it).
void GridCell(int i, int width, MeReal &x, MeReal &z) {
  x = (MeReal)(-width + 2 * (i % width));
  z = (MeReal)(-3 - 2 * (i / width));
}

UniverseScene::UniverseScene(const UniverseOptions &o) {
  const int cubes = o.sleepingCubes + 4 * o.restingStacks + o.awakeCubes;
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  sizes.dynamicBodiesMaxCount = cubes + o.chainLinks + 2;
  sizes.dynamicConstraintsMaxCount = 6 * cubes + o.chainLinks + 8;  // a group and 4 contacts a cube
  sizes.collisionModelsMaxCount = cubes + o.frozenStatics + 4;
  sizes.collisionPairsMaxCount = 3 * cubes + 16;
  sizes.collisionGeometryInstancesMaxCount = 8;
  u_ = MstUniverseCreate(&sizes);
  MdtWorldID w = world();
  MdtWorldSetGravity(w, 0, (MeReal)-9.81, 0);
  McdFrameworkID fw = MstUniverseGetFramework(u_);
  MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u_), 0, 0);
  if (o.frictionless) {
    MdtContactParamsSetType(p, MdtContactTypeFrictionZero);
  } else {
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoefficient(p, o.mu);
  }
  // McdPlane's normal is its local z: turn z onto world y.
  const MeMatrix4 tm = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MeMatrix4Copy(groundTM_, tm);
  MstFixedModelCreate(u_, McdPlaneCreate(fw), groundTM_);
  cubeGeometry_ = McdBoxCreate(fw, 1, 1, 1);
  if (o.ball) {
    McdModelID m = MstModelAndBodyCreate(u_, McdSphereCreate(fw, (MeReal)0.5), 1);
    ball_ = McdModelGetBody(m);
    MdtBodySetPosition(ball_, 0, (MeReal)0.5, 5);
    MdtBodySetLinearVelocity(ball_, 2, 0, 0);
    MdtBodySetAngularVelocity(ball_, 0, 0, -4);  // rolling: v = -w x r
  }
  const int width = std::max(1, (int)std::ceil(std::sqrt((double)(o.sleepingCubes + o.awakeCubes))));
  MeReal x, z;
  for (int i = 0; i < o.sleepingCubes + o.awakeCubes; ++i) {
    GridCell(i, width, x, z);
    cube(x, (MeReal)0.5, z);
  }
  for (int s = 0; s < o.restingStacks; ++s) {
    GridCell(s, 10, x, z);
    for (int k = 0; k < 4; ++k) cube(x, (MeReal)0.5 + (MeReal)k, z);
  }
  staticTMs_ = std::make_unique<MeMatrix4[]>((size_t)std::max(1, o.frozenStatics));
  const int staticWidth = std::max(1, (int)std::ceil(std::sqrt((double)o.frozenStatics)));
  for (int i = 0; i < o.frozenStatics; ++i) {
    GridCell(i, staticWidth, x, z);
    MeMatrix4Ptr t = staticTMs_[(size_t)i];
    MeMatrix4TMMakeIdentity(t);
    t[3][0] = x;
    t[3][1] = (MeReal)0.5;
    t[3][2] = z;
    MstFixedModelCreate(u_, cubeGeometry_, t);
  }
  MdtBodyID prev = nullptr;
  for (int i = 0; i < o.chainLinks; ++i) {
    const MeReal len = (MeReal)0.5, dx = len * (MeReal)0.5, dy = -len * (MeReal)0.866;
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetPosition(b, dx * ((MeReal)i + (MeReal)0.5), 20 + dy * ((MeReal)i + (MeReal)0.5), 0);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, b, prev);
    MdtBSJointSetPosition(j, dx * (MeReal)i, 20 + dy * (MeReal)i, 0);
    MdtBSJointEnable(j);
    prev = b;
  }
  if (o.awakeCubes > 0 || o.chainLinks > 0) MdtWorldSetAutoDisable(w, FALSE);
  settle();
}

McdModelID UniverseScene::cube(MeReal x, MeReal y, MeReal z) {
  McdModelID m = MstModelAndBodyCreate(u_, cubeGeometry_, 1);
  MdtBodySetPosition(McdModelGetBody(m), x, y, z);
  return m;
}

// Steps until only the ball (if any) is awake, or 1,000 steps.
void UniverseScene::settle() {
  const int awakeGoal = ball_ ? 1 : 0;
  if (!MdtWorldGetAutoDisable(world())) {
    for (int i = 0; i < 30; ++i) step();
    return;
  }
  for (int i = 0; i < 1000 && enabledBodies() > awakeGoal; ++i) step();
}

void UniverseScene::step() {
  // The ball rolls back and forth over the same 80 m of ground.
  if (ball_) {
    MeVector3 x;
    MdtBodyGetPosition(ball_, x);
    if (x[0] > 40) MdtBodySetPosition(ball_, x[0] - 80, x[1], x[2]);
  }
  MstUniverseStep(u_, kStep);
}

// The chain of UniverseOptions::chainLinks in a plain world.
class PlainChain : public Scene {
 public:
  explicit PlainChain(int links) {
    w_ = MdtWorldCreate((unsigned)links + 2, (unsigned)links + 8, 1, 1);
    MdtWorldSetGravity(w_, 0, (MeReal)-9.81, 0);
    MdtWorldSetAutoDisable(w_, FALSE);
    MdtBodyID prev = nullptr;
    for (int i = 0; i < links; ++i) {
      const MeReal len = (MeReal)0.5, dx = len * (MeReal)0.5, dy = -len * (MeReal)0.866;
      MdtBodyID b = MdtBodyCreate(w_);
      MdtBodySetPosition(b, dx * ((MeReal)i + (MeReal)0.5), 20 + dy * ((MeReal)i + (MeReal)0.5), 0);
      MdtBodyEnable(b);
      MdtBSJointID j = MdtBSJointCreate(w_);
      MdtBSJointSetBodies(j, b, prev);
      MdtBSJointSetPosition(j, dx * (MeReal)i, 20 + dy * (MeReal)i, 0);
      MdtBSJointEnable(j);
      prev = b;
    }
    for (int i = 0; i < 30; ++i) step();
  }
  ~PlainChain() override { MdtWorldDestroy(w_); }
  void step() override { MdtWorldStep(w_, kStep); }
  MdtWorldID world() const override { return w_; }

 private:
  MdtWorldID w_ = nullptr;
};

// ---------------------------------------------------------------------------
// The scenes, built once on first use.

enum SceneId {
  kBall,
  kSleepers100,
  kSleepers1000,
  kSleepers10000,
  kResting,
  kMuZero,
  kFrictionless,
  kStatics,
  kChainUniverse,
  kChainWorld,
  kSceneCount
};

const char *const kSceneNames[kSceneCount] = {
    "ball",      "ball+100_sleeping",  "ball+1000_sleeping",       "ball+10000_sleeping", "ball+resting_stacks",
    "cubes_mu0", "cubes_frictionless", "ball+1000_frozen_statics", "chain_in_universe",   "chain_in_world"};

std::unique_ptr<Scene> Build(int id) {
  UniverseOptions o;
  switch (id) {
    case kBall:
      break;
    case kSleepers100:
      o.sleepingCubes = 100;
      break;
    case kSleepers1000:
      o.sleepingCubes = 1000;
      break;
    case kSleepers10000:
      o.sleepingCubes = 10000;
      break;
    case kResting:
      o.restingStacks = 50;
      break;
    case kMuZero:
    case kFrictionless:
      o.ball = false;
      o.awakeCubes = 50;
      o.mu = 0;
      o.frictionless = id == kFrictionless;
      break;
    case kStatics:
      o.frozenStatics = 1000;
      break;
    case kChainUniverse:
      o.ball = false;
      o.chainLinks = 10;
      break;
    case kChainWorld:
      return std::make_unique<PlainChain>(10);
    default:
      return nullptr;
  }
  return std::make_unique<UniverseScene>(o);
}

Scene &Get(int id) {
  static std::unique_ptr<Scene> scenes[kSceneCount];
  if (!scenes[id]) scenes[id] = Build(id);
  return *scenes[id];
}

// The rules: subject / reference <= goal.
struct Rule {
  const char *name;
  int subject, reference;
  double goal;
  const char *statement;
};

const Rule kRules[] = {
    {"sleepers", kSleepers100, kBall, 1.2, "one moving body beside 100 sleeping cubes <= 1.2x the body alone"},
    {"sleepers", kSleepers1000, kBall, 1.2, "one moving body beside 1,000 sleeping cubes <= 1.2x the body alone"},
    {"sleepers", kSleepers10000, kBall, 1.2, "one moving body beside 10,000 sleeping cubes <= 1.2x the body alone"},
    {"resting", kResting, kBall, 1.2, "a resting scene (50 sleeping stacks of 4) <= 1.2x its awake part"},
    {"mu0", kMuZero, kFrictionless, 1.1, "contacts with mu = 0 within 10% of the frictionless contact type"},
    {"statics", kStatics, kBall, 1.2, "1,000 frozen static models within 20% of an empty space"},
    {"joints", kChainUniverse, kChainWorld, 1.1, "joints without contacts pay nothing for the collision universe"},
};

// The rule a scene is the subject of (or the reference for).
std::string RuleOf(int id) {
  std::string out;
  for (const Rule &r : kRules) {
    if (r.subject != id && r.reference != id) continue;
    if (!out.empty()) out += "; ";
    out += r.subject == id ? std::string(r.name) + ": " + r.statement : std::string("reference of ") + r.name;
  }
  return out;
}

void BM_Effects(benchmark::State &state) {
  const int id = (int)state.range(0);
  Scene &s = Get(id);
  for (auto _ : state) s.step();
  state.counters["awake"] = s.enabledBodies();
  state.counters["rows"] = s.rows();
  state.SetLabel(std::string(kSceneNames[id]) + " [" + RuleOf(id) + "]");
}
BENCHMARK(BM_Effects)->DenseRange(0, kSceneCount - 1)->Unit(benchmark::kMicrosecond);

// Microseconds per step of one batch of at least minUs of CPU time.
double Batch(Scene &s, double minUs) {
  int steps = 0;
  const double t0 = CpuUs();
  double t = t0;
  while (t - t0 < minUs || steps < 3) {
    s.step();
    ++steps;
    t = CpuUs();
  }
  return (t - t0) / steps;
}

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void PrintRatios(int rounds) {
  std::vector<std::vector<double>> us(kSceneCount);
  for (int id = 0; id < kSceneCount; ++id) Batch(Get(id), 2000);  // warm caches
  for (int r = 0; r < rounds; ++r)
    for (int id = 0; id < kSceneCount; ++id) us[(size_t)id].push_back(Batch(Get(id), 5000));
  std::printf("\nEffects (issue 17): medians of %d interleaved rounds, us per step (thread CPU time)\n\n", rounds);
  std::printf(
      "| rule | subject (awake bodies, rows) | us | reference (awake bodies, rows) | us | ratio | goal | holds |\n");
  std::printf("|---|---|---:|---|---:|---:|---:|---|\n");
  for (const Rule &rule : kRules) {
    Scene &s = Get(rule.subject), &r = Get(rule.reference);
    const double a = Median(us[(size_t)rule.subject]), b = Median(us[(size_t)rule.reference]);
    const double ratio = a / b;
    std::printf("| %s: %s | %s (%d, %d) | %.1f | %s (%d, %d) | %.1f | %.2f | <= %.2f | %s |\n", rule.name,
                rule.statement, kSceneNames[rule.subject], s.enabledBodies(), s.rows(), a, kSceneNames[rule.reference],
                r.enabledBodies(), r.rows(), b, ratio, rule.goal, ratio <= rule.goal ? "yes" : "no");
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char **argv) {
  int rounds = 15;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--effects_rounds=", 17) == 0) {
      rounds = std::max(1, std::atoi(argv[i] + 17));
      for (int k = i; k < argc - 1; ++k) argv[k] = argv[k + 1];
      --argc;
      --i;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  PrintRatios(rounds);
  return 0;
}
