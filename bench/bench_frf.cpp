// Tap-test FRF files: a 100 000-line ASCII universal file (four datasets 58 of 25 000 points, one
// point a line) read, and the same FRFs as 58b. Target: the ASCII read <= 100 ms.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <complex>
#include <string>
#include <vector>

#include "frf/uff_reader.h"
#include "frf/uff_writer.h"

namespace {

std::vector<mx::FrfDataset> datasets(int count, int points) {
  std::vector<mx::FrfDataset> out;
  for (int k = 0; k < count; ++k) {
    mx::FrfDataset d;
    d.index = k + 1;
    d.name = "bench " + std::to_string(k);
    d.response_direction = d.reference_direction = static_cast<mx::FrfDirection>(k % 3);
    for (int i = 0; i < points; ++i) {
      const double f = 0.5 + 0.25 * i;
      d.frequency_hz.push_back(f);
      // One mode at 600 Hz, k = 5e6 N/m, zeta = 0.03.
      const double r = f / 600.0;
      d.values.push_back(1.0 / (5e6 * std::complex<double>(1.0 - r * r, 2.0 * 0.03 * r)));
    }
    out.push_back(std::move(d));
  }
  return out;
}

void BM_ReadUff58Ascii(benchmark::State& state) {
  const std::string text = mx::uff58String(datasets(4, static_cast<int>(state.range(0)) / 4));
  for (auto _ : state) benchmark::DoNotOptimize(mx::readUff(text, "bench.unv").datasets.size());
  state.counters["lines"] = static_cast<double>(std::count(text.begin(), text.end(), '\n'));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ReadUff58Ascii)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_ReadUff58b(benchmark::State& state) {
  const std::string bytes = mx::uff58bString(datasets(4, static_cast<int>(state.range(0)) / 4));
  for (auto _ : state) benchmark::DoNotOptimize(mx::readUff(bytes, "bench.uff").datasets.size());
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bytes.size()));
}
BENCHMARK(BM_ReadUff58b)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_WriteUff58(benchmark::State& state) {
  const auto d = datasets(4, static_cast<int>(state.range(0)) / 4);
  for (auto _ : state) benchmark::DoNotOptimize(mx::uff58String(d).size());
}
BENCHMARK(BM_WriteUff58)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
