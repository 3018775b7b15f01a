// Convergence of the iterative solver (projected Gauss-Seidel in body space,
// MdtKeaMethodPGS) to the exact solver's answer (MdtKeaMethodActiveSet, the
// default) as its sweep count grows, on a stack, a jointed chain on the
// ground and a small pile; a hanging chain of joints solved in one sweep; a heap that lands and sleeps; and bit-identical repeated runs.
//
// The measure: from the same state (the scene built afresh and stepped by
// the exact solver, which is deterministic), one step with each solver; the
// largest difference of a body's velocity after that step,
//     e = max_b max(|v_b - v*_b|, r |w_b - w*_b|),
// in units of g h (the speed gravity gives in one step), with r a body's
// half size so that both terms are speeds of points on the body. After one
// step from one state, v - v* = M^-1 J^T (lambda - lambda*): e measures the
// solver's impulse error alone, without the chaos of a trajectory, and
// Gauss-Seidel's error shrinks as the sweeps grow.
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "anchor_scene.h"
#include "step_scene.h"
#include "support/state_hash.h"

namespace {

using step_test::kG;
using step_test::kH;
using step_test::Scene;

// A scene builder adds its bodies to the scene and returns them with each
// one's half size r (the arm that turns angular velocity into speed).
struct Body {
  MdtBodyID body;
  MeReal arm;
};
using Builder = std::function<std::vector<Body>(Scene &)>;

constexpr int kExact = 0;  // "sweeps" of the exact solver

// Each body's velocity (linear, then angular times its arm) after `settle`
// exact steps and one step of the solver given (sweeps, or kExact).
std::vector<MeReal> VelocitiesAfterOneStep(const Builder &build, int settle, int sweeps) {
  Scene s(true, 64);
  const std::vector<Body> bodies = build(s);
  s.step(settle);
  if (sweeps != kExact) {
    MdtWorldSetKeaMethod(s.u->world, MdtKeaMethodPGS);
    MdtWorldSetKeaMaxIterations(s.u->world, sweeps);
  }
  s.step();
  std::vector<MeReal> out;
  for (const Body &b : bodies) {
    MeVector3 v, w;
    MdtBodyGetLinearVelocity(b.body, v);
    MdtBodyGetAngularVelocity(b.body, w);
    for (int k = 0; k < 3; ++k) out.push_back(v[k]);
    for (int k = 0; k < 3; ++k) out.push_back(w[k] * b.arm);
  }
  return out;
}

// e of the comment above, in units of g h.
MeReal VelocityError(const std::vector<MeReal> &a, const std::vector<MeReal> &b) {
  MeReal e = 0;
  for (size_t i = 0; i < a.size(); ++i) e = std::fmax(e, std::fabs(a[i] - b[i]));
  return e / (kG * kH);
}

// The sweep counts compared; the first is "very few".
const std::vector<int> kSweeps = {1, 2, 5, 10, 20, 50};

// The error after one step with each sweep count.
std::vector<MeReal> Errors(const Builder &build, int settle, const std::vector<int> &sweeps) {
  const std::vector<MeReal> exact = VelocitiesAfterOneStep(build, settle, kExact);
  std::vector<MeReal> errors;
  for (int n : sweeps) errors.push_back(VelocityError(VelocitiesAfterOneStep(build, settle, n), exact));
  return errors;
}

// The checks: the fewest sweeps are measurably off (above `fewAbove`, so
// the test can fail); from sweeps[monotoneFrom] on, the error never grows
// by more than 5% (Gauss-Seidel decreases the error in A's energy norm,
// not in this max norm, so a sweep may raise it a little) plus the floor
// below which both solvers' stopping tolerances decide; the most sweeps
// end below `bound` and ten times below the fewest.
void ExpectConverges(const std::vector<int> &sweeps, const std::vector<MeReal> &errors, MeReal fewAbove, MeReal bound,
                     size_t monotoneFrom = 1) {
  // PGS stops once a sweep changes no row velocity by more than its
  // tolerance (1e-4 in single precision, 1e-10 in double) relative to the
  // right-hand side, and Kea's tolerance is of the same order: below about
  // 1e-3 g h in single precision (1e-7 in double) the differences are where
  // each solver stopped, not convergence.
  const MeReal floor = sizeof(MeReal) == 4 ? (MeReal)1e-3 : (MeReal)1e-7;
  for (size_t i = 0; i < sweeps.size(); ++i) std::printf("%5d sweeps: %.3g g h\n", sweeps[i], (double)errors[i]);
  EXPECT_GT(errors.front(), fewAbove) << sweeps.front() << " sweeps already agree: the test could not fail";
  for (size_t i = monotoneFrom; i < errors.size(); ++i)
    EXPECT_LE(errors[i], errors[i - 1] * (MeReal)1.05 + floor) << sweeps[i] << " sweeps";
  EXPECT_LT(errors.back(), bound) << sweeps.back() << " sweeps";
  EXPECT_LT(errors.back(), errors.front() / 10) << sweeps.back() << " sweeps are not ten times better";
}

// Eight 1 m cubes of 100 kg standing on one another, just touching: the
// first step's contacts are new, so neither solver has a warm start.
std::vector<Body> Stack(Scene &s) {
  std::vector<Body> out;
  for (int i = 0; i < 8; ++i) out.push_back({McdModelGetBody(s.box(1, 1, 1, 0, (MeReal)0.5 + (MeReal)i, 0)), 0.5});
  return out;
}

// Ten rods of 1 kg, 0.4 m long and 0.1 m thick (no collision models),
// end to end on a straight chain of ball joints from a world pivot 10 m
// up, held at 40 degrees from the vertical and released: the joints carry
// tension and the chain starts to swing. A rod's inertia about its centre
// is m l^2/12 across its axis d and m t^2/6 along it (a square section of
// side t), I = I_across (1 - d d^T) + I_along d d^T in world axes.
std::vector<Body> Chain(Scene &s) {
  const MeReal link = (MeReal)0.4, thick = (MeReal)0.1;
  const MeReal d[3] = {std::sin((MeReal)0.7), -std::cos((MeReal)0.7), 0};
  const MeReal across = link * link / 12, along = thick * thick / 6;
  MeMatrix3 inertia;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) inertia[i][j] = (i == j ? across : 0) + (along - across) * d[i] * d[j];
  std::vector<Body> out;
  MdtBodyID previous = nullptr;
  for (int i = 0; i < 10; ++i) {
    const MeReal centre = ((MeReal)i + (MeReal)0.5) * link, end = (MeReal)i * link;
    MdtBodyID b = MdtBodyCreate(s.u->world);
    MdtBodySetMass(b, 1);
    MdtBodySetInertiaTensor(b, inertia);
    MdtBodySetPosition(b, centre * d[0], 10 + centre * d[1], 0);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(s.u->world);
    MdtBSJointSetBodies(j, b, previous);
    MdtBSJointSetPosition(j, end * d[0], 10 + end * d[1], 0);
    MdtBSJointEnable(j);
    out.push_back({b, link / 2});
    previous = b;
  }
  return out;
}

