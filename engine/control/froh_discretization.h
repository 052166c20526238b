#pragma once
// beta-FROH discretization (Rubio, De la Sen & Ibeas 2006, eq. 24-25) of a 2nd-order SISO continuous plant
// dx/dt = A x + B u, y = C x. The hold output over [kT, (k+1)T) is
//   u(t) = u_k + beta (u_k - u_{k-1}) (t - kT) / T,   beta in [-1, 1] (0: ZOH, 1: FOH).
// H_beta is built, as in eq. 25, from the ZOH transforms of G and of G/s:
//   H_beta(z) = (z - beta)/z Z[h0 G] + beta (z - 1)/(T z) Z[h0 G/s].
// Both ZOH transforms come from ONE matrix exponential (Van Loan block [[A,I,0],[0,0,I],[0,0,0]] T), so
// repeated or nearly equal time constants need no special case and nothing is divided by their difference.
#include <Eigen/Core>
#include <complex>

#include "control/polynomial.h"

namespace mx {

struct StateSpace2 {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Eigen::Vector2d B = Eigen::Vector2d::Zero();
  Eigen::RowVector2d C = Eigen::RowVector2d::Zero();
};

// H(z) = num(z) / den(z), descending powers, den monic. For beta != 0: den = z (z^2 + d1 z + d2), num of
// degree 2 (eq. 32-33); for beta == 0 the common factor z is removed exactly (eq. 30-31).
struct DiscreteTransferFunction {
  Poly num;
  Poly den;
  double sampling_period_s = 0.0;
  double beta = 0.0;

  Roots poles() const;
  Roots zeros() const;
  double maxZeroModulus() const;  // 0 when there is no finite zero
  double dcGain() const;          // num(1) / den(1)
};

// The exact sampled quantities of one period, from the Van Loan exponential.
struct ZohBlocks {
  Eigen::Matrix2d Phi;  // e^{AT}
  Eigen::Matrix2d Psi;  // int_0^T e^{A s} ds
  Eigen::Matrix2d Xi;   // int_0^T int_0^t e^{A s} ds dt
};
ZohBlocks zohBlocks(const StateSpace2& plant, double T);

DiscreteTransferFunction zohDiscretize(const StateSpace2& plant, double T);
// Throws InvalidInput for T <= 0, beta outside [-1, 1] or non-finite entries.
DiscreteTransferFunction frohDiscretize(const StateSpace2& plant, double T, double beta);

// Second-order reference model G_m(s) = wn^2 / (s^2 + 2 xi wn s + wn^2) in state-space form.
StateSpace2 referenceModel(double damping_ratio, double natural_frequency_rad_s);

}  // namespace mx
