#include "control/pole_placement.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/invalid_input.h"

namespace mx {

namespace {

RstDesign failed(RstDesign d, const std::string& why) {
  d.ok = false;
  d.message = why;
  return d;
}

bool allFinite(const Poly& p) {
  return std::all_of(p.begin(), p.end(), [](double c) { return std::isfinite(c); });
}

// coefficient of z^power in a descending polynomial
double coeff(const Poly& p, int power) {
  const int n = static_cast<int>(p.size()) - 1;
  return power < 0 || power > n ? 0.0 : p[static_cast<std::size_t>(n - power)];
}

}  // namespace

void validatePolePlacementSettings(const PolePlacementSettings& s) {
  if (!(s.cancel_radius > 0.0 && s.cancel_radius <= 1.0))
    throw InvalidInput("pole placement: cancel_radius = " + std::to_string(s.cancel_radius) + ": must be in (0, 1]");
  if (!(s.common_factor_tolerance >= 0.0 && s.common_factor_tolerance < 1.0))
    throw InvalidInput("pole placement: common_factor_tolerance = " + std::to_string(s.common_factor_tolerance) +
                       ": must be in [0, 1)");
  if (!(std::abs(s.observer_pole) < 1.0))
    throw InvalidInput("pole placement: observer_pole = " + std::to_string(s.observer_pole) + ": must be in (-1, 1)");
  if (!(s.leading_tolerance >= 0.0 && s.leading_tolerance < 1.0))
    throw InvalidInput("pole placement: leading_tolerance = " + std::to_string(s.leading_tolerance) +
                       ": must be in [0, 1)");
}

RstDesign designModelFollowing(const Poly& A_in, const Poly& B_in, const Poly& Am_in, const Poly& Bm_in,
                               const PolePlacementSettings& st) {
  validatePolePlacementSettings(st);
  RstDesign d;
  if (!allFinite(A_in) || !allFinite(B_in) || !allFinite(Am_in) || !allFinite(Bm_in))
    return failed(d, "non-finite coefficients");
  const Poly A = polyTrim(A_in), Am = polyTrim(Am_in), Bm = polyTrim(Bm_in);
  Poly B = polyTrim(B_in, st.leading_tolerance);
  if (A.empty() || A[0] != 1.0 || Am.empty() || Am[0] != 1.0) return failed(d, "A and Am must be monic");
  if (B.empty() || polyMaxAbs(B) == 0.0) return failed(d, "B is zero: no control authority");
  if (Bm.empty()) return failed(d, "Bm is zero");
  if (polyDegree(B) >= polyDegree(A)) return failed(d, "deg B >= deg A: not strictly proper");

  // 1. near-common factors
  Roots poles = polyRoots(A);
  Roots zeros = B.size() > 1 ? polyRoots(B) : Roots{};
  const double lead = B[0];
  Roots kept_zeros;
  for (const auto& z : zeros) {
    std::size_t best = poles.size();
    double best_distance = 0.0;
    for (std::size_t i = 0; i < poles.size(); ++i) {
      const double dist = std::abs(poles[i] - z);
      if (best == poles.size() || dist < best_distance) {
        best = i;
        best_distance = dist;
      }
    }
    if (best < poles.size() && best_distance < st.common_factor_tolerance * std::max(1.0, std::abs(z))) {
      if (std::abs(z) >= 1.0 || std::abs(poles[best]) >= 1.0) d.unstable_common_factor = true;
      poles.erase(poles.begin() + static_cast<std::ptrdiff_t>(best));
      ++d.common_factors_removed;
    } else {
      kept_zeros.push_back(z);
    }
  }
  d.A_used = d.common_factors_removed > 0 ? polyFromRoots(poles) : A;
  d.B_used = d.common_factors_removed > 0 ? polyScale(polyFromRoots(kept_zeros), lead) : B;

  // 2. split the remaining zeros
  Roots cancel, keep;
  for (const auto& z : kept_zeros) (std::abs(z) < st.cancel_radius ? cancel : keep).push_back(z);
  d.zeros_cancelled = static_cast<int>(cancel.size());
  d.zeros_kept = static_cast<int>(keep.size());
  d.B_plus = polyFromRoots(cancel);
  d.B_minus = polyScale(polyFromRoots(keep), lead);
  d.model_zeros_followed = keep.empty();
  if (d.model_zeros_followed) {
    d.Bm_prime = polyScale(Bm, 1.0 / lead);  // lead != 0: B was trimmed
  } else {
    const double bm1 = polyEval(d.B_minus, 1.0);
    if (!(std::abs(bm1) > 1e-12 * polyMaxAbs(d.B_minus))) return failed(d, "B- has a zero at z = 1: no static gain");
    d.Bm_prime = {polyEval(Am, 1.0) / bm1};
  }

  // 3. degrees (eq. 27) and the smallest observer polynomial that keeps the controller causal
  const int n = polyDegree(d.A_used), mminus = polyDegree(d.B_minus), dbp = polyDegree(d.B_plus);
  const int dam = polyDegree(Am), dbmp = polyDegree(d.Bm_prime);
  int k = -1;
  for (int cand = std::max(0, 2 * n - dam - dbp - 1); cand <= 32; ++cand) {
    const int r = dam + cand - n;
    if (r >= mminus && r >= 0 && dbp + r >= n - 1 && dbp + r >= cand + dbmp) {
      k = cand;
      break;
    }
  }
  if (k < 0 || n < 1) return failed(d, "no causal controller for these degrees");
  const int r = dam + k - n;
  d.Ao = polyFromRoots(Roots(static_cast<std::size_t>(k), std::complex<double>(st.observer_pole, 0.0)));
  const Poly rhs = polyMultiply(Am, d.Ao);  // degree n + r, monic

  // 4. Sylvester system for R' = z^r + r1 z^{r-1} + ... and S = s0 z^{n-1} + ... + s_{n-1}
  const int N = n + r;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(N, N);
  Eigen::VectorXd b(N);
  for (int row = 0; row < N; ++row) {
    const int power = N - 1 - row;
    b(row) = coeff(rhs, power) - coeff(d.A_used, power - r);
    for (int i = 1; i <= r; ++i) M(row, i - 1) = coeff(d.A_used, power - (r - i));
    for (int j = 0; j < n; ++j) M(row, r + j) = coeff(d.B_minus, power - (n - 1 - j));
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
  d.sylvester_rcond = lu.rcond();
  if (!(d.sylvester_rcond > 1e-13)) return failed(d, "Sylvester matrix singular: A and B- share a factor");
  const Eigen::VectorXd x = lu.solve(b);
  d.R_prime.assign(static_cast<std::size_t>(r) + 1, 1.0);
  for (int i = 1; i <= r; ++i) d.R_prime[static_cast<std::size_t>(i)] = x(i - 1);
  d.S.assign(static_cast<std::size_t>(n), 0.0);
  for (int j = 0; j < n; ++j) d.S[static_cast<std::size_t>(j)] = x(r + j);

  const Poly lhs = polyAdd(polyMultiply(d.A_used, d.R_prime), polyMultiply(d.B_minus, d.S));
  d.diophantine_residual = polyMaxAbs(polySubtract(lhs, rhs)) / polyMaxAbs(rhs);
  d.R = polyMultiply(d.B_plus, d.R_prime);
  d.T = polyMultiply(d.Bm_prime, d.Ao);
  if (!allFinite(d.R) || !allFinite(d.S) || !allFinite(d.T) || !std::isfinite(d.diophantine_residual))
    return failed(d, "non-finite controller");
  d.ok = true;
  d.message = d.model_zeros_followed ? "model following (all zeros cancelled)"
                                     : "fallback: " + std::to_string(d.zeros_kept) + " zero(s) not cancelled";
  return d;
}

}  // namespace mx
