// spinner.h: a test body on a hinge about z to the world, spinning at
// `rate` about z (no gravity acts on it about the hinge), with the hinge's
// limit at hand. Shared by the limit tests (mdt/) and the row-count tests
// (effects/).
#pragma once

#include "Mdt.h"

namespace karma_test {

struct Spinner {
  MdtBodyID body;
  MdtHingeID hinge;
  MdtLimitID limit;
  Spinner(MdtWorldID w, MeReal rate) {
    body = MdtBodyCreate(w);
    MdtBodySetAngularVelocity(body, 0, 0, rate);
    MdtBodyEnable(body);
    hinge = MdtHingeCreate(w);
    MdtHingeSetBodies(hinge, body, nullptr);
    MdtHingeSetAxis(hinge, 0, 0, 1);
    MdtHingeEnable(hinge);
    limit = MdtHingeGetLimit(hinge);
  }
  // The body's angular velocity about the hinge axis.
  MeReal rate() const {
    MeVector3 w;
    MdtBodyGetAngularVelocity(body, w);
    return w[2];
  }
};

}  // namespace karma_test
