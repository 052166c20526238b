#include "stability/zero_order_lobes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>

#include "model/cutting_force.h"
#include "model/vector_state.h"
#include "stability/lobe_envelope.h"
#include "stability/zoa_dynamics.h"
#include "stability/zoa_variable_pitch.h"

namespace mx {

namespace {

using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;

// Boundary point for one eigenvalue and lobe k. With c = -4 pi Lambda / (n_t K_t), the
// characteristic equation at s = -delta + i w reads e^{delta T} e^{-i w T} = 1 - c u, u = 1/b.
// delta = 0: u0 = 2 Re c / |c|^2 (eq. 8 with kappa = Lambda_I / Lambda_R). delta > 0: solve
// F(u) = ln|1 - c u| - delta T(u) = 0, T(u) = (theta(u) + 2 pi k) / w, theta = -arg(1 - c u) in (0, 2 pi).
class BoundarySolver {
 public:
  BoundarySolver(cplx c, double w, int k, double delta) : c_(c), w_(w), k_(k), delta_(delta) {}

  double theta(double u) const {
    double t = -std::arg(1.0 - c_ * u);
    if (t <= 0.0) t += 2.0 * kPi;
    return t;
  }
  double period(double u) const { return (theta(u) + 2.0 * kPi * k_) / w_; }
  double f(double u) const { return std::log(std::abs(1.0 - c_ * u)) - delta_ * period(u); }
  // Newton from a guess (continuation along the lobe); nullopt when it does not converge. Quadratic
  // convergence: once a step is below 1e-5 u, the remaining error is ~1e-10 u and we stop. `theta_out`
  // gets theta at the returned u, corrected to first order from the last iterate (d theta / du =
  // Im(c / z)), so that the caller needs no further atan2.
  std::optional<double> newton(double u, double& theta_out) const {
    for (int it = 0; it < 12; ++it) {
      const cplx z = 1.0 - c_ * u;
      const double nz = std::norm(z);
      double t = -std::atan2(z.imag(), z.real());
      if (t <= 0.0) t += 2.0 * kPi;
      const double value = 0.5 * std::log(nz) - delta_ * (t + 2.0 * kPi * k_) / w_;
      const cplx r = c_ * std::conj(z) / nz;  // c / z
      const double slope = -r.real() - delta_ * r.imag() / w_;
      if (!(slope > 0.0)) return std::nullopt;
      const double step = value / slope;
      u -= step;
      if (!(u > 0.0)) return std::nullopt;
      if (std::abs(step) < 1e-5 * u) {
        theta_out = t - r.imag() * step;
        return u;
      }
    }
    return std::nullopt;
  }

  // F < 0 wherever |1 - c u| <= 1 (u <= u0 when Re c > 0); with Re c <= 0, |1 - c u| > 1 for all
  // u > 0 and roots exist too. Bracket the first root above `lo` upwards, then Illinois regula falsi.
  std::optional<double> bracketed(double lo) const {
    double f_lo = f(lo), hi = lo, f_hi = f_lo;
    if (f_lo >= 0.0) return std::nullopt;  // root below lo: depth above the range of interest
    for (int it = 0; it < 200 && f_hi < 0.0; ++it) {
      lo = hi;
      f_lo = f_hi;
      hi *= 1.2;
      f_hi = f(hi);
    }
    if (!(f_hi >= 0.0)) return std::nullopt;
    double u = hi;
    int side = 0;
    for (int it = 0; it < 100 && (hi - lo) > 1e-13 * hi; ++it) {
      u = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      const double fu = f(u);
      if (fu == 0.0) break;
      if (fu > 0.0) {
        hi = u, f_hi = fu;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      } else {
        lo = u, f_lo = fu;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      }
    }
    return u;
  }