// Eight cubes of 0.3 m in a row on the ground, 0.05 m apart, joined by
// ball joints in the middle of each gap, and a 0.5 m cube of four times
// the density lying across the middle two, just touching: contact rows and
// joint rows act on the same bodies.
std::vector<Body> GroundChain(Scene &s) {
  const MeReal side = (MeReal)0.3, pitch = (MeReal)0.35;
  std::vector<Body> out;
  MdtBodyID previous = nullptr;
  for (int i = 0; i < 8; ++i) {
    const MeReal x = pitch * ((MeReal)i - (MeReal)3.5);
    MdtBodyID b = McdModelGetBody(s.box(side, side, side, x, side / 2, 0));
    if (previous) {
      MdtBSJointID j = MdtBSJointCreate(s.u->world);
      MdtBSJointSetBodies(j, previous, b);
      MdtBSJointSetPosition(j, x - pitch / 2, side / 2, 0);
      MdtBSJointEnable(j);
    }
    out.push_back({b, side / 2});
    previous = b;
  }
  out.push_back(
      {McdModelGetBody(s.box((MeReal)0.5, (MeReal)0.5, (MeReal)0.5, 0, side + (MeReal)0.25, 0, 400)), (MeReal)0.25});
  return out;
}

// 27 cubes of 0.5 m, 3 x 3 x 3 with 0.1 m gaps, each turned a little about
// a different axis, dropped from 0.1 m.
std::vector<Body> Pile(Scene &s) {
  std::vector<Body> out;
  int n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k, ++n) {
        McdModelID m = s.box((MeReal)0.5, (MeReal)0.5, (MeReal)0.5, (MeReal)0.6 * (MeReal)(i - 1),
                             (MeReal)0.35 + (MeReal)0.6 * (MeReal)j, (MeReal)0.6 * (MeReal)(k - 1));
        // A rotation of about 0.1 rad about the axis (sin n, 1, cos n).
        const MeReal half = (MeReal)0.05, sn = std::sin((MeReal)n), cn = std::cos((MeReal)n);
        const MeReal norm = std::sqrt(sn * sn + 1 + cn * cn), sh = std::sin(half) / norm;
        MdtBodySetQuaternion(McdModelGetBody(m), std::cos(half), sh * sn, sh, sh * cn);
        out.push_back({McdModelGetBody(m), 0.25});
      }
  return out;
}

