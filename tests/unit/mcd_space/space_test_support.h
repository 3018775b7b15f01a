// space_test_support.h: a few spheres in a McdSpace and one step of the
// guide's loop collected into plain lists.
#pragma once

#include "../mcd/mcd_test_support.h"

#include <memory>
#include <vector>

namespace space_test {

using mcd_test::Framework;
using mcd_test::TM;
using mcd_test::WarningCapture;

struct Events {
  std::vector<McdModelPair *> goodbye, hello, staying;
  int calls = 0;  // McdSpaceGetPairs calls made
};

// EndChanges, every event through McdSpaceGetPairs (or GetTransitions) with
// a container of `size`, then (unless stayOutside) BeginChanges.
inline Events Step(McdSpaceID s, int size = 64, bool transitions = false, bool stayOutside = false) {
  Events e;
  McdSpaceEndChanges(s);
  McdModelPairContainer *c = McdModelPairContainerCreate(size);
  McdSpacePairIterator it;
  McdSpacePairIteratorBegin(s, &it);
  int more;
  do {
    McdModelPairContainerReset(c);
    more = transitions ? McdSpaceGetTransitions(s, &it, c) : McdSpaceGetPairs(s, &it, c);
    ++e.calls;
    for (int i = c->goodbyeFirst; i < c->goodbyeEnd; ++i) e.goodbye.push_back(c->array[i]);
    for (int i = c->helloFirst; i < c->helloEnd; ++i) e.hello.push_back(c->array[i]);
    for (int i = c->stayingFirst; i < c->stayingEnd; ++i) e.staying.push_back(c->array[i]);
  } while (more && e.calls < 1000);
  McdModelPairContainerDestroy(c);
  if (!stayOutside) McdSpaceBeginChanges(s);
  return e;
}

// n spheres of radius 1, each with its own TM at (x_i, 0, 0), in one space.
struct Balls {
  Framework fw{64, 0};
  McdSpaceID space;
  McdGeometryID geom;
  std::vector<std::unique_ptr<TM>> tms;
  std::vector<McdModelID> models;
  // insert false: the models are created, the caller inserts them.
  Balls(const std::vector<MeReal> &xs, int pairCount = 100, int objectCount = 32, bool insert = true) {
    space = McdSpaceAxisSortCreate(fw, McdAllAxes, objectCount, pairCount);
    geom = McdSphereCreate(fw, 1);
    for (MeReal x : xs) add(x, insert);
  }
  McdModelID add(MeReal x, bool insert = true) {
    tms.push_back(std::make_unique<TM>(x, 0, 0));
    McdModelID m = McdModelCreate(geom);
    McdModelSetTransformPtr(m, *tms.back());
    models.push_back(m);
    if (insert) McdSpaceInsertModel(space, m);
    return m;
  }
  void move(int i, MeReal x) { MeMatrix4TMSetPosition(tms[(size_t)i]->m, x, 0, 0); }
  ~Balls() {
    McdSpaceDestroy(space);
    for (McdModelID m : models) McdModelDestroy(m);
    McdGeometryDestroy(geom);
  }
};

}  // namespace space_test
