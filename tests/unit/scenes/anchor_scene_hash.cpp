// anchor_scene_hash SCENE STEPS: steps an anchor scene (scenes/) STEPS times
// on the platform backend that KARMA_PLATFORM chooses (engine/platform/
// kernels.h, DefaultKernels) and prints
//     backend NAME
//     state hash 0x...
// The hash is the golden toolkit's (StateHash.h) over every body's state
// (position, quaternion, linear and angular velocity, in description order)
// after every step, in the build's precision. The test anchor_hash_test runs
// this program once per backend, each in its own process since the backend
// is chosen once per process.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

#include <karma/golden/StateHash.h>

#include "anchor_scene.h"
#include "kernels.h"

namespace {

namespace kg = karma::golden;
using karma::scenes::AnchorScene;

std::unique_ptr<AnchorScene> MakeScene(const char *name) {
  if (!std::strcmp(name, "car")) return karma::scenes::MakeCar();
  if (!std::strcmp(name, "topple")) return karma::scenes::MakeTopple();
  if (!std::strcmp(name, "ragdoll")) return karma::scenes::MakeRagdoll();
  if (!std::strcmp(name, "stack21")) return karma::scenes::MakeStack21();
  if (!std::strcmp(name, "pile1000")) return karma::scenes::MakePile1000();
  return nullptr;
}

void AddStates(const AnchorScene &scene, kg::StateHash &hash) {
  for (McdModelID model : scene.models()) {
    MdtBodyID body = McdModelGetBody(model);
    MeVector3 x, v, w;
    MeVector4 q;
    MdtBodyGetPosition(body, x);
    MdtBodyGetQuaternion(body, q);
    MdtBodyGetLinearVelocity(body, v);
    MdtBodyGetAngularVelocity(body, w);
    kg::BodyState s;
    for (int i = 0; i < 3; ++i) {
      s.position[static_cast<std::size_t>(i)] = x[i];
      s.linearVelocity[static_cast<std::size_t>(i)] = v[i];
      s.angularVelocity[static_cast<std::size_t>(i)] = w[i];
    }
    for (int i = 0; i < 4; ++i) s.quaternion[static_cast<std::size_t>(i)] = q[i];
    hash.AddBody(s, kg::kBuildPrecision);
  }
}

}  // namespace

int main(int argc, char **argv) {
  const int steps = argc == 3 ? std::atoi(argv[2]) : 0;
  std::unique_ptr<AnchorScene> scene = argc == 3 ? MakeScene(argv[1]) : nullptr;
  if (!scene || steps < 1) {
    std::fprintf(stderr, "usage: anchor_scene_hash car|topple|ragdoll|stack21|pile1000 STEPS\n");
    return 2;
  }
  std::printf("backend %s\n", karma::platform::DefaultKernels().name);
  kg::StateHash hash;
  for (int i = 0; i < steps; ++i) {
    scene->advance();
    AddStates(*scene, hash);
  }
  std::printf("state hash %s\n", kg::FormatHash(hash.Value()).c_str());
  return 0;
}
