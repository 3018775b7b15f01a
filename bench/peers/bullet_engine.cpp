// bullet_engine.cpp: an anchor scene in Bullet 3.24 (Debian libbullet-dev,
// single precision): a btDiscreteDynamicsWorld with the default collision
// configuration, a dynamic AABB tree broad phase and the default
// sequential-impulse solver (10 iterations, split impulse as configured by
// default), one internal step of 1/60 s per step.
//
// The mapping of the description:
// - mass and the principal inertia from UniformInertia (Bullet's own
//   capsule inertia is a box approximation), no damping, sleeping off
//   (SetPeersSleep: Bullet's default deactivation);
// - btBoxShape, btSphereShape, btCapsuleShapeZ (cylinder length as in the
//   description) with Bullet's default collision margins; the ground a
//   static box whose top face is y = 0 (kGroundHalfWidth);
// - friction: each body carries its material's coefficient and the pair
//   combines them by the larger one (gCalculateCombinedFrictionCallback;
//   Bullet's default is the product), restitution 0;
// - a car wheel: btHinge2Constraint (a btGeneric6DofSpring2Constraint):
//   the spring along the steering axis with k and c given as they are
//   (Bullet's automatic stiffness limiting off), equilibrium at the
//   initial pose, travel bounded to [lowLimit, highLimit], steering
//   locked by angular limits at 0;
// - a ball joint: btPoint2PointConstraint at the anchor;
// - pairs that must not collide: a broad-phase filter.
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>

#include "peer_engine.h"

namespace karma::peers {

namespace {

using scenes::ShapeKind;
using scenes::Vec3;

// The ground: a static box whose top face is the plane y = 0, wide enough
// for every scene (the car travels about 41 m along x). Bullet's
// btStaticPlaneShape lets the bottom boxes of pile1000 sink through it
// under the landing pile (one contact point per box and step).
constexpr btScalar kGroundHalfWidth = 60;

btScalar LargerFriction(const btCollisionObject *a, const btCollisionObject *b) {
  return std::max(a->getFriction(), b->getFriction());
}

btVector3 ToBullet(const Vec3 &v) { return btVector3((btScalar)v[0], (btScalar)v[1], (btScalar)v[2]); }

std::uint64_t Key(int a, int b) {
  return ((std::uint64_t)(std::uint32_t)std::min(a, b) << 32) | (std::uint32_t)std::max(a, b);
}

// Rejects the description's disabled pairs (bodies carry their index as
// the user index, the ground -1).
class PairFilter final : public btOverlapFilterCallback {
 public:
  explicit PairFilter(const SceneSpec &spec) {
    for (const auto &[a, b] : spec.disabledPairs) disabled_.insert(Key(a, b));
  }
  bool needBroadphaseCollision(btBroadphaseProxy *p0, btBroadphaseProxy *p1) const override {
    const int a = static_cast<btCollisionObject *>(p0->m_clientObject)->getUserIndex();
    const int b = static_cast<btCollisionObject *>(p1->m_clientObject)->getUserIndex();
    return a < 0 || b < 0 || disabled_.count(Key(a, b)) == 0;
  }

 private:
  std::unordered_set<std::uint64_t> disabled_;
};

class BulletEngine final : public PeerEngine {
 public:
  explicit BulletEngine(const SceneSpec &spec)
      : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase_, &solver_, &configuration_), filter_(spec) {
    gCalculateCombinedFrictionCallback = &LargerFriction;
    world_.setGravity(btVector3(0, (btScalar)-scenes::kGravity, 0));
    world_.getPairCache()->setOverlapFilterCallback(&filter_);
    addGround(spec.friction[(size_t)spec.groundMaterial]);
    for (const scenes::BodySpec &b : spec.bodies) addBody(spec, b);
    for (const scenes::CarWheelSpec &w : spec.carWheels) addCarWheel(spec, w);
    for (const scenes::BallJointSpec &j : spec.ballJoints) addBall(spec, j);
    drives_ = spec.drives;
  }
  ~BulletEngine() override {
    for (auto &c : constraints_) world_.removeConstraint(c.get());
    for (auto &b : bodies_) world_.removeRigidBody(b.get());
    world_.removeRigidBody(ground_.get());
  }

  void step() override {
    applyDrives();
    world_.stepSimulation((btScalar)scenes::kStepSeconds, 0);  // 0: one step of exactly h
  }

  void states(std::vector<BodyState> &out) const override {
    out.resize(bodies_.size());
    for (size_t i = 0; i < bodies_.size(); ++i) {
      const btRigidBody &b = *bodies_[i];
      const btVector3 &x = b.getCenterOfMassPosition(), &v = b.getLinearVelocity(), &w = b.getAngularVelocity();
      const btMatrix3x3 &R = b.getWorldTransform().getBasis();
      for (int k = 0; k < 3; ++k) {
        out[i].position[k] = x[k];
        out[i].velocity[k] = v[k];
        out[i].angularVelocity[k] = w[k];
        for (int j = 0; j < 3; ++j) out[i].axes[k][j] = R[j][k];  // R's columns
      }
    }
  }

  double penetration() override {
    world_.performDiscreteCollisionDetection();  // contact points of the current poses
    double deepest = 0;
    for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
      const btPersistentManifold *manifold = dispatcher_.getManifoldByIndexInternal(m);
      for (int p = 0; p < manifold->getNumContacts(); ++p)
        deepest = std::max(deepest, -(double)manifold->getContactPoint(p).getDistance());
    }
    return deepest;
  }

