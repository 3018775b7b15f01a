// anchor_scene.cpp: Karma's builder of an anchor scene from its
// description: the universe, materials, ground, bodies, pairs that never
// collide, joints and drives; and the figures of a run.
#include "anchor_scene.h"

#include <algorithm>
#include <cmath>

namespace karma::scenes {

namespace {

bool SameShape(const ShapeSpec &a, const ShapeSpec &b) {
  return a.kind == b.kind && a.a == b.a && a.b == b.b && a.c == b.c;
}

}  // namespace

AnchorScene::AnchorScene(SceneSpec spec) : spec_(std::move(spec)), monitor_(spec_) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  sizes.dynamicBodiesMaxCount = spec_.capacity.bodies;
  sizes.collisionModelsMaxCount = spec_.capacity.models;
  sizes.collisionPairsMaxCount = spec_.capacity.pairs;
  sizes.dynamicConstraintsMaxCount = spec_.capacity.constraints;
  sizes.materialsMaxCount = 8;
  universe_ = MstUniverseCreate(&sizes);
  MdtWorldID w = world();
  MdtWorldSetGravity(w, 0, -(MeReal)kGravity, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  createMaterials();
  createGround();
  std::vector<std::pair<ShapeSpec, McdGeometryID>> geometries;  // identical shapes share one
  for (const BodySpec &b : spec_.bodies) {
    auto same =
        std::find_if(geometries.begin(), geometries.end(), [&](const auto &g) { return SameShape(g.first, b.shape); });
    McdGeometryID g = nullptr;
    if (same != geometries.end()) {
      g = same->second;
    } else {
      const ShapeSpec &s = b.shape;
      g = s.kind == ShapeKind::kBox      ? McdBoxCreate(framework(), (MeReal)s.a, (MeReal)s.b, (MeReal)s.c)
          : s.kind == ShapeKind::kSphere ? McdSphereCreate(framework(), (MeReal)s.a)
                                         : McdSphylCreate(framework(), (MeReal)s.a, (MeReal)s.b);
      geometries.push_back({s, g});
    }
    const MeReal density = (MeReal)b.mass / McdGeometryGetVolume(g);
    McdModelID model = MstModelAndBodyCreate(universe_, g, density);
    MdtBodyID body = McdModelGetBody(model);
    MdtBodySetPosition(body, (MeReal)b.position[0], (MeReal)b.position[1], (MeReal)b.position[2]);
    if (b.axes != kIdentityAxes) {
      MeMatrix3 R;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) R[i][j] = (MeReal)b.axes[i][j];
      MdtBodySetOrientation(body, R);
    }
    McdModelSetMaterial(model, materials_[(size_t)b.material]);
    bodies_.push_back(model);
  }
  for (const auto &[a, b] : spec_.disabledPairs) disablePair(bodies_[(size_t)a], bodies_[(size_t)b]);
  // The offset moves every body (and below, every anchor); a zero
  // component is left alone.
  const bool offset = spec_.offset != Vec3{0, 0, 0};
  for (McdModelID model : bodies_) {
    if (!offset) break;
    MdtBodyID b = McdModelGetBody(model);
    MeVector3 x;
    MdtBodyGetPosition(b, x);
    for (int i = 0; i < 3; ++i)
      if (spec_.offset[i] != 0) x[i] += (MeReal)spec_.offset[i];
    MdtBodySetPosition(b, x[0], x[1], x[2]);
  }
  for (const CarWheelSpec &wheel : spec_.carWheels) createCarWheel(wheel);
  for (const BallJointSpec &joint : spec_.ballJoints) createBallJoint(joint);
  states(states_);
  monitor_.start(states_);
}

AnchorScene::~AnchorScene() {
  if (universe_) MstUniverseDestroy(universe_);
}

MdtWorldID AnchorScene::world() const { return MstUniverseGetWorld(universe_); }
McdFrameworkID AnchorScene::framework() const { return MstUniverseGetFramework(universe_); }

void AnchorScene::createMaterials() {
  MstBridgeID bridge = MstUniverseGetBridge(universe_);
  mu_.assign(1, 0);  // the default material: frictionless unless a scene says otherwise
  for (double friction : spec_.friction) {
    const MeReal mu = (MeReal)friction;
    const MstMaterialID id = MstBridgeGetNewMaterial(bridge);
    if ((size_t)id >= mu_.size()) mu_.resize((size_t)id + 1, 0);
    mu_[(size_t)id] = mu;
    // Every pair with this material: Coulomb friction, the larger coefficient.
    for (size_t other = 0; other < mu_.size(); ++other) {
      MdtContactParamsID p = MstBridgeGetContactParams(bridge, id, (MstMaterialID)other);
      MdtContactParamsSetType(p, MdtContactTypeFriction2D);
      MdtContactParamsSetPrimaryFrictionModel(p, MdtFrictionModelNormalForce);
      MdtContactParamsSetSecondaryFrictionModel(p, MdtFrictionModelNormalForce);
      MdtContactParamsSetFrictionCoefficient(p, std::max(mu, mu_[other]));
      MdtContactParamsSetRestitution(p, 0);
    }
    materials_.push_back(id);
  }
}

void AnchorScene::createGround() {
  // McdPlane's normal is its local z: turn z onto world y.
  const MeMatrix4 tm = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MeMatrix4Copy(groundTM_, tm);
  McdModelID plane = MstFixedModelCreate(universe_, McdPlaneCreate(framework()), groundTM_);
  McdModelSetMaterial(plane, materials_[(size_t)spec_.groundMaterial]);
}

