#include <benchmark/benchmark.h>

#include <numbers>

#include "bench_fixtures.h"
#include "model/cutting_force.h"

static void BM_EvaluateCut(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  const mx::OperatingPoint point{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
  for (auto _ : state) benchmark::DoNotOptimize(mx::evaluateCut(setup, point));
}
BENCHMARK(BM_EvaluateCut);

// The readout of the largest cutter the project allows: a 100-tooth, 100 mm face mill with alternating
// pitch (3.5 / 3.7 deg), a 60 deg helix and runout (0-8 um), at 2 mm depth (one revolution of samples).
static void BM_EvaluateCutHundredTeeth(benchmark::State& state) {
  mx::MillingSetup setup = mx::bench::toolR1();
  setup.teeth = mx::MillingSetup::kMaxTeeth;
  setup.diameter_m = 0.1;
  setup.helix_rad = 60.0 * std::numbers::pi / 180.0;
  for (int j = 0; j < setup.teeth; ++j) {
    setup.pitch_rad.push_back((j % 2 == 0 ? 3.5 : 3.7) * std::numbers::pi / 180.0);
    setup.runout_m.push_back((j % 5) * 2e-6);
  }
  const mx::OperatingPoint point{3000.0 / 60.0, 2e-3, 0.1e-3};
  for (auto _ : state) benchmark::DoNotOptimize(mx::evaluateCut(setup, point));
}
BENCHMARK(BM_EvaluateCutHundredTeeth)->Unit(benchmark::kMillisecond);
