#include "supervisor/supervision_metrics.h"

#include <algorithm>
#include <cmath>

namespace mx {

SupervisionMetricsAccumulator::SupervisionMetricsAccumulator(const MetricsSettings& settings) : settings_(settings) {
  metrics_.reference_force_N = settings.reference_force_N;
}

void SupervisionMetricsAccumulator::addPower(double power_W, bool steady) {
  metrics_.max_power_W = std::max(metrics_.max_power_W, power_W);
  if (steady)
    metrics_.steady_max_power_pct_of_limit =
        std::max(metrics_.steady_max_power_pct_of_limit, 100.0 * power_W / settings_.power_limit_W);
}

void SupervisionMetricsAccumulator::addChatterIndicator(double t_s, bool applicable, double indicator) {
  if (applicable && indicator > settings_.chatter_indicator_threshold) {
    metrics_.tds_chatter_s += settings_.sample_period_s;
    if (tds_run_start_ < 0.0) tds_run_start_ = t_s;
    if (tds_first_ < 0.0 && t_s - tds_run_start_ >= 10.0 * settings_.spindle_period_s) tds_first_ = tds_run_start_;
  } else {
    tds_run_start_ = -1.0;
  }
}

void SupervisionMetricsAccumulator::addDetectorSignal(double t_s, bool chatter_signalled) {
  if (chatter_signalled && !metrics_.detector_fired) {
    metrics_.detector_fired = true;
    metrics_.chatter_time_s = t_s;
  }
}

void SupervisionMetricsAccumulator::startForceTransient(double t_s) {
  metrics_.force_transients.push_back({t_s, 0.0, -100.0, -1.0});
  inside_band_since_ = -1.0;
}

void SupervisionMetricsAccumulator::addContactForce(double t_s, double F_Y_N) {
  metrics_.max_F_Y_N = std::max(metrics_.max_F_Y_N, F_Y_N);
  if (metrics_.force_transients.empty()) return;
  ForceTransient& tr = metrics_.force_transients.back();
  const double F_ref = settings_.reference_force_N;
  if (F_Y_N > tr.peak_F_Y_N) {
    tr.peak_F_Y_N = F_Y_N;
    tr.overshoot_pct = 100.0 * (F_Y_N - F_ref) / F_ref;
  }
  // Settled once F_Y has stayed in the band for the hold time; the exit from the part comes later.
  if (tr.settling_s >= 0.0) return;
  if (std::abs(F_Y_N - F_ref) > settings_.settling_band * F_ref) {
    inside_band_since_ = -1.0;
    return;
  }
  if (inside_band_since_ < 0.0) inside_band_since_ = t_s;
  if (t_s - inside_band_since_ >= settings_.settling_hold_s - 1e-9) tr.settling_s = inside_band_since_ - tr.t_s;
}

SupervisionMetrics SupervisionMetricsAccumulator::finish(double cycle_time_s, double run_seconds) const {
  SupervisionMetrics m = metrics_;
  m.max_power_pct_of_limit = 100.0 * m.max_power_W / settings_.power_limit_W;
  m.overshoot_pct = 100.0 * (m.max_F_Y_N - settings_.reference_force_N) / settings_.reference_force_N;
  // Without a firing detector, sustained TDS chatter still counts.
  const bool tds_chatter = tds_first_ >= 0.0;
  if (!m.detector_fired && tds_chatter) m.chatter_time_s = tds_first_;
  m.chatter_detected = m.detector_fired || tds_chatter;
  m.cycle_time_s = cycle_time_s;
  m.run_seconds = run_seconds;
  return m;
}

}  // namespace mx
