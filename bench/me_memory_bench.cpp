// MePool against the general allocator behind MeMemoryAPI: the pool is what
// bodies and constraints come from, so its get/put must be far cheaper than
// create/destroy. Compare BM_PoolGetPut with BM_MemoryCreateDestroy.
#include <benchmark/benchmark.h>

#include "MeMemory.h"
#include "MePool.h"

namespace {

constexpr int kBatch = 64;  // structs held at once, as a world step would
constexpr int kStructSize = 256;

void BM_PoolGetPut(benchmark::State &state) {
  MePool pool;
  MePoolInit(&pool, kBatch, kStructSize, 16);
  void *held[kBatch];
  for (auto _ : state) {
    for (auto &p : held) p = MePoolGetStruct(&pool);
    benchmark::DoNotOptimize(held);
    for (auto *p : held) MePoolPutStruct(&pool, p);
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
  MePoolDestroy(&pool);
}
BENCHMARK(BM_PoolGetPut);

void BM_MemoryCreateDestroy(benchmark::State &state) {
  void *held[kBatch];
  for (auto _ : state) {
    for (auto &p : held) p = MeMemoryAPI.create(kStructSize);
    benchmark::DoNotOptimize(held);
    for (auto *p : held) MeMemoryAPI.destroy(p);
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
}
BENCHMARK(BM_MemoryCreateDestroy);

}  // namespace
