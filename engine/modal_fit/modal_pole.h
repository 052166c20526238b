#pragma once
// Continuous-time pole and residue of one mode of a receptance, and back (real-mode assumption).
//
// One term of mx::receptance, G(s) = (w^2/k) / (s^2 + 2 zeta w s + w^2), in partial fractions
// (Ewins, Modal Testing, 2000, sec. 2.3; Heylen et al., Modal Analysis Theory and Testing, 1997):
//   G(s) = A / (s - lambda) + conj(A) / (s - conj(lambda)),
//   lambda = -zeta w + i w_d,   w_d = w sqrt(1 - zeta^2),
//   A = (w^2/k) / (lambda - conj(lambda)) = -i w^2 / (2 k w_d) = -i / (2 m w_d),   m = k / w^2.
// Inverted, with only the imaginary part of A carrying a real (proportionally damped) mode:
//   k = -w^2 / (2 w_d Im A) = -w / (2 sqrt(1 - zeta^2) Im A),   m = -1 / (2 w_d Im A).
// A driving-point receptance has Im A < 0, i.e. k > 0.
#include <complex>

#include "model/modal_model.h"

namespace mx {

std::complex<double> poleOf(const Mode& mode);       // lambda [rad/s]
std::complex<double> residueOf(const Mode& mode);    // A [m/(N s)]
double poleFrequencyHz(std::complex<double> pole);   // |lambda| / (2 pi)
double poleDampingRatio(std::complex<double> pole);  // -Re lambda / |lambda|

// Frequency and damping from the pole, k from Im A (formula above); k <= 0 or inf when Im A >= 0.
Mode modeFromResidue(std::complex<double> pole, std::complex<double> residue);

}  // namespace mx