// The bounds below hold in both precisions: single precision's own floor
// (1e-3 g h, see ExpectConverges) is below each of them.

TEST(PgsConvergence, AStackApproachesTheExactImpulsesAsSweepsGrow) {
  // Cold (new contacts, no warm start) and settled for half a second (PGS
  // starts from the exact solver's impulses of the step before).
  ExpectConverges(kSweeps, Errors(Stack, 0, kSweeps), (MeReal)0.1, (MeReal)0.005);
  ExpectConverges(kSweeps, Errors(Stack, 30, kSweeps), (MeReal)0.01, (MeReal)0.005);
}

TEST(PgsConvergence, AHangingChainIsSolvedInOneSweep) {
  // The chain's rows are all equality rows, which the iterative solver
  // updates as one block (solver_pgs.cpp): one sweep gives the exact
  // solver's answer, swinging and warm-started after 10 steps or cold from
  // rest, where row by row the tension had to travel down the ten links
  // (200 sweeps left 0.004 g h).
  const std::vector<int> one = {1};
  for (int settle : {10, 0}) {
    const MeReal e = Errors(Chain, settle, one).front();
    std::printf("after %d steps, 1 sweep: %.3g g h\n", settle, (double)e);
    EXPECT_LT(e, sizeof(MeReal) == 4 ? (MeReal)1e-3 : (MeReal)1e-7) << "after " << settle << " steps";
  }
}

TEST(PgsConvergence, AJointedChainOnTheGroundApproachesTheExactImpulsesAsSweepsGrow) {
  // The joint block alternates with the contacts' rows: block Gauss-Seidel.
  // Cold (the first step, contacts new): the friction of eight cubes and
  // the heavy one converges slowly (50 sweeps leave about 0.05 g h).
  const std::vector<int> many = {1, 10, 50, 200, 1000};
  ExpectConverges(many, Errors(GroundChain, 0, many), (MeReal)0.5, (MeReal)0.005);
}

TEST(PgsConvergence, ASmallPileApproachesTheExactImpulsesAsSweepsGrow) {
  // Step 13 of the drop: the bottom layer has landed and the layers above
  // strike it, so the impulses differ much from the step before's. The
  // landed layer's faces are persistent and over-relaxed (solver_pgs.cpp)
  // while the striking ones are new: their second sweep may overshoot what
  // the first left (single precision: 5.69 then 6.1 g h, where the plain
  // step gave 5.96), so the error is checked to fall from 5 sweeps on.
  ExpectConverges(kSweeps, Errors(Pile, 12, kSweeps), (MeReal)1, (MeReal)0.005, 2);
}

// A heap of 200 cubes of 0.5 m and 5 kg: a 5 x 8 x 5 lattice 0.7 m apart
// (0.2 m gaps), each turned by a small pseudo-random yaw and tilt, like
// pile1000 (scenes/box_specs.cpp), dropped on the ground with friction 0.4.
karma::scenes::SceneSpec Heap200Spec() {
  using namespace karma::scenes;
  SceneSpec s;
  s.name = "heap200";
  s.friction = {0.4, 0.4};  // boxes, ground
  s.groundMaterial = 1;
  std::uint64_t state = 200;
  auto next = [&state] {  // a 64-bit LCG's top bits, in [-1, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(state >> 11) / (double)(1ull << 52) - 1;
  };
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 5; ++k) {
        const double yaw = 0.3 * next(), a = 0.1 * next(), b = 0.1 * next();
        s.bodies.push_back({{ShapeKind::kBox, 0.5, 0.5, 0.5},
                            5,
                            {(i - 2) * 0.7, 0.6 + 0.7 * j, (k - 2) * 0.7},
                            TiltAxes(yaw, a, b),
                            0});
      }
  s.expectation = Expectation::kNothingLost;
  s.capacity = {200, 201, 4000, 6000};
  return s;
}

