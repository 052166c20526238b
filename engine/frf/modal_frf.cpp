#include "frf/modal_frf.h"

#include <cmath>
#include <numbers>
#include <random>

#include "frf/receptance_conversion.h"

namespace mx {

FrfDataset modalFrfDataset(const ModalAxis& modes, FrfQuantity quantity, const std::vector<double>& frequency_hz,
                           FrfDirection direction, std::string name) {
  Receptance r{direction, direction, frequency_hz, {}};
  r.h_m_per_n.reserve(frequency_hz.size());
  for (const double f : frequency_hz) r.h_m_per_n.push_back(receptance(modes, {0.0, 2.0 * std::numbers::pi * f}));
  return fromReceptance(r, quantity, std::move(name));
}

void addRelativeNoise(std::vector<std::complex<double>>& values, double noise, std::uint32_t seed) {
  std::mt19937 rng(seed);
  const auto uniform = [&rng] { return (static_cast<double>(rng()) + 0.5) / 4294967296.0; };  // (0, 1)
  for (std::complex<double>& h : values) {
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    const std::complex<double> n(radius * std::cos(angle), radius * std::sin(angle));
    h *= 1.0 + noise * n / std::numbers::sqrt2;
  }
}

}  // namespace mx
