// Time-domain simulation hot paths (RK4, seed section 2E). Counter "steps/s": RK4 steps per second
// (benchmark::Counter::kIsRate), for the 2-mode, 3-tooth tool R1 at the 2006 operating point q*.
#include <benchmark/benchmark.h>

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

// The CVODE reference over 20 revolutions (rtol 1e-8), for scale.
void BM_TimeDomainCvodeReference(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  for (auto _ : state) benchmark::DoNotOptimize(mx::simulateMillingCvode(setup, kQStar, 20, 1e-8).size());
}
BENCHMARK(BM_TimeDomainCvodeReference)->Unit(benchmark::kMillisecond);

}  // namespace
