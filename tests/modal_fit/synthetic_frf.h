#pragma once
// Synthetic receptances for the modal-fit tests: mx::receptance of known modes on a frequency grid,
// optionally with complex noise relative to |H| at each point, H (1 + noise (n1 + i n2) / sqrt 2),
// n1, n2 standard normal from a seeded std::mt19937.
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "modal_fit/fit_settings.h"
#include "model/modal_model.h"

namespace mx::test {

struct SyntheticFrf {
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> h_m_per_n;
};

// `points` frequencies from f0 to f1; uneven spacing f0 + (f1 - f0) u^1.5 with u uniform in [0, 1].
inline SyntheticFrf syntheticFrf(const ModalAxis& modes, double f0, double f1, int points, double noise = 0.0,
                                 unsigned seed = 1, bool uneven = false) {
  SyntheticFrf frf;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  for (int i = 0; i < points; ++i) {
    const double u = static_cast<double>(i) / (points - 1);
    const double f = f0 + (f1 - f0) * (uneven ? std::pow(u, 1.5) : u);
    std::complex<double> h = receptance(modes, {0.0, 2.0 * std::numbers::pi * f});
    if (noise > 0.0) h *= 1.0 + noise * std::complex<double>(normal(rng), normal(rng)) / std::sqrt(2.0);
    frf.frequency_hz.push_back(f);
    frf.h_m_per_n.push_back(h);
  }
  return frf;
}

inline ModalFitSettings bandSettings(double from_hz, double to_hz, int max_modes = 10,
                                     std::optional<int> modes = std::nullopt) {
  ModalFitSettings settings;
  settings.from_hz = from_hz;
  settings.to_hz = to_hz;
  settings.max_modes = max_modes;
  settings.modes = modes;
  return settings;
}

inline double relativeError(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

}  // namespace mx::test
