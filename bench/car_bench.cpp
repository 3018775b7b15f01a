// car_bench.cpp: MdtWorldStep time for the guide's car: a chassis, four
// CarWheel joints and four hand-made wheel contacts with flat ground (no
// collision library), driving under a hinge motor at 60 Hz.
//
// The contacts are what a collision pass would hand over: each step, every
// wheel's contact is moved to the lowest point of the wheel sphere with the
// ground (y = 0), with the sphere's penetration, and the wheel's fast spin
// axis is set to its hinge axis (as the CarTerrain tutorial does).
#include <benchmark/benchmark.h>

#include "Mdt.h"

namespace {

constexpr MeReal kWheelRadius = (MeReal)0.3;
constexpr MeReal kStep = (MeReal)1 / 60;

struct Car {
  MdtWorldID world;
  MdtBodyID chassis;
  MdtBodyID wheel[4];
  MdtCarWheelID joint[4];
  MdtContactID contact[4];

  Car() {
    world = MdtWorldCreate(8, 16, 1, 1);
    MdtWorldSetGravity(world, 0, -(MeReal)9.81, 0);
    MdtWorldSetAutoDisable(world, FALSE);
    chassis = MdtBodyCreate(world);
    MdtBodySetMass(chassis, 200);
    MdtBodySetPosition(chassis, 0, (MeReal)0.8, 0);
    MdtBodyEnable(chassis);
    for (int i = 0; i < 4; ++i) {
      const MeReal x = (i & 1) ? (MeReal)1.2 : -(MeReal)1.2;
      const MeReal z = (i & 2) ? (MeReal)0.7 : -(MeReal)0.7;
      wheel[i] = MdtBodyCreate(world);
      MdtBodySetMass(wheel[i], 10);
      MdtBodySetPosition(wheel[i], x, kWheelRadius, z);
      MdtBodyEnable(wheel[i]);
      joint[i] = MdtCarWheelCreate(world);
      MdtCarWheelSetBodies(joint[i], chassis, wheel[i]);  // chassis first
      MdtCarWheelSetPosition(joint[i], x, kWheelRadius, z);
      MdtCarWheelSetSteeringAndHingeAxes(joint[i], 0, 1, 0, 0, 0, 1);
      if (x < 0) MdtCarWheelSetSteeringLock(joint[i], 1);
      MdtCarWheelSetSuspension(joint[i], 50000, (MeReal)0.4, (MeReal)0.001, -(MeReal)0.15, (MeReal)0.15, 0);
      MdtCarWheelSetHingeLimitedForceMotor(joint[i], -10, 200);
      MdtCarWheelEnable(joint[i]);
      contact[i] = MdtContactCreate(world);
      MdtContactSetBodies(contact[i], wheel[i], nullptr);
      MdtContactSetNormal(contact[i], 0, 1, 0);
      MdtContactParamsID params = MdtContactGetParams(contact[i]);
      MdtContactParamsSetType(params, MdtContactTypeFriction2D);
      MdtContactParamsSetFriction(params, 2000);
      MdtContactEnable(contact[i]);
    }
  }
  ~Car() { MdtWorldDestroy(world); }
  Car(const Car &) = delete;
  Car &operator=(const Car &) = delete;

  // What a collision pass and the tutorial's per-step code would do.
  void updateContacts() {
    for (int i = 0; i < 4; ++i) {
      MeVector3 x, axis;
      MdtBodyGetPosition(wheel[i], x);
      MdtContactSetPosition(contact[i], x[0], 0, x[2]);
      MdtContactSetPenetration(contact[i], kWheelRadius - x[1]);
      MdtCarWheelGetHingeAxis(joint[i], axis);
      MdtBodySetFastSpinAxis(wheel[i], axis[0], axis[1], axis[2]);
    }
  }

  void step() {
    updateContacts();
    MdtWorldStep(world, kStep);
  }
};

void BM_CarOnFourHandMadeContacts(benchmark::State &state) {
  Car car;
  for (int i = 0; i < 120; ++i) car.step();  // settle on the suspension, start rolling
  for (auto _ : state) car.step();
  MeVector3 x;
  MdtBodyGetPosition(car.chassis, x);
  // The car must still be driving upright on its wheels for the figure to
  // mean anything: report how far it went, its height and its up vector's y.
  MeMatrix4Ptr tm = MdtBodyGetTransformPtr(car.chassis);
  state.counters["chassis_x"] = (double)x[0];
  state.counters["chassis_y"] = (double)x[1];
  state.counters["up_y"] = (double)tm[1][1];
}
BENCHMARK(BM_CarOnFourHandMadeContacts)->Unit(benchmark::kMicrosecond);

}  // namespace
