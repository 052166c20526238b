#include "point_evaluator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/cutting_force.h"

namespace mx::gui {

PointEvaluator::PointEvaluator(std::shared_ptr<const LobeSnapshot> snapshot, SpindlePowerCurve spindle_power)
    : snapshot_(std::move(snapshot)), spindle_power_(std::move(spindle_power)) {
  if (!snapshot_) return;
  for (const ToolLobes& t : snapshot_->tools) {
    if (t.margined.speed_rev_per_s.size() < 2) return;
    boundaries_.emplace_back(t.margined, snapshot_->alpha);
    // Peak power is proportional to N b s_t at fixed immersion (Pareto eq. 8).
    power_per_depth_feed_speed_.push_back(peakPowerPerDepthFeed(t.setup, 1.0));
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
  if (!boundary.covers(n)) {
    r.message = QObject::tr("%1 rpm is outside the computed lobes (%2-%3 rpm)")
                    .arg(speed_rpm, 0, 'f', 0)
                    .arg(revPerSToRpm(boundary.minSpeed()), 0, 'f', 0)
                    .arg(revPerSToRpm(boundary.maxSpeed()), 0, 'f', 0);
    return r;
  }
  r.blim_mm = boundary.depthLimit(n) * 1e3;
  r.stable = boundary.isStable(n, b);
  r.delta_ns_rpm = revPerSToRpm(boundary.speedSecurity(n, b));
  r.ros = b > 0.0 ? boundary.robustness(n, b) : std::numeric_limits<double>::quiet_NaN();
  r.valid = true;
  return r;
}

QVector<double> PointEvaluator::powerLimitMm(int tool, double feed) const {
  QVector<double> out;
  if (!ready() || tool < 0 || tool >= toolCount() || feed <= 0.0) return out;
  const ToolLobes& t = snapshot_->tools[static_cast<size_t>(tool)];
  const double k = power_per_depth_feed_speed_[static_cast<size_t>(tool)] * feed * 1e-3;
  for (double n : t.margined.speed_rev_per_s) {
    const double available = spindle_power_.available(n);
    if (!std::isfinite(available)) return {};
    out.push_back(available / (k * n) * 1e3);
  }
  return out;
}

}  // namespace mx::gui