TEST(Heap, AHeapOf200LandsAndSleepsWithNothingLost) {
  // The default settings (the exact solver) with auto-disable on, the
  // world's default (the anchor scenes turn it off). Within 10 s every body
  // sleeps, none is below the ground or flung away (kNothingLost: no centre
  // below 0.2 m, none farther than 20 m from the middle), and the boxes
  // overlap by under 2 cm (a resting contact's depth is set by the contact
  // tolerance, a few millimetres).
  karma::scenes::AnchorScene scene(Heap200Spec());
  MdtWorldSetAutoDisable(scene.world(), TRUE);
  int steps = 0;
  while (MdtWorldGetEnabledBodyCount(scene.world()) > 0 && steps < 600) {
    scene.step();
    ++steps;
  }
  std::printf("asleep after %d steps\n", steps);
  EXPECT_EQ(MdtWorldGetEnabledBodyCount(scene.world()), 0u) << "still awake after 10 s";
  EXPECT_GT(steps, 30) << "asleep before landing";
  const karma::scenes::SceneFigures f = scene.finish();
  std::printf("%s, penetration %.1f mm\n", f.detail.c_str(), f.penetration * 1e3);
  EXPECT_TRUE(f.stable()) << f.detail;
  EXPECT_LT(f.penetration, 0.02);
}

// topple's six stacks through 600 steps with the iterative solver at the
// given sweep count on every partition.
// Every collision pair is tested every step (no contact reuse): the drift
// then measures the sweeps alone, not contacts carried up to 0.1 mm.
karma::scenes::SceneFigures ToppleWithSweeps(int sweeps) {
  auto scene = karma::scenes::MakeTopple();
  McdFrameworkSetContactReuseDistance(MstUniverseGetFramework(scene->universe()), 0);
  MdtWorldSetKeaMethod(scene->world(), MdtKeaMethodPGS);
  MdtWorldSetKeaIterativeRows(scene->world(), 0);
  MdtWorldSetKeaMaxIterations(scene->world(), sweeps);
  return scene->run();
}

// The sweeps alternate direction and the last one always runs backward, so
// an odd sweep count biases no direction either: topple's stacks stand and
// drift less as the sweeps grow, whether the count is odd or even (when an
// odd count ended on a forward sweep, 9, 11 and 13 sweeps let top boxes
// drift 94-137 mm in single precision while 8, 10 and 12 held them to 2-19
// mm).
TEST(PgsConvergence, ToppleStandsAtOddAndEvenSweepCountsAndDriftsLessWithMore) {
  double drift9 = 0, drift13 = 0;
  for (int sweeps = 9; sweeps <= 13; ++sweeps) {
    const karma::scenes::SceneFigures f = ToppleWithSweeps(sweeps);
    std::printf("%d sweeps: %s\n", sweeps, f.detail.c_str());
    EXPECT_EQ(f.standing, f.stacks) << sweeps << " sweeps";
    EXPECT_LT(f.drift, 0.015) << sweeps << " sweeps";
    if (sweeps == 9) drift9 = f.drift;
    if (sweeps == 13) drift13 = f.drift;
  }
  // (In double precision the stacks do not drift at all at these counts:
  // the drift is single precision's rounding, amplified by the sweeps'
  // bias; 0.1 mm is below what the comparison can tell apart.)
  EXPECT_LE(drift13, drift9 / 2 + 1e-4);
}

