// The QuadBike tutorial's behaviour (issue 6, item 7), beyond its goldens:
// the simulation of step 19 (quadbike_sim: the same sources as the
// programs, no viewer), driven directly through the bike's control inputs.
//
//   - on flat ground the bike rests on its four wheels at the ride height
//     the suspension predicts;
//   - it moves forward under throttle at the acceleration the wheel torque
//     predicts;
//   - it stops under the brake;
//   - it turns (left) when steered left, the front wheels at the commanded
//     angle;
//   - over the scripted ride (flat and height field) the rider stays on, every
//     joint's error under 1 cm, and nothing becomes NaN.
// Each test prints its figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "quadbike.h"

namespace {

constexpr double kG = 20;         // the guide's gravity (m/s^2)
constexpr double kKp = 50000;     // suspension stiffness (N/m), PASTE_08
constexpr double kChassis = 150;  // kg, PASTE_06
constexpr double kWheel = 10;     // kg, PASTE_07
constexpr double kWheelI = 0.25;  // kg m^2, PASTE_07
constexpr double kLimb = 1;       // MdtBodyCreate's default mass (handlebars, limbs)

class QuadBike : public ::testing::Test {
 protected:
  void Create(int useTriList, int ride) {
    QuadBikeOptions o;
    o.useTriList = useTriList;
    o.ride = ride;
    ASSERT_TRUE(QuadBikeCreate(&o));
    ASSERT_NE(quadBike.chassisBody, nullptr);
  }
  void TearDown() override { QuadBikeDestroy(); }

