// Pareto set of 100k points with four objectives: SaLSa (pareto/pareto_front.h) on uniform
// random scores and on anti-correlated scores (large fronts), and the objective table + front of the
// case study's admissible grid (projects/rubio-pareto-case.mxproj, 20 rpm grid). Recorded in
// docs/performance.md.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "expert/admissible_grid.h"
#include "pareto/objective_table.h"
#include "pareto/pareto_front.h"

namespace {

std::vector<mx::ObjectiveVector> points(std::size_t n, bool anti) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<mx::ObjectiveVector> out(n);
  for (auto& p : out) {
    p = {u(rng), u(rng), u(rng), u(rng)};
    if (anti) {
      const double s = p[0] + p[1] + p[2] + p[3];
      for (double& v : p) v = v * 2.0 / s + 0.02 * u(rng);
    }
  }
  return out;
}

// The non-dominated set of n uniform (small front) or anti-correlated (almost all non-dominated) points.
void BM_ParetoFront(benchmark::State& state, bool anti_correlated) {
  const auto pts = points(static_cast<std::size_t>(state.range(0)), anti_correlated);
  std::size_t m = 0;
  for (auto _ : state) {
    auto f = mx::nonDominated(pts);
    m = f.size();
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["front"] = static_cast<double>(m);
}
BENCHMARK_CAPTURE(BM_ParetoFront, Uniform, false)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ParetoFront, AntiCorrelated, true)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_ParetoFrontBruteForce(benchmark::State& state) {
  const auto pts = points(static_cast<std::size_t>(state.range(0)), false);
  for (auto _ : state) benchmark::DoNotOptimize(mx::nonDominatedBruteForce(pts).data());
}
BENCHMARK(BM_ParetoFrontBruteForce)->Arg(10000)->Unit(benchmark::kMillisecond);

mx::MillingSetup caseTool() {
  mx::MillingSetup s;
  s.teeth = 3;
  s.diameter_m = 0.030;
  s.tangential_coefficient_pa = 6e8;
  s.radial_ratio = 0.3;
  s.modes_x = {{603.0, 0.039, 5.59e6}};
  s.modes_y = {{666.0, 0.035, 5.715e6}};
  s.direction = mx::MillingDirection::Up;
  s.radial_depth_m = 0.030;
  s.immersion = mx::Immersion::fromRadialDepth(0.030, 0.030, s.direction);
  return s;
}

void BM_ParetoCaseGrid(benchmark::State& state) {
  mx::ExpertSettings s;
  s.grid.speed_from_rev_per_s = 1000.0 / 60.0;
  s.grid.speed_to_rev_per_s = 5000.0 / 60.0;
  s.grid.speed_step_rev_per_s = 20.0 / 60.0;
  s.grid.feed_step_m = 0.01e-3;
  s.limits.spindle_power_w = 2745.3;
  s.limits.max_feed_velocity_m_per_s = 25e-3;
  s.limits.max_feed_per_tooth_m = 0.3e-3;
  s.stability.delta_per_s = 0.05;
  s.stability.alpha = 0.95;
  const mx::AdmissibleGrid grid(caseTool(), s);
  std::size_t n = 0, m = 0;
  for (auto _ : state) {
    const mx::ObjectiveTable table(grid, mx::ParetoModels{});
    const auto f = mx::nonDominated(table.scores());
    n = table.size();
    m = f.size();
  }
  state.counters["points"] = static_cast<double>(n);
  state.counters["front"] = static_cast<double>(m);
}
BENCHMARK(BM_ParetoCaseGrid)->Unit(benchmark::kMillisecond);

}  // namespace
