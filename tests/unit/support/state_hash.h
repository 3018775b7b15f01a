// state_hash.h: FNV-1a (64-bit) over the bytes of bodies' positions,
// quaternions and velocities, for determinism tests: two runs that are
// bit-identical give equal hashes, and any bit that differs changes it
// (with probability 1 - 2^-64). Shared by the unit test folders.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "MdtBody.h"

namespace karma_test {

class StateHash {
 public:
  void mix(const void *bytes, std::size_t n) {
    const auto *c = static_cast<const unsigned char *>(bytes);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ c[i]) * 1099511628211ull;
  }
  void mixBody(MdtBodyID b) {
    MeVector3 x, v, w;
    MeVector4 q;
    MdtBodyGetPosition(b, x);
    MdtBodyGetQuaternion(b, q);
    MdtBodyGetLinearVelocity(b, v);
    MdtBodyGetAngularVelocity(b, w);
    mix(x, sizeof x);
    mix(q, sizeof q);
    mix(v, sizeof v);
    mix(w, sizeof w);
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 1469598103934665603ull;  // the FNV-1a offset basis
};

inline std::uint64_t HashBodies(const std::vector<MdtBodyID> &bodies) {
  StateHash h;
  for (MdtBodyID b : bodies) h.mixBody(b);
  return h.value();
}

}  // namespace karma_test
