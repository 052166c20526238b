#include "stability/sdm_arnoldi.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace mx {

namespace {

// Deterministic pseudo-random vector in [-0.5, 0.5)^n (64-bit LCG, Knuth MMIX constants).
Eigen::VectorXd seedVector(Eigen::Index n) {
  Eigen::VectorXd v(n);
  std::uint64_t x = 0x9E3779B97F4A7C15ULL;
  for (Eigen::Index i = 0; i < n; ++i) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    v[i] = static_cast<double>(x >> 11) * 0x1.0p-53 - 0.5;
  }
  return v.normalized();
}

// Index of the largest-modulus eigenvalue; of a conjugate pair, the one with Im >= 0.
Eigen::Index dominantIndex(const Eigen::VectorXcd& values) {
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < values.size(); ++i) {
    const double a = std::abs(values[i]), b = std::abs(values[best]);
    if (a > b * (1.0 + 1e-12) || (a >= b * (1.0 - 1e-12) && values[i].imag() > values[best].imag())) best = i;
  }
  return best;
}

struct Ritz {
  std::complex<double> value{0.0, 0.0};
  Eigen::VectorXcd y;
  double residual = std::numeric_limits<double>::infinity();
};

// Dominant Ritz pair of the k x k Hessenberg matrix; h_next = h_{k+1,k}.
Ritz dominantRitz(const Eigen::MatrixXd& h, Eigen::Index k, double h_next) {
  Ritz out;
  Eigen::EigenSolver<Eigen::MatrixXd> es(h.topLeftCorner(k, k));
  if (es.info() != Eigen::Success) return out;
  const Eigen::Index i = dominantIndex(es.eigenvalues());
  out.value = es.eigenvalues()[i];
  out.y = es.eigenvectors().col(i).normalized();
  out.residual = std::abs(h_next) * std::abs(out.y[k - 1]);
  return out;
}

}  // namespace

SdmArnoldi::SdmArnoldi(int krylov_dimension, double tolerance, int max_restarts)
    : krylov_(krylov_dimension), tolerance_(tolerance), max_restarts_(max_restarts) {}

SdmEigenpair SdmArnoldi::denseDominant(const Eigen::MatrixXd& m) {
  SdmEigenpair out;
  out.dense = true;
  Eigen::EigenSolver<Eigen::MatrixXd> es(m);
  const Eigen::Index i = dominantIndex(es.eigenvalues());
  out.value = es.eigenvalues()[i];
  out.vector = es.eigenvectors().col(i).normalized();
  return out;
}

SdmEigenpair SdmArnoldi::dominant(const SdmMonodromy& map, const Eigen::VectorXd* warm) const {
  const Eigen::Index n = map.dimension();
  const Eigen::Index kmax = std::min<Eigen::Index>(krylov_, n);
  Eigen::VectorXd start = seedVector(n);
  if (warm != nullptr && warm->size() == n && warm->norm() > 0.0) start = warm->normalized() + 1e-2 * start;

  Eigen::MatrixXd v(n, kmax + 1);
  Eigen::MatrixXd h(kmax + 1, kmax);
  Eigen::VectorXd w(n);
  int applications = 0;
  for (int restart = 0; restart <= max_restarts_; ++restart) {
    h.setZero();
    v.col(0) = start.normalized();
    double scale = 0.0;
    Ritz best;
    Eigen::Index k = 0;
    bool breakdown = false;
    for (Eigen::Index j = 0; j < kmax; ++j) {
      map.apply(v.col(j), w);
      ++applications;
      scale = std::max(scale, w.norm());
      // Modified Gram-Schmidt, two passes (re-orthogonalisation).
      for (int pass = 0; pass < 2; ++pass) {
        for (Eigen::Index i = 0; i <= j; ++i) {
          const double c = v.col(i).dot(w);
          h(i, j) += c;
          w -= c * v.col(i);
        }
      }
      const double beta = w.norm();
      k = j + 1;
      breakdown = beta <= 1e-14 * scale;  // invariant subspace: Ritz pairs are exact
      h(j + 1, j) = breakdown ? 0.0 : beta;
      if (!breakdown) v.col(j + 1) = w / beta;
      const bool check = breakdown || k == kmax || (k >= 8 && k % 6 == 2);
      if (!check) continue;
      best = dominantRitz(h, k, h(j + 1, j));
      if (breakdown || best.residual <= tolerance_ * std::abs(best.value)) break;
    }
    const Eigen::VectorXcd x = (v.leftCols(k).cast<std::complex<double>>() * best.y).normalized();
    if (breakdown || best.residual <= tolerance_ * std::abs(best.value)) {
      SdmEigenpair out;
      out.value = best.value;
      out.vector = x;
      out.residual = best.residual;
      out.applications = applications;
      return out;
    }
    if (best.y.size() == 0 || !std::isfinite(best.residual)) break;
    start = warmStart(x);
  }
  SdmEigenpair out = denseDominant(map.dense());
  out.applications = applications + static_cast<int>(n);
  return out;
}

}  // namespace mx
