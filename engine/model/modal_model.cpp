#include "model/modal_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mx {

double Mode::angularFrequency() const {
  return 2.0 * std::numbers::pi * natural_frequency_hz;
}

double Mode::modalMass() const {
  const double w = angularFrequency();
  return stiffness_n_per_m / (w * w);
}

double Mode::decayRate() const {
  return damping_ratio * angularFrequency();
}

std::complex<double> receptance(const ModalAxis& axis, std::complex<double> s) {
  std::complex<double> g{0.0, 0.0};
  for (const Mode& m : axis) {
    const double w = m.angularFrequency();
    g += (w * w / m.stiffness_n_per_m) / (s * s + 2.0 * m.damping_ratio * w * s + w * w);
  }
  return g;
}

double smallestDecayRate(const ModalAxis& x, const ModalAxis& y) {
  double rate = std::numeric_limits<double>::infinity();
  for (const Mode& m : x) rate = std::min(rate, m.decayRate());
  for (const Mode& m : y) rate = std::min(rate, m.decayRate());
  return rate;
}

}  // namespace mx
