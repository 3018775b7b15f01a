// scene_spec.h: an engine-neutral description of an anchor scene of
// ../shared/bench/SCENES.md, as plain data in double precision. Karma's
// builder (anchor_scene.cpp) and the other engines' builders
// (bench/peers/) all read the same description, so every engine runs the
// same bodies, joints, materials and drives.
//
// Conventions: SI units, y up, gravity (0, -9.81, 0), steps of 1/60 s, a
// static ground plane y = 0, restitution 0, no damping, sleeping off, zero
// initial velocities. A body's frame is its centre of mass and its shape's
// centre; its inertia follows from its mass at uniform density
// (UniformInertia). Contact friction is Coulomb with the larger of the two
// materials' coefficients.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace karma::scenes {

using Vec3 = std::array<double, 3>;
// Rows are a body's x, y and z axes in world coordinates, so a body-frame
// vector b is R^T b in world and a world vector w is R w in the body frame.
using Axes = std::array<Vec3, 3>;

inline constexpr Axes kIdentityAxes = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
inline constexpr double kGravity = 9.81;  // m/s^2, along -y
inline constexpr double kStepSeconds = 1.0 / 60;

enum class ShapeKind { kBox, kSphere, kCapsule };

// box: full side lengths (x, y, z); sphere: radius; capsule: radius and
// the length of its cylinder (the segment between the two hemispheres'
// centres), along the body's z axis.
struct ShapeSpec {
  ShapeKind kind = ShapeKind::kBox;
  double a = 0, b = 0, c = 0;
};

struct BodySpec {
  ShapeSpec shape;
  double mass = 0;  // kg
  Vec3 position{};  // before the scene's offset
  Axes axes = kIdentityAxes;
  int material = 0;  // index into SceneSpec::friction
};

// A ball-and-socket joint at `anchor` (world, before the offset).
struct BallJointSpec {
  int body0 = 0, body1 = 0;
  Vec3 anchor{};
};

// A car-wheel joint at the wheel centre: the wheel slides along the
// steering/suspension axis (fixed in the chassis) against a spring-damper
// about its initial pose, and turns freely about the hinge axis (fixed in
// the wheel); steering is locked. Karma also bounds the travel to
// [lowLimit, highLimit] about the initial pose.
struct CarWheelSpec {
  int chassis = 0, wheel = 0;
  Vec3 anchor{};
  Vec3 steeringAxis{};
  Vec3 hingeAxis{};
  double spring = 0;   // N/m
  double damping = 0;  // N s/m
  double lowLimit = 0, highLimit = 0;
};

// Every step, before the step: the wheel of car-wheel joint `joint` gets
// `torque` N m about the joint's current hinge axis, the chassis the
// reaction.
struct DriveSpec {
  int joint = 0;
  double torque = 0;
};

// What a run must show (SCENES.md), checked by Evaluate (scene_figures.h).
enum class Expectation {
  kCarRolls,     // watched[0] = chassis: v and x along x within 5% of a t, a t^2/2
  kStacksStand,  // watched = the top boxes: drift and drop < 50 mm
  kTopStill,     // watched[0] = the top box: drift < 50 mm
  kJointsWhole,  // the ball joints' gap at the end < 20 mm
  kNothingLost,  // no centre below 0.2 m nor farther than 20 m from the middle
};

// Upper bounds for an engine that preallocates (Karma's universe).
struct SceneCapacity {
  int bodies = 0, models = 0, pairs = 0, constraints = 0;
};

struct SceneSpec {
  std::string name;
  int steps = 0;                 // the scene's run length, steps of 1/60 s
  std::vector<double> friction;  // per material, in creation order
  int groundMaterial = 0;
  std::vector<BodySpec> bodies;
  std::vector<BallJointSpec> ballJoints;
  std::vector<CarWheelSpec> carWheels;
  std::vector<std::pair<int, int>> disabledPairs;  // body pairs that never collide
  std::vector<DriveSpec> drives;
  Vec3 offset{};  // added to every body position and joint anchor
  Expectation expectation = Expectation::kNothingLost;
  std::vector<int> watched;
  double carAcceleration = 0;  // kCarRolls: the analytic acceleration, m/s^2
  SceneCapacity capacity;
};

SceneSpec CarSpec();
SceneSpec ToppleSpec();
SceneSpec Stack21Spec();
SceneSpec RagdollSpec();
SceneSpec Pile1000Spec();
// Not an anchor scene: 10,000 cubes in 100 columns (issue 14), for
// bench/peers' growth from pile1000.
SceneSpec Pile10kSpec();
// The five in SCENES.md's order.
std::vector<SceneSpec> AnchorSpecs();

// Volume of a shape, m^3.
double ShapeVolume(const ShapeSpec &s);
// Principal moments of inertia about the body axes at uniform density,
// kg m^2. Box: m (b^2 + c^2)/12 etc.; sphere: 2/5 m r^2; capsule of radius
// r and cylinder length h, with cylinder mass mc and hemispheres' mass ms
// in proportion to their volumes:
//   Izz = mc r^2/2 + ms 2r^2/5,
//   Ixx = Iyy = mc (h^2/12 + r^2/4) + ms (2r^2/5 + h^2/4 + 3hr/8).
Vec3 UniformInertia(const ShapeSpec &s, double mass);
// The lowest y of a shape at `position` with `axes`.
double LowestPoint(const ShapeSpec &s, const Vec3 &position, const Axes &axes);
// The body axes (rows: each axis in world coordinates, y up) of the rotation
// Ry(yaw) Rx(a) Rz(b): the pile's boxes and the tests that rebuild them.
Axes TiltAxes(double yaw, double a, double b);

}  // namespace karma::scenes
