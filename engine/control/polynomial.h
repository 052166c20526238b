#pragma once
// Real polynomials in z for the discrete control units. Coefficients are stored in DESCENDING powers:
// p = {p0, p1, ..., pn} means p0 z^n + p1 z^(n-1) + ... + pn. An empty vector is the zero polynomial.
#include <complex>
#include <vector>

namespace mx {

using Poly = std::vector<double>;
using Roots = std::vector<std::complex<double>>;

// Leading coefficients with |c| <= tol * max|c| are dropped (tol = 0: only exact zeros).
Poly polyTrim(const Poly& p, double tol = 0.0);
int polyDegree(const Poly& p);  // -1 for the zero polynomial
Poly polyMultiply(const Poly& a, const Poly& b);
Poly polyAdd(const Poly& a, const Poly& b);  // aligned at the constant term
Poly polySubtract(const Poly& a, const Poly& b);
Poly polyScale(const Poly& p, double factor);
double polyEval(const Poly& p, double z);
std::complex<double> polyEval(const Poly& p, std::complex<double> z);
double polyMaxAbs(const Poly& p);

// Roots by the eigenvalues of the companion matrix (Eigen). Trailing zero coefficients give exact roots at
// z = 0; degree 1 is solved directly. Throws InvalidInput for the zero polynomial.
Roots polyRoots(const Poly& p);
// Monic polynomial with the given roots; complex roots must come in conjugate pairs (imaginary parts of
// the product are discarded).
Poly polyFromRoots(const Roots& roots);

}  // namespace mx
