#include "control/froh_discretization.h"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/invalid_input.h"

namespace mx {

namespace {

void validate(const StateSpace2& plant, double T, double beta) {
  if (!(T > 0.0) || !std::isfinite(T))
    throw InvalidInput("beta-FROH: sampling_period = " + std::to_string(T) + " s: must be finite and > 0");
  if (!(beta >= -1.0 && beta <= 1.0))
    throw InvalidInput("beta-FROH: beta = " + std::to_string(beta) + ": must be in [-1, 1]");
  if (!plant.A.allFinite() || !plant.B.allFinite() || !plant.C.allFinite())
    throw InvalidInput("beta-FROH: plant matrices contain non-finite entries: must be finite");
}

// adj(zI - Phi) = z I + K
Eigen::Matrix2d adjugateConstant(const Eigen::Matrix2d& Phi) {
  Eigen::Matrix2d K;
  K << -Phi(1, 1), Phi(0, 1), Phi(1, 0), -Phi(0, 0);
  return K;
}

}  // namespace

ZohBlocks zohBlocks(const StateSpace2& plant, double T) {
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.block<2, 2>(0, 0) = plant.A * T;
  M.block<2, 2>(0, 2) = Eigen::Matrix2d::Identity() * T;
  M.block<2, 2>(2, 4) = Eigen::Matrix2d::Identity() * T;
  const Eigen::Matrix<double, 6, 6> E = M.exp();
  // E = [[e^{AT}, int e^{As} ds, int int e^{As} ds dt], [0, I, T I], [0, 0, I]] (the I blocks absorb the T scaling:
  // the (0,2) block of exp(M) is int_0^1 e^{A T r} dr * T = Psi, the (0,4) block is Xi).
  return {E.block<2, 2>(0, 0), E.block<2, 2>(0, 2), E.block<2, 2>(0, 4)};
}

DiscreteTransferFunction zohDiscretize(const StateSpace2& plant, double T) {
  return frohDiscretize(plant, T, 0.0);
}

DiscreteTransferFunction frohDiscretize(const StateSpace2& plant, double T, double beta) {
  validate(plant, T, beta);
  const ZohBlocks z = zohBlocks(plant, T);
  const Eigen::Matrix2d K = adjugateConstant(z.Phi);
  const double tr = z.Phi.trace();
  const double det = z.Phi.determinant();
  const Eigen::Vector2d gamma0 = z.Psi * plant.B;  // ZOH input matrix
  // Z[h0 G] = N0 / D with N0 = C adj(zI - Phi) Gamma0, D = z^2 - tr z + det.
  const double n0_1 = plant.C * gamma0;
  const double n0_0 = plant.C * K * gamma0;
  // (z - 1) Z[h0 G/s] = N1 / D: the integral of y over one period is C (Psi x_k + Xi B u_k).
  const double cxb = plant.C * z.Xi * plant.B;
  const double n1_2 = cxb;
  const double n1_1 = plant.C * z.Psi * gamma0 - tr * cxb;
  const double n1_0 = plant.C * z.Psi * K * gamma0 + det * cxb;

  DiscreteTransferFunction h;
  h.sampling_period_s = T;
  h.beta = beta;
  if (beta == 0.0) {
    h.num = {n0_1, n0_0};
    h.den = {1.0, -tr, det};
    return h;
  }
  // H_beta = [(z - beta) N0 + (beta / T) N1] / (z D)
  const double g = beta / T;
  h.num = {n0_1 + g * n1_2, n0_0 - beta * n0_1 + g * n1_1, -beta * n0_0 + g * n1_0};
  h.den = {1.0, -tr, det, 0.0};
  return h;
}

Roots DiscreteTransferFunction::poles() const {
  return polyRoots(den);
}

Roots DiscreteTransferFunction::zeros() const {
  const Poly n = polyTrim(num);
  if (n.size() <= 1) return {};
  return polyRoots(n);
}

double DiscreteTransferFunction::maxZeroModulus() const {
  double m = 0.0;
  for (const auto& r : zeros()) m = std::max(m, std::abs(r));
  return m;
}

double DiscreteTransferFunction::dcGain() const {
  const double d = polyEval(den, 1.0);
  return d == 0.0 ? std::numeric_limits<double>::infinity() : polyEval(num, 1.0) / d;
}

StateSpace2 referenceModel(double damping_ratio, double natural_frequency_rad_s) {
  if (!(damping_ratio > 0.0) || !std::isfinite(damping_ratio))
    throw InvalidInput("reference model: xi = " + std::to_string(damping_ratio) + ": must be finite and > 0");
  if (!(natural_frequency_rad_s > 0.0) || !std::isfinite(natural_frequency_rad_s))
    throw InvalidInput("reference model: omega_n = " + std::to_string(natural_frequency_rad_s) +
                       " rad/s: must be finite and > 0");
  const double w = natural_frequency_rad_s;
  StateSpace2 m;
  m.A << 0.0, 1.0, -w * w, -2.0 * damping_ratio * w;
  m.B << 0.0, 1.0;
  m.C << w * w, 0.0;
  return m;
}

}  // namespace mx