  static void Inputs(MeReal throttle, MeReal brake, MeReal steering) {
    quadBike.throttleInput = throttle;
    quadBike.brakeInput = brake;
    quadBike.steeringInput = steering;
  }
  static void Run(double seconds) {
    const long n = std::lround(seconds / (double)timeStep);
    for (long i = 0; i < n; ++i) tick();
  }
  static void Position(MdtBodyID b, double p[3]) {
    MeVector3 v;
    MdtBodyGetPosition(b, v);
    for (int k = 0; k < 3; ++k) p[k] = (double)v[k];
  }
  static double Speed() {
    MeVector3 v;
    MdtBodyGetLinearVelocity(quadBike.chassisBody, v);
    return (double)MeVector3Magnitude(v);
  }
  // Forward speed: along the chassis's x axis.
  static double ForwardSpeed() {
    MeVector3 v;
    MdtBodyGetLinearVelocity(quadBike.chassisBody, v);
    const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
    return (double)(tm[0] * v[0] + tm[1] * v[1] + tm[2] * v[2]);
  }
  // Heading: the angle of the chassis's x axis about +y from +x (positive:
  // turned towards -z, the bike's left).
  static double Heading() {
    const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
    return std::atan2(-(double)tm[2], (double)tm[0]);
  }
  // The sprung weight the four springs carry: everything but the wheels.
  static double SprungWeight() { return (kChassis + kLimb /* handlebars */ + int(NUM_LIMBS) * kLimb) * kG; }
};

TEST_F(QuadBike, RestsOnItsFourWheelsAtThePredictedRideHeight) {
  Create(0, 0);
  Run(2);
  // Each spring carries a quarter of the sprung weight (mean over the four:
  // exact whatever the rider's fore-aft balance), so its compression is
  // W / (4 Kp), and the chassis sits that much lower than where the wheel
  // joints were set, with the wheels on the ground (centres at r).
  const double sag = SprungWeight() / (4 * kKp);
  const double r = (double)quadBikeData.wheelRadius;
  const double predictedY = r - (double)quadBikeData.wheelOffset[0][1] - sag;
  double meanHeight = 0, chassis[3];
  for (int i = 0; i < 4; ++i) {
    double w[3];
    Position(quadBike.wheelBody[i], w);
    const double h = (double)MdtCarWheelGetSuspensionHeight(quadBike.wheelJoint[i]);
    meanHeight += h / 4;
    std::printf("wheel %d: centre y %.5f m (radius %.3f), suspension height %.5f m\n", i, w[1], r, h);
    EXPECT_NEAR(w[1], r, 0.002) << "wheel " << i << " rests on the ground";
    EXPECT_GT(h, 0.0) << "wheel " << i << " carries load";
  }
  Position(quadBike.chassisBody, chassis);
  std::printf("sprung weight %.1f N: predicted spring compression %.5f m, mean %.5f m\n", SprungWeight(), sag,
              meanHeight);
  std::printf("chassis ride height: predicted %.5f m, measured %.5f m, speed %.2e m/s\n", predictedY, chassis[1],
              Speed());
  EXPECT_NEAR(meanHeight, sag, 0.1 * sag);     // within 10 % (1.6 mm)
  EXPECT_NEAR(chassis[1], predictedY, 0.003);  // within 3 mm, contact give included
  EXPECT_LT(Speed(), 0.01);
}

TEST_F(QuadBike, MovesForwardUnderThrottle) {
  Create(0, 0);
  Run(1);
  double start[3], end[3];
  Position(quadBike.chassisBody, start);
  Inputs((MeReal)0.6, 0, 0);
  const double seconds = 2;
  Run(seconds);
  Position(quadBike.chassisBody, end);
  // Rear-wheel drive: 2 x 0.6 x 200 N m at radius r pushes the bike; the
  // whole mass plus the wheels' spin inertia (4 I / r^2) accelerates.
  const double r = (double)quadBikeData.wheelRadius;
  const double force = 2 * 0.6 * 200 / r;
  const double mass = kChassis + 4 * kWheel + kLimb + int(NUM_LIMBS) * kLimb + 4 * kWheelI / (r * r);
  const double predicted = force / mass * seconds;
  const double v = ForwardSpeed();
  std::printf(
      "throttle 0.6 for %.0f s: forward speed %.3f m/s (predicted %.3f), moved %.3f m in x, "
      "%.4f m in z\n",
      seconds, v, predicted, end[0] - start[0], end[2] - start[2]);
  EXPECT_NEAR(v, predicted, 0.05 * predicted);
  EXPECT_GT(end[0] - start[0], 0.4 * predicted * seconds);
  EXPECT_LT(std::fabs(end[2] - start[2]), 0.05);  // straight ahead
}

TEST_F(QuadBike, StopsUnderTheBrake) {
  Create(0, 0);
  Inputs((MeReal)0.6, 0, 0);
  Run(3);
  const double v0 = ForwardSpeed();
  double start[3], end[3];
  Position(quadBike.chassisBody, start);
  Inputs(0, 1, 0);
  int stepsToStop = -1;
  for (int i = 0; i < 120; ++i) {  // 2 s
    tick();
    if (stepsToStop < 0 && Speed() < 0.05) stepsToStop = i + 1;
  }
  Position(quadBike.chassisBody, end);
  std::printf("brake at %.2f m/s: below 0.05 m/s after %.2f s, %.2f m; speed after 2 s %.2e m/s\n", v0,
              stepsToStop * (double)timeStep, end[0] - start[0], Speed());
  EXPECT_GT(v0, 5);
  ASSERT_GT(stepsToStop, 0) << "the bike never stopped";
  EXPECT_LT(stepsToStop * (double)timeStep, 2.0);
  EXPECT_LT(Speed(), 0.01);
  for (int i = 0; i < 4; ++i)
    EXPECT_LT(std::fabs((double)MdtCarWheelGetHingeAngleRate(quadBike.wheelJoint[i])), 0.05) << "wheel " << i;
}

// Heading change from a to b, in (-pi, pi].
double Turn(double a, double b) {
  double d = b - a;
  while (d > M_PI) d -= 2 * M_PI;
  while (d <= -M_PI) d += 2 * M_PI;
  return d;
}

// Drives straight at throttle 0.3 for 1 s (about 2.2 m/s), then steers
// `steering` for 1.5 s; returns the heading turned meanwhile and prints it.
double SteeredTurn(double steering, double *yawRate, double *kinematic, double *angleL, double *angleR) {
  QuadBikeOptions o;
  o.useTriList = 0;
  o.ride = 0;
  if (!QuadBikeCreate(&o)) return 0;
  quadBike.throttleInput = (MeReal)0.3;
  for (int i = 0; i < 60; ++i) tick();
  auto heading = [] {
    const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
    return std::atan2(-(double)tm[2], (double)tm[0]);
  };
  double h0 = heading(), turned = 0;
  quadBike.steeringInput = (MeReal)steering;
  for (int i = 0; i < 90; ++i) {
    tick();
    const double h = heading();
    turned += Turn(h0, h);
    h0 = h;
  }
  // The kinematic yaw rate of a bike rolling without slip: v tan(phi) / L
  // (L = 1.25 m, the wheelbase; phi the front wheels' mean steering angle).
  const double wheelbase = (double)(quadBikeData.wheelOffset[FRONT_LEFT][0] - quadBikeData.wheelOffset[BACK_LEFT][0]);
  MeVector3 v, w;
  MdtBodyGetLinearVelocity(quadBike.chassisBody, v);
  MdtBodyGetAngularVelocity(quadBike.chassisBody, w);
  // The wheels' turn relative to the chassis (positive: left): the joint
  // reports the chassis relative to the wheel (MdtCarWheel.h), hence the minus.
  *angleL = -(double)MdtCarWheelGetSteeringAngle(quadBike.wheelJoint[FRONT_LEFT]);
  *angleR = -(double)MdtCarWheelGetSteeringAngle(quadBike.wheelJoint[FRONT_RIGHT]);
  *yawRate = (double)w[1];
  *kinematic = (double)MeVector3Magnitude(v) * std::tan((*angleL + *angleR) / 2) / wheelbase;
  std::printf(
      "steering %+.0f for 1.5 s, now at %.2f m/s: heading turned %+.3f rad; yaw rate %+.3f rad/s "
      "(rolling without slip: %+.3f); front wheels steered %+.3f and %+.3f rad (command %+.1f)\n",
      steering, (double)MeVector3Magnitude(v), turned, *yawRate, *kinematic, *angleL, *angleR, 0.5 * steering);
  QuadBikeDestroy();
  return turned;
}

TEST(QuadBikeSteering, TurnsLeftWhenSteeredLeftAndRightWhenSteeredRight) {
  double yaw, kinematic, angleL, angleR;
  // Left (steering +1: the front wheels turn 0.5 rad about +y).
  double turned = SteeredTurn(1, &yaw, &kinematic, &angleL, &angleR);
  EXPECT_GT(turned, 0.5);
  EXPECT_GT(yaw, 0.5 * kinematic);  // the tyres slip sideways, so less than kinematic
  EXPECT_LE(yaw, 1.05 * kinematic);
  // The limited-force steering motors (500 N m) give a little under load.
  EXPECT_NEAR(angleL, 0.5, 0.08);
  EXPECT_NEAR(angleR, 0.5, 0.08);
  // Right: the mirror image.
  turned = SteeredTurn(-1, &yaw, &kinematic, &angleL, &angleR);
  EXPECT_LT(turned, -0.5);
  EXPECT_LT(yaw, 0.5 * kinematic);
  EXPECT_GE(yaw, 1.05 * kinematic);
  EXPECT_NEAR(angleL, -0.5, 0.08);
  EXPECT_NEAR(angleR, -0.5, 0.08);
}

void RideKeepsTheRiderOn(int useTriList) {
  QuadBikeOptions o;
  o.useTriList = useTriList;
  o.ride = 1;
  ASSERT_TRUE(QuadBikeCreate(&o));
  double worst = 0, worstAt = 0, minHead = 1e9;
  MdtBodyID bodies[14];
  const int n = QuadBikeBodies(bodies);
  ASSERT_EQ(n, 14);
  bool finite = true;
  for (int i = 0; i < 420; ++i) {  // 7 s: the whole ride, and 2.5 s braked
    tick();
    const double e = (double)QuadBikeRiderJointError();
    if (e > worst) worst = e, worstAt = (double)QuadBikeTime();
    // The head stays above the chassis, in the chassis's up direction.
    MeVector3 head, chassis, d;
    MdtBodyGetPosition(rider.limbBody[HEAD], head);
    MdtBodyGetPosition(quadBike.chassisBody, chassis);
    MeVector3Subtract(d, head, chassis);
    const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
    const double up = (double)(d[0] * tm[4] + d[1] * tm[5] + d[2] * tm[6]);
    if (up < minHead) minHead = up;
    for (int b = 0; b < n; ++b) {
      MeVector3 p;
      MdtBodyGetPosition(bodies[b], p);
      finite = finite && std::isfinite((double)p[0]) && std::isfinite((double)p[1]) && std::isfinite((double)p[2]);
    }
  }
  MeVector3 p;
  MdtBodyGetPosition(quadBike.chassisBody, p);
  const MeReal *tm = (const MeReal *)MdtBodyGetTransformPtr(quadBike.chassisBody);
  MeVector3 v;
  MdtBodyGetLinearVelocity(quadBike.chassisBody, v);
  std::printf(
      "%s ride, 7 s: largest joint error %.5f m (at %.2f s); head at least %.3f m above the "
      "chassis; bike ends at (%.2f, %.2f, %.2f), up axis y %.3f, speed %.2e m/s\n",
      useTriList ? "height field" : "flat", worst, worstAt, minHead, (double)p[0], (double)p[1], (double)p[2],
      (double)tm[5], (double)MeVector3Magnitude(v));
  // On the flat the brakes hold the bike. On a slope it creeps: the wheel
  // contacts' friction is the guide's slip model (PASTE_02: force = slip
  // velocity / slip), which yields in proportion to the load.
  if (!useTriList) {
    EXPECT_LT(MeVector3Magnitude(v), (MeReal)0.05) << "the brake holds the bike";
  }
  EXPECT_TRUE(finite);
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(minHead, 0.8);
  EXPECT_GT(tm[5], (MeReal)0.8) << "the bike stays upright";
  QuadBikeDestroy();
}

TEST(QuadBikeRide, RiderStaysOnOverTheScriptedRideOnFlatGround) { RideKeepsTheRiderOn(0); }
TEST(QuadBikeRide, RiderStaysOnOverTheScriptedRideOnTheHeightField) { RideKeepsTheRiderOn(1); }

}  // namespace
