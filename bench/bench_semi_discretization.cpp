#include <benchmark/benchmark.h>

#include <numbers>

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
  options.delay_order = 1;  // the first-order SDM these figures were first taken with
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

// Accuracy against time (docs/performance.md): Insperger's benchmark, 5000-25000 rpm by 100 rpm
// (201 speeds), first-order SDM at fixed steps (Arg 1: steps) against the default (cubic delay
// interpolation, steps per autoSdmSteps: Arg 0). Arg 2: a/D in percent.
static void BM_SdmLobes_Insperger(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::insperger(static_cast<double>(state.range(2)) / 100.0);
  const auto grid = mx::SpeedGrid{5000.0 / 60, 25000.0 / 60, 100.0 / 60}.values();
  mx::SdmOptions options;
  if (state.range(1) > 0) {
    options.steps_per_period = static_cast<int>(state.range(1));
    options.delay_order = static_cast<int>(state.range(0));
  }
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeSdmLobes(setup, grid, options));
}
BENCHMARK(BM_SdmLobes_Insperger)
    ->ArgNames({"order", "steps", "aD_pct"})
    ->Args({1, 40, 100})
    ->Args({1, 100, 100})
    ->Args({1, 200, 100})
    ->Args({1, 400, 100})
    ->Args({3, 0, 100})
    ->Args({1, 40, 5})
    ->Args({1, 100, 5})
    ->Args({3, 0, 5})
    ->Unit(benchmark::kMillisecond);

// Real cutters at the default accuracy (docs/performance.md): a 4-tooth 70/110/70/110 deg cutter on
// Insperger's slot (one revolution of 4 m steps per principal period, two delays) over 200 speeds, and
// a 3-tooth 30 deg helix cutter at a/D = 0.1 (exact helix average, recomputed at every depth tried).
static void BM_SdmLobes_VariablePitch4_200speeds(benchmark::State& state) {
  mx::MillingSetup setup = mx::bench::insperger(1.0);
  setup.teeth = 4;
  const double deg = std::numbers::pi / 180.0;
  setup.pitch_rad = {70 * deg, 110 * deg, 70 * deg, 110 * deg};
  const auto grid = mx::SpeedGrid{5000.0 / 60, 24900.0 / 60, 100.0 / 60}.values();
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeSdmLobes(setup, grid, {}));
}
BENCHMARK(BM_SdmLobes_VariablePitch4_200speeds)->Unit(benchmark::kMillisecond);

static void BM_SdmLobes_Helix30_3teeth_aD10_200speeds(benchmark::State& state) {
  mx::MillingSetup setup = mx::bench::insperger(0.1);
  setup.teeth = 3;
  setup.helix_rad = 30.0 * std::numbers::pi / 180.0;
  const auto grid = mx::SpeedGrid{5000.0 / 60, 24900.0 / 60, 100.0 / 60}.values();
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeSdmLobes(setup, grid, {}));
}
BENCHMARK(BM_SdmLobes_Helix30_3teeth_aD10_200speeds)->Unit(benchmark::kMillisecond);

// One dominant-multiplier evaluation (cold Arnoldi start, including the step exponentials).
static void BM_SdmSpectralRadius_R1_40steps(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  for (auto _ : state) benchmark::DoNotOptimize(mx::sdmSpectralRadius(setup, 5800.0 / 60, 0.8e-3, 40));
}
BENCHMARK(BM_SdmSpectralRadius_R1_40steps)->Unit(benchmark::kMicrosecond);