// stack21 (21 flat boxes, the anchor scene) through its 1200 steps with
// every partition iterative: the mean sweeps per step, and the scene's
// figures.
struct SweepRun {
  double meanSweeps = 0;
  karma::scenes::SceneFigures figures;
};
SweepRun Stack21Iterative() {
  auto scene = karma::scenes::MakeStack21();
  MdtWorldSetKeaIterativeRows(scene->world(), 1);
  long sweeps = 0;
  for (int i = 0; i < scene->steps(); ++i) {
    scene->step();
    MdtWorldStepStats stats;
    MdtWorldGetStepStats(scene->world(), &stats);
    sweeps += stats.keaIterations;
  }
  return {(double)sweeps / scene->steps(), scene->finish()};
}

// The load of twenty boxes reaches the ground one face per sweep; the
// persistent faces' over-relaxation (solver_pgs.cpp) carries it in about
// half the sweeps the plain step takes, and the stack still stands within
// the 5 mm of issue 14. Mean sweeps per step with the plain step and
// over-relaxed: 21.0 and 11.1 in single precision, 21.1 and 12.1 in double.
TEST(PgsConvergence, Stack21StandsOnFewerSweepsWithItsFacesOverRelaxed) {
  const SweepRun run = Stack21Iterative();
  std::printf("%.2f sweeps a step; %s\n", run.meanSweeps, run.figures.detail.c_str());
  EXPECT_LT(run.meanSweeps, 15.0);
  EXPECT_GT(run.meanSweeps, 2.0) << "a stack this tall cannot settle in a sweep or two";
  EXPECT_TRUE(run.figures.stable()) << run.figures.detail;
  EXPECT_LT(run.figures.drift, 0.005);
}

// The largest |friction impulse| / (mu normal impulse) over every contact
// of every topple step with the iterative solver at `sweeps` sweeps (mu
// 0.4 everywhere in topple). Each friction row is bounded by mu times its
// normal impulse, so two rows give at most sqrt 2.
double ToppleWorstFrictionRatio(int sweeps) {
  auto scene = karma::scenes::MakeTopple();
  MdtWorldSetKeaMethod(scene->world(), MdtKeaMethodPGS);
  MdtWorldSetKeaIterativeRows(scene->world(), 0);
  MdtWorldSetKeaMaxIterations(scene->world(), sweeps);
  double worst = 0;
  for (int i = 0; i < scene->steps(); ++i) {
    scene->step();
    for (McdModelID m : scene->models())
      for (MdtContactID c = MdtBodyGetFirstContact(McdModelGetBody(m)); c;
           c = MdtBodyGetNextContact(McdModelGetBody(m), c)) {
        MeVector3 f;
        const double normal = MdtContactGetImpulse(c, f), friction = MeVector3Magnitude(f);
        if (friction > 0) worst = std::fmax(worst, normal > 0 ? friction / (0.4 * normal) : INFINITY);
      }
  }
  return worst;
}

// A face's last visit in a sweep may lower its normal impulses after its
// contacts' friction pairs had their last visit; the solver then brings
// friction back inside its bounds before it returns (solver_pgs.cpp), so
// Coulomb's bound holds on every contact however few the sweeps.
TEST(PgsConvergence, FrictionEndsInsideItsBoundsAtAnySweepCount) {
  for (int sweeps : {1, 2, 3, 5}) {
    const double worst = ToppleWorstFrictionRatio(sweeps);
    std::printf("%d sweeps: largest |friction| / (mu normal) %.4f\n", sweeps, worst);
    EXPECT_LE(worst, std::sqrt(2.0) * (1 + 1e-5)) << sweeps << " sweeps";
  }
}

// Hash of the small pile's bodies after a second, with the given method.
std::uint64_t PileHash(MdtKeaMethod method) {
  Scene s(true, 64);
  MdtWorldSetKeaMethod(s.u->world, method);
  std::vector<MdtBodyID> bodies;
  for (const Body &b : Pile(s)) bodies.push_back(b.body);
  s.step(60);
  return karma_test::HashBodies(bodies);
}

TEST(Determinism, RepeatedRunsOfAPileAreBitIdentical) {
  for (MdtKeaMethod method : {MdtKeaMethodActiveSet, MdtKeaMethodPGS}) {
    const std::uint64_t first = PileHash(method);
    EXPECT_EQ(PileHash(method), first) << "method " << (int)method;
  }
  EXPECT_NE(PileHash(MdtKeaMethodActiveSet), PileHash(MdtKeaMethodPGS)) << "the hash does not see the solver";
}

}  // namespace
