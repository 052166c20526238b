#include "modal_fit/fit_error.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/invalid_input.h"

namespace mx {

double fitErrorPercent(const std::vector<std::complex<double>>& measured,
                       const std::vector<std::complex<double>>& fitted) {
  if (measured.size() != fitted.size())
    throw InvalidInput("fit error: fitted size = " + std::to_string(fitted.size()) + ": must equal the measured size " +
                       std::to_string(measured.size()));
  double difference = 0.0, reference = 0.0;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    difference += std::norm(fitted[i] - measured[i]);
    reference += std::norm(measured[i]);
  }
  if (reference == 0.0) return difference == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return 100.0 * std::sqrt(difference / reference);
}

}  // namespace mx
