// Farfield: the axis-sort space against the O(n^2) brute force on boxes in
// coherent motion (each moves a small, steady step per frame and bounces off
// the walls of a cube sized so the density is the same for every count).
//
//   BM_FarfieldAxisSort/N   one frame: BeginChanges, move, UpdateAll (the
//                           AABB function on every box, the insertion sort),
//                           EndChanges (pair events), reading every pair
//                           through GetPairs in chunks of 256
//   BM_FarfieldBruteForce/N one frame: move, the AABBs, every pair tested
//
// Counters: pairs reported per frame, endpoint swaps that changed an overlap
// per frame. Run e.g.  build/bench/bench/farfield_bench
#include "axis_sort_space.h"
#include "brute_force.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace karma::mcd;

struct Box {
  MeReal pos[3], vel[3], half[3];
};

struct Scene {
  explicit Scene(int n)
      : size(MeReal(4) * static_cast<MeReal>(std::cbrt(static_cast<double>(n)))), boxes(static_cast<std::size_t>(n)) {
    std::mt19937 rng(12345u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (Box &b : boxes) {
      for (int k = 0; k < 3; ++k) {
        b.pos[k] = static_cast<MeReal>(u(rng)) * size;
        b.vel[k] = static_cast<MeReal>(u(rng) - 0.5) * MeReal(0.04);  // about 2% of a box per frame
        b.half[k] = MeReal(0.3) + static_cast<MeReal>(u(rng)) * MeReal(0.4);
      }
    }
  }
  void Move() {
    for (Box &b : boxes) {
      for (int k = 0; k < 3; ++k) {
        b.pos[k] += b.vel[k];
        if (b.pos[k] < 0 || b.pos[k] > size) b.vel[k] = -b.vel[k];
      }
    }
  }
  MeReal size;
  std::vector<Box> boxes;
};

void BoxAabb(void *user, void *, MeReal min[3], MeReal max[3]) {
  const auto *b = static_cast<const Box *>(user);
  for (int k = 0; k < 3; ++k) {
    min[k] = b->pos[k] - b->half[k];
    max[k] = b->pos[k] + b->half[k];
  }
}

void BM_FarfieldAxisSort(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  Scene scene(n);
  AxisSortSpace *space = AxisSortSpace::Create(kAllAxes, n, 16 * n);
  for (Box &b : scene.boxes) {
    MeReal min[3], max[3];
    BoxAabb(&b, nullptr, min, max);
    space->Insert(&b, min, max);
  }
  space->EndChanges();
  space->SetAabbFn(&BoxAabb, nullptr);
  std::vector<const PairRecord *> storage(256);
  long long pairs = 0, swaps = 0, frames = 0;
  for (auto _ : state) {
    space->BeginChanges();
    scene.Move();
    space->UpdateAll();
    space->EndChanges();
    PairIterator it;
    space->PairIteratorBegin(&it);
    PairChunk chunk;
    chunk.array = storage.data();
    chunk.size = 256;
    bool more = true;
    while (more) {
      more = space->GetPairs(&it, &chunk);
      pairs += chunk.stayingEnd - chunk.helloFirst;
      benchmark::DoNotOptimize(chunk.array[0]);
    }
    swaps += space->Stats().swaps;
    ++frames;
  }
  state.counters["pairs"] = static_cast<double>(pairs) / static_cast<double>(frames);
  state.counters["swaps"] = static_cast<double>(swaps) / static_cast<double>(frames);
  AxisSortSpace::Destroy(space);
}

void BM_FarfieldBruteForce(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  Scene scene(n);
  std::vector<Aabb> boxes(static_cast<std::size_t>(n));
  std::vector<std::pair<int, int>> out;
  long long pairs = 0, frames = 0;
  for (auto _ : state) {
    scene.Move();
    for (int i = 0; i < n; ++i) {
      BoxAabb(&scene.boxes[static_cast<std::size_t>(i)], nullptr, boxes[static_cast<std::size_t>(i)].min,
              boxes[static_cast<std::size_t>(i)].max);
    }
    BruteForceOverlaps(boxes, kAllAxes, out);
    pairs += static_cast<long long>(out.size());
    ++frames;
  }
  state.counters["pairs"] = static_cast<double>(pairs) / static_cast<double>(frames);
}

BENCHMARK(BM_FarfieldAxisSort)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FarfieldBruteForce)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace
