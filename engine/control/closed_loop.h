#pragma once
// Adaptive model-following force control under beta-FROH (2006 paper, section 4), simulated over a workpiece
// depth profile (and, for a sequence of programmed points, a spindle speed per step: Pareto paper, Fig. 6). Each
// sampling period T (one spindle period, or Rule 4 of the Pareto paper: k spindle periods while the programmed N
// and b stay constant, one after any change): sample the force, update the RLS estimate (eq. 26), redesign the RST
// controller by pole placement (eq. 27-29) for the reference model sampled at this T, compute the saturated feed
// command, hold it with the beta-FROH over T, and integrate the continuous plant with CVODE until the next sample.
// The tool position (integral of the actual feed) decides the depth of cut and the programmed point.
//
// Units: SI everywhere in the API (N, m/s, m, s). The estimator and controller work internally in kN and mm/s
// (control_force_unit_N = 1e3, control_feed_unit_m_s = 1e-3): the paper's theta(0) = 0.2 and P(0) = 1e5 I are
// unit-dependent, and in these units the gains (b_i ~ 0.06 kN/(mm/s)) and the regressor entries (y ~ 1 kN,
// u ~ 10 mm/s) are of comparable size, so that the reset covariance P(0) = 1e5 I does not favour the a_i.
#include <vector>

#include "control/plant_integrator.h"
#include "control/pole_placement.h"
#include "control/rls_estimator.h"
#include "core/cancellation.h"
#include "core/invalid_input.h"

