// run.cpp: running a scene with a setting, and comparing runs (run.h).
#include "run.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace karma::tradeoff {

namespace {

// The sample instants k/60 s (k = 1 .. frames) fall after step
// round(k / (60 h)).
constexpr double kSampleRate = 60;

bool Finite(const Vec3d &v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

void Sample(const TradeoffScene &scene, Trajectory &t, double &maxSpeed, bool &finite) {
  const std::vector<MdtBodyID> &bodies = scene.bodies();
  std::vector<Vec3d> x(bodies.size());
  Vec3d p{0, 0, 0};
  for (size_t i = 0; i < bodies.size(); ++i) {
    MeVector3 position, v;
    MdtBodyGetPosition(bodies[i], position);
    MdtBodyGetLinearVelocity(bodies[i], v);
    const double m = MdtBodyGetMass(bodies[i]);
    for (int k = 0; k < 3; ++k) {
      x[i][(size_t)k] = position[k];
      p[(size_t)k] += m * v[k];
    }
    finite = finite && Finite(x[i]) && std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
    maxSpeed = std::max(maxSpeed, (double)MeVector3Magnitude(v));
  }
  t.positions.push_back(std::move(x));
  t.momentum.push_back(p);
  t.energy.push_back(MechanicalEnergy(scene.world(), bodies));
}

double Distance(const Vec3d &a, const Vec3d &b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

double MechanicalEnergy(MdtWorldID world, const std::vector<MdtBodyID> &bodies) {
  MeVector3 g;
  MdtWorldGetGravity(world, g);
  double energy = 0;
  for (MdtBodyID b : bodies) {
    MeVector3 v, w, x;
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    MdtBodyGetPosition(b, x);
    MeMatrix4 tm;
    MdtBodyGetTransform(b, tm);
    double wb[3];  // body frame (rows of tm: the body axes)
    for (int i = 0; i < 3; ++i) wb[i] = (double)tm[i][0] * w[0] + (double)tm[i][1] * w[1] + (double)tm[i][2] * w[2];
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(b, I);
    double rotational = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rotational += wb[i] * I[i][j] * wb[j];
    const double m = MdtBodyGetMass(b);
    const double vv = (double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2];
    const double gx = (double)g[0] * x[0] + (double)g[1] * x[1] + (double)g[2] * x[2];
    energy += 0.5 * m * vv + 0.5 * rotational - m * gx;
  }
  return energy;
}

double DeepestContact(const std::vector<MdtBodyID> &bodies) {
  double deepest = 0;
  for (MdtBodyID b : bodies)
    for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c))
      deepest = std::max(deepest, (double)MdtContactGetPenetration(c));
  return deepest;
}

bool RunScene(const SceneEntry &entry, const Setting &setting, double seconds, RunRecord &out) {
  out = RunRecord{};
  std::unique_ptr<TradeoffScene> scene = entry.make();
  if (!scene || !scene->world()) return false;
  setting.apply(scene->world(), scene->framework());
  const MeReal h = (MeReal)setting.h;
  out.steps = std::max(1, (int)std::lround(seconds / setting.h));
  const int frames = (int)std::lround(seconds * kSampleRate);
  int nextFrame = 1;
  std::chrono::steady_clock::duration spent{};
  for (int step = 1; step <= out.steps; ++step) {
    const auto start = std::chrono::steady_clock::now();
    scene->advance(h);
    spent += std::chrono::steady_clock::now() - start;
    scene->observe();
    MdtWorldStepStats stats;
    MdtWorldGetStepStats(scene->world(), &stats);
    out.residual = std::max(out.residual, (double)stats.keaResidual);
    if (stats.keaUnsolved > 0) ++out.unsolvedSteps;
    out.jointError = std::max(out.jointError, scene->jointGap());
    out.penetration = std::max(out.penetration, DeepestContact(scene->bodies()));
    while (nextFrame <= frames && std::lround(nextFrame / (kSampleRate * setting.h)) <= step) {
      Sample(*scene, out.trajectory, out.maxSpeed, out.finite);
      ++nextFrame;
    }
  }
  out.stepSeconds = std::chrono::duration<double>(spent).count();
  out.outcome = scene->finish(out.steps * setting.h);
  out.jointError = std::max(out.jointError, out.outcome.jointErrorMax);
  if (!out.finite) out.jointError = out.penetration = std::nan("");
  return true;
}

Errors CompareWithReference(const RunRecord &run, const RunRecord &reference) {
  Errors e;
  if (!run.finite) {
    e.drift = e.energy = e.momentum = std::nan("");
    return e;
  }
  const Trajectory &a = run.trajectory, &b = reference.trajectory;
  const size_t samples = std::min(a.positions.size(), b.positions.size());
  for (size_t k = 0; k < samples; ++k) {
    const size_t bodies = std::min(a.positions[k].size(), b.positions[k].size());
    double sum = 0;
    for (size_t i = 0; i < bodies; ++i) {
      const double d = Distance(a.positions[k][i], b.positions[k][i]);
      sum += d * d;
    }
    if (bodies > 0) e.drift = std::max(e.drift, std::sqrt(sum / (double)bodies));
    e.energy = std::max(e.energy, std::fabs(a.energy[k] - b.energy[k]));
    e.momentum = std::max(e.momentum, Distance(a.momentum[k], b.momentum[k]));
  }
  return e;
}

}  // namespace karma::tradeoff
