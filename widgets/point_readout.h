#pragma once
// Everything the operating-point readouts show (shop units). Filled by the app's PointEvaluator.
#include <QMetaType>
#include <QString>

namespace mx::widgets {

struct PointReadout {
  QString tool_id;
  double speed_rpm = 0.0;
  double depth_mm = 0.0;
  double feed_mm_per_tooth = 0.0;
  double surface_speed_m_min = 0.0;  // v_c = pi D N
  double feed_rate_mm_min = 0.0;     // v_f = s_t n_t N
  double peak_power_w = 0.0;
  double power_limit_w = 0.0;  // 0 = no machine section
  double mrr_mm3_per_s = 0.0;
  double peak_force_n = 0.0;   // peak resultant static force over a tooth period
  double force_limit_n = 0.0;  // the tool's F_allow (Rule 3); 0 = none
  double blim_mm = 0.0;        // alpha * delta-lobe at this speed; +inf: none below the cap
  double delta_ns_rpm = 0.0;   // spindle speed security change (2006, section 3.B)
  double ros = 0.0;            // StabilityBoundary::robustness (negative when unstable)
  bool stable = false;         // below alpha * b_lim
  bool marginal = false;       // not stable, but within StabilityBoundary's marginal band of the lobe
  bool valid = false;          // false: no lobes yet, or the speed is outside the computed range
  QString message;             // why not valid

  double powerFraction() const { return power_limit_w > 0.0 ? peak_power_w / power_limit_w : 0.0; }
  bool powerOk() const { return power_limit_w <= 0.0 || peak_power_w <= power_limit_w; }
  double forceFraction() const { return force_limit_n > 0.0 ? peak_force_n / force_limit_n : 0.0; }
  bool forceOk() const { return force_limit_n <= 0.0 || peak_force_n <= force_limit_n; }
};

// The time-domain simulation of the same point (tool, speed, depth, feed), shown beside the lobes.
struct SimulationCheck {
  enum class State { None, Running, Done };
  State state = State::None;
  bool chatter = false;
  double eta = 0.0;  // chatter indicator eta (1 = no growth)
};

}  // namespace mx::widgets

Q_DECLARE_METATYPE(mx::widgets::PointReadout)
