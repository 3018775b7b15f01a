// ode_engine.cpp: an anchor scene in ODE 0.16 (Debian libode-dev, double
// precision), stepped by dWorldStep (the exact "big matrix" LCP) or
// dWorldQuickStep with 20 iterations (projected SOR).
//
// The mapping of the description:
// - mass and the principal inertia from UniformInertia (the same formulas
//   as Karma's geometries), set with dMassSetParameters;
// - boxes, spheres, capsules (ODE's capsule lies along its local z, its
//   length the cylinder's, as in the description); the ground a dPlane;
// - contacts: Coulomb friction with mu = the larger material coefficient,
//   the friction pyramid scaled by the normal force (dContactApprox1), no
//   bounce, the world's default ERP 0.2 and CFM 1e-5; up to 8 contacts per
//   pair (as Karma's box-box test) unless SetOdeMaxContacts says fewer; a
//   hash space for broad phase;
// - auto-disable off (SetPeersSleep: on, at ODE's default thresholds);
// - a car wheel: a hinge2 joint, axis 1 the steering axis on the chassis
//   locked by stops at 0, axis 2 the wheel's hinge; the suspension
//   spring k and damper c through ODE's soft constraint,
//     ERP = h k / (h k + c),  CFM = 1 / (h k + c)
//   (ODE user guide, "Soft constraint and constraint force mixing");
//   hinge2 has no suspension travel limits;
// - a ball joint: dJointCreateBall at the anchor.
#include <ode/ode.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>

#include "peer_engine.h"

namespace karma::peers {

namespace {

using scenes::ShapeKind;
using scenes::Vec3;

// Contacts per colliding pair: up to kMaxContacts, SetOdeMaxContacts()
// picks fewer (dBoxBox culls a face-face contact to that many points).
constexpr int kMaxContacts = 8;
int maxContacts = kMaxContacts;
constexpr int kQuickStepIterations = 20;

void InitOde() {
  static const bool done = [] {
    dInitODE2(0);
    return true;
  }();
  (void)done;
}

class OdeEngine final : public PeerEngine {
 public:
  OdeEngine(const SceneSpec &spec, bool quick) : quick_(quick) {
    InitOde();
    world_ = dWorldCreate();
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    dWorldSetGravity(world_, 0, -scenes::kGravity, 0);
    dWorldSetAutoDisableFlag(world_, PeersSleep() ? 1 : 0);  // ODE's default thresholds
    if (quick_) dWorldSetQuickStepNumIterations(world_, kQuickStepIterations);
    groundMu_ = spec.friction[(size_t)spec.groundMaterial];
    dGeomSetData(dCreatePlane(space_, 0, 1, 0, 0), nullptr);
    for (const scenes::BodySpec &b : spec.bodies) addBody(spec, b);
    for (const auto &[a, b] : spec.disabledPairs) disabled_.insert(Key(a, b));
    for (const scenes::CarWheelSpec &w : spec.carWheels) addCarWheel(spec, w);
    for (const scenes::BallJointSpec &j : spec.ballJoints) {
      dJointID joint = dJointCreateBall(world_, nullptr);
      dJointAttach(joint, bodies_[(size_t)j.body0], bodies_[(size_t)j.body1]);
      dJointSetBallAnchor(joint, j.anchor[0] + spec.offset[0], j.anchor[1] + spec.offset[1],
                          j.anchor[2] + spec.offset[2]);
    }
    drives_ = spec.drives;
    for (const scenes::CarWheelSpec &w : spec.carWheels)
      driven_.push_back({bodies_[(size_t)w.chassis], bodies_[(size_t)w.wheel]});
  }
  ~OdeEngine() override {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
  }

  void step() override {
    applyDrives();
    dSpaceCollide(space_, this, &OdeEngine::Contacts);
    if (quick_)
      dWorldQuickStep(world_, scenes::kStepSeconds);
    else
      dWorldStep(world_, scenes::kStepSeconds);
    dJointGroupEmpty(contacts_);
  }

  void states(std::vector<BodyState> &out) const override {
    out.resize(bodies_.size());
    for (size_t i = 0; i < bodies_.size(); ++i) {
      const dReal *x = dBodyGetPosition(bodies_[i]), *R = dBodyGetRotation(bodies_[i]);
      const dReal *v = dBodyGetLinearVel(bodies_[i]), *w = dBodyGetAngularVel(bodies_[i]);
      for (int k = 0; k < 3; ++k) {
        out[i].position[k] = x[k];
        out[i].velocity[k] = v[k];
        out[i].angularVelocity[k] = w[k];
        for (int j = 0; j < 3; ++j) out[i].axes[k][j] = R[j * 4 + k];  // R's columns
      }
    }
  }

  double penetration() override {
    deepest_ = 0;
    dSpaceCollide(space_, this, &OdeEngine::Depths);
    return deepest_;
  }

 private:
  static std::uint64_t Key(int a, int b) {
    return ((std::uint64_t)(std::uint32_t)std::min(a, b) << 32) | (std::uint32_t)std::max(a, b);
  }
  // A geom's body index + 1, 0 for the ground.
  static int Index(dGeomID g) { return (int)(std::intptr_t)dGeomGetData(g) - 1; }

