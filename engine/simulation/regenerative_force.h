#pragma once
// The regenerative chip thickness and the cutting force it produces (2006, eq. 2 and 7), summed over
// the edges engaged at one instant. With K remembered passes, for pass k (1-based) of tooth j
//   h_jk = (s_t n_t A_jk / 2 pi + x(t) - x(t - tau_jk)) sin phi + (y(t) - y(t - tau_jk)) cos phi + rho_j - rho_{j+k},
//   h = min_k h_jk  (eq. 7 for K = 1, uniform pitch, no runout: A_1 = 2 pi / n_t; see cutter_edges.h).
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "simulation/cutter_edges.h"
#include "simulation/engagement_plan.h"

namespace mx {

inline constexpr int kMaxRegenerativePasses = 8;

// The coefficients of sin phi (ax) and cos phi (ay) and the constant (runout) term of h_jk, for each
// pass set and remembered pass (index ToothPasses::index). `plain`: straight teeth sharing one set of
// passes without runout, whose chip needs neither the runout term nor the edge's depth share.
struct Regeneration {
  int passes = 1;
  bool plain = true;
  std::vector<double> ax, ay, offset;

  Regeneration() = default;
  Regeneration(const ToothPasses& p, bool sliced)
      : passes(p.passes),
        plain(p.sets == 1 && !sliced &&
              std::all_of(p.runout_m.begin(), p.runout_m.end(), [](double r) { return r == 0.0; })),
        ax(p.feed_m.size()),
        ay(p.feed_m.size()),
        offset(p.runout_m) {}
};

// Summed cutting force of the engaged edges: F_tj = K_t b_e h_j for h_j > 0 (eq. 2), else 0.
struct CutForce {
  double fx = 0.0, fy = 0.0, tangential = 0.0, max_chip = 0.0;
};

// The terms beyond the chip force, for edges with h_j > 0: the edge forces b_e (ex_unit, ey_unit) and
// K_te b_e (Altintas 2000, eq. 2.22), and the process damping -(C_i / V) b_e (n . v) n with n = (sin phi,
// cos phi), the direction in which the chip grows, and v the tool's velocity (docs/fidelity.md, "Process
// damping").
struct CutExtras {
  bool active = false;        // some edge force or process damping is not 0
  double kte = 0.0;           // K_te [N/m]
  double damping = 0.0;       // C_i / V [N s / m^2]
  double vx = 0.0, vy = 0.0;  // the tool's velocity [m/s]
};

// Inlined into the RK4 stage, the hot loop of the simulation.
template <bool kPlain, bool kExtended>
[[gnu::always_inline]] inline CutForce cutForceOf(std::span<const ActiveTooth> teeth, const Regeneration& r,
                                                  double depth, double kt, const CutExtras& extras) {
  double sum_h = 0.0, sum_x = 0.0, sum_y = 0.0, max_h = 0.0;
  double sum_b = 0.0, extra_x = 0.0, extra_y = 0.0;  // kExtended only
  const auto passes = static_cast<std::size_t>(r.passes);
  const double* ax = r.ax.data();
  const double* ay = r.ay.data();
  const double* offset = r.offset.data();
  for (const ActiveTooth& tooth : teeth) {
    const std::size_t first = kPlain ? 0 : tooth.pass_set * passes;
    auto chip = [&](std::size_t k) {
      const double h = ax[k] * tooth.sin_phi + ay[k] * tooth.cos_phi;
      return kPlain ? h : h + offset[k];
    };
    double h = chip(first);
    for (std::size_t k = first + 1; k < first + passes; ++k) h = std::min(h, chip(k));
    if (h > 0.0) {
      const double hb = kPlain ? h : h * tooth.depth_fraction;
      sum_h += hb;
      sum_x += hb * tooth.fx_unit;
      sum_y += hb * tooth.fy_unit;
      max_h = std::max(max_h, h);
      if constexpr (kExtended) {
        const double b = kPlain ? 1.0 : tooth.depth_fraction;
        const double pushed = extras.damping * b * (tooth.sin_phi * extras.vx + tooth.cos_phi * extras.vy);
        sum_b += b;
        extra_x += b * tooth.ex_unit - pushed * tooth.sin_phi;
        extra_y += b * tooth.ey_unit - pushed * tooth.cos_phi;
      }
    }
  }
  if constexpr (kExtended)
    return {depth * (sum_x + extra_x), depth * (sum_y + extra_y), depth * (kt * sum_h + extras.kte * sum_b), max_h};
  return {depth * sum_x, depth * sum_y, kt * depth * sum_h, max_h};
}

inline CutForce cutForce(std::span<const ActiveTooth> teeth, const Regeneration& r, double depth, double kt,
                         const CutExtras& extras = {}) {
  if (extras.active)
    return r.plain ? cutForceOf<true, true>(teeth, r, depth, kt, extras)
                   : cutForceOf<false, true>(teeth, r, depth, kt, extras);
  return r.plain ? cutForceOf<true, false>(teeth, r, depth, kt, extras)
                 : cutForceOf<false, false>(teeth, r, depth, kt, extras);
}

}  // namespace mx
