#pragma once
// Modal description of the tool's structural dynamics (Rubio et al. 2006, eq. 1),
// extended to any number of modes per axis. SI units throughout.
#include <complex>
#include <vector>

namespace mx {

struct Mode {
  double natural_frequency_hz = 0.0;
  double damping_ratio = 0.0;      // zeta, dimensionless (0, 1)
  double stiffness_n_per_m = 0.0;  // modal stiffness k

  double angularFrequency() const;  // omega_n [rad/s]
  double modalMass() const;         // m = k / omega_n^2 [kg]
  double decayRate() const;         // zeta * omega_n [1/s]
};

using ModalAxis = std::vector<Mode>;  // empty axis = rigid

// Receptance of one axis: G(s) = sum_r (omega_r^2 / k_r) / (s^2 + 2 zeta_r omega_r s + omega_r^2) [m/N].
std::complex<double> receptance(const ModalAxis& axis, std::complex<double> s);

// Smallest zeta*omega_n over both axes; +inf when both are rigid.
double smallestDecayRate(const ModalAxis& x, const ModalAxis& y);

}  // namespace mx
