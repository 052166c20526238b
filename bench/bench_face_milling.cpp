// Face-milling process of Landers & Ulsoy (A1-A12, RK4 at 50 us): step rate in the full cut at 1 and
// 2 mm (2 mm chatters), and a whole supervised run (two 1 mm passes over a 100 mm part, ~42 s
// simulated) under a fixed always-cutting logic. Counters: "steps/s" and "sim_s/s" (simulated seconds
// per wall-clock second).
#include <benchmark/benchmark.h>

#include "supervisor/face_milling_process.h"
#include "supervisor/supervision_run.h"

namespace {

void BM_FaceMillingSteps(benchmark::State& state) {
  mx::FaceMillingParameters p;
  p.part_start_x_m = -1.0;
  p.part_length_m = 2.0;
  mx::FaceMillingProcess proc(p);
  proc.setDepth(static_cast<double>(state.range(0)) * 1e-3);
  proc.setFeedRate(0.01);
  proc.reset(0.0);
  const int n = 20000;  // 1 s simulated
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) proc.step();
    benchmark::DoNotOptimize(proc.output().fy_N);
  }
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FaceMillingSteps)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// SMC I-like fixed logic: monitoring, contact and the model-based controller always on.
class AlwaysOn : public mx::SupervisorLogic {
 public:
  void reset() override {}
  mx::ScanOutput scan(const mx::SignalValues&) override {
    mx::ScanOutput o;
    o.active_steps = {"4"};
    o.level_actions = {"A", "B", "I", "J", "L"};
    return o;
  }
};

void BM_SupervisedRun(benchmark::State& state) {
  mx::SupervisionScenario sc;
  sc.controller = mx::SupervisionController::SmcI;
  sc.pass_depths_m = mx::defaultPassDepths(sc.controller);
  AlwaysOn logic;
  double simulated = 0.0;
  for (auto _ : state) {
    const mx::SupervisionResult r = mx::runSupervision(sc, logic);
    simulated = r.metrics.cycle_time_s;
    benchmark::DoNotOptimize(r.metrics.max_power_W);
  }
  state.counters["sim_s/s"] =
      benchmark::Counter(simulated * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SupervisedRun)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
