#pragma once
// The SDNRP of Cus & Zuperl (2008): the system for dynamic adjusting of cutting parameters that holds
// the cutting force at F_d = K1(Ra_desired) so that the produced roughness K5(F) meets the desired Ra.
// Loop (section 5.1, with the feedback the printed models need):
//   F_d  = K1(Ra_d)
//   n_c  = clamp(K3(F_d))                           spindle speed command (feed-forward)
//   f_ff = clamp(K2(F_d))                           feed feed-forward (K2 < 0 below 177 N: clamped)
//   f_c  = clamp(f_ff + x),  dx/dt = lambda (F_d - F_meas) / dK4/df(n_a, f_a)   integral action on feed,
//          normalised by K4's feed sensitivity (loop pole at -lambda whatever the operating point),
//          with anti-windup (x frozen while f_c is clamped and the error pushes further)
//   feed servo:    f_a'' = w^2 (f_c - f_a) - 2 zeta w f_a'     (2nd order, w = 30 rad/s, zeta = 0.7)
//   spindle drive: n_a'  = (n_c - n_a) / tau_s                (1st order, tau_s = 0.3 s)
//   F = K4(n_a, f_a),  F_meas = F + disturbance (UnmodelledDynamics),  Ra = K5(F), Ra_dyn = K5(F_meas)
// Integrated with RK4 at a fixed step (disturbance held over a step). The drive models are ours: the
// paper's Figs 1 and 3 (Heller servo-drive data) were lost in extraction; see docs/sdnrp-gcode-notes.md.
// control = false is the paper's run "without application of SDNRP" (Figs 12 and 14): the commands are
// held at the loop's own starting point (f_c = f_a(0), n_c = n_a(0): the initial cutting conditions of
// Table 1 / Table 2, or f_ff and n_c when unset), so the same plant, drives and disturbance (same seed)
// act on a constant feed and speed, and the disturbance reaches F and Ra unopposed.
// API in SI units (Ra in m, feed in m/s, speed in rev/s); the GP models run in the paper's units.
#include <limits>
#include <vector>

#include "core/cancellation.h"
#include "core/invalid_input.h"
#include "sdnrp/unmodelled_dynamics.h"

namespace mx {

struct SdnrpDriveSettings {
  double feed_natural_frequency_rad_s = 30.0;
  double feed_damping = 0.7;
  double spindle_time_constant_s = 0.3;
};

struct SdnrpSettings {
  double ra_desired_m = 0.81e-6;  // 0.25 .. 2.5 um
  double duration_s = 15.0;       // Table 2: "servo drive system after 15 s"
  double time_step_s = 1e-3;
  double output_period_s = 0.01;  // one sample of the six signals every output_period_s
  double final_window_s = 1.0;    // final values: means over the last final_window_s
  double initial_feed_m_per_s = std::numeric_limits<double>::quiet_NaN();     // NaN: start at f_ff
  double initial_speed_rev_per_s = std::numeric_limits<double>::quiet_NaN();  // NaN: start at n_c
  double min_feed_m_per_s = 100e-3 / 60.0;                                    // above K4's turning feed (69.7 mm/min)
  double max_feed_m_per_s = 2000e-3 / 60.0;
  double min_speed_rev_per_s = 500.0 / 60.0;
  double max_speed_rev_per_s = 6000.0 / 60.0;
  double integral_rate_per_s = 2.0;  // lambda
  bool control = true;               // false: no SDNRP, feed and speed held at the initial ones
  SdnrpDriveSettings drives;
  UnmodelledDynamicsSettings disturbance;
};

// The six console signals of the paper's section 5, plus the two commands.
struct SdnrpSample {
  double t_s = 0.0;
  double ra_m = 0.0;             // actual surface roughness, K5(F)
  double ra_dynamic_m = 0.0;     // with the machine-tool dynamics, K5(F + disturbance)
  double force_N = 0.0;          // maximal cutting force, K4
  double force_dynamic_N = 0.0;  // with the dynamical component
  double feed_m_per_s = 0.0;     // actual feed f_a
  double speed_rev_per_s = 0.0;  // actual spindle speed n_a
  double feed_command_m_per_s = 0.0;
  double speed_command_rev_per_s = 0.0;
};

// Spread of a signal over an interval, sampled at every integration step.
struct SdnrpSpread {
  double min = 0.0, max = 0.0, mean = 0.0;
  double std = 0.0;        // about the mean
  double rms_error = 0.0;  // about the target (F_d, Ra_d): what the loop is there to remove
};

struct SdnrpResult {
  std::vector<SdnrpSample> samples;
  double ra_desired_m = 0.0;
  double fd_N = 0.0;
  double f_final_N = 0.0;           // mean measured force (with disturbance) over the final window
  double feed_final_m_per_s = 0.0;  // mean f_a over the final window
  double speed_final_rev_per_s = 0.0;
  double ra_produced_m = 0.0;                 // mean K5(F + disturbance) over the final window
  double feed_feedforward_raw_m_per_s = 0.0;  // K2(F_d) before clamping (may be negative)
  double speed_command_rev_per_s = 0.0;       // clamped K3(F_d)
  double initial_feed_m_per_s = 0.0;
  double initial_speed_rev_per_s = 0.0;
  bool feed_saturated = false;  // f_c on a limit at the end: F_d not reachable (false without control)
  bool control = true;          // the loop ran (SdnrpSettings::control)
  // Measured force F + disturbance [N] and Ra = K5(F + disturbance) [m], over the whole run and over
  // the final window.
  SdnrpSpread force_run, force_final, ra_run, ra_final;
};

class SdnrpSimulator {
 public:
  // Throws InvalidInput naming the field for Ra outside 0.25..2.5 um, non-positive times or steps,
  // inconsistent limits, or a non-positive gain or drive constant.
  explicit SdnrpSimulator(SdnrpSettings settings);
  // Polls job.cancelled() every simulated 0.1 s (throws Cancelled) and reports progress.
  SdnrpResult run(const JobControl& job = {}) const;
  const SdnrpSettings& settings() const { return settings_; }

 private:
  SdnrpSettings settings_;
};

}  // namespace mx
