// step_scene.h: a small Mst universe for the step tests: y up, gravity
// 9.81, an optional ground plane y = 0, steps of 1/60 s.
#pragma once

#include <gtest/gtest.h>

#include "Mst.h"

namespace step_test {

inline constexpr MeReal kG = (MeReal)9.81;
inline constexpr MeReal kH = (MeReal)1 / 60;

struct Scene {
  MstUniverseID u;
  MeMatrix4 groundTM;
  McdModelID ground = nullptr;
  explicit Scene(bool withGround = true, int bodies = 100) {
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = bodies;
    sizes.collisionModelsMaxCount = bodies + 10;
    sizes.dynamicConstraintsMaxCount = 50 * bodies;
    sizes.collisionPairsMaxCount = 20 * bodies;
    u = MstUniverseCreate(&sizes);
    MdtWorldSetGravity(u->world, 0, -kG, 0);
    MdtWorldSetAutoDisable(u->world, FALSE);
    // The plane's normal is its TM's z axis: turn it to +y.
    MeMatrix4TMMakeIdentity(groundTM);
    groundTM[1][1] = 0, groundTM[1][2] = -1;
    groundTM[2][1] = 1, groundTM[2][2] = 0;
    if (withGround) ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  }
  ~Scene() { MstUniverseDestroy(u); }
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;

  McdModelID box(MeReal lx, MeReal ly, MeReal lz, MeReal x, MeReal y, MeReal z, MeReal density = 100) {
    McdModelID m = MstModelAndBodyCreate(u, McdBoxCreate(u->frame, lx, ly, lz), density);
    MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
  }
  McdModelID ball(MeReal r, MeReal x, MeReal y, MeReal z, MeReal density = 100) {
    McdModelID m = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, r), density);
    MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
  }
  McdModelID fixedBox(MeReal lx, MeReal ly, MeReal lz, MeReal x, MeReal y, MeReal z) {
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    tm[3][0] = x, tm[3][1] = y, tm[3][2] = z;
    EXPECT_LT(fixedCount_, 4);
    MeMatrix4Copy(fixedTMs_[fixedCount_], tm);
    return MstFixedModelCreate(u, McdBoxCreate(u->frame, lx, ly, lz), fixedTMs_[fixedCount_++]);
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) MstUniverseStep(u, kH);
  }
  static void position(McdModelID m, MeVector3 p) { MdtBodyGetPosition(McdModelGetBody(m), p); }
  static void velocity(McdModelID m, MeVector3 v) { MdtBodyGetLinearVelocity(McdModelGetBody(m), v); }

 private:
  MeMatrix4 fixedTMs_[4];  // a fixed model keeps a pointer to its transform
  int fixedCount_ = 0;
};

// The contacts of a body, in the order MdtBodyGetNextContact gives.
inline int Contacts(McdModelID m, MdtContactID *out, int max) {
  MdtBodyID b = McdModelGetBody(m);
  int n = 0;
  for (MdtContactID c = MdtBodyGetFirstContact(b); c && n < max; c = MdtBodyGetNextContact(b, c)) out[n++] = c;
  return n;
}

}  // namespace step_test
