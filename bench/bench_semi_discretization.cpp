#include <benchmark/benchmark.h>

#include "bench_fixtures.h"
#include "stability/semi_discretization.h"

// Target: SDM envelope of R1 (one mode per axis), 100 speeds, 40 steps, 0.1 % depth tolerance:
// 2 s or less, single-threaded. Grid 2000 rpm upward in 200 rpm steps (100) or 100 rpm steps (200).
static void sdmEnvelope(benchmark::State& state, int speeds, int steps) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  const double step_rpm = 20000.0 / speeds;
  const auto grid = mx::SpeedGrid{2000.0 / 60, (2000.0 + (speeds - 1) * step_rpm) / 60, step_rpm / 60}.values();
  mx::SdmOptions options;
  options.steps_per_period = steps;
  options.depth_tolerance = 1e-3;
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeSdmLobes(setup, grid, options));
  state.counters["speeds"] = static_cast<double>(grid.size());
}

static void BM_SdmEnvelope_R1_100speeds_40steps(benchmark::State& state) {
  sdmEnvelope(state, 100, 40);
}
BENCHMARK(BM_SdmEnvelope_R1_100speeds_40steps)->Unit(benchmark::kMillisecond);

// GUI responsiveness probe: 200 speeds.
static void BM_SdmEnvelope_R1_200speeds_40steps(benchmark::State& state) {
  sdmEnvelope(state, 200, 40);
}
BENCHMARK(BM_SdmEnvelope_R1_200speeds_40steps)->Unit(benchmark::kMillisecond);

// One dominant-multiplier evaluation (cold Arnoldi start, including the step exponentials).
static void BM_SdmSpectralRadius_R1_40steps(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  for (auto _ : state) benchmark::DoNotOptimize(mx::sdmSpectralRadius(setup, 5800.0 / 60, 0.8e-3, 40));
}
BENCHMARK(BM_SdmSpectralRadius_R1_40steps)->Unit(benchmark::kMicrosecond);