  void addBody(const SceneSpec &spec, const scenes::BodySpec &b) {
    dBodyID body = dBodyCreate(world_);
    dMass m;
    const Vec3 I = scenes::UniformInertia(b.shape, b.mass);
    dMassSetParameters(&m, b.mass, 0, 0, 0, I[0], I[1], I[2], 0, 0, 0);
    dBodySetMass(body, &m);
    dBodySetPosition(body, b.position[0] + spec.offset[0], b.position[1] + spec.offset[1],
                     b.position[2] + spec.offset[2]);
    dMatrix3 R = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R[i * 4 + j] = b.axes[j][i];  // columns: the body axes
    dBodySetRotation(body, R);
    dGeomID g = nullptr;
    switch (b.shape.kind) {
      case ShapeKind::kBox:
        g = dCreateBox(space_, b.shape.a, b.shape.b, b.shape.c);
        break;
      case ShapeKind::kSphere:
        g = dCreateSphere(space_, b.shape.a);
        break;
      case ShapeKind::kCapsule:
        g = dCreateCapsule(space_, b.shape.a, b.shape.b);
        break;
    }
    dGeomSetBody(g, body);
    dGeomSetData(g, (void *)(std::intptr_t)(bodies_.size() + 1));
    bodies_.push_back(body);
    mu_.push_back(spec.friction[(size_t)b.material]);
  }

  void addCarWheel(const SceneSpec &spec, const scenes::CarWheelSpec &w) {
    dJointID j = dJointCreateHinge2(world_, nullptr);
    dJointAttach(j, bodies_[(size_t)w.chassis], bodies_[(size_t)w.wheel]);
    dJointSetHinge2Anchor(j, w.anchor[0] + spec.offset[0], w.anchor[1] + spec.offset[1], w.anchor[2] + spec.offset[2]);
    const dReal axis1[3] = {w.steeringAxis[0], w.steeringAxis[1], w.steeringAxis[2]};
    const dReal axis2[3] = {w.hingeAxis[0], w.hingeAxis[1], w.hingeAxis[2]};
    dJointSetHinge2Axes(j, axis1, axis2);
    dJointSetHinge2Param(j, dParamHiStop, 0);
    dJointSetHinge2Param(j, dParamLoStop, 0);
    const double hk = scenes::kStepSeconds * w.spring;
    dJointSetHinge2Param(j, dParamSuspensionERP, hk / (hk + w.damping));
    dJointSetHinge2Param(j, dParamSuspensionCFM, 1 / (hk + w.damping));
    wheels_.push_back(j);
  }

  void applyDrives() {
    for (const scenes::DriveSpec &d : drives_) {
      dVector3 axis;
      dJointGetHinge2Axis2(wheels_[(size_t)d.joint], axis);
      const auto [chassis, wheel] = driven_[(size_t)d.joint];
      dBodyAddTorque(wheel, d.torque * axis[0], d.torque * axis[1], d.torque * axis[2]);
      dBodyAddTorque(chassis, -d.torque * axis[0], -d.torque * axis[1], -d.torque * axis[2]);
    }
  }

  bool collides(dGeomID a, dGeomID b) const {
    const int ia = Index(a), ib = Index(b);
    return ia < 0 || ib < 0 || disabled_.empty() || disabled_.count(Key(ia, ib)) == 0;
  }
  double friction(dGeomID g) const {
    const int i = Index(g);
    return i < 0 ? groundMu_ : mu_[(size_t)i];
  }

  static void Contacts(void *data, dGeomID a, dGeomID b) {
    auto *self = static_cast<OdeEngine *>(data);
    if (!self->collides(a, b)) return;
    dContactGeom geoms[kMaxContacts];
    const int n = dCollide(a, b, maxContacts, geoms, sizeof(dContactGeom));
    const double mu = std::max(self->friction(a), self->friction(b));
    for (int i = 0; i < n; ++i) {
      dContact c{};
      c.surface.mode = dContactApprox1;
      c.surface.mu = mu;
      c.geom = geoms[i];
      dJointID j = dJointCreateContact(self->world_, self->contacts_, &c);
      dJointAttach(j, dGeomGetBody(a), dGeomGetBody(b));
    }
  }

  static void Depths(void *data, dGeomID a, dGeomID b) {
    auto *self = static_cast<OdeEngine *>(data);
    if (!self->collides(a, b)) return;
    dContactGeom geoms[kMaxContacts];
    const int n = dCollide(a, b, maxContacts, geoms, sizeof(dContactGeom));
    for (int i = 0; i < n; ++i) self->deepest_ = std::max(self->deepest_, (double)geoms[i].depth);
  }

  bool quick_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::vector<dBodyID> bodies_;
  std::vector<double> mu_;
  double groundMu_ = 0;
  std::unordered_set<std::uint64_t> disabled_;
  std::vector<dJointID> wheels_;
  std::vector<std::pair<dBodyID, dBodyID>> driven_;  // per car wheel: chassis, wheel
  std::vector<scenes::DriveSpec> drives_;
  double deepest_ = 0;
};

}  // namespace

void SetOdeMaxContacts(int n) { maxContacts = std::clamp(n, 1, kMaxContacts); }

std::unique_ptr<PeerEngine> MakeOdeStep(const SceneSpec &spec) { return std::make_unique<OdeEngine>(spec, false); }
std::unique_ptr<PeerEngine> MakeOdeQuickStep(const SceneSpec &spec) { return std::make_unique<OdeEngine>(spec, true); }

}  // namespace karma::peers
