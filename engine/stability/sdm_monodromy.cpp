#include "stability/sdm_monodromy.h"

#include <cmath>
#include <numbers>

namespace mx {

void SdmMonodromy::reset(const Eigen::MatrixXd& output_c, int steps, int back, int stencil) {
  c_ = output_c;
  steps_ = steps;
  back_ = back;
  stencil_ = stencil;
  cut_index_.assign(static_cast<size_t>(steps), -1);
  phi_.clear();
  g_.clear();
  history_.resize(2, 2 * steps + back);
  z_.resize(c_.cols());
  z_next_.resize(c_.cols());
}

void SdmMonodromy::setCutStep(int i, const Eigen::MatrixXd& phi, const std::vector<StepInput>& g) {
  cut_index_[static_cast<size_t>(i)] = static_cast<int>(phi_.size());
  phi_.push_back(phi);
  g_.push_back(g);
}

void SdmMonodromy::apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const {
  const Eigen::Index n = c_.cols();
  const int m = steps_, past = steps_ + back_;
  z_ = in.head(n);
  // history_.col(j) = r_{j-m-back}: columns 0..m+back-1 from the input, the rest produced here.
  history_.leftCols(past) = Eigen::Map<const Eigen::Matrix<double, 2, Eigen::Dynamic>>(in.data() + n, 2, past);
  for (int k = 0; k < m; ++k) {
    history_.col(past + k).noalias() = c_ * z_;
    const int idx = cut_index_[static_cast<size_t>(k)];
    if (idx < 0) {
      z_next_.noalias() = free_phi_ * z_;
    } else {
      const auto u = static_cast<size_t>(idx);
      z_next_.noalias() = phi_[u] * z_;
      // r_{k-m+j-back} = col(k + j); the last, col(k + stencil - 1), is at most r_k (stencil <= past + 1).
      for (int j = 0; j < stencil_; ++j) z_next_.noalias() += g_[u][static_cast<size_t>(j)] * history_.col(k + j);
    }
    z_.swap(z_next_);
  }
  out.head(n) = z_;
  out.tail(2 * past) = Eigen::Map<const Eigen::VectorXd>(history_.data() + 2 * m, 2 * past);
}

Eigen::MatrixXd SdmMonodromy::dense() const {
  const int d = dimension();
  Eigen::MatrixXd m(d, d);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(d);
  for (int k = 0; k < d; ++k) {
    e[k] = 1.0;
    apply(e, m.col(k));
    e[k] = 0.0;
  }
  return m;
}

double SdmMonodromy::chatterFrequencyHz(std::complex<double> mu, const Eigen::VectorXcd& v, double period_s) const {
  const int m = steps_;
  const Eigen::Index n = c_.cols();
  if (std::abs(mu) == 0.0 || v.size() != dimension() || v.tail(2 * m).norm() == 0.0) return 0.0;
  const Eigen::Index first = n + 2 * back_;  // r_{-m}
  const std::complex<double> log_mu = std::log(mu);
  const double two_pi = 2.0 * std::numbers::pi;
  // p_j = r_j mu^{-(j-m)/m}: the periodic factor of the Floquet mode at the sample times.
  Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic> p(2, m);
  for (int j = 0; j < m; ++j) {
    const std::complex<double> scale = std::exp(-log_mu * (static_cast<double>(j - m) / m));
    p(0, j) = v[first + 2 * j] * scale;
    p(1, j) = v[first + 2 * j + 1] * scale;
  }
  // Dominant harmonic k in [-m/2, m/2) of p (DFT over the m samples).
  int best_k = 0;
  double best_power = -1.0;
  for (int k = -m / 2; k < m - m / 2; ++k) {
    std::complex<double> sx{0.0, 0.0}, sy{0.0, 0.0};
    for (int j = 0; j < m; ++j) {
      const std::complex<double> w = std::polar(1.0, -two_pi * k * j / m);
      sx += p(0, j) * w;
      sy += p(1, j) * w;
    }
    const double power = std::norm(sx) + std::norm(sy);
    if (power > best_power) {
      best_power = power;
      best_k = k;
    }
  }
  return std::abs(std::arg(mu) / two_pi + best_k) / period_s;
}

}  // namespace mx
