#include "supervisor/machining_modules.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <sstream>

#include "core/invalid_input.h"

namespace mx {

double MachiningContext::currentDepth() const {
  return current_pass >= 0 && current_pass < static_cast<int>(passes_m.size())
             ? passes_m[static_cast<std::size_t>(current_pass)]
             : 0.0;
}

void FeedrateRoutine::run(MachiningContext& ctx) {
  // Programmed feed, zero under a feed hold, or the force controller's override.
  ctx.commanded_feed_m_per_s =
      ctx.feed_hold ? 0.0 : (ctx.override_valid ? ctx.override_feed_m_per_s : ctx.programmed_feed_m_per_s);
}

void OperatorInputMonitor::run(MachiningContext& ctx) {
  ctx.a = ctx.operator_feed_hold;
}

void OperatorChatterDetector::run(MachiningContext& ctx) {
  if (ctx.operator_chatter_key && !ctx.c) ctx.report("chatter_manual", "operator signalled chatter");
  ctx.c = ctx.operator_chatter_key;
}

AutomaticChatterDetector::AutomaticChatterDetector(ChatterDetectorSettings s)
    : MachiningModule('E', "automatic chatter detector", 0.040), s_(s) {
  if (!std::isfinite(s_.threshold_N) || s_.threshold_N <= 0.0)
    throw InvalidInput("automatic chatter detector: threshold_N = " + std::to_string(s_.threshold_N) + ": must be > 0");
}

double AutomaticChatterDetector::nonHarmonicAmplitude(const std::deque<double>& x, int teeth) {
  const std::size_t n = x.size();
  if (n < 8) return 0.0;
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
  double peak = 0.0;
  // Window = one revolution, so bin k is the k-th spindle harmonic; multiples of `teeth` are the
  // tooth-passing harmonics of the forced response, every other bin is chatter (or a transient).
  for (std::size_t k = 1; k <= n / 2; ++k) {
    if (teeth > 0 && k % static_cast<std::size_t>(teeth) == 0) continue;
    std::complex<double> acc(0.0, 0.0);
    const double w = -2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    for (std::size_t j = 0; j < n; ++j) acc += (x[j] - mean) * std::polar(1.0, w * static_cast<double>(j));
    peak = std::max(peak, 2.0 * std::abs(acc) / static_cast<double>(n));
  }
  return peak;
}

void AutomaticChatterDetector::run(MachiningContext& ctx) {
  if (ctx.t_s + 1e-9 < armed_at_) return;
  ctx.chatter_indicator = nonHarmonicAmplitude(ctx.fy_samples, ctx.teeth);
  const bool chatter = ctx.chatter_indicator > s_.threshold_N;
  if (chatter && !ctx.d) {
    std::ostringstream os;
    os << "non-harmonic F_y amplitude " << ctx.chatter_indicator << " N > " << s_.threshold_N << " N";
    ctx.report("chatter_detected", os.str());
  }
  ctx.d = chatter;
}

void AutomaticChatterDetector::reset(MachiningContext& ctx) {
  ctx.d = false;
  ctx.chatter_indicator = 0.0;
  armed_at_ = ctx.t_s + 1.0 / ctx.spindle_rev_per_s;
}

void ChatterSuppressor::run(MachiningContext& ctx) {
  const auto from = static_cast<std::size_t>(std::max(0, ctx.current_pass));
  if (from >= ctx.passes_m.size()) return;
  const double remaining =
      std::accumulate(ctx.passes_m.begin() + static_cast<std::ptrdiff_t>(from), ctx.passes_m.end(), 0.0);
  const std::size_t count = ctx.passes_m.size() - from + 1;
  ctx.passes_m.resize(from);
  ctx.passes_m.insert(ctx.passes_m.end(), count, remaining / static_cast<double>(count));
  ctx.replanned = true;
  std::ostringstream os;
  os << "part program re-planned: " << count << " passes of " << remaining / static_cast<double>(count) * 1e3 << " mm";
  ctx.report("replan", os.str());
}

void ChatterSuppressionRoutine::run(MachiningContext& ctx) {
  if (started_ < 0.0) {
    started_ = ctx.t_s;
    suppressor_.run(ctx);
    ctx.report("feed_hold", "chatter suppression hold " + std::to_string(static_cast<int>(hold_s_ * 1e3)) + " ms");
  }
  if (ctx.t_s - started_ + 1e-9 >= hold_s_) {
    ctx.feed_hold = false;
    if (!ctx.e) ctx.report("suppression_complete", "chatter suppression routine complete");
    ctx.e = true;
    ctx.c = ctx.d = false;
    ctx.operator_chatter_key = false;
  } else {
    ctx.feed_hold = true;
  }
}

void ChatterSuppressionRoutine::reset(MachiningContext& ctx) {
  started_ = -1.0;
  ctx.e = false;
}

void ChatterSuppressionRoutine::deactivate(MachiningContext& ctx) {
  started_ = -1.0;
  ctx.e = false;
  ctx.feed_hold = false;
}

ParameterEstimator::ParameterEstimator(double feed_exponent, double forgetting)
    : MachiningModule('H', "parameter estimator", 0.040),
      a_(feed_exponent),
      rls_settings_{forgetting, 1e8, 0.0, CovarianceReset::None, 0.05, 1e-6, 1e12},
      rls_(1, rls_settings_) {
  if (!std::isfinite(a_) || a_ <= 0.0 || a_ > 2.0)
    throw InvalidInput("parameter estimator: feed_exponent = " + std::to_string(a_) + ": must be in (0, 2]");
}

void ParameterEstimator::run(MachiningContext& ctx) {
  // y = F_Y, phi = f^a with f [mm/tooth] the mean feed over the revolution F_Y was taken from.
  if (ctx.estimator_restart) {
    reset(ctx);
    ctx.estimator_restart = false;
  }
  if (ctx.feed_samples.empty() || ctx.F_Y_N <= 50.0) return;
  const double v = std::accumulate(ctx.feed_samples.begin(), ctx.feed_samples.end(), 0.0) /
                   static_cast<double>(ctx.feed_samples.size());
  const double f_mm = v / (ctx.teeth * ctx.spindle_rev_per_s) * 1e3;
  if (f_mm < 1e-4) return;
  Eigen::VectorXd phi(1);
  phi(0) = std::pow(f_mm, a_);
  rls_.update(phi, ctx.F_Y_N);
  ctx.estimated_gain = rls_.theta()(0);
  ctx.gain_valid = ctx.estimated_gain > 0.0;
}

void ParameterEstimator::reset(MachiningContext& ctx) {
  rls_ = RlsEstimator(1, rls_settings_);
  ctx.gain_valid = false;
  ctx.estimated_gain = 0.0;
}

void ForceSignalProcessor::run(MachiningContext& ctx) {
  if (ctx.t_s + 1e-9 < armed_at_) return;
  double m = 0.0;
  for (double f : ctx.fy_samples) m = std::max(m, std::abs(f));
  ctx.F_Y_N = m;
}

namespace {
double limitFeed(const MachiningContext& ctx, double v) {
  const double v_tooth = ctx.limits.max_feed_per_tooth_m * ctx.teeth * ctx.spindle_rev_per_s;
  return std::clamp(v, 0.0, std::min(ctx.limits.max_feed_rate_m_per_s, v_tooth));
}
}  // namespace

void AdaptiveForceController::run(MachiningContext& ctx) {
  // Certainty equivalence on F_Y = theta f^a: f = (F_ref / theta)^(1/a), theta from the estimator H.
  if (!ctx.gain_valid) return;  // until the first estimate the programmed feed stands
  const double f_mm = std::pow(ctx.reference_force_N / ctx.estimated_gain, 1.0 / a_);
  ctx.override_feed_m_per_s = limitFeed(ctx, f_mm * 1e-3 * ctx.teeth * ctx.spindle_rev_per_s);
  ctx.override_valid = true;
}

ModelBasedForceLoop ModelBasedForceModule::makeLoop(const MachiningContext& ctx) const {
  ModelBasedForceLoopSettings s;
  s.controller.model = settings_.model;
  s.controller.reference_force_N = ctx.reference_force_N;
  s.controller.teeth = ctx.teeth;
  s.controller.max_feed_rate_m_per_s = ctx.limits.max_feed_rate_m_per_s;
  s.controller.max_feed_per_tooth_m = ctx.limits.max_feed_per_tooth_m;
  s.period_s = period();
  s.time_constant_s = settings_.time_constant_s;
  s.reset_feed = settings_.reset_feed;
  return ModelBasedForceLoop(s);
}

void ModelBasedForceModule::reset(MachiningContext& ctx) {
  loop_.emplace(makeLoop(ctx));
  loop_->reset(ctx.commanded_feed_m_per_s, ctx.currentDepth(), ctx.spindle_rev_per_s);
  ctx.override_valid = false;
}

void ModelBasedForceModule::run(MachiningContext& ctx) {
  // The loop reads F_Y of the revolution just measured (I) and sets the feed for the next one.
  if (!loop_) reset(ctx);
  ctx.override_feed_m_per_s = loop_->update(ctx.F_Y_N, ctx.spindle_rev_per_s);
  ctx.override_valid = true;
}

std::vector<std::unique_ptr<MachiningModule>> makeStandardModules(ChatterDetectorSettings chatter,
                                                                  ModelBasedForceModuleSettings force) {
  std::vector<std::unique_ptr<MachiningModule>> m;
  m.push_back(std::make_unique<OperatorInputMonitor>());
  m.push_back(std::make_unique<OperatorChatterDetector>());
  m.push_back(std::make_unique<ForceSignalProcessor>());
  m.push_back(std::make_unique<ContactMonitor>());
  m.push_back(std::make_unique<AutomaticChatterDetector>(chatter));
  m.push_back(std::make_unique<ParameterEstimator>(force.model.feed_exponent));
  m.push_back(std::make_unique<AdaptiveForceController>(force.model.feed_exponent));
  m.push_back(std::make_unique<ModelBasedForceModule>(force));
  m.push_back(std::make_unique<ChatterSuppressionRoutine>());
  m.push_back(std::make_unique<FeedHold>());
  m.push_back(std::make_unique<FeedrateRoutine>());
  return m;
}

}  // namespace mx
