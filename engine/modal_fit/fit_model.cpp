#include "modal_fit/fit_model.h"

#include <numbers>

namespace mx {

std::complex<double> fittedReceptance(const FittedModel& model, double frequency_hz) {
  const std::complex<double> s{0.0, 2.0 * std::numbers::pi * frequency_hz};
  return receptance(model.modes, s) + model.residuals.lower / (s * s) + model.residuals.upper;
}

std::vector<std::complex<double>> fittedReceptance(const FittedModel& model, const std::vector<double>& frequency_hz) {
  std::vector<std::complex<double>> h;
  h.reserve(frequency_hz.size());
  for (double f : frequency_hz) h.push_back(fittedReceptance(model, f));
  return h;
}

}  // namespace mx