 private:
  cplx c_;
  double w_;
  int k_;
  double delta_;
};

// u_floor: depths above 1/u_floor are not of interest. guess, previous: the last two points' u on
// this lobe (0 if none; Newton starts from their linear extrapolation); updated on success.
bool boundaryPoint(cplx c, double w, int k, double delta, double u_floor, double& guess, double& previous,
                   double& depth, double& period) {
  if (c.real() <= 0.0 && delta == 0.0) return false;
  const BoundarySolver solver(c, w, k, delta);
  const double u0 = c.real() > 0.0 ? 2.0 * c.real() / std::norm(c) : 0.0;
  std::optional<double> u = u0;
  double theta = -1.0;  // theta at u when Newton already has it
  if (delta > 0.0) {
    const double lower = std::max(u0, u_floor);
    u = std::nullopt;
    // Continuation along the lobe: a Newton root at or above `lower` is the boundary point.
    const double start = previous > 0.0 && 2.0 * guess - previous > lower ? 2.0 * guess - previous : guess;
    if (start > lower) u = solver.newton(start, theta);
    if (!u || *u < lower) {
      theta = -1.0;
      u = std::nullopt;
      if (solver.f(lower) < 0.0) {
        // The nominal root u0 (F(u0) = -delta T), else bracketing from `lower`.
        if (u0 >= lower) u = solver.newton(u0, theta);
        if (!u || *u < lower) {
          theta = -1.0;
          u = solver.bracketed(lower);
        }
      }
    }
    if (!u) return false;
  }
  depth = 1.0 / *u;
  period = theta > 0.0 ? (theta + 2.0 * kPi * k) / w : solver.period(*u);
  previous = guess;
  guess = *u;
  return std::isfinite(depth) && period > 0.0;
}

}  // namespace

LobeDiagram computeZoaLobes(const MillingSetup& setup, const std::vector<double>& speeds, const ZoaOptions& options,
                            const JobControl& control) {
  if (!setup.uniformPitch()) return computeZoaLobesAnyPitch(setup, speeds, options, control);
  clearUpperVectorState();
  setup.validateGeometry();
  const ZoaDynamics dynamics = zoaDynamics(setup, speeds, options);
  LobeDiagram out = emptyZoaDiagram(speeds, options.delta_per_s);
  if (dynamics.rigid()) return out;  // rigid tool: no chatter
  const ZoaAxisDynamics& x = dynamics.x;
  const ZoaAxisDynamics& y = dynamics.y;

  const DirectionalFactors alpha = averageDirectionalFactors(setup.immersion, setup.radial_ratio);
  const std::vector<double> omegas = zoaChatterFrequencyGrid(dynamics, options);
  if (omegas.empty()) return out;
  const double min_speed = speeds.empty() ? 1.0 : *std::min_element(speeds.begin(), speeds.end());
  const double max_speed = speeds.empty() ? 1.0 : *std::max_element(speeds.begin(), speeds.end());
  // Lobe k at chatter frequency w lies between w / (2 pi n_t (k + 1)) and w / (2 pi n_t k) (eq. 9-10,
  // 0 < eps < 2 pi); points whose whole interval is outside the requested speeds (+-10 %) are skipped.
  auto inRange = [&](double w, int k) {
    const double per_lobe = w / (2.0 * kPi * setup.teeth);
    return per_lobe / (k + 1) <= 1.1 * max_speed && (k == 0 || per_lobe / k >= min_speed / 1.1);
  };
  // Capped in floating point first: a huge chatter frequency must not overflow the conversion to int.
  const double needed = std::floor(omegas.back() / (2 * kPi * setup.teeth * min_speed)) + 2.0;
  const int lobes = options.lobe_count > 0 ? options.lobe_count : static_cast<int>(std::min(400.0, needed));
  const double scale = -4.0 * kPi / (setup.teeth * setup.tangential_coefficient_pa);
  const cplx shift{-options.delta_per_s, 0.0};
  const double u_floor = 1.0 / (10.0 * options.max_depth_m);  // lobe points above 10x the cap are dropped

  // Eigenvalues depend on omega only; lobes k differ through T (eq. 9-10).
  std::vector<std::array<cplx, 2>> cs(omegas.size());
  std::vector<int> counts(omegas.size());
  for (size_t i = 0; i < omegas.size(); ++i) {
    const cplx s = shift + cplx{0.0, omegas[i]};
    cplx roots[2];
    counts[i] = zoaCharacteristicRoots(alpha, x.at(s), y.at(s), roots);
    for (int r = 0; r < counts[i]; ++r) cs[i][static_cast<size_t>(r)] = scale * roots[r];
  }

  LobeEnvelopeBuilder envelope(speeds);
  for (int k = 0; k < lobes; ++k) {
    if (control.cancelled()) throw Cancelled();
    for (int branch = 0; branch < 2; ++branch) {
      LobeCurve curve;
      curve.index = k;
      double guess = 0.0, previous = 0.0;
      auto flush = [&] {
        guess = previous = 0.0;
        if (curve.speed_rev_per_s.size() >= 2) {
          envelope.add(curve);
          out.lobes.push_back(curve);
        }
        curve = LobeCurve{k, {}, {}, {}};
      };
      for (size_t i = 0; i < omegas.size(); ++i) {
        double depth = 0.0, period = 0.0;
        if (branch < counts[i] && inRange(omegas[i], k) &&
            boundaryPoint(cs[i][static_cast<size_t>(branch)], omegas[i], k, options.delta_per_s, u_floor, guess,
                          previous, depth, period)) {
          curve.speed_rev_per_s.push_back(1.0 / (setup.teeth * period));  // eq. 10
          curve.depth_m.push_back(depth);
          curve.chatter_hz.push_back(omegas[i] / (2.0 * kPi));
        } else {
          flush();
        }
      }
      flush();
    }
    control.report(static_cast<double>(k + 1) / lobes);
  }
  envelope.finish(out, options.max_depth_m);
  return out;
}

double singleModeMinimumDepth(const MillingSetup& setup) {
  const Mode& m = setup.modes_x.front();
  const double re_g_min = -1.0 / (4.0 * m.stiffness_n_per_m * m.damping_ratio * (1.0 + m.damping_ratio));
  const double axx = averageDirectionalFactors(setup.immersion, setup.radial_ratio).xx;
  return 2.0 * kPi / (setup.teeth * setup.tangential_coefficient_pa * axx * re_g_min);
}

}  // namespace mx
