#include <benchmark/benchmark.h>

#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "modal_fit/frf_band.h"
#include "modal_fit/lscf_diagram.h"
#include "modal_fit/modal_fit.h"

namespace {

// 4000 lines to 4 kHz of five modes with 2 % complex noise relative to |H|.
mx::FrfBand noisyFiveModes() {
  const mx::ModalAxis modes{
      {350.0, 0.025, 1.5e7}, {1000.0, 0.03, 3e7}, {1650.0, 0.015, 5e7}, {2500.0, 0.02, 4e7}, {3300.0, 0.03, 6e7}};
  std::mt19937 rng(1);
  std::normal_distribution<double> normal;
  mx::FrfBand band{1.0, 4000.0, {}, {}};
  for (int i = 1; i <= 4000; ++i) {
    const double f = i;
    const auto h = mx::receptance(modes, {0.0, 2.0 * std::numbers::pi * f});
    band.frequency_hz.push_back(f);
    band.h_m_per_n.push_back(h * (1.0 + 0.02 * std::complex<double>(normal(rng), normal(rng)) / std::sqrt(2.0)));
  }
  return band;
}

}  // namespace

// Target: LSCF over 4000 lines, orders 2..40, with the stabilisation diagram: 200 ms or less.
static void BM_LscfDiagram_4000lines_order40(benchmark::State& state) {
  const mx::FrfBand band = noisyFiveModes();
  for (auto _ : state) benchmark::DoNotOptimize(mx::lscfDiagram(band, 40));
}
BENCHMARK(BM_LscfDiagram_4000lines_order40)->Unit(benchmark::kMillisecond);

// The whole fit (diagram to order 40, selection, LSFD, Levenberg-Marquardt) on the same data.
static void BM_FitModes_4000lines_20modes(benchmark::State& state) {
  const mx::FrfBand band = noisyFiveModes();
  mx::ModalFitSettings settings;
  settings.from_hz = band.from_hz;
  settings.to_hz = band.to_hz;
  settings.max_modes = 20;
  for (auto _ : state) benchmark::DoNotOptimize(mx::fitModes(band.frequency_hz, band.h_m_per_n, settings));
}
BENCHMARK(BM_FitModes_4000lines_20modes)->Unit(benchmark::kMillisecond);
