#include "stability/sdm_monodromy.h"

#include <cmath>
#include <numbers>

namespace mx {

void SdmMonodromy::reset(const Eigen::MatrixXd& output_c, int steps, int depth) {
  c_ = output_c;
  steps_ = steps;
  depth_ = depth;
  cut_index_.assign(static_cast<size_t>(steps), -1);
  phi_.clear();
  terms_.clear();
  history_.resize(2, steps + depth);
  z_.resize(c_.cols());
  z_next_.resize(c_.cols());
}

void SdmMonodromy::setCutStep(int i, const Eigen::MatrixXd& phi, std::vector<DelayedTerm> terms) {
  cut_index_[static_cast<size_t>(i)] = static_cast<int>(phi_.size());
  phi_.push_back(phi);
  terms_.push_back(std::move(terms));
}

void SdmMonodromy::apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const {
  const Eigen::Index n = c_.cols();
  z_ = in.head(n);
  // history_.col(k + D) = r_k: columns 0 .. D-1 from the input, the rest produced here.
  history_.leftCols(depth_) = Eigen::Map<const Eigen::Matrix<double, 2, Eigen::Dynamic>>(in.data() + n, 2, depth_);
  for (int k = 0; k < steps_; ++k) {
    history_.col(depth_ + k).noalias() = c_ * z_;
    const int idx = cut_index_[static_cast<size_t>(k)];
    if (idx < 0) {
      z_next_.noalias() = free_phi_ * z_;
    } else {
      const auto u = static_cast<size_t>(idx);
      z_next_.noalias() = phi_[u] * z_;
      for (const DelayedTerm& t : terms_[u]) z_next_.noalias() += t.g * history_.col(depth_ + k - t.offset);
    }
    z_.swap(z_next_);
  }
  out.head(n) = z_;
  out.tail(2 * depth_) = Eigen::Map<const Eigen::VectorXd>(history_.data() + 2 * steps_, 2 * depth_);
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

Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic> SdmMonodromy::periodSamples(const Eigen::VectorXcd& v) const {
  const int m = steps_;
  const Eigen::Index n = c_.cols();
  Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic> r =
      Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic>::Zero(2, m);
  if (depth_ >= m) {  // r_{-m} .. r_{-1} are stored: p_j below uses t_j = (j - m) T/m
    for (int j = 0; j < m; ++j) {
      r(0, j) = v[n + 2 * (depth_ - m + j)];
      r(1, j) = v[n + 2 * (depth_ - m + j) + 1];
    }
    return r;
  }
  Eigen::VectorXd image(dimension());
  for (const bool imaginary : {false, true}) {
    const Eigen::VectorXd part = imaginary ? Eigen::VectorXd(v.imag()) : Eigen::VectorXd(v.real());
    apply(part, image);  // fills history_ with r_0 .. r_{m-1}
    for (int j = 0; j < m; ++j)
      for (int a = 0; a < 2; ++a)
        r(a, j) += imaginary ? std::complex<double>(0.0, history_(a, depth_ + j))
                             : std::complex<double>(history_(a, depth_ + j), 0.0);
  }
  return r;
}

double SdmMonodromy::chatterFrequencyHz(std::complex<double> mu, const Eigen::VectorXcd& v, double period_s) const {
  const int m = steps_;
  if (std::abs(mu) == 0.0 || v.size() != dimension() || v.tail(2 * depth_).norm() == 0.0) return 0.0;
  const std::complex<double> log_mu = std::log(mu);
  const double two_pi = 2.0 * std::numbers::pi;
  const double first = depth_ >= m ? -m : 0;  // time index of the first sample
  // p_j = r_j mu^{-t_j/T}: the periodic factor of the Floquet mode at the sample times.
  Eigen::Matrix<std::complex<double>, 2, Eigen::Dynamic> p = periodSamples(v);
  for (int j = 0; j < m; ++j) p.col(j) *= std::exp(-log_mu * ((first + j) / m));
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
