#pragma once
// The measured receptance restricted to the fitting band.
#include <complex>
#include <vector>

namespace mx {

struct FrfBand {
  double from_hz = 0.0;
  double to_hz = 0.0;
  std::vector<double> frequency_hz;             // increasing, from_hz <= f <= to_hz, f > 0
  std::vector<std::complex<double>> h_m_per_n;  // receptance at frequency_hz [m/N]

  std::size_t size() const { return frequency_hz.size(); }
  double rmsMagnitude() const;  // sqrt(mean |H|^2)
};

// The points with from_hz <= f <= to_hz and f > 0 (the lower residual term is singular at 0 Hz).
FrfBand selectBand(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                   double from_hz, double to_hz);

}  // namespace mx
