#pragma once
// A measured receptance FRF of one axis, used directly by the ZOA, which needs G(i omega) only at the
// chatter frequency (Rubio et al. 2006, eq. 8). SI units: Hz lines, m/N.
#include <complex>
#include <string_view>
#include <vector>

namespace mx {

// A measured receptance FRF of one axis (m/N at Hz lines), as the ZOA uses it.
struct MeasuredAxis {
  std::vector<double> frequency_hz;  // strictly increasing, > 0 after the first line may be 0
  std::vector<std::complex<double>> h_m_per_n;

  // Throws InvalidInput (core/invalid_input.h) naming `name` (e.g. "frf_x"), the offending index/value and the
  // rule: sizes equal, >= 2 lines, finite, frequencies strictly increasing and >= 0.
  void validate(std::string_view name) const;

  // Linear interpolation of the real and imaginary parts at omega [rad/s]; 0 outside [f_front, f_back] (no
  // measured compliance there).
  std::complex<double> at(double omega_rad_per_s) const;
};

}  // namespace mx
