// The platform kernels (engine/platform/kernels.h) on every backend this CPU
// supports: dot, gatherDot and sparseRowsTimes at n = 8, 32, 128 and 1024
// (for sparseRowsTimes n entries in CSR rows of up to 16 random columns;
// for contactRowsTimes, the same kernel on rows as a stack's contact rows
// are: up to 36 columns, in runs of 12 consecutive ones, ascending),
// nanoseconds per call; the binary ends with a Markdown table of each
// backend's speed-up over the reference (reference time / backend time, the
// medians when run with --benchmark_repetitions). Run e.g.
//   build/bench/bench/platform_kernels_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "kernels.h"

namespace {

namespace platform = karma::platform;
using platform::Kernels;

constexpr int kSizes[] = {8, 32, 128, 1024};
constexpr int kRowLength = 16;
constexpr int kContactRowLength = 36, kContactRun = 12;
constexpr const char *kKernelNames[] = {"dot", "gatherDot", "sparseRowsTimes", "contactRowsTimes"};

// Random operands of one size: x is indexed by index (a permutation-free
// random pick, as a sparse row gathers from a dense vector).
struct Operands {
  std::vector<MeReal> a, x, y;
  std::vector<int> index, rowStart; /* CSR rows of up to kRowLength entries */
  explicit Operands(int n) {
    std::mt19937 rng(static_cast<unsigned>(n));
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> pick(0, n - 1);
    for (int k = 0; k < n; ++k) {
      a.push_back(static_cast<MeReal>(u(rng)));
      x.push_back(static_cast<MeReal>(u(rng)));
      y.push_back(static_cast<MeReal>(u(rng)));
      index.push_back(pick(rng));
    }
    for (int k = 0; k < n; k += kRowLength) rowStart.push_back(k);
    rowStart.push_back(n);
  }
  // CSR rows of up to kContactRowLength columns in runs of kContactRun
  // consecutive ones (x of 4n values).
  static Operands ContactRows(int n) {
    Operands o(n);
    o.x.resize(4 * (size_t)n, MeReal(0.5));
    o.rowStart.clear();
    std::mt19937 rng(static_cast<unsigned>(n) + 1);
    std::uniform_int_distribution<int> gap(0, kContactRun);
    for (int k = 0; k < n; k += kContactRowLength) {
      o.rowStart.push_back(k);
      int column = gap(rng);
      for (int e = k; e < std::min(n, k + kContactRowLength); ++e) {
        if (e > k && (e - k) % kContactRun == 0) column += gap(rng);
        o.index[(size_t)e] = column++;
      }
    }
    o.rowStart.push_back(n);
    return o;
  }
  int rows() const { return static_cast<int>(rowStart.size()) - 1; }
};

void Run(benchmark::State &state, const Kernels *k, int kernel) {
  const int n = static_cast<int>(state.range(0));
  const Operands o = kernel == 3 ? Operands::ContactRows(n) : Operands(n);
  std::vector<MeReal> y = o.y;
  for (auto _ : state) {
    if (kernel == 0) {
      benchmark::DoNotOptimize(k->dot(o.a.data(), o.x.data(), n));
    } else if (kernel == 1) {
      benchmark::DoNotOptimize(k->gatherDot(o.a.data(), o.index.data(), o.x.data(), n));
    } else {
      k->sparseRowsTimes(o.rowStart.data(), o.index.data(), o.a.data(), nullptr, o.rows(), o.x.data(), y.data());
      benchmark::ClobberMemory();
    }
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// Collects each benchmark's time (the median aggregate when there are
// repetitions, else the single run) while printing as usual.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  // name "kernel/backend" -> n -> ns per call
  std::map<std::string, std::map<std::string, double>> ns;

  void ReportRuns(const std::vector<Run> &runs) override {
    for (const Run &run : runs) {
      const bool median = run.aggregate_name == "median";
      if (run.run_type == Run::RT_Aggregate && !median) continue;
      if (run.run_type == Run::RT_Iteration && run.repetitions > 1) continue;
      ns[run.run_name.function_name][run.run_name.args] = run.GetAdjustedRealTime();
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void PrintTable(const std::vector<const Kernels *> &backends) {
    std::printf("\nPlatform kernels: ns per call and speed-up over reference (reference / backend)\n\n");
    std::printf("| kernel | n |");
    for (const Kernels *k : backends) {
      std::printf(" %s ns |", k->name);
      if (k != backends.front()) std::printf(" %s × |", k->name);
    }
    std::printf("\n|---|---:|");
    for (const Kernels *k : backends) std::printf("---:|%s", k == backends.front() ? "" : "---:|");
    std::printf("\n");
    for (const char *kernel : kKernelNames)
      for (int n : kSizes) {
        const std::string arg = std::to_string(n);
        const double ref = ns[std::string(kernel) + "/reference"][arg];
        std::printf("| %s | %d |", kernel, n);
        for (const Kernels *k : backends) {
          const double t = ns[std::string(kernel) + "/" + k->name][arg];
          std::printf(" %.1f |", t);
          if (k != backends.front()) std::printf(" %.2f |", t > 0 ? ref / t : 0.0);
        }
        std::printf("\n");
      }
    std::printf("\n");
  }
};

}  // namespace

int main(int argc, char **argv) {
  std::vector<const Kernels *> backends;
  for (const Kernels *k : platform::AllKernels())
    if (platform::Supported(*k))
      backends.push_back(k);
    else
      std::printf("platform_kernels_bench: this CPU lacks %s: skipped\n", k->name);
  for (int kernel = 0; kernel < 4; ++kernel)
    for (const Kernels *k : backends) {
      benchmark::internal::Benchmark *b =
          benchmark::RegisterBenchmark((std::string(kKernelNames[kernel]) + "/" + k->name).c_str(),
                                       [k, kernel](benchmark::State &state) { Run(state, k, kernel); });
      for (int n : kSizes) b->Arg(n);
    }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  reporter.PrintTable(backends);
  return 0;
}
