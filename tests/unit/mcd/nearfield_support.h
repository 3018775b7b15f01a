// nearfield_support.h: models at heap TMs and one-shot intersection queries
// for the nearfield tests (convex, aggregate and triangle list families).
#pragma once

#include "mcd_test_support.h"

#include <memory>

namespace mcd_test {

// A model of g at a heap TM (position p, optional rotation), updated.
struct Placed {
  McdModelID model;
  std::unique_ptr<TM> tm;
  Placed(McdGeometryID g, MeReal x, MeReal y, MeReal z) : model(McdModelCreate(g)), tm(new TM(x, y, z)) {
    McdModelSetTransformPtr(model, *tm);
    McdModelUpdate(model);
  }
  ~Placed() { McdModelDestroy(model); }
  Placed(const Placed &) = delete;
  Placed &operator=(const Placed &) = delete;
  void rotate(MeReal ax, MeReal ay, MeReal az, MeReal angle) {
    const MeVector3 a = {ax, ay, az};
    tm->rotate(a, angle);
    McdModelUpdate(model);
  }
  void moveTo(MeReal x, MeReal y, MeReal z) {
    MeMatrix4TMSetPosition(tm->m, x, y, z);
    McdModelUpdate(model);
  }
};

// McdHello + McdIntersect + McdGoodbye on (a, b).
struct Hit {
  McdContact contacts[64];
  McdIntersectResult r{};
  int touch = 0;
  Hit(McdModelID a, McdModelID b, int max = 64) {
    McdModelPair *pair = McdModelPairCreate(a, b);
    McdHello(pair);
    r.contacts = contacts;
    r.contactMaxCount = max;
    touch = McdIntersect(pair, &r);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
  }
  int count() const { return r.contactCount; }
  double deepest() const {
    double s = 1e30;
    for (int i = 0; i < r.contactCount; ++i) s = std::fmin(s, (double)contacts[i].separation);
    return s;
  }
};

// Every contact: unit, finite normal; finite position and separation.
inline void expectSane(const Hit &h) {
  for (int i = 0; i < h.r.contactCount; ++i) {
    const McdContact &c = h.contacts[i];
    const double len = std::sqrt((double)MeVector3Dot(c.normal, c.normal));
    EXPECT_NEAR(len, 1, 1e-4) << "contact " << i;
    EXPECT_TRUE(std::isfinite((double)c.separation));
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite((double)c.position[k]));
  }
}

// The two orders mirror: same count, separations and positions, normals negated.
inline void expectMirrored(McdModelID a, McdModelID b, double eps) {
  Hit f(a, b), g(b, a);
  ASSERT_EQ(f.touch, g.touch);
  ASSERT_EQ(f.count(), g.count());
  for (int i = 0; i < f.count(); ++i) {
    EXPECT_NEAR(f.contacts[i].separation, g.contacts[i].separation, eps);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(f.contacts[i].normal[k], -g.contacts[i].normal[k], eps);
      EXPECT_NEAR(f.contacts[i].position[k], g.contacts[i].position[k], eps);
    }
  }
}

}  // namespace mcd_test
