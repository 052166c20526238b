// closedLoopMetrics (declared in closed_loop.h): overshoot and settling per depth step, J_c (eq. 34), extremes.
#include <algorithm>
#include <cmath>
#include <limits>

#include "control/closed_loop.h"

namespace mx {

namespace {

struct Window {
  double from, to;
  bool closed = true;  // [from, to] for the last window, [from, to) otherwise
};

// Overshoot (upward) or undershoot (downward) in % of F_r, and settling into the band, over one window.
void windowMetrics(const std::vector<ClosedLoopDensePoint>& dense, Window w, bool upward, double fr, double band,
                   double& overshoot_pct, double& settling_s, bool& settled, double& peak) {
  double extreme = upward ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  double last_out = w.from;
  bool any = false, last_in_band = false;
  peak = 0.0;
  for (const auto& p : dense) {
    if (p.t < w.from || p.t > w.to || (!w.closed && p.t == w.to)) continue;
    any = true;
    extreme = upward ? std::max(extreme, p.force_N) : std::min(extreme, p.force_N);
    peak = std::max(peak, p.force_N);
    last_in_band = std::abs(p.force_N - fr) <= band * fr;
    if (!last_in_band) last_out = p.t;
  }
  if (!any) {
    overshoot_pct = 0.0;
    settling_s = 0.0;
    settled = false;
    return;
  }
  overshoot_pct = std::max(0.0, upward ? (extreme - fr) / fr : (fr - extreme) / fr) * 100.0;
  settled = last_in_band;
  settling_s = (settled ? last_out : w.to) - w.from;
}

}  // namespace

ClosedLoopMetrics closedLoopMetrics(const ClosedLoopResult& run, double fr, double band) {
  ClosedLoopMetrics m;
  m.samples = static_cast<int>(run.samples.size());
  if (run.samples.empty() || run.dense.empty()) return m;
  const double t_end = run.dense.back().t;
  m.duration_s = t_end;

  // windows: engagement, then one per depth change
  const auto& tc = run.depth_change_times_s;
  const double first_change = tc.empty() ? t_end : tc.front();
  bool settled = false;
  double peak = 0.0;
  windowMetrics(run.dense, {0.0, first_change, tc.empty()}, true, fr, band, m.initial_overshoot_pct,
                m.initial_settling_time_s, settled, peak);
  for (std::size_t i = 0; i < tc.size(); ++i) {
    DepthStepMetrics st;
    st.time_s = tc[i];
    const double to = i + 1 < tc.size() ? tc[i + 1] : t_end;
    // depth before/after from the dense points around the change
    for (const auto& p : run.dense) {
      if (p.t < tc[i]) st.depth_from_m = p.depth_m;
      if (p.t > tc[i]) {
        st.depth_to_m = p.depth_m;
        break;
      }
    }
    st.upward = st.depth_to_m >= st.depth_from_m;
    windowMetrics(run.dense, {tc[i], to, i + 1 == tc.size()}, st.upward, fr, band, st.overshoot_pct, st.settling_time_s,
                  st.settled, st.peak_force_N);
    m.settling_time_s = std::max(m.settling_time_s, st.settling_time_s);
    m.steps.push_back(st);
  }

  // J_c (eq. 34): area between the continuous output and the linear interpolation of its samples (trapezoid)
  for (std::size_t i = 1; i < run.dense.size(); ++i) {
    const auto &a = run.dense[i - 1], &b = run.dense[i];
    m.Jc_N_s += 0.5 * (std::abs(a.force_N - a.interpolated_N) + std::abs(b.force_N - b.interpolated_N)) * (b.t - a.t);
    m.Jc_model_N_s += 0.5 *
                      (std::abs(a.force_N - a.model_interpolated_N) + std::abs(b.force_N - b.model_interpolated_N)) *
                      (b.t - a.t);
  }
  m.max_force_N = 0.0;
  m.min_feed_command_m_s = std::numeric_limits<double>::infinity();
  m.max_feed_command_m_s = -std::numeric_limits<double>::infinity();
  for (const auto& p : run.dense) {
    m.max_force_N = std::max(m.max_force_N, p.force_N);
    if (p.t > 0.0) {
      m.min_feed_command_m_s = std::min(m.min_feed_command_m_s, p.feed_command_m_s);
      m.max_feed_command_m_s = std::max(m.max_feed_command_m_s, p.feed_command_m_s);
    }
  }
  if (!std::isfinite(m.min_feed_command_m_s)) m.min_feed_command_m_s = m.max_feed_command_m_s = 0.0;
  m.min_feed_m_s = std::numeric_limits<double>::infinity();
  m.max_feed_m_s = -std::numeric_limits<double>::infinity();
  for (const auto& smp : run.samples) {
    m.min_feed_m_s = std::min(m.min_feed_m_s, smp.feed_m_s);
    m.max_feed_m_s = std::max(m.max_feed_m_s, smp.feed_m_s);
    if (smp.rls_reset) ++m.rls_resets;
    if (!smp.design_ok) ++m.design_failures;
    if (smp.design_ok && !smp.model_zeros_followed) ++m.fallback_samples;
    m.max_diophantine_residual = std::max(m.max_diophantine_residual, smp.diophantine_residual);
  }
  m.max_zero_modulus = run.plant.maxZeroModulus();
  m.unstable_zero = m.max_zero_modulus >= 1.0;
  return m;
}

}  // namespace mx
