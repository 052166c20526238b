#include <benchmark/benchmark.h>

#include "bench_fixtures.h"
#include "model/cutting_force.h"

static void BM_EvaluateCut(benchmark::State& state) {
  const mx::MillingSetup setup = mx::bench::toolR1();
  const mx::OperatingPoint point{5800.0 / 60.0, 0.4924e-3, 0.2722e-3};
  for (auto _ : state) benchmark::DoNotOptimize(mx::evaluateCut(setup, point));
}
BENCHMARK(BM_EvaluateCut);
