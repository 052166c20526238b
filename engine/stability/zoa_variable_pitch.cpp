#include "stability/zoa_variable_pitch.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "model/cutting_force.h"
#include "model/vector_state.h"
#include "stability/zoa_dynamics.h"

namespace mx {

namespace {

using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;
// Samples per period 2 pi / tau_max of the fastest-turning regenerative term e^{-i omega tau_max}: enough
// to follow its oscillation of Im u, so that two sign changes rarely fall between neighbouring samples
// (checked against a 400 000-frequency scan, stability.zoa_variable_pitch).
constexpr int kSamplesPerDelayPeriod = 16;

// Eigenvalues mu of [A0][G(s)] at one chatter frequency, mu = -1 / Lambda (zoaCharacteristicRoots).
struct Eigenvalues {
  int count = 0;
  cplx mu[2];
};

// Keeps each branch continuous in omega: b swapped when that brings it nearer to a.
void alignTo(const Eigenvalues& a, Eigenvalues& b) {
  if (a.count != 2 || b.count != 2) return;
  if (std::abs(b.mu[0] - a.mu[0]) + std::abs(b.mu[1] - a.mu[1]) >
      std::abs(b.mu[0] - a.mu[1]) + std::abs(b.mu[1] - a.mu[0]))
    std::swap(b.mu[0], b.mu[1]);
}

// One chatter-frequency point of the scan for one speed: the eigenvalues and u = K_t S mu / 4 pi.
struct ScanPoint {
  double w = 0.0;
  Eigenvalues e;
  cplx u[2];
};

// A boundary candidate: Im u = 0 at w, depth 1 / Re u.
struct Root {
  double w = 0.0;
  cplx u;
};

class PitchProblem {
 public:
  PitchProblem(const MillingSetup& setup, const ZoaDynamics& dynamics, double delta)
      : setup_(setup),
        dynamics_(dynamics),
        alpha_(averageDirectionalFactors(setup.immersion, setup.radial_ratio)),
        delta_(delta) {}

  cplx s(double w) const { return {-delta_, w}; }

  Eigenvalues eigenvalues(double w) const {
    Eigenvalues e;
    cplx lambda[2];
    e.count = zoaCharacteristicRoots(alpha_, dynamics_.x.at(s(w)), dynamics_.y.at(s(w)), lambda);
    for (int r = 0; r < e.count; ++r) e.mu[r] = -1.0 / lambda[r];
    return e;
  }

  ScanPoint point(double w, const Eigenvalues& e, double speed) const {
    ScanPoint p{w, e, {}};
    const cplx factor = setup_.tangential_coefficient_pa * regenerativePitchSum(setup_, speed, s(w)) / (4.0 * kPi);
    for (int r = 0; r < e.count; ++r) p.u[r] = factor * e.mu[r];
    return p;
  }

  // u on branch r at w inside [a.w, b.w]: the eigenvalue nearest the branch's linear interpolation.
  cplx branchU(const ScanPoint& a, const ScanPoint& b, int r, double w, double speed) const {
    const Eigenvalues e = eigenvalues(w);
    const double t = (w - a.w) / (b.w - a.w);
    const cplx expected = a.e.mu[r] + t * (b.e.mu[r] - a.e.mu[r]);
    int nearest = 0;
    for (int k = 1; k < e.count; ++k)
      if (std::abs(e.mu[k] - expected) < std::abs(e.mu[nearest] - expected)) nearest = k;
    Eigenvalues one;
    one.count = 1;
    one.mu[0] = e.mu[nearest];
    return point(w, one, speed).u[0];
  }

  // Im u = 0 on branch r between a and b (opposite signs there): Illinois regula falsi in omega.
  Root refine(const ScanPoint& a, const ScanPoint& b, int r, double speed) const {
    double lo = a.w, hi = b.w, f_lo = a.u[r].imag(), f_hi = b.u[r].imag();
    Root root{lo, a.u[r]};
    int side = 0;
    for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it) {
      const double w = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      root = {w, branchU(a, b, r, w, speed)};
      const double f = root.u.imag();
      if (f == 0.0) break;
      if ((f > 0.0) == (f_hi > 0.0)) {
        hi = w, f_hi = f;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      } else {
        lo = w, f_lo = f;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      }
    }
    return root;
  }

