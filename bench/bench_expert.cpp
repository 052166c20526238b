// Expert system: building the session of the 20-tool library (lobes + admissible grids),
// re-ranking after a weight change (a pass over the cached grids), and the full ranking with the
// time-domain refinement (Rules 4-6). The library is projects/library-20-tools.mxproj, repeated
// here because the benchmark links the engine only (no project reader).
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "expert/expert_session.h"

namespace {

struct LibTool {
  const char* id;
  double d_mm;
  int teeth;
  std::vector<std::array<double, 3>> x, y;  // Hz, %, N/um
};

std::vector<mx::MillingSetup> library20() {
  const std::vector<LibTool> tools{
      {"E04-2", 4, 2, {{2950, 1.2, 0.55}}, {{2890, 1.3, 0.52}}},
      {"E05-3", 5, 3, {{2700, 1.4, 0.75}}, {{2650, 1.5, 0.72}}},
      {"E06-2", 6, 2, {{2400, 1.6, 1.0}}, {{2350, 1.5, 0.95}}},
      {"E06-4", 6, 4, {{2450, 1.8, 1.1}}, {{2380, 1.7, 1.05}}},
      {"E08-2", 8, 2, {{2100, 2.0, 1.6}}, {{2050, 2.1, 1.5}}},
      {"E08-3", 8, 3, {{2150, 2.2, 1.7}}, {{2080, 2.0, 1.6}}},
      {"E10-3", 10, 3, {{1800, 2.5, 2.4}}, {{1750, 2.4, 2.3}}},
      {"E10-4", 10, 4, {{1850, 2.3, 2.5}, {2900, 3.0, 9.0}}, {{1790, 2.2, 2.4}}},
      {"E12-2", 12, 2, {{1550, 2.8, 3.2}}, {{1500, 2.9, 3.0}}},
      {"E12-3", 12, 3, {{1600, 3.0, 3.4}}, {{1560, 2.8, 3.3}}},
      {"E12-4", 12, 4, {{1620, 2.6, 3.5}, {2600, 3.5, 12.0}}, {{1580, 2.7, 3.4}}},
      {"E14-3", 14, 3, {{1400, 3.2, 4.5}}, {{1360, 3.0, 4.3}}},
      {"E16-3", 16, 3, {{1250, 3.4, 5.8}}, {{1220, 3.3, 5.6}}},
      {"E16-4", 16, 4, {{1280, 3.0, 6.0}, {2200, 4.0, 15.0}}, {{1240, 3.1, 5.9}}},
      {"E16-6", 16, 6, {{1300, 2.8, 6.2}}, {{1260, 2.9, 6.0}}},
      {"E20-3", 20, 3, {{950, 3.8, 8.5}}, {{920, 3.6, 8.2}}},
      {"E20-4", 20, 4, {{980, 3.5, 9.0}, {1900, 4.5, 18.0}}, {{940, 3.4, 8.8}}},
      {"E20-5", 20, 5, {{1000, 3.2, 9.5}}, {{970, 3.3, 9.2}}},
      {"E25-4", 25, 4, {{620, 4.5, 14.0}, {1500, 5.0, 20.0}}, {{600, 4.2, 13.5}}},
      {"E25-6", 25, 6, {{650, 4.8, 15.0}}, {{410, 4.0, 12.0}}},
  };
  std::vector<mx::MillingSetup> out;
  for (const LibTool& t : tools) {
    mx::MillingSetup s;
    s.tool_id = t.id;
    s.teeth = t.teeth;
    s.diameter_m = t.d_mm * 1e-3;
    s.tangential_coefficient_pa = 700e6;
    s.radial_ratio = 0.3;
    for (const auto& m : t.x) s.modes_x.push_back({m[0], m[1] / 100.0, m[2] * 1e6});
    for (const auto& m : t.y) s.modes_y.push_back({m[0], m[1] / 100.0, m[2] * 1e6});
    s.direction = mx::MillingDirection::Down;
    s.radial_depth_m = 0.5 * s.diameter_m;
    s.immersion = mx::Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
    out.push_back(s);
  }
  return out;
}

// The project's settings: default grid 1000-12000 rpm by 100 rpm (+ Rule 7.2 speeds), depth b_min/10,
// feed 0.01 mm; 7.5 kW, 12000 rpm, 150 mm/s, 0.2 mm/tooth; delta 0.05 1/s, alpha 0.95.
mx::ExpertSettings librarySettings() {
  mx::ExpertSettings s;
  s.limits.spindle_power_w = 7500.0;
  s.limits.max_spindle_rev_per_s = 200.0;
  s.limits.max_feed_velocity_m_per_s = 0.150;
  s.limits.max_feed_per_tooth_m = 0.2e-3;
  s.stability.delta_per_s = 0.05;
  s.stability.alpha = 0.95;
  return s;
}

void BM_ExpertLibrary20_BuildSession(benchmark::State& state) {
  const auto tools = library20();
  for (auto _ : state) {
    mx::ExpertSession session(tools, librarySettings());
    benchmark::DoNotOptimize(session.normalisation());
  }
}
BENCHMARK(BM_ExpertLibrary20_BuildSession)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ExpertLibrary20_Reweigh(benchmark::State& state) {
  const mx::ExpertSession session(library20(), librarySettings());
  std::int64_t points = 0;
  for (std::size_t t = 0; t < session.toolCount(); ++t) points += session.grid(t).pointCount();
  state.counters["points"] = static_cast<double>(points);
  int i = 0;
  for (auto _ : state) {
    const double c1 = 0.05 + 0.01 * (i++ % 50);
    benchmark::DoNotOptimize(session.rank({c1, 0.9 - c1, 0.1}));
  }
}
BENCHMARK(BM_ExpertLibrary20_Reweigh)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ExpertLibrary20_FullRanking(benchmark::State& state) {
  const auto tools = library20();
  for (auto _ : state) {
    mx::ExpertSession session(tools, librarySettings());
    benchmark::DoNotOptimize(session.run(mx::CostWeights{}, true));
  }
}
BENCHMARK(BM_ExpertLibrary20_FullRanking)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

}  // namespace
