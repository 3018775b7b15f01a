// Two ways to compose rotations: 3x3 matrix products against quaternion
// products (plus one conversion to a matrix at the end). The integrator and
// the joint code choose between them; compare the two rates.
#include <benchmark/benchmark.h>

#include "MeMath.h"

namespace {

constexpr int kChain = 32;  // rotations composed per iteration

void BM_ComposeMatrices(benchmark::State &state) {
  const MeVector3 axis = {(MeReal)0.267, (MeReal)0.535, (MeReal)0.802};
  MeMatrix3 step, acc;
  MeMatrix3FromAxisAngle(step, axis, (MeReal)0.01);
  for (auto _ : state) {
    MeMatrix3MakeIdentity(acc);
    for (int i = 0; i < kChain; ++i) MeMatrix3Multiply(acc, acc, step);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kChain);
}
BENCHMARK(BM_ComposeMatrices);

void BM_ComposeQuaternions(benchmark::State &state) {
  const MeVector3 axis = {(MeReal)0.267, (MeReal)0.535, (MeReal)0.802};
  MeVector4 step, acc;
  MeMatrix3 R;
  MeQuaternionMake(step, axis, (MeReal)0.01);
  for (auto _ : state) {
    MeQuaternionMakeIdentity(acc);
    for (int i = 0; i < kChain; ++i) MeQuaternionMultiply(acc, acc, step);
    MeQuaternionToR(R, acc);
    benchmark::DoNotOptimize(R);
  }
  state.SetItemsProcessed(state.iterations() * kChain);
}
BENCHMARK(BM_ComposeQuaternions);

}  // namespace
