// car_scene.cpp: SCENES.md's "car": a 150 kg chassis on four 10 kg sphere
// wheels joined by CarWheel joints, rear wheels driven by 100 N m each.
//
// Rolling without slip, the car accelerates at
//   a = (2T/r) / (M + 4 I_w / r^2),  I_w = 2/5 m_w r^2,
// = (200/0.3) / (190 + 16) = 3.236 m/s^2: v(5 s) = 16.18 m/s, x(5 s) = 40.45 m.
// The static sag is the load per wheel over k: (150 g / 4) / 20000 = 18.4 mm.
#include <cmath>
#include <cstdio>

#include "anchor_scene.h"

namespace karma::scenes {

namespace {

constexpr MeReal kTorque = 100;
constexpr double kAccel = (2 * 100 / 0.3) / (190 + 4 * (0.4 * 10 * 0.09) / 0.09);

class CarScene final : public AnchorScene {
 public:
  CarScene() : AnchorScene("car", 300, 8, 8, 32, 64) {
    ground(material((MeReal)0.4));  // the wheels' 1.0 is the larger, so it applies
    const MstMaterialID chassisMat = material((MeReal)0.4), wheelMat = material(1);
    const MeVector3 at = {0, (MeReal)0.6, 0};
    chassis_ = body(McdBoxCreate(framework(), (MeReal)1.6, (MeReal)0.4, (MeReal)0.8), 150, at,
                    chassisMat);
    McdGeometryID ball = McdSphereCreate(framework(), (MeReal)0.3);
    for (int i = 0; i < 4; ++i) {
      const MeReal x = (i & 1) ? (MeReal)0.6 : -(MeReal)0.6;
      const MeReal z = (i & 2) ? (MeReal)0.5 : -(MeReal)0.5;
      const MeVector3 p = {x, (MeReal)0.3, z};
      wheel_[i] = body(ball, 10, p, wheelMat);
      disablePair(chassis_, wheel_[i]);
      for (int j = 0; j < i; ++j) disablePair(wheel_[i], wheel_[j]);
      joint_[i] = MdtCarWheelCreate(world());
      MdtCarWheelSetBodies(joint_[i], McdModelGetBody(chassis_), McdModelGetBody(wheel_[i]));
      MdtCarWheelSetPosition(joint_[i], x, (MeReal)0.3, z);
      MdtCarWheelSetSteeringAndHingeAxes(joint_[i], 0, 1, 0, 0, 0, 1);
      MdtCarWheelSetSteeringLock(joint_[i], 1);
      MdtCarWheelSetSuspension(joint_[i], 20000, 500, 0, -(MeReal)0.2, (MeReal)0.2, 0);
      MdtCarWheelEnable(joint_[i]);
    }
  }

 private:
  void applyForces() override {
    MdtBodyID chassis = McdModelGetBody(chassis_);
    for (int i = 0; i < 4; ++i) {
      if ((i & 1) != 0) continue;  // rear wheels: x = -0.6
      MeVector3 axis;
      MdtCarWheelGetHingeAxis(joint_[i], axis);
      MdtBodyAddTorque(McdModelGetBody(wheel_[i]), -kTorque * axis[0], -kTorque * axis[1],
                       -kTorque * axis[2]);
      MdtBodyAddTorque(chassis, kTorque * axis[0], kTorque * axis[1], kTorque * axis[2]);
    }
  }

  void check(SceneFigures &f) override {
    MeVector3 x, v;
    MdtBodyGetPosition(McdModelGetBody(chassis_), x);
    MdtBodyGetLinearVelocity(McdModelGetBody(chassis_), v);
    f.carPosition = x[0];
    f.carVelocity = v[0];
    f.carRideHeight = x[1];
    const double t = f.steps * (double)kStep;
    const double vExpected = kAccel * t, xExpected = kAccel * t * t / 2;
    f.expectation = std::fabs(f.carVelocity - vExpected) < 0.05 * vExpected &&
                    std::fabs(f.carPosition - xExpected) < 0.05 * xExpected;
    char text[160];
    std::snprintf(text, sizeof text, "v %.3f m/s (analytic %.3f), x %.3f m (analytic %.3f)",
                  f.carVelocity, vExpected, f.carPosition, xExpected);
    f.detail = text;
  }

  McdModelID chassis_;
  McdModelID wheel_[4];
  MdtCarWheelID joint_[4];
};

}  // namespace

std::unique_ptr<AnchorScene> MakeCar() { return std::make_unique<CarScene>(); }

}  // namespace karma::scenes
