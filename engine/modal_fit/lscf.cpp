#include "modal_fit/lscf.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <string>

#include "core/invalid_input.h"

namespace mx {

LscfEstimator::LscfEstimator(const FrfBand& band, int max_order)
    : dt_(1.0 / (2.0 * band.to_hz)), max_order_(max_order) {
  if (max_order < 1) throw InvalidInput("LSCF: max_order = " + std::to_string(max_order) + ": must be >= 1");
  if (!(band.to_hz > 0.0)) throw InvalidInput("LSCF: to_hz = " + std::to_string(band.to_hz) + ": must be > 0 Hz");
  const auto n = static_cast<std::size_t>(max_order);
  const double scale = band.rmsMagnitude() > 0.0 ? 1.0 / band.rmsMagnitude() : 1.0;
  r_.assign(n + 1, 0.0);
  t_.assign(n + 1, 0.0);
  s_.assign(2 * n + 1, 0.0);
  for (std::size_t k = 0; k < band.size(); ++k) {
    const std::complex<double> z = std::polar(1.0, 2.0 * std::numbers::pi * band.frequency_hz[k] * dt_);
    const std::complex<double> h = band.h_m_per_n[k] * scale;
    const double h2 = std::norm(h);
    std::complex<double> zd{1.0, 0.0};  // z^d
    for (std::size_t d = 0; d <= n; ++d, zd *= z) {
      r_[d] += zd.real();
      t_[d] += h2 * zd.real();
      s_[n + d] -= (h * zd).real();
      s_[n - d] -= (h * std::conj(zd)).real();  // z^-d; d = 0 written twice with the same value
    }
  }
  s_[n] *= 0.5;
}

std::vector<std::complex<double>> LscfEstimator::poles(int order) const {
  if (order < 1 || order > max_order_)
    throw InvalidInput("LSCF: order = " + std::to_string(order) + ": must be in [1, " + std::to_string(max_order_) +
                       "]");
  const int m = order + 1;
  const auto offset = static_cast<std::size_t>(max_order_);
  Eigen::MatrixXd R(m, m), S(m, m), T(m, m);
  for (int j = 0; j < m; ++j)
    for (int l = 0; l < m; ++l) {
      const auto d = static_cast<std::size_t>(std::abs(l - j));
      R(j, l) = r_[d];
      T(j, l) = t_[d];
      S(j, l) = s_[static_cast<std::size_t>(static_cast<long>(offset) + (l - j))];
    }
  const Eigen::MatrixXd M = T - S.transpose() * R.ldlt().solve(S);
  const Eigen::VectorXd a = M.topLeftCorner(order, order).colPivHouseholderQr().solve(-M.topRightCorner(order, 1));
  // Companion matrix of the monic z^n + a_{n-1} z^{n-1} + ... + a_0.
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(order, order);
  for (int j = 0; j < order; ++j) companion(0, j) = -a(order - 1 - j);
  for (int j = 1; j < order; ++j) companion(j, j - 1) = 1.0;
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(companion, false);
  std::vector<std::complex<double>> lambdas;
  lambdas.reserve(static_cast<std::size_t>(order));
  for (int j = 0; j < order; ++j) lambdas.push_back(std::log(eigen.eigenvalues()(j)) / dt_);
  return lambdas;
}

}  // namespace mx
