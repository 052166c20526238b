#pragma once
// Least-squares complex-frequency estimator (LSCF; Guillaume et al., IMAC 2003; Peeters et al.,
// PolyMAX, Shock Vib. 11, 2004) for one FRF: the common-denominator model in the z-domain
//   H(w) = N(z) / D(z),  N = sum_j b_j z^j,  D = sum_j a_j z^j,  z = exp(i w dt),  dt = 1 / (2 f_max),
// with real coefficients, j = 0..n, fitted by the linearised least squares of e_k = N(z_k) - H_k D(z_k).
// Unit weighting makes the normal equations' blocks Toeplitz (d = l - j):
//   R_jl = r(d) = Re sum_k z_k^d,  S_jl = s(d) = -Re sum_k H_k z_k^d,  T_jl = t(d) = Re sum_k |H_k|^2 z_k^d.
// Eliminating the numerator (b = -R^-1 S a) leaves the reduced normal equations M a = 0,
// M = T - S^T R^-1 S, solved with the last coefficient a_n = 1. The poles are the roots z_r of D (the
// companion matrix's eigenvalues), lambda_r = ln(z_r) / dt. z-domain basis functions lie on the unit
// circle, which scales the frequencies for conditioning; H is scaled by its RMS.
#include <complex>
#include <vector>

#include "modal_fit/frf_band.h"

namespace mx {

class LscfEstimator {
 public:
  // The Toeplitz sequences up to max_order (>= 1) over band (to_hz > 0 sets dt); throws InvalidInput.
  LscfEstimator(const FrfBand& band, int max_order);

  // All n = order continuous-time poles of the order-n model [rad/s]; 1 <= order <= max_order.
  std::vector<std::complex<double>> poles(int order) const;

  double samplingInterval() const { return dt_; }
  int maxOrder() const { return max_order_; }

 private:
  double dt_ = 0.0;
  int max_order_ = 0;
  std::vector<double> r_, t_;  // d = 0..max_order (even sequences)
  std::vector<double> s_;      // d = -max_order..max_order at index d + max_order
};

}  // namespace mx
