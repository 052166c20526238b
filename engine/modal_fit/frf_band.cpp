#include "modal_fit/frf_band.h"

#include <cmath>
#include <complex>

namespace mx {

double FrfBand::rmsMagnitude() const {
  double sum = 0.0;
  for (const auto& h : h_m_per_n) sum += std::norm(h);
  return h_m_per_n.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(h_m_per_n.size()));
}

FrfBand selectBand(const std::vector<double>& frequency_hz, const std::vector<std::complex<double>>& h_m_per_n,
                   double from_hz, double to_hz) {
  FrfBand band{from_hz, to_hz, {}, {}};
  for (std::size_t i = 0; i < frequency_hz.size() && i < h_m_per_n.size(); ++i) {
    const double f = frequency_hz[i];
    if (f < from_hz || f > to_hz || f <= 0.0) continue;
    band.frequency_hz.push_back(f);
    band.h_m_per_n.push_back(h_m_per_n[i]);
  }
  return band;
}

}  // namespace mx