void AnchorScene::createCarWheel(const CarWheelSpec &w) {
  MeVector3 at;
  for (int i = 0; i < 3; ++i)
    at[i] = spec_.offset[i] != 0 ? (MeReal)w.anchor[i] + (MeReal)spec_.offset[i] : (MeReal)w.anchor[i];
  MdtCarWheelID joint = MdtCarWheelCreate(world());
  MdtCarWheelSetBodies(joint, body(w.chassis), body(w.wheel));
  MdtCarWheelSetPosition(joint, at[0], at[1], at[2]);
  MdtCarWheelSetSteeringAndHingeAxes(joint, (MeReal)w.steeringAxis[0], (MeReal)w.steeringAxis[1],
                                     (MeReal)w.steeringAxis[2], (MeReal)w.hingeAxis[0], (MeReal)w.hingeAxis[1],
                                     (MeReal)w.hingeAxis[2]);
  MdtCarWheelSetSteeringLock(joint, 1);
  MdtCarWheelSetSuspension(joint, (MeReal)w.spring, (MeReal)w.damping, 0, (MeReal)w.lowLimit, (MeReal)w.highLimit, 0);
  MdtCarWheelEnable(joint);
  carWheels_.push_back(joint);
}

void AnchorScene::createBallJoint(const BallJointSpec &j) {
  MeVector3 at;
  for (int i = 0; i < 3; ++i)
    at[i] = spec_.offset[i] != 0 ? (MeReal)j.anchor[i] + (MeReal)spec_.offset[i] : (MeReal)j.anchor[i];
  MdtBSJointID joint = MdtBSJointCreate(world());
  MdtBSJointSetBodies(joint, body(j.body0), body(j.body1));
  MdtBSJointSetPosition(joint, at[0], at[1], at[2]);
  MdtBSJointEnable(joint);
}

void AnchorScene::disablePair(McdModelID a, McdModelID b) {
  McdSpaceID space = MstUniverseGetSpace(universe_);
  const bool open = McdSpaceIsChanging(space) == 0;
  if (open) McdSpaceBeginChanges(space);
  McdSpaceDisablePair(a, b);
  if (open) McdSpaceEndChanges(space);
}

void AnchorScene::advance() {
  // A drive's torque about the wheel's current hinge axis; the chassis
  // takes the reaction.
  for (const DriveSpec &d : spec_.drives) {
    const CarWheelSpec &w = spec_.carWheels[(size_t)d.joint];
    MeVector3 axis;
    MdtCarWheelGetHingeAxis(carWheels_[(size_t)d.joint], axis);
    const MeReal t = (MeReal)d.torque;
    MdtBodyAddTorque(body(w.wheel), t * axis[0], t * axis[1], t * axis[2]);
    MdtBodyAddTorque(body(w.chassis), -t * axis[0], -t * axis[1], -t * axis[2]);
  }
  MstUniverseStep(universe_, kStep);
  ++done_;
}

void AnchorScene::step() {
  advance();
  states(states_);
  monitor_.observe(states_);
}

void AnchorScene::states(std::vector<BodyState> &out) const {
  out.resize(bodies_.size());
  for (size_t i = 0; i < bodies_.size(); ++i) {
    MdtBodyID b = McdModelGetBody(bodies_[i]);
    MeMatrix4 tm;
    MeVector3 v, w;
    MdtBodyGetTransform(b, tm);
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    for (int k = 0; k < 3; ++k) {
      out[i].position[k] = tm[3][k];
      out[i].velocity[k] = v[k];
      out[i].angularVelocity[k] = w[k];
      for (int j = 0; j < 3; ++j) out[i].axes[k][j] = tm[k][j];  // rows: the body axes
    }
  }
}

double AnchorScene::kineticEnergy() const {
  double energy = 0;
  for (McdModelID m : bodies_) {
    MdtBodyID b = McdModelGetBody(m);
    MeVector3 v, w, wb;
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    MeMatrix4 tm;
    MdtBodyGetTransform(b, tm);
    for (int i = 0; i < 3; ++i) wb[i] = MeVector3Dot(tm[i], w);  // body frame (rows: axes)
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(b, I);
    double rotational = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rotational += (double)wb[i] * I[i][j] * wb[j];
    energy += 0.5 * MdtBodyGetMass(b) * MeVector3Dot(v, v) + 0.5 * rotational;
  }
  return energy;
}

SceneFigures AnchorScene::run() {
  while (done_ < spec_.steps) step();
  return finish();
}

SceneFigures AnchorScene::finish() {
  states(states_);
  return monitor_.finish(states_, done_, DeepestPenetration(bodies_));
}

double DeepestPenetration(const std::vector<McdModelID> &models) {
  double deepest = 0;
  for (McdModelID m : models) {
    MdtBodyID b = McdModelGetBody(m);
    for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c))
      deepest = std::max(deepest, (double)MdtContactGetPenetration(c));
  }
  return deepest;
}

std::unique_ptr<AnchorScene> MakeCar() { return std::make_unique<AnchorScene>(CarSpec()); }
std::unique_ptr<AnchorScene> MakeTopple() { return std::make_unique<AnchorScene>(ToppleSpec()); }
std::unique_ptr<AnchorScene> MakeStack21() { return std::make_unique<AnchorScene>(Stack21Spec()); }
std::unique_ptr<AnchorScene> MakeRagdoll() { return std::make_unique<AnchorScene>(RagdollSpec()); }
std::unique_ptr<AnchorScene> MakePile1000() { return std::make_unique<AnchorScene>(Pile1000Spec()); }
std::unique_ptr<AnchorScene> MakePile10k() { return std::make_unique<AnchorScene>(Pile10kSpec()); }

}  // namespace karma::scenes
