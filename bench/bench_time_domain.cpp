// Time-domain simulation hot paths (RK4, seed section 2E). Counter "steps/s": RK4 steps per second
// (benchmark::Counter::kIsRate), for the 2-mode, 3-tooth tool R1 at the 2006 operating point q*.
#include <benchmark/benchmark.h>

#include <numbers>

#include "bench_fixtures.h"
#include "simulation/simulation.h"
#include "simulation/time_domain_simulator.h"

namespace {

const mx::OperatingPoint kQStar{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};

void reportSteps(benchmark::State& state, double steps_per_iteration) {
  state.counters["steps/s"] =
      benchmark::Counter(steps_per_iteration * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// The RK4 kernel alone (constant speed: tabulated angles, fixed delay), full trace recording.
void BM_TimeDomainRK4(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  mx::SimulationOptions options;
  options.regenerative_passes = static_cast<int>(state.range(0));
  double steps = 0.0;
  for (auto _ : state) {
    mx::TimeDomainSimulator simulator(setup, kQStar, options);
    simulator.run();
    benchmark::DoNotOptimize(simulator.window().max_force_n);
    steps = static_cast<double>(simulator.totalSteps());
  }
  reportSteps(state, steps);
}
BENCHMARK(BM_TimeDomainRK4)->Arg(1)->Arg(4)->Unit(benchmark::kMillisecond);

// The same kernel with edge forces and process damping (the extended force of regenerative_force.h: the
// stage's velocities and two more terms per engaged edge); arg 0: neither, 1: both.
void BM_TimeDomainRK4EdgeAndProcessDamping(benchmark::State& state) {
  mx::MillingSetup setup = mx::bench::toolR1();
  if (state.range(0) != 0) {
    setup.tangential_edge_n_per_m = 25e3;
    setup.radial_edge_n_per_m = 30e3;
    setup.process_damping_n_per_m = 1e5;
  }
  double steps = 0.0;
  for (auto _ : state) {
    mx::TimeDomainSimulator simulator(setup, kQStar, mx::SimulationOptions{});
    simulator.run();
    benchmark::DoNotOptimize(simulator.window().max_force_n);
    steps = static_cast<double>(simulator.totalSteps());
  }
  reportSteps(state, steps);
}
BENCHMARK(BM_TimeDomainRK4EdgeAndProcessDamping)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The general kernel under spindle speed variation (theta(t), Newton delay, Hermite history).
void BM_TimeDomainRK4Ssv(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  mx::SimulationOptions options;
  options.ssv = {0.1, 2.0};
  double steps = 0.0;
  for (auto _ : state) {
    mx::TimeDomainSimulator simulator(setup, kQStar, options);
    simulator.run();
    benchmark::DoNotOptimize(simulator.window().max_force_n);
    steps = static_cast<double>(simulator.totalSteps());
  }
  reportSteps(state, steps);
}
BENCHMARK(BM_TimeDomainRK4Ssv)->Unit(benchmark::kMillisecond);

// simulateMilling end to end: validation, RK4, indicators and the FFTW spectra.
void BM_TimeDomainSimulateMilling(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  const mx::SimulationOptions options;
  double steps = 0.0;
  for (auto _ : state) {
    const mx::SimulationResult result = mx::simulateMilling(setup, kQStar, options);
    benchmark::DoNotOptimize(result.indicators.eta);
    steps = static_cast<double>(result.steps_per_tooth_period) * setup.teeth * options.revolutions;
  }
  reportSteps(state, steps);
}
BENCHMARK(BM_TimeDomainSimulateMilling)->Unit(benchmark::kMillisecond);

// A real cutter at a stable point: 4-flute 12 mm end mill (modes 1000 / 1100 Hz), half immersion
// down-milling, variable pitch (80/100 deg), 30 deg helix, b = 3 mm (lag 16.5 deg: 9 slices by default;
// the argument overrides the slice count), 10000 rpm.
void BM_TimeDomainVariablePitchHelix(benchmark::State& state) {
  mx::MillingSetup setup;
  setup.teeth = 4;
  setup.diameter_m = 0.012;
  setup.tangential_coefficient_pa = 6e8;
  setup.radial_ratio = 0.3;
  setup.modes_x = {{1000.0, 0.03, 2.0e7}};
  setup.modes_y = {{1100.0, 0.03, 2.2e7}};
  setup.direction = mx::MillingDirection::Down;
  setup.radial_depth_m = 0.006;
  setup.immersion = mx::Immersion::fromRadialDepth(setup.radial_depth_m, setup.diameter_m, setup.direction);
  const double deg = std::numbers::pi / 180.0;
  setup.pitch_rad = {80 * deg, 100 * deg, 80 * deg, 100 * deg};
  setup.helix_rad = 30 * deg;
  const mx::OperatingPoint point{10000.0 / 60.0, 3e-3, 0.05e-3};
  mx::SimulationOptions options;
  options.axial_slices = static_cast<int>(state.range(0));
  double steps = 0.0;
  for (auto _ : state) {
    mx::TimeDomainSimulator simulator(setup, point, options);
    simulator.run();
    benchmark::DoNotOptimize(simulator.window().max_force_n);
    steps = static_cast<double>(simulator.totalSteps());
  }
  reportSteps(state, steps);
}
BENCHMARK(BM_TimeDomainVariablePitchHelix)->Arg(0)->Arg(1)->Arg(32)->Unit(benchmark::kMillisecond);

// The CVODE reference over 20 revolutions (rtol 1e-8), for scale.
void BM_TimeDomainCvodeReference(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  for (auto _ : state) benchmark::DoNotOptimize(mx::simulateMillingCvode(setup, kQStar, 20, 1e-8).size());
}
BENCHMARK(BM_TimeDomainCvodeReference)->Unit(benchmark::kMillisecond);

}  // namespace
