// scene_figures.cpp: the per-step bookkeeping and the expectations of
// SCENES.md, on engine-neutral body states.
#include "scene_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace karma::scenes {

namespace {

// World point of a body-frame vector b: x + R^T b.
Vec3 ToWorld(const BodyState &s, const Vec3 &b) {
  Vec3 w = s.position;
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) w[i] += b[k] * s.axes[k][i];
  return w;
}

// Body-frame vector of a world point p: R (p - x).
Vec3 ToBody(const BodyState &s, const Vec3 &p) {
  Vec3 b{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) b[k] += s.axes[k][i] * (p[i] - s.position[i]);
  return b;
}

double Distance(const Vec3 &a, const Vec3 &b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

bool Finite(const Vec3 &v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

}  // namespace

void SceneMonitor::start(const std::vector<BodyState> &bodies) {
  anchors_.clear();
  for (const BallJointSpec &j : spec_->ballJoints) {
    Vec3 anchor = j.anchor;
    for (int i = 0; i < 3; ++i) anchor[i] += spec_->offset[i];
    anchors_.push_back(ToBody(bodies[(size_t)j.body0], anchor));
    anchors_.push_back(ToBody(bodies[(size_t)j.body1], anchor));
  }
  watchedStart_.clear();
  for (int w : spec_->watched) watchedStart_.push_back(bodies[(size_t)w].position);
  running_ = SceneFigures{};
}

void SceneMonitor::observe(const std::vector<BodyState> &bodies) {
  for (const BodyState &b : bodies) {
    if (!Finite(b.position) || !Finite(b.velocity) || !Finite(b.angularVelocity)) running_.finite = false;
    const Vec3 &v = b.velocity;
    running_.maxSpeed = std::max(running_.maxSpeed, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  }
  if (!anchors_.empty()) running_.jointErrorMax = std::max(running_.jointErrorMax, jointError(bodies));
}

double SceneMonitor::jointError(const std::vector<BodyState> &bodies) const {
  double worst = 0;
  for (size_t j = 0; j < spec_->ballJoints.size(); ++j) {
    const BallJointSpec &joint = spec_->ballJoints[j];
    const Vec3 p0 = ToWorld(bodies[(size_t)joint.body0], anchors_[2 * j]);
    const Vec3 p1 = ToWorld(bodies[(size_t)joint.body1], anchors_[2 * j + 1]);
    worst = std::max(worst, Distance(p0, p1));
  }
  return worst;
}

SceneFigures SceneMonitor::finish(const std::vector<BodyState> &bodies, int steps, double penetration) const {
  SceneFigures f = running_;
  f.steps = steps;
  f.penetration = penetration;
  if (!anchors_.empty()) f.jointErrorEnd = jointError(bodies);
  check(bodies, f);
  return f;
}

void SceneMonitor::check(const std::vector<BodyState> &bodies, SceneFigures &f) const {
  char text[160];
  switch (spec_->expectation) {
    case Expectation::kCarRolls: {
      const BodyState &chassis = bodies[(size_t)spec_->watched[0]];
      f.carPosition = chassis.position[0];
      f.carVelocity = chassis.velocity[0];
      f.carRideHeight = chassis.position[1];
      const double t = f.steps * kStepSeconds, a = spec_->carAcceleration;
      const double vExpected = a * t, xExpected = a * t * t / 2;
      f.expectation = std::fabs(f.carVelocity - vExpected) < 0.05 * vExpected &&
                      std::fabs(f.carPosition - xExpected) < 0.05 * xExpected;
      std::snprintf(text, sizeof text, "v %.3f m/s (analytic %.3f), x %.3f m (analytic %.3f), height %.3f m",
                    f.carVelocity, vExpected, f.carPosition, xExpected, f.carRideHeight);
      break;
    }
    case Expectation::kStacksStand:
    case Expectation::kTopStill: {
      f.stacks = (int)spec_->watched.size();
      for (size_t i = 0; i < spec_->watched.size(); ++i) {
        const Vec3 &x = bodies[(size_t)spec_->watched[i]].position, &x0 = watchedStart_[i];
        const double drift = std::hypot(x[0] - x0[0], x[2] - x0[2]), drop = x0[1] - x[1];
        f.drift = std::max(f.drift, drift);
        f.drop = std::max(f.drop, drop);
        if (drift < 0.05 && drop < 0.05) ++f.standing;
      }
      if (spec_->expectation == Expectation::kStacksStand) {
        f.expectation = f.drift < 0.05 && f.drop < 0.05;
        std::snprintf(text, sizeof text, "worst top box: drift %.1f mm, drop %.1f mm (%d of %d stand)", f.drift * 1e3,
                      f.drop * 1e3, f.standing, f.stacks);
      } else {
        f.expectation = f.drift < 0.05;
        std::snprintf(text, sizeof text, "top box drift %.2f mm, height %.4f m", f.drift * 1e3,
                      bodies[(size_t)spec_->watched[0]].position[1]);
      }
      break;
    }
    case Expectation::kJointsWhole:
      // SCENES.md asks only to report the error; the check is that the
      // body is whole again once it has landed (the peak, at the impact,
      // is a reported figure).
      f.expectation = f.jointErrorEnd < 0.02;
      std::snprintf(text, sizeof text, "joint error: max %.2f mm, end %.2f mm", f.jointErrorMax * 1e3,
                    f.jointErrorEnd * 1e3);
      break;
    case Expectation::kNothingLost: {
      // No box below the ground (a centre at least 0.25 m up, less 50 mm)
      // and none lost (within 20 m of the middle of the 6.3 m lattice).
      f.lowest = 1e9;
      for (const BodyState &b : bodies) {
        f.lowest = std::min(f.lowest, b.position[1]);
        f.farthest = std::max(f.farthest, std::hypot(b.position[0], b.position[2]));
      }
      f.expectation = f.lowest > 0.2 && f.farthest < 20;
      std::snprintf(text, sizeof text, "lowest centre %.3f m, farthest %.2f m from the middle", f.lowest, f.farthest);
      break;
    }
  }
  f.detail = text;
}

}  // namespace karma::scenes
