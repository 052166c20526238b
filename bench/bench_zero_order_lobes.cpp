#include <benchmark/benchmark.h>

#include <numbers>

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

// ZOA on R1's receptances sampled at 4001 lines (0-4000 Hz by 1 Hz), no modes: every line plus the
// subdivisions of the resonance intervals is a chatter frequency.
static void BM_ZoaLobes_R1_measured_4001_lines(benchmark::State& state) {
  mx::MillingSetup setup = mx::bench::toolR1();
  auto sampled = [](const mx::ModalAxis& modes) {
    mx::MeasuredAxis axis;
    for (int i = 0; i <= 4000; ++i) {
      const double f = static_cast<double>(i);
      axis.frequency_hz.push_back(f);
      axis.h_m_per_n.push_back(mx::receptance(modes, {0.0, 2.0 * std::numbers::pi * f}));
    }
    return axis;
  };
  setup.measured_x = sampled(setup.modes_x);
  setup.measured_y = sampled(setup.modes_y);
  setup.modes_x.clear();
  setup.modes_y.clear();
  const auto speeds = mx::SpeedGrid{1000.0 / 60, 20000.0 / 60, 100.0 / 60}.values();
  mx::ZoaOptions options;
  options.lobe_count = 30;
  options.dynamics = mx::DynamicsSource::Measured;
  for (auto _ : state) benchmark::DoNotOptimize(mx::computeZoaLobes(setup, speeds, options));
}
BENCHMARK(BM_ZoaLobes_R1_measured_4001_lines)->Unit(benchmark::kMillisecond);
