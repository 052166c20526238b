#include "frf/receptance_conversion.h"

#include <algorithm>
#include <numbers>

namespace mx {

Receptance toReceptance(const FrfDataset& d) {
  Receptance r;
  r.direction = d.response_direction;
  r.reference_direction = d.reference_direction;
  r.frequency_hz.reserve(d.frequency_hz.size());
  r.h_m_per_n.reserve(d.values.size());
  const std::size_t n = std::min(d.frequency_hz.size(), d.values.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double f = d.frequency_hz[i];
    const std::complex<double> s(0.0, 2.0 * std::numbers::pi * f);
    std::complex<double> h = d.values[i];
    if (d.quantity != FrfQuantity::Receptance && f == 0.0) continue;
    if (d.quantity == FrfQuantity::Mobility) h /= s;
    if (d.quantity == FrfQuantity::Accelerance) h /= s * s;
    r.frequency_hz.push_back(f);
    r.h_m_per_n.push_back(h);
  }
  return r;
}

FrfDataset fromReceptance(const Receptance& r, FrfQuantity quantity, std::string name) {
  FrfDataset d;
  d.index = 1;
  d.quantity = quantity;
  d.response_direction = r.direction;
  d.reference_direction = r.reference_direction;
  d.response_node = d.reference_node = 1;
  d.name = std::move(name);
  d.frequency_hz = r.frequency_hz;
  d.values.reserve(r.h_m_per_n.size());
  for (std::size_t i = 0; i < r.h_m_per_n.size(); ++i) {
    const std::complex<double> s(0.0, 2.0 * std::numbers::pi * r.frequency_hz[i]);
    std::complex<double> h = r.h_m_per_n[i];
    if (quantity == FrfQuantity::Mobility) h *= s;
    if (quantity == FrfQuantity::Accelerance) h *= s * s;
    d.values.push_back(h);
  }
  return d;
}

}  // namespace mx
