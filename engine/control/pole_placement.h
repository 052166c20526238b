#pragma once
// Model-following pole placement (2006 paper, eq. 27-29; Astrom & Wittenmark's RST design).
// Plant A y = B u (A monic, deg B < deg A), model Am ym = Bm uc. B = B+ B- with B+ monic (cancelled zeros),
// R = B+ R', T = Bm' Ao, and the Diophantine equation (eq. 28)
//   A R' + B- S = Am Ao
// solved through its Sylvester matrix (Eigen, full-pivot LU). Controller (eq. 29): R u = T uc - S y.
//
// Safeguards (all reported, none divides by zero or returns NaN):
// - near-common factors of A and B (|pole - zero| < tol max(1, |zero|)) are removed from both first; they are
//   either structural (the FROH pole at z = 0 against the drive zero near 0) or artefacts of an
//   over-parameterised estimate, and would make the Sylvester matrix singular;
// - zeros with |z| >= cancel_radius (unstable or poorly damped) are not cancelled: they stay in B-, and the
//   closed loop becomes B- Bm' / Am with the scalar Bm' = Am(1) / B-(1) (unit static gain) instead of Bm / Am;
// - a singular Sylvester matrix, a zero static gain of B- or any non-finite number gives ok = false.
#include <string>

#include "control/polynomial.h"

namespace mx {

struct PolePlacementSettings {
  double cancel_radius = 0.98;            // cancel zeros strictly inside this radius
  double common_factor_tolerance = 1e-2;  // relative distance for a near-common pole/zero pair
  double observer_pole = 0.0;             // Ao = (z - observer_pole)^deg(Ao)
  double leading_tolerance = 1e-9;        // |b_i| <= tol max|b| at the front of B counts as 0
};

void validatePolePlacementSettings(const PolePlacementSettings& s);

struct RstDesign {
  bool ok = false;
  std::string message;  // why not ok, or what was done
  Poly R, S, T;         // R monic; deg S, deg T <= deg R
  Poly A_used, B_used;  // after removal of near-common factors
  Poly B_plus, B_minus, Ao, R_prime, Bm_prime;
  int common_factors_removed = 0;
  bool unstable_common_factor = false;  // a removed pair lay on or outside the unit circle
  int zeros_cancelled = 0;
  int zeros_kept = 0;                 // unstable / poorly damped zeros left in B-
  bool model_zeros_followed = false;  // closed loop = Bm / Am exactly
  double diophantine_residual = 0.0;  // max|A R' + B- S - Am Ao| / max|Am Ao|
  double sylvester_rcond = 0.0;
};

RstDesign designModelFollowing(const Poly& A, const Poly& B, const Poly& Am, const Poly& Bm,
                               const PolePlacementSettings& settings = {});

}  // namespace mx