namespace mx {

// How the sampling period is chosen (Pareto paper, Rule 4).
enum class SamplePeriodRule {
  Spindle,  // T = 60/N at every sample
  Rule4,    // T = k 60/N while N and b stay constant, 60/N after a change (SamplingTimeSelector)
};

// The most spindle periods one closed-loop run samples (max_time_s at the fastest speed): 30 s at
// 100 000 rpm is 50 000.
inline constexpr double kMaxClosedLoopSamples = 2e5;

struct AdaptiveControlSettings {
  CuttingProcess process;  // 715 rpm, 4 teeth, K_c = 1200 N/mm^2, full immersion
  ControlWorkpiece workpiece = rubio2006ControlWorkpiece();
  double force_reference_N = 1200.0;  // F_r (1.2 kN)
  double feed_max_m_s = 0.03;         // drive maximum (not given by the paper); minimum is 0
  double beta = 0.0;                  // FROH gain in [-1, 1]
  double damping_ratio = 0.75;        // xi of the reference model
  double rise_time_periods = 4.0;     // T_r = 4 T; omega_n = 2.5 / T_r
  RlsSettings rls;                    // lambda = 1, P0 = 1e5, theta0 = 0.2, 5 % reset
  PolePlacementSettings design;
  double control_force_unit_N = 1e3;    // controller force unit (kN)
  double control_feed_unit_m_s = 1e-3;  // controller feed unit (mm/s)
  int dense_points_per_sample = 32;     // continuous output points per period
  double rtol = 1e-8;                   // CVODE relative tolerance
  double max_time_s = 30.0;             // stop if the tool has not left the profile by then
  double settling_band = 0.05;          // +-5 % of F_r
  SamplePeriodRule sample_period = SamplePeriodRule::Spindle;
  int rule4_periods = 4;  // k of Rule 4, in [1, 100]
};

void validateAdaptiveControlSettings(const AdaptiveControlSettings& s);  // InvalidInput naming the field

struct ClosedLoopSample {
  double t = 0.0;
  double sampling_period_s = 0.0;  // T of the period that starts at t (0 for the last sample)
  double spindle_rev_s = 0.0;      // programmed N at t
  double reference_N = 0.0, model_N = 0.0, force_N = 0.0, error_N = 0.0;  // error = F_p - F_pm
  double feed_m_s = 0.0;                                                  // applied (saturated) command u_k
  double feed_unsaturated_m_s = 0.0;                                      // the RST law before saturation
  double depth_m = 0.0, position_m = 0.0;
  std::vector<double> theta;  // [a1 a2 b0 b1 (b2)], controller units (kN, mm/s)
  bool rls_reset = false;
  bool design_ok = false;             // false: the previous controller was kept
  bool model_zeros_followed = false;  // false: fallback, some zeros not cancelled
  int common_factors_removed = 0;
  double diophantine_residual = 0.0;
};

struct ClosedLoopDensePoint {
  double t = 0.0, force_N = 0.0, interpolated_N = 0.0;  // continuous output and the linear interpolation of samples
  double model_interpolated_N = 0.0;                    // linear interpolation of the reference model's samples
  double feed_command_m_s = 0.0, feed_actual_m_s = 0.0, position_m = 0.0, depth_m = 0.0;
};

struct DepthStepMetrics {
  double time_s = 0.0, depth_from_m = 0.0, depth_to_m = 0.0;
  bool upward = true;
  double overshoot_pct = 0.0;    // upward: max(F - F_r)/F_r; downward: the undershoot max(F_r - F)/F_r (continuous F)
  double settling_time_s = 0.0;  // from the step until F stays within the band (to the end of the window if never)
  bool settled = false;
  double peak_force_N = 0.0;
};

struct ClosedLoopMetrics {
  std::vector<DepthStepMetrics> steps;  // one per depth change (3 for the paper's workpiece)
  double initial_overshoot_pct = 0.0;   // engagement transient, before the first depth change
  double initial_settling_time_s = 0.0;
  double settling_time_s = 0.0;                   // the largest settling time of the depth steps
  double Jc_N_s = 0.0;                            // eq. 34: int |F(t) - linear interpolation of F(kT)| dt
  double Jc_model_N_s = 0.0;                      // alternative reading of eq. 34: int |F(t) - interpolated F_m(kT)| dt
  double max_force_N = 0.0;                       // continuous output
  double min_feed_m_s = 0.0, max_feed_m_s = 0.0;  // sampled commands u_k
  double min_feed_command_m_s = 0.0, max_feed_command_m_s = 0.0;  // continuous hold output
  double max_zero_modulus = 0.0;                                  // of the true plant's H_beta
  bool unstable_zero = false;                                     // max_zero_modulus >= 1
  bool completed = false;  // the tool reached the end of the profile before max_time_s
  double duration_s = 0.0;
  int samples = 0, rls_resets = 0, design_failures = 0, fallback_samples = 0;
  double max_diophantine_residual = 0.0;
  long cvode_steps = 0;
  double min_sampling_period_s = 0.0, max_sampling_period_s = 0.0;
  double spindle_revolutions = 0.0;  // sum of T N over the periods: the samples a once-per-revolution loop takes
};

struct ClosedLoopResult {
  double beta = 0.0, sampling_period_s = 0.0, tau_c_s = 0.0;  // at the first point, one spindle period
  DiscreteTransferFunction plant;                             // H_beta of the true plant at the first depth
  DiscreteTransferFunction model;                             // H_m,beta at sampling_period_s
  std::vector<ClosedLoopSample> samples;
  std::vector<ClosedLoopDensePoint> dense;
  std::vector<double> depth_change_times_s;
  ClosedLoopMetrics metrics;
};

ClosedLoopResult simulateAdaptiveForceControl(const AdaptiveControlSettings& settings, const JobControl& job = {});

// The beta below which a zero of H_beta of the true plant (at the workpiece's first depth; 1 mm when
// that is 0) leaves the unit circle (unstableZeroThreshold); -1 for an empty workpiece.
double closedLoopZeroThreshold(const AdaptiveControlSettings& settings);

// The metrics from finished time series (used by simulateAdaptiveForceControl; public for tests and tools).
ClosedLoopMetrics closedLoopMetrics(const ClosedLoopResult& run, double force_reference_N, double settling_band);
// The sampling-period extremes and the spindle revolutions the samples cover.
void samplingMetrics(const std::vector<ClosedLoopSample>& samples, ClosedLoopMetrics& metrics);

}  // namespace mx
