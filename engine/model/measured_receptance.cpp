#include "model/measured_receptance.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "core/invalid_input.h"

namespace mx {

namespace {

[[noreturn]] void fail(std::string_view name, const std::string& what) {
  std::ostringstream msg;
  msg << name << ": " << what;
  throw InvalidInput(msg.str());
}

}  // namespace

void MeasuredAxis::validate(std::string_view name) const {
  if (frequency_hz.size() != h_m_per_n.size()) {
    std::ostringstream msg;
    msg << "frequency_hz has " << frequency_hz.size() << " lines and h_m_per_n " << h_m_per_n.size()
        << ": the sizes must be equal";
    fail(name, msg.str());
  }
  if (frequency_hz.size() < 2) {
    std::ostringstream msg;
    msg << frequency_hz.size() << " lines: a measured FRF needs >= 2 lines";
    fail(name, msg.str());
  }
  for (std::size_t i = 0; i < frequency_hz.size(); ++i) {
    const double f = frequency_hz[i];
    const std::complex<double> h = h_m_per_n[i];
    std::ostringstream msg;
    if (!std::isfinite(f)) {
      msg << "frequency_hz[" << i << "] = " << f << " Hz: must be finite";
    } else if (f < 0.0) {
      msg << "frequency_hz[" << i << "] = " << f << " Hz: must be >= 0";
    } else if (i > 0 && !(f > frequency_hz[i - 1])) {
      msg << "frequency_hz[" << i << "] = " << f << " Hz: must be strictly increasing (frequency_hz[" << i - 1
          << "] = " << frequency_hz[i - 1] << " Hz)";
    } else if (!std::isfinite(h.real()) || !std::isfinite(h.imag())) {
      msg << "h_m_per_n[" << i << "] = (" << h.real() << ", " << h.imag() << ") m/N: must be finite";
    } else {
      continue;
    }
    fail(name, msg.str());
  }
}

std::complex<double> MeasuredAxis::at(double omega_rad_per_s) const {
  if (frequency_hz.empty()) return {};
  // A relative slack of 1e-12 at the ends, so that omega = 2 pi f_line hits the end lines despite rounding.
  const double slack = 1e-12 * std::abs(frequency_hz.back());
  double f = omega_rad_per_s / (2.0 * std::numbers::pi);
  if (!(f >= frequency_hz.front() - slack && f <= frequency_hz.back() + slack)) return {};
  f = std::clamp(f, frequency_hz.front(), frequency_hz.back());
  // First line above f; f == f_back takes the last interval at t = 1.
  auto upper = std::upper_bound(frequency_hz.begin(), frequency_hz.end(), f);
  if (upper == frequency_hz.end()) --upper;
  const auto i = static_cast<std::size_t>(upper - frequency_hz.begin());
  if (i == 0) return h_m_per_n.front();
  const double t = (f - frequency_hz[i - 1]) / (frequency_hz[i] - frequency_hz[i - 1]);
  return h_m_per_n[i - 1] + t * (h_m_per_n[i] - h_m_per_n[i - 1]);
}

}  // namespace mx
