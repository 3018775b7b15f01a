// mst_test_support.h: a universe with z up, gravity and a ground plane.
#pragma once

#include <gtest/gtest.h>

#include "Mst.h"
#include "../mcd/mcd_test_support.h"

namespace mst_test {

using mcd_test::WarningCapture;

inline constexpr MeReal kG = (MeReal)9.81;
inline constexpr MeReal kH = (MeReal)0.01;

struct Scene {
  MstUniverseID u;
  MeMatrix4 groundTM;
  McdModelID ground = nullptr;
  explicit Scene(bool withGround = true) {
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    u = MstUniverseCreate(&sizes);
    MdtWorldSetGravity(u->world, 0, 0, -kG);
    MeMatrix4TMMakeIdentity(groundTM);
    if (withGround) ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  }
  ~Scene() { MstUniverseDestroy(u); }
  Scene(const Scene &) = delete;
  Scene &operator=(const Scene &) = delete;
  McdModelID ball(MeReal r, MeReal x, MeReal y, MeReal z, MeReal density = 1) {
    McdModelID m = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, r), density);
    MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
  }
  void step(int n = 1) {
    for (int i = 0; i < n; ++i) MstUniverseStep(u, kH);
  }
  static MeReal z(McdModelID m) {
    MeVector3 p;
    MdtBodyGetPosition(McdModelGetBody(m), p);
    return p[2];
  }
  static MeReal vz(McdModelID m) {
    MeVector3 v;
    MdtBodyGetLinearVelocity(McdModelGetBody(m), v);
    return v[2];
  }
};

}  // namespace mst_test
