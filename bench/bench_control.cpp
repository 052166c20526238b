// Adaptive force control under beta-FROH: one closed-loop simulation of the 2006 paper's workpiece
// (targets: >= 100x real time, i.e. the run's simulated duration / wall time >= 100), the 31-point beta sweep
// (target: <= 2 s on 2 cores), and the beta-FROH discretization itself. Counters: realtime_factor = simulated
// seconds per wall second.
#include <benchmark/benchmark.h>

#include "control/beta_sweep.h"
#include "control/closed_loop.h"
#include "control/force_plant.h"
#include "control/froh_discretization.h"

namespace {

void BM_ControlClosedLoopPaperWorkpiece(benchmark::State& state) {
  mx::AdaptiveControlSettings s;
  s.beta = static_cast<double>(state.range(0)) / 10.0;
  double simulated = 0.0;
  for (auto _ : state) {
    const mx::ClosedLoopResult r = mx::simulateAdaptiveForceControl(s);
    simulated += r.metrics.duration_s;
    benchmark::DoNotOptimize(r.metrics.Jc_N_s);
  }
  state.counters["realtime_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ControlClosedLoopPaperWorkpiece)
    ->Arg(-3)
    ->Arg(0)
    ->Arg(3)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ControlBetaSweep31(benchmark::State& state) {
  const mx::AdaptiveControlSettings s;
  for (auto _ : state) {
    const mx::BetaSweepResult r = mx::sweepBeta(s, {-1.0, 1.0, 2.0 / 30.0, 0});
    benchmark::DoNotOptimize(r.best_beta);
  }
}
BENCHMARK(BM_ControlBetaSweep31)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ControlFrohDiscretize(benchmark::State& state) {
  const mx::CuttingProcess process;
  const mx::StateSpace2 plant = mx::makeForcePlant(process, 3e-3).stateSpace();
  const double T = mx::spindlePeriod(process);
  for (auto _ : state) benchmark::DoNotOptimize(mx::frohDiscretize(plant, T, -0.3).num.data());
}
BENCHMARK(BM_ControlFrohDiscretize);

}  // namespace
