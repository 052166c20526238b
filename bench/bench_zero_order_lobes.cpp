#include <benchmark/benchmark.h>

#include "bench_fixtures.h"
#include "stability/zero_order_lobes.h"

// Target: zeroth-order lobes, 2 modes, 30 lobes: 5 ms or less.
static void BM_ZoaLobes_R1_2modes_30lobes(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  const auto speeds = mx::SpeedGrid{1000.0 / 60, 20000.0 / 60, 100.0 / 60}.values();
  mx::ZoaOptions options;
  options.lobe_count = 30;
  options.delta_per_s = static_cast<double>(state.range(0)) / 100.0;  // Arg in 0.01 1/s
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeZoaLobes(setup, speeds, options));
}
BENCHMARK(BM_ZoaLobes_R1_2modes_30lobes)->Arg(0)->Arg(5)->Arg(500)->Unit(benchmark::kMillisecond);
