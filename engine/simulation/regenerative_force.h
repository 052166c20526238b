#pragma once
// The regenerative chip thickness and the cutting force it produces (2006, eq. 2 and 7), summed over
// the teeth engaged at one instant. With K remembered passes, for pass k (1-based)
//   h_k = (k s_t + x(t) - x(t - kT)) sin phi + (y(t) - y(t - kT)) cos phi,  h = min_k h_k  (eq. 7 for K = 1).
#include <algorithm>
#include <array>
#include <span>

#include "simulation/engagement_plan.h"

namespace mx {

inline constexpr int kMaxRegenerativePasses = 8;

// The coefficients of sin phi (ax) and cos phi (ay) in h_k, for each remembered pass.
struct Regeneration {
  int passes = 1;
  std::array<double, kMaxRegenerativePasses> ax{}, ay{};
};

// Summed cutting force of the engaged teeth: F_tj = K_t b h_j for h_j > 0 (eq. 2), else 0.
struct CutForce {
  double fx = 0.0, fy = 0.0, tangential = 0.0, max_chip = 0.0;
};

inline CutForce cutForce(std::span<const ActiveTooth> teeth, const Regeneration& r, double depth, double kt) {
  double sum_h = 0.0, sum_x = 0.0, sum_y = 0.0, max_h = 0.0;
  for (const ActiveTooth& tooth : teeth) {
    double h = r.ax[0] * tooth.sin_phi + r.ay[0] * tooth.cos_phi;
    for (int k = 1; k < r.passes; ++k) h = std::min(h, r.ax[k] * tooth.sin_phi + r.ay[k] * tooth.cos_phi);
    if (h > 0.0) {
      sum_h += h;
      sum_x += h * tooth.fx_unit;
      sum_y += h * tooth.fy_unit;
      max_h = std::max(max_h, h);
    }
  }
  return {depth * sum_x, depth * sum_y, kt * depth * sum_h, max_h};
}

}  // namespace mx
