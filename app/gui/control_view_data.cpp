#include "control_view_data.h"

namespace mx::gui {

widgets::ControlTraces controlTracesOf(const ClosedLoopResult& r) {
  widgets::ControlTraces t;
  const std::size_t n_theta = r.samples.empty() ? 0 : r.samples.front().theta.size();
  const char* names[] = {"a1", "a2", "b0", "b1", "b2"};
  for (std::size_t k = 0; k < n_theta && k < 5; ++k) t.theta_names << names[k];
  for (const ClosedLoopSample& s : r.samples) {
    t.t_s << s.t;
    t.reference_n << s.reference_N;
    t.model_n << s.model_N;
    t.force_sampled_n << s.force_N;
    t.error_n << s.error_N;
    t.feed_mm_s << s.feed_m_s * 1e3;
    t.theta << QVector<double>(s.theta.begin(), s.theta.end());
  }
  for (const ClosedLoopDensePoint& d : r.dense) {
    t.dense_t_s << d.t;
    t.dense_force_n << d.force_N;
    t.dense_feed_mm_s << d.feed_command_m_s * 1e3;
    t.depth_t_s << d.t;
    t.depth_mm << d.depth_m * 1e3;
  }
  t.change_t_s = QVector<double>(r.depth_change_times_s.begin(), r.depth_change_times_s.end());
  return t;
}

widgets::ControlMetricsView controlMetricsOf(const ClosedLoopResult& r) {
  const ClosedLoopMetrics& m = r.metrics;
  widgets::ControlMetricsView v;
  for (const DepthStepMetrics& s : m.steps) v.overshoot_pct << s.overshoot_pct;
  v.settling_time_s = m.settling_time_s;
  v.jc_n_s = m.Jc_N_s;
  v.max_force_n = m.max_force_N;
  v.min_feed_mm_s = m.min_feed_m_s * 1e3;
  v.max_feed_mm_s = m.max_feed_m_s * 1e3;
  v.unstable_zero = m.unstable_zero;
  return v;
}

widgets::PoleZeroView poleZeroOf(const ClosedLoopResult& r) {
  widgets::PoleZeroView v;
  for (const auto& p : r.plant.poles()) v.poles << p;
  for (const auto& z : r.plant.zeros()) v.zeros << z;
  return v;
}

widgets::JcCurveView jcCurveOf(const BetaSweepResult& r, double threshold_beta) {
  widgets::JcCurveView v;
  v.beta = QVector<double>(r.beta.begin(), r.beta.end());
  v.jc_n_s = QVector<double>(r.Jc_N_s.begin(), r.Jc_N_s.end());
  if (r.found) v.best_beta = r.best_beta;
  v.threshold_beta = threshold_beta;
  return v;
}

widgets::ControllerSettingsView controllerSettingsOf(const app::ControlRequest& request) {
  const AdaptiveControlSettings& s = request.settings;
  widgets::ControllerSettingsView v;
  v.lambda = s.rls.forgetting_factor;
  v.p0 = s.rls.initial_covariance;
  v.theta0 = s.rls.initial_parameter;
  v.reset = s.rls.reset == CovarianceReset::None ? 0 : s.rls.reset == CovarianceReset::ErrorFraction ? 1 : 2;
  v.reset_fraction = s.rls.reset_error_fraction;
  v.xi = s.damping_ratio;
  v.tr_periods = s.rise_time_periods;
  v.tau_c_ms = s.process.process_time_constant_s * 1e3;
  v.feed_max_mm_s = s.feed_max_m_s * 1e3;
  v.force_reference_n = s.force_reference_N;
  return v;
}

void applyControllerSettings(const widgets::ControllerSettingsView& v, app::ControlRequest& request) {
  AdaptiveControlSettings& s = request.settings;
  s.rls.forgetting_factor = v.lambda;
  s.rls.initial_covariance = v.p0;
  s.rls.initial_parameter = v.theta0;
  s.rls.reset = v.reset == 0   ? CovarianceReset::None
                : v.reset == 1 ? CovarianceReset::ErrorFraction
                               : CovarianceReset::Trace;
  s.rls.reset_error_fraction = v.reset_fraction;
  s.damping_ratio = v.xi;
  s.rise_time_periods = v.tr_periods;
  s.process.process_time_constant_s = v.tau_c_ms * 1e-3;
  s.feed_max_m_s = v.feed_max_mm_s * 1e-3;
  if (v.force_reference_n != s.force_reference_N) {
    s.force_reference_N = v.force_reference_n;
    request.reference.force_N = v.force_reference_n;
    request.reference.binding = "project";
  }
}

QVector<widgets::DepthStepView> workpieceViewOf(const ControlWorkpiece& w) {
  QVector<widgets::DepthStepView> out;
  for (const ControlDepthStep& s : w.steps) out.append({s.length_m * 1e3, s.depth_m * 1e3});
  return out;
}

ControlWorkpiece workpieceOf(const QVector<widgets::DepthStepView>& steps, const ControlWorkpiece& previous) {
  ControlWorkpiece w;
  for (const widgets::DepthStepView& s : steps) {
    const std::size_t i = w.steps.size();
    const double speed = i < previous.steps.size() ? previous.steps[i].spindle_rev_s : 0.0;
    w.steps.push_back({s.length_mm * 1e-3, s.depth_mm * 1e-3, speed});
  }
  return w;
}

}  // namespace mx::gui
