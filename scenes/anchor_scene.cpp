// anchor_scene.cpp: what every anchor scene shares: the universe, the
// ground, materials, bodies of a given mass, and the figures of a run.
#include "anchor_scene.h"

#include <algorithm>
#include <cmath>

namespace karma::scenes {

AnchorScene::AnchorScene(const char *name, int steps, int bodies, int models, int pairs,
                         int constraints)
    : name_(name), steps_(steps) {
  MstUniverseSizes sizes = MstUniverseDefaultSizes;
  sizes.dynamicBodiesMaxCount = bodies;
  sizes.collisionModelsMaxCount = models;
  sizes.collisionPairsMaxCount = pairs;
  sizes.dynamicConstraintsMaxCount = constraints;
  sizes.materialsMaxCount = 8;
  universe_ = MstUniverseCreate(&sizes);
  MdtWorldID w = world();
  MdtWorldSetGravity(w, 0, -(MeReal)9.81, 0);
  MdtWorldSetAutoDisable(w, FALSE);
  mu_.push_back(0);  // the default material: frictionless unless a scene says otherwise
}

AnchorScene::~AnchorScene() {
  if (universe_) MstUniverseDestroy(universe_);
}

MdtWorldID AnchorScene::world() const { return MstUniverseGetWorld(universe_); }
McdFrameworkID AnchorScene::framework() const { return MstUniverseGetFramework(universe_); }

MstMaterialID AnchorScene::material(MeReal mu) {
  MstBridgeID bridge = MstUniverseGetBridge(universe_);
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
  return id;
}

McdModelID AnchorScene::ground(MstMaterialID m) {
  // McdPlane's normal is its local z: turn z onto world y.
  const MeMatrix4 tm = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
  MeMatrix4Copy(groundTM_, tm);
  McdModelID plane = MstFixedModelCreate(universe_, McdPlaneCreate(framework()), groundTM_);
  McdModelSetMaterial(plane, m);
  return plane;
}

McdModelID AnchorScene::body(McdGeometryID g, MeReal mass, const MeVector3 p, MstMaterialID m,
                             const MeMatrix3 *R) {
  const MeReal density = mass / McdGeometryGetVolume(g);
  McdModelID model = MstModelAndBodyCreate(universe_, g, density);
  MdtBodyID b = McdModelGetBody(model);
  MdtBodySetPosition(b, p[0], p[1], p[2]);
  if (R) MdtBodySetOrientation(b, *R);
  McdModelSetMaterial(model, m);
  bodies_.push_back(model);
  return model;
}

void AnchorScene::disablePair(McdModelID a, McdModelID b) {
  McdSpaceID space = MstUniverseGetSpace(universe_);
  const bool open = McdSpaceIsChanging(space) == 0;
  if (open) McdSpaceBeginChanges(space);
  McdSpaceDisablePair(a, b);
  if (open) McdSpaceEndChanges(space);
}

void AnchorScene::step() {
  applyForces();
  MstUniverseStep(universe_, kStep);
  ++done_;
  for (McdModelID m : bodies_) {
    MdtBodyID b = McdModelGetBody(m);
    MeVector3 x, v, w;
    MdtBodyGetPosition(b, x);
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(x[i]) || !std::isfinite(v[i]) || !std::isfinite(w[i]))
        figures_.finite = false;
    figures_.maxSpeed = std::max(figures_.maxSpeed, (double)MeVector3Magnitude(v));
  }
  afterStep();
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
  while (done_ < steps_) step();
  return finish();
}

SceneFigures AnchorScene::finish() {
  SceneFigures f = figures_;
  f.steps = done_;
  f.penetration = DeepestPenetration(bodies_);
  check(f);
  return f;
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

}  // namespace karma::scenes
