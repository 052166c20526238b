#pragma once
// Dominant (largest-modulus) Floquet multiplier of an SdmMonodromy without forming the matrix:
// Arnoldi iteration (Saad, "Numerical Methods for Large Eigenvalue Problems", ch. 6) on the implicit
// map, with explicit restarts from the best Ritz vector. A Ritz pair (theta, x = V y) is accepted when
// its residual ||M x - theta x|| = h_{k+1,k} |e_k^T y| <= tolerance * |theta|. If it never converges,
// the monodromy matrix is formed and solved densely.
#include <Eigen/Dense>
#include <complex>

#include "stability/sdm_monodromy.h"

namespace mx {

struct SdmEigenpair {
  std::complex<double> value{0.0, 0.0};  // of a complex pair, the member with Im >= 0
  Eigen::VectorXcd vector;               // unit-norm eigenvector
  double residual = 0.0;                 // ||M x - theta x|| (0 for the dense solve)
  int applications = 0;                  // monodromy applications used
  bool dense = false;                    // true when the dense fallback was used
};

class SdmArnoldi {
 public:
  explicit SdmArnoldi(int krylov_dimension = 24, double tolerance = 1e-9, int max_restarts = 4);

  // `warm` (optional, any real vector of the right size, e.g. Re + Im of an earlier eigenvector) is
  // mixed with a fixed pseudo-random vector so that no direction is missing from the start vector.
  SdmEigenpair dominant(const SdmMonodromy& map, const Eigen::VectorXd* warm = nullptr) const;

  // Real start vector spanning a pair's invariant subspace: Re(v) + Im(v).
  static Eigen::VectorXd warmStart(const Eigen::VectorXcd& v) { return v.real() + v.imag(); }

  static SdmEigenpair denseDominant(const Eigen::MatrixXd& m);

 private:
  int krylov_;
  double tolerance_;
  int max_restarts_;
};

}  // namespace mx