 private:
  void addGround(double mu) {
    shapes_.push_back(std::make_unique<btBoxShape>(btVector3(kGroundHalfWidth, 1, kGroundHalfWidth)));
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shapes_.back().get());
    info.m_startWorldTransform.setOrigin(btVector3(0, -1, 0));  // top face at y = 0
    info.m_friction = (btScalar)mu;
    info.m_restitution = 0;
    ground_ = std::make_unique<btRigidBody>(info);
    ground_->setUserIndex(-1);
    world_.addRigidBody(ground_.get());
  }

  void addBody(const SceneSpec &spec, const scenes::BodySpec &b) {
    switch (b.shape.kind) {
      case ShapeKind::kBox:
        shapes_.push_back(std::make_unique<btBoxShape>(
            btVector3((btScalar)b.shape.a / 2, (btScalar)b.shape.b / 2, (btScalar)b.shape.c / 2)));
        break;
      case ShapeKind::kSphere:
        shapes_.push_back(std::make_unique<btSphereShape>((btScalar)b.shape.a));
        break;
      case ShapeKind::kCapsule:
        shapes_.push_back(std::make_unique<btCapsuleShapeZ>((btScalar)b.shape.a, (btScalar)b.shape.b));
        break;
    }
    const Vec3 I = scenes::UniformInertia(b.shape, b.mass);
    btRigidBody::btRigidBodyConstructionInfo info((btScalar)b.mass, nullptr, shapes_.back().get(), ToBullet(I));
    info.m_friction = (btScalar)spec.friction[(size_t)b.material];
    info.m_restitution = 0;
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    Vec3 p = b.position;
    for (int i = 0; i < 3; ++i) p[i] += spec.offset[i];
    btMatrix3x3 basis;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) basis[i][j] = (btScalar)b.axes[j][i];  // columns: the body axes
    info.m_startWorldTransform = btTransform(basis, ToBullet(p));
    auto body = std::make_unique<btRigidBody>(info);
    if (!PeersSleep()) body->setActivationState(DISABLE_DEACTIVATION);
    body->setUserIndex((int)bodies_.size());
    world_.addRigidBody(body.get());
    bodies_.push_back(std::move(body));
  }

  void addCarWheel(const SceneSpec &spec, const scenes::CarWheelSpec &w) {
    Vec3 at = w.anchor;
    for (int i = 0; i < 3; ++i) at[i] += spec.offset[i];
    btVector3 anchor = ToBullet(at), axis1 = ToBullet(w.steeringAxis), axis2 = ToBullet(w.hingeAxis);
    btRigidBody &chassis = *bodies_[(size_t)w.chassis], &wheel = *bodies_[(size_t)w.wheel];
    auto joint = std::make_unique<btHinge2Constraint>(chassis, wheel, anchor, axis1, axis2);
    // Frame axes: z the steering axis (suspension travel), x the hinge.
    joint->setLinearLowerLimit(btVector3(0, 0, (btScalar)w.lowLimit));
    joint->setLinearUpperLimit(btVector3(0, 0, (btScalar)w.highLimit));
    joint->setLowerLimit(0);  // steering angle locked
    joint->setUpperLimit(0);
    joint->setStiffness(2, (btScalar)w.spring, false);
    joint->setDamping(2, (btScalar)w.damping, false);
    // The hinge axis in the wheel's frame, to drive it about its current
    // direction.
    hingeInWheel_.push_back(wheel.getWorldTransform().getBasis().transpose() * axis2);
    driven_.push_back({&chassis, &wheel});
    world_.addConstraint(joint.get(), true);
    constraints_.push_back(std::move(joint));
  }

  void addBall(const SceneSpec &spec, const scenes::BallJointSpec &j) {
    Vec3 at = j.anchor;
    for (int i = 0; i < 3; ++i) at[i] += spec.offset[i];
    btRigidBody &a = *bodies_[(size_t)j.body0], &b = *bodies_[(size_t)j.body1];
    const btVector3 anchor = ToBullet(at);
    auto joint = std::make_unique<btPoint2PointConstraint>(a, b, a.getWorldTransform().inverse() * anchor,
                                                           b.getWorldTransform().inverse() * anchor);
    world_.addConstraint(joint.get(), true);
    constraints_.push_back(std::move(joint));
  }

  void applyDrives() {
    for (const scenes::DriveSpec &d : drives_) {
      const auto [chassis, wheel] = driven_[(size_t)d.joint];
      const btVector3 axis = wheel->getWorldTransform().getBasis() * hingeInWheel_[(size_t)d.joint];
      const btVector3 torque = (btScalar)d.torque * axis;
      wheel->applyTorque(torque);
      chassis->applyTorque(-torque);
    }
  }

  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  PairFilter filter_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btRigidBody> ground_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> constraints_;
  std::vector<btVector3> hingeInWheel_;
  std::vector<std::pair<btRigidBody *, btRigidBody *>> driven_;  // per car wheel
  std::vector<scenes::DriveSpec> drives_;
};

}  // namespace

std::unique_ptr<PeerEngine> MakeBullet(const SceneSpec &spec) { return std::make_unique<BulletEngine>(spec); }

}  // namespace karma::peers
