#include "modal_fit/modal_pole.h"

#include <cmath>
#include <numbers>

namespace mx {

std::complex<double> poleOf(const Mode& mode) {
  const double w = mode.angularFrequency();
  const double z = mode.damping_ratio;
  return {-z * w, w * std::sqrt(1.0 - z * z)};
}

std::complex<double> residueOf(const Mode& mode) {
  const double w = mode.angularFrequency();
  const double wd = w * std::sqrt(1.0 - mode.damping_ratio * mode.damping_ratio);
  return {0.0, -w * w / (2.0 * mode.stiffness_n_per_m * wd)};
}

double poleFrequencyHz(std::complex<double> pole) {
  return std::abs(pole) / (2.0 * std::numbers::pi);
}

double poleDampingRatio(std::complex<double> pole) {
  return -pole.real() / std::abs(pole);
}

Mode modeFromResidue(std::complex<double> pole, std::complex<double> residue) {
  const double w = std::abs(pole);
  const double wd = std::abs(pole.imag());
  return {poleFrequencyHz(pole), poleDampingRatio(pole), -w * w / (2.0 * wd * residue.imag())};
}

}  // namespace mx