  double maxPitchRad() const {
    double p = 0.0;
    for (int j = 0; j < setup_.teeth; ++j) p = std::max(p, setup_.pitchRad(j));
    return p;
  }

 private:
  const MillingSetup& setup_;
  const ZoaDynamics& dynamics_;
  DirectionalFactors alpha_;
  double delta_;
};

// The boundary with the largest u (smallest depth) at one speed over the scan grid; u = 0 if none.
Root limitAtSpeed(const PitchProblem& problem, const std::vector<double>& omegas, const std::vector<Eigenvalues>& eigen,
                  double speed) {
  const double max_step = 2.0 * kPi * 2.0 * kPi * speed / (problem.maxPitchRad() * kSamplesPerDelayPeriod);
  Root best{0.0, {0.0, 0.0}};
  ScanPoint previous = problem.point(omegas.front(), eigen.front(), speed);
  auto visit = [&](ScanPoint next) {
    alignTo(previous.e, next.e);
    // A sample on the boundary itself (Im u rounds to exactly 0, e.g. at a speed taken from a lobe point).
    for (int r = 0; r < next.e.count; ++r)
      if (next.u[r].imag() == 0.0 && next.u[r].real() > best.u.real()) best = {next.w, next.u[r]};
    if (next.e.count == previous.e.count) {
      for (int r = 0; r < next.e.count; ++r) {
        const double f0 = previous.u[r].imag(), f1 = next.u[r].imag();
        const bool crosses = (f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0);
        if (!crosses || !(previous.u[r].real() > 0.0 || next.u[r].real() > 0.0)) continue;
        const Root root = problem.refine(previous, next, r, speed);
        if (root.u.real() > best.u.real()) best = root;
      }
    }
    previous = next;
  };
  for (size_t i = 1; i < omegas.size(); ++i) {
    const double w0 = omegas[i - 1], w1 = omegas[i];
    const int parts = std::max(1, static_cast<int>(std::ceil((w1 - w0) / max_step)));
    for (int k = 1; k < parts; ++k) {
      const double w = w0 + (w1 - w0) * k / parts;
      visit(problem.point(w, problem.eigenvalues(w), speed));
    }
    visit(problem.point(w1, eigen[i], speed));
  }
  return best;
}

}  // namespace

cplx regenerativePitchSum(const MillingSetup& setup, double spindle_rev_per_s, cplx s) {
  const double omega = 2.0 * kPi * spindle_rev_per_s;
  cplx sum{0.0, 0.0};
  for (int j = 0; j < setup.teeth; ++j) sum += 1.0 - std::exp(-s * (setup.pitchRad(j) / omega));
  return sum;
}

LobeDiagram computeZoaLobesAnyPitch(const MillingSetup& setup, const std::vector<double>& speeds,
                                    const ZoaOptions& options, const JobControl& control) {
  clearUpperVectorState();
  setup.validateGeometry();
  const ZoaDynamics dynamics = zoaDynamics(setup, speeds, options);
  LobeDiagram out = emptyZoaDiagram(speeds, options.delta_per_s);
  if (dynamics.rigid()) return out;  // rigid tool: no chatter
  const std::vector<double> omegas = zoaChatterFrequencyGrid(dynamics, options);
  if (omegas.size() < 2) return out;

  const PitchProblem problem(setup, dynamics, options.delta_per_s);
  std::vector<Eigenvalues> eigen(omegas.size());
  for (size_t i = 0; i < omegas.size(); ++i) eigen[i] = problem.eigenvalues(omegas[i]);

  for (size_t i = 0; i < speeds.size(); ++i) {
    if (control.cancelled()) throw Cancelled();
    const Root root = limitAtSpeed(problem, omegas, eigen, speeds[i]);
    const double depth = root.u.real() > 0.0 ? 1.0 / root.u.real() : LobeDiagram::kNone;
    if (depth <= options.max_depth_m) {
      out.envelope_depth_m[i] = depth;
      out.envelope_chatter_hz[i] = root.w / (2.0 * kPi);
    }
    control.report(static_cast<double>(i + 1) / static_cast<double>(speeds.size()));
  }
  out.minima = envelopeMinima(out.speed_rev_per_s, out.envelope_depth_m, out.envelope_chatter_hz);
  return out;
}

}  // namespace mx
