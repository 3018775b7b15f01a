// scene_support.h: universes with a y-up ground plane for the hard cases.
#pragma once

#include <vector>

#include "Mst.h"
#include "hard_support.h"

namespace hard {

struct Universe {
  MstUniverseID u;
  McdModelID ground = nullptr;
  MeMatrix4 groundTM;
  explicit Universe(MstUniverseSizes sizes = MstUniverseDefaultSizes, bool withGround = true)
      : u(MstUniverseCreate(&sizes)) {
    MdtWorldSetGravity(u->world, 0, (MeReal)-kG, 0);
    if (!withGround) return;
    // A plane y = 0: its z normal along +y.
    MeMatrix4TMMakeIdentity(groundTM);
    groundTM[1][1] = 0;
    groundTM[1][2] = -1;
    groundTM[2][1] = 1;
    groundTM[2][2] = 0;
    ground = MstFixedModelCreate(u, McdPlaneCreate(u->frame), groundTM);
  }
  ~Universe() { MstUniverseDestroy(u); }
  Universe(const Universe &) = delete;
  Universe &operator=(const Universe &) = delete;
  MdtWorldID world() const { return u->world; }
  void step(double h) { MstUniverseStep(u, (MeReal)h); }
};

// A box model with a body of mass `mass`, centred at (x, y, z).
inline McdModelID addBox(Universe &U, double sx, double sy, double sz, double mass, double x, double y, double z) {
  McdGeometryID g = McdBoxCreate(U.u->frame, (MeReal)sx, (MeReal)sy, (MeReal)sz);
  McdModelID m = MstModelAndBodyCreate(U.u, g, (MeReal)(mass / (sx * sy * sz)));
  MdtBodySetPosition(McdModelGetBody(m), (MeReal)x, (MeReal)y, (MeReal)z);
  return m;
}

inline MdtBodyID bodyOf(McdModelID m) { return McdModelGetBody(m); }

inline void position(MdtBodyID b, double p[3]) {
  MeVector3 x;
  MdtBodyGetPosition(b, x);
  p[0] = x[0];
  p[1] = x[1];
  p[2] = x[2];
}

inline double speed(MdtBodyID b) {
  MeVector3 v;
  MdtBodyGetLinearVelocity(b, v);
  return MeVector3Magnitude(v);
}

}  // namespace hard
