#include "control/polynomial.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/invalid_input.h"

namespace mx {

double polyMaxAbs(const Poly& p) {
  double m = 0.0;
  for (double c : p) m = std::max(m, std::abs(c));
  return m;
}

Poly polyTrim(const Poly& p, double tol) {
  const double limit = tol * polyMaxAbs(p);
  std::size_t first = 0;
  while (first < p.size() && (p[first] == 0.0 || std::abs(p[first]) <= limit)) ++first;
  return Poly(p.begin() + static_cast<std::ptrdiff_t>(first), p.end());
}

int polyDegree(const Poly& p) {
  return static_cast<int>(polyTrim(p).size()) - 1;
}

Poly polyMultiply(const Poly& a, const Poly& b) {
  if (a.empty() || b.empty()) return {};
  Poly c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

Poly polyAdd(const Poly& a, const Poly& b) {
  const std::size_t n = std::max(a.size(), b.size());
  Poly c(n, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) c[n - a.size() + i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) c[n - b.size() + i] += b[i];
  return c;
}

Poly polySubtract(const Poly& a, const Poly& b) {
  return polyAdd(a, polyScale(b, -1.0));
}

Poly polyScale(const Poly& p, double factor) {
  Poly c(p);
  for (double& x : c) x *= factor;
  return c;
}

double polyEval(const Poly& p, double z) {
  double v = 0.0;
  for (double c : p) v = v * z + c;
  return v;
}

std::complex<double> polyEval(const Poly& p, std::complex<double> z) {
  std::complex<double> v = 0.0;
  for (double c : p) v = v * z + c;
  return v;
}

Roots polyRoots(const Poly& p) {
  Poly q = polyTrim(p);
  if (q.empty()) throw InvalidInput("polynomial roots: the polynomial is zero (all coefficients 0): need degree >= 0");
  Roots roots;
  while (q.size() > 1 && q.back() == 0.0) {  // exact factors z
    q.pop_back();
    roots.emplace_back(0.0, 0.0);
  }
  const int n = static_cast<int>(q.size()) - 1;
  if (n == 1) {
    roots.emplace_back(-q[1] / q[0], 0.0);
  } else if (n > 1) {
    Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
    for (int j = 0; j < n; ++j) companion(0, j) = -q[static_cast<std::size_t>(j) + 1] / q[0];
    for (int i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
    Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
    for (int i = 0; i < n; ++i) roots.push_back(solver.eigenvalues()(i));
  }
  return roots;
}

Poly polyFromRoots(const Roots& roots) {
  std::vector<std::complex<double>> c{1.0};
  for (const auto& r : roots) {
    std::vector<std::complex<double>> next(c.size() + 1, 0.0);
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i] += c[i];
      next[i + 1] -= r * c[i];
    }
    c = std::move(next);
  }
  Poly p(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) p[i] = c[i].real();
  return p;
}

}  // namespace mx
