#include "point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "model/cutting_force.h"

namespace mx::gui {

PointEvaluator::PointEvaluator(std::shared_ptr<const LobeSnapshot> snapshot, SpindlePowerCurve spindle_power)
    : snapshot_(std::move(snapshot)), spindle_power_(std::move(spindle_power)) {
  if (!snapshot_) return;
  for (const ToolLobes& t : snapshot_->tools) {
    if (t.margined.speed_rev_per_s.size() < 2) return;
    boundaries_.emplace_back(t.margined, snapshot_->alpha);
  }
}

int PointEvaluator::toolIndex(const QString& id) const {
  if (!snapshot_) return -1;
  for (size_t i = 0; i < snapshot_->tools.size(); ++i)
    if (QString::fromStdString(snapshot_->tools[i].setup.tool_id) == id) return static_cast<int>(i);
  return -1;
}

widgets::PointReadout PointEvaluator::evaluate(int tool, double speed_rpm, double depth_mm, double feed) const {
  widgets::PointReadout r;
  r.speed_rpm = speed_rpm;
  r.depth_mm = depth_mm;
  r.feed_mm_per_tooth = feed;
  const double available = spindle_power_.available(rpmToRevPerS(speed_rpm));
  r.power_limit_w = std::isfinite(available) ? available : 0.0;  // P_av at the point's speed; 0: no limit
  if (!ready() || tool < 0 || tool >= toolCount()) {
    r.message = QObject::tr("no lobes computed yet");
    return r;
  }
  const ToolLobes& t = snapshot_->tools[static_cast<size_t>(tool)];
  const StabilityBoundary& boundary = boundaries_[static_cast<size_t>(tool)];
  r.tool_id = QString::fromStdString(t.setup.tool_id);
  const double n = rpmToRevPerS(speed_rpm), b = depth_mm * 1e-3;
  const CutPerformance perf = evaluateCut(t.setup, {n, b, feed * 1e-3});
  r.peak_power_w = perf.peak_power_w;
  r.peak_force_n = perf.peak_force_n;
  const std::size_t i = static_cast<std::size_t>(tool);
  if (i < force_limits_n_.size() && std::isfinite(force_limits_n_[i])) r.force_limit_n = force_limits_n_[i];
  r.mrr_mm3_per_s = perf.mrr_m3_per_s * 1e9;
  r.surface_speed_m_min = perf.cutting_speed_m_per_s * 60.0;
  r.feed_rate_mm_min = feed * t.setup.teeth * speed_rpm;
  if (!boundary.covers(n)) {
    r.message = QObject::tr("%1 rpm is outside the computed lobes (%2-%3 rpm)")
                    .arg(speed_rpm, 0, 'f', 0)
                    .arg(revPerSToRpm(boundary.minSpeed()), 0, 'f', 0)
                    .arg(revPerSToRpm(boundary.maxSpeed()), 0, 'f', 0);
    return r;
  }
  r.blim_mm = boundary.depthLimit(n) * 1e3;
  const StabilityVerdict verdict = boundary.verdict(n, b);
  r.stable = verdict == StabilityVerdict::Stable;
  r.marginal = verdict == StabilityVerdict::Marginal;
  r.delta_ns_rpm = revPerSToRpm(boundary.speedSecurity(n, b));
  r.ros = b > 0.0 ? boundary.robustness(n, b) : std::numeric_limits<double>::quiet_NaN();
  r.valid = true;
  return r;
}

double PointEvaluator::depthLimitMm(int tool, double speed_rpm) const {
  if (!ready() || tool < 0 || tool >= toolCount()) return std::numeric_limits<double>::quiet_NaN();
  const StabilityBoundary& boundary = boundaries_[static_cast<size_t>(tool)];
  const double n = rpmToRevPerS(speed_rpm);
  return boundary.covers(n) ? boundary.depthLimit(n) * 1e3 : std::numeric_limits<double>::quiet_NaN();
}

std::pair<double, double> PointEvaluator::speedRangeRpm(int tool) const {
  if (!ready() || tool < 0 || tool >= toolCount()) return {0.0, 0.0};
  const StabilityBoundary& b = boundaries_[static_cast<size_t>(tool)];
  return {revPerSToRpm(b.minSpeed()), revPerSToRpm(b.maxSpeed())};
}

std::optional<StablePointSuggestion> PointEvaluator::suggestStablePoint(int tool, double speed_rpm, double depth_mm,
                                                                        std::optional<double> chatter_hz,
                                                                        double max_speed_rpm) const {
  if (!ready() || tool < 0 || tool >= toolCount()) return std::nullopt;
  const int teeth = snapshot_->tools[static_cast<size_t>(tool)].setup.teeth;
  return mx::suggestStablePoint(boundaries_[static_cast<size_t>(tool)], rpmToRevPerS(speed_rpm), depth_mm * 1e-3,
                                chatter_hz, teeth, 0.0, rpmToRevPerS(max_speed_rpm));
}

namespace {

// b at which b k(b) reaches `target` [W / (rev/s m)], by log-log interpolation in a table of b k(b) over
// [1 um, max_depth]; +inf beyond the table.
class PowerDepthTable {
 public:
  PowerDepthTable(const MillingSetup& setup, double feed_m, double max_depth_m) {
    constexpr int kRows = 24;
    const double lo = std::log(1e-6), hi = std::log(std::max(max_depth_m, 2e-6));
    for (int i = 0; i < kRows; ++i) {
      const double b = std::exp(lo + (hi - lo) * i / (kRows - 1));
      log_b_.push_back(std::log(b));
      log_g_.push_back(std::log(b * peakPerDepthFeed(setup, b, feed_m).power_w_per_rev_per_s));
    }
  }
  double depthFor(double target) const {
    const double g = std::log(target);
    if (g <= log_g_.front()) return std::exp(log_b_.front() + g - log_g_.front());  // linear below 1 um
    for (std::size_t i = 1; i < log_g_.size(); ++i) {
      if (g <= log_g_[i]) {
        const double f = (g - log_g_[i - 1]) / (log_g_[i] - log_g_[i - 1]);
        return std::exp(log_b_[i - 1] + f * (log_b_[i] - log_b_[i - 1]));
      }
    }
    return std::numeric_limits<double>::infinity();
  }

 private:
  std::vector<double> log_b_, log_g_;
};

}  // namespace

QVector<double> PointEvaluator::powerLimitMm(int tool, double feed) const {
  QVector<double> out;
  if (!ready() || tool < 0 || tool >= toolCount() || feed <= 0.0) return out;
  const ToolLobes& t = snapshot_->tools[static_cast<size_t>(tool)];
  const double s = feed * 1e-3;
  const bool linear = t.setup.helix_rad == 0.0 && !t.setup.hasRunout();
  double max_depth = 0.0;
  for (double b : t.margined.envelope_depth_m)
    if (std::isfinite(b)) max_depth = std::max(max_depth, b);
  std::function<double(double)> depth_for;  // b [m] at which b k(b) reaches the target
  if (linear) {
    const double k = peakPerDepthFeed(t.setup, 1e-3, s).power_w_per_rev_per_s;
    depth_for = [k](double target) { return target / k; };
  } else {
    auto table = std::make_shared<const PowerDepthTable>(t.setup, s, 4.0 * std::max(max_depth, 1e-3));
    depth_for = [table](double target) { return table->depthFor(target); };
  }
  for (double n : t.margined.speed_rev_per_s) {
    const double available = spindle_power_.available(n);
    if (!std::isfinite(available)) return {};
    const double target = available / (n * s);
    out.push_back(depth_for(target) * 1e3);
  }
  return out;
}

}  // namespace mx::gui
