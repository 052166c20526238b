#pragma once
// Every FRF as receptance X/F in m/N. With s = i*omega, omega = 2*pi*f: mobility V/F = s X/F and
// accelerance A/F = s^2 X/F, so receptance = mobility / (i omega) = accelerance / (-omega^2).
// At f = 0 a mobility or accelerance says nothing about the static receptance (0/0): such points are
// dropped (tap tests often start at 0 Hz, and the rest of the FRF stays usable). Receptance input keeps
// every point.
#include <complex>
#include <string>
#include <vector>

#include "frf/frf_dataset.h"

namespace mx {

struct Receptance {
  FrfDirection direction = FrfDirection::X;            // of the response
  FrfDirection reference_direction = FrfDirection::X;  // of the force; equal to direction for a direct FRF
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> h_m_per_n;
};

Receptance toReceptance(const FrfDataset& dataset);

// The inverse: a receptance as `quantity` (times i omega or (i omega)^2) in positive `direction`, node 1.
FrfDataset fromReceptance(const Receptance& receptance, FrfQuantity quantity, std::string name);

}  // namespace mx
