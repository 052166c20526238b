#include "stability/sdm_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "model/cutting_force.h"

namespace mx {

namespace {
const double kFirstStep = std::log(1.04);  // first bracketing step in log(b)
const double kMaxStep = std::log(1.25);    // bracketing steps double up to this
constexpr int kMaxBrentIterations = 60;
const double kScanRatio = 1.1;          // island-scan grid ratio
constexpr double kNearCritical = 0.05;  // refine sampled maxima with f > -0.05
constexpr int kMaxGoldenIterations = 10;
const double kGoldenTolerance = std::log(1.01);
}  // namespace

SdmBoundarySearch::SdmBoundarySearch(const SdmModel& model, const SdmOptions& options)
    : model_(model), options_(options) {}

double SdmBoundarySearch::coldGuess(const MillingSetup& setup, double max_depth_m) {
  const DirectionalFactors a = averageDirectionalFactors(setup.immersion, setup.radial_ratio);
  const double norm = std::sqrt(a.xx * a.xx + a.xy * a.xy + a.yx * a.yx + a.yy * a.yy);
  const double denom = setup.teeth * setup.tangential_coefficient_pa * norm;
  double guess = std::numeric_limits<double>::infinity();
  for (const ModalAxis* axis : {&setup.modes_x, &setup.modes_y}) {
    for (const Mode& m : *axis) {
      const double z = m.damping_ratio;
      guess = std::min(guess, 4.0 * std::numbers::pi * m.stiffness_n_per_m * z * (1.0 + z) / denom);
    }
  }
  if (!std::isfinite(guess) || guess <= 0.0) guess = 0.01 * max_depth_m;
  return std::min(guess, max_depth_m);
}

SdmBoundarySearch::Sample SdmBoundarySearch::evaluate(double depth_m) {
  ++evaluations_;
  model_.build(speed_, depth_m, free_step_, map_);
  built_depth_m_ = depth_m;
  Sample s;
  s.depth = depth_m;
  s.pair = arnoldi_.dominant(map_, warm_.size() > 0 ? &warm_ : nullptr);
  warm_ = SdmArnoldi::warmStart(s.pair.vector);
  s.f = std::log(std::abs(s.pair.value)) + options_.delta_per_s * period_;
  return s;
}

SdmBoundaryPoint SdmBoundarySearch::finish(const Sample& s) {
  // The frequency may run the map over a period (SdmMonodromy::chatterFrequencyHz): it must be s's map.
  if (built_depth_m_ != s.depth) {
    model_.build(speed_, s.depth, free_step_, map_);
    built_depth_m_ = s.depth;
  }
  SdmBoundaryPoint out;
  out.depth_m = s.depth;
  out.multiplier = s.pair.value;
  out.chatter_hz = map_.chatterFrequencyHz(s.pair.value, s.pair.vector, period_);
  out.evaluations = evaluations_;
  return out;
}

// Steps:
// 1. Continuation bracket [lo, hi], f(lo) <= 0 < f(hi), by geometric steps from the guess (the
//    previous speed's b_lim): an unstable guess steps DOWN until the first stable depth (so a lobe
//    that dropped below the previous b_lim at a kink is followed down), a stable guess steps UP
//    until the first unstable depth. Steps start at 4 % and double up to 25 %.
// 2. Brent's method on u = log b gives the crossing b*.
// 3. Island scan: unstable bands closed in depth (flip "lenses" at low immersion) or stable pockets
//    can put a crossing below b* that steps 1-2 never see. f is sampled below b* on a 1.2-ratio grid
//    down to half of min(b*, lowest_known); the lowest unstable sample, or else a sampled local
//    maximum with f > -0.05 whose golden-section refinement crosses zero, brackets a lower crossing,
//    which Brent then solves. Bands narrower than the grid whose peak stays below the refinement
//    threshold can still be missed.
SdmBoundaryPoint SdmBoundarySearch::solve(double spindle_rev_per_s, double guess_depth_m, double lowest_known_m) {
  speed_ = spindle_rev_per_s;
  period_ = model_.principalPeriodS(speed_);
  free_step_ = model_.freeStep(speed_);
  evaluations_ = 0;
  const double b_max = options_.max_depth_m;
  const bool warm = std::isfinite(guess_depth_m) && guess_depth_m > 0.0;
  const double b0 = std::min(warm ? guess_depth_m : cold_guess_, b_max);

  Sample lo, hi;
  Sample s = evaluate(b0);
  double step = kFirstStep;
  bool none = false;
  if (s.f > 0.0) {
    hi = std::move(s);
    for (;;) {
      Sample t = evaluate(hi.depth * std::exp(-step));
      step = std::min(2.0 * step, kMaxStep);
      if (t.f <= 0.0) {
        lo = std::move(t);
        break;
      }
      hi = std::move(t);
      if (hi.depth < 1e-12 * b_max) return finish(hi);  // unreachable while f(0) < 0
    }
  } else {
    lo = std::move(s);
    for (;;) {
      if (lo.depth >= b_max) {
        none = true;
        break;
      }
      Sample t = evaluate(std::min(lo.depth * std::exp(step), b_max));
      step = std::min(2.0 * step, kMaxStep);
      if (t.f > 0.0) {
        hi = std::move(t);
        break;
      }
      lo = std::move(t);
    }
  }
  Sample root = none ? std::move(lo) : brent(std::move(lo), std::move(hi));
  const double top = root.depth;
  const double floor = 0.5 * std::min(top, std::isfinite(lowest_known_m) ? lowest_known_m : top);
  Sample island_lo, island_hi;
  if (scanBelow(root, floor, island_lo, island_hi)) {
    root = brent(std::move(island_lo), std::move(island_hi));
    none = false;
  }
  if (none) {
    SdmBoundaryPoint out;
    out.depth_m = LobeDiagram::kNone;
    out.evaluations = evaluations_;
    return out;
  }
  return finish(root);
}

bool SdmBoundarySearch::scanBelow(const Sample& top, double floor_depth_m, Sample& lo, Sample& hi) {
  std::vector<Sample> samples{top};  // descending depth; samples[0] = the crossing b* or b_max
  const double top_depth_m = top.depth;
  for (double b = top_depth_m / kScanRatio; samples.back().depth > floor_depth_m; b /= kScanRatio) {
    samples.push_back(evaluate(b));
  }
  if (samples.size() < 2) return false;
  // Lowest unstable sample (the sample below it is stable, or step further down while unstable).
  for (size_t k = samples.size() - 1; k >= 1; --k) {
    if (samples[k].f <= 0.0) continue;
    hi = samples[k];
    if (k + 1 < samples.size()) {
      lo = samples[k + 1];
      return true;
    }
    for (;;) {
      Sample t = evaluate(hi.depth / kScanRatio);
      if (t.f <= 0.0) {
        lo = std::move(t);
        return true;
      }
      hi = std::move(t);
    }
  }
  // Near-critical local maxima, lowest first.
  for (size_t k = samples.size() - 2; k >= 1; --k) {
    const Sample& s = samples[k];
    if (s.f > -kNearCritical && s.f >= samples[k + 1].f && s.f >= samples[k - 1].f &&
        maximiseNear(samples[k + 1], s, samples[k - 1], hi)) {
      lo = samples[k + 1];
      return true;
    }
  }
  return false;
}

// Golden-section search for max f on u = log b in [below, above] around peak; true (and hi = an
// unstable sample) as soon as f > 0 is found.
bool SdmBoundarySearch::maximiseNear(const Sample& below, const Sample& peak, const Sample& above, Sample& hi) {
  constexpr double kGolden = 0.3819660112501051;
  double ua = std::log(below.depth), uc = std::log(above.depth), ub = std::log(peak.depth);
  Sample best = peak;
  for (int it = 0; it < kMaxGoldenIterations && uc - ua > kGoldenTolerance; ++it) {
    const double ux = (ub - ua > uc - ub) ? ub - kGolden * (ub - ua) : ub + kGolden * (uc - ub);
    Sample x = evaluate(std::exp(ux));
    if (x.f > 0.0) {
      hi = std::move(x);
      return true;
    }
    if (x.f > best.f) {
      (ux < ub ? uc : ua) = ub;
      ub = ux;
      best = std::move(x);
    } else {
      (ux < ub ? ua : uc) = ux;
    }
  }
  return false;
}

SdmBoundarySearch::Sample SdmBoundarySearch::brent(Sample lo, Sample hi) {
  const double tol = std::log1p(options_.depth_tolerance);
  Sample a = std::move(lo), b = std::move(hi);
  double ua = std::log(a.depth), ub = std::log(b.depth);
  Sample c = a;
  double uc = ua, d = ub - ua, e = d;
  for (int it = 0; it < kMaxBrentIterations; ++it) {
    if ((b.f > 0.0) == (c.f > 0.0)) {  // keep the root between b and c
      c = a;
      uc = ua;
      d = e = ub - ua;
    }
    if (std::abs(c.f) < std::abs(b.f)) {  // b is the best estimate
      a = b;
      ua = ub;
      std::swap(b, c);
      std::swap(ub, uc);
      c = a;
      uc = ua;
    }
    const double tol1 = 2.0 * std::numeric_limits<double>::epsilon() * std::abs(ub) + 0.5 * tol;
    const double xm = 0.5 * (uc - ub);
    if (std::abs(xm) <= tol1 || b.f == 0.0) break;
    if (std::abs(e) >= tol1 && std::abs(a.f) > std::abs(b.f)) {
      double p, q;
      const double sb = b.f / a.f;
      if (ua == uc) {  // secant
        p = 2.0 * xm * sb;
        q = 1.0 - sb;
      } else {  // inverse quadratic interpolation
        const double qa = a.f / c.f, r = b.f / c.f;
        p = sb * (2.0 * xm * qa * (qa - r) - (ub - ua) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (sb - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * xm * q - std::abs(tol1 * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = std::move(b);
    ua = ub;
    ub += std::abs(d) > tol1 ? d : (xm > 0.0 ? tol1 : -tol1);
    b = evaluate(std::exp(ub));
  }
  return b;
}

}  // namespace mx
