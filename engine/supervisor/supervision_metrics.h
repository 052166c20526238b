#pragma once
// The figures of merit of a supervised run (power against the spindle limit, force overshoot,
// chatter, cycle time), accumulated sample by sample.
#include <vector>

namespace mx {

// The force from one restart of a force controller (an impulse L* or K* at contact) to the next.
struct ForceTransient {
  double t_s = 0.0;            // the restart
  double peak_F_Y_N = 0.0;     // largest F_Y in contact until the next restart
  double overshoot_pct = 0.0;  // 100 (peak - F_ref) / F_ref
  double settling_s = -1.0;    // until F_Y enters the settling band for good (settling_hold_s); -1: never
};

struct SupervisionMetrics {
  double reference_force_N = 0.0;
  double max_power_W = 0.0;
  double max_power_pct_of_limit = 0.0;         // 100 P_max / P_limit, P = tooth-period mean cutting power
  double steady_max_power_pct_of_limit = 0.0;  // same, last pass, tool fully over the part
  double max_F_Y_N = 0.0;
  double overshoot_pct = 0.0;     // 100 (max F_Y in contact - F_ref) / F_ref
  bool chatter_detected = false;  // by the supervisor (D, E) or, without detector, by the TDS
  double chatter_time_s = -1.0;   // first detection, -1 if none
  bool detector_fired = false;    // E or D signalled chatter
  double tds_chatter_s = 0.0;     // time with the TDS chatter indicator above threshold
  int passes = 0;                 // passes executed
  double cycle_time_s = 0.0;
  double run_seconds = 0.0;  // wall-clock time of the run
  std::vector<ForceTransient> force_transients;
};

struct MetricsSettings {
  double reference_force_N = 0.0;
  double power_limit_W = 1.0;
  double sample_period_s = 5e-4;
  double spindle_period_s = 0.04;
  double chatter_indicator_threshold = 0.02;  // on the TDS indicator RMS regen / f_t
  double settling_band = 0.02;                // force transients: |F_Y - F_ref| <= band F_ref
  double settling_hold_s = 0.4;               // ... for this long (10 revolutions at 1500 rpm)
};

class SupervisionMetricsAccumulator {
 public:
  explicit SupervisionMetricsAccumulator(const MetricsSettings& settings);

  void countPass() { ++metrics_.passes; }
  // The tooth-period mean power of a sample; `steady`: last pass with the tool fully over the part.
  void addPower(double power_W, bool steady);
  // The TDS chatter indicator at t_s, counted only while `applicable` (tool over the part, feeding).
  // Chatter is sustained after 10 revolutions in a row above the threshold: entry and exit impacts
  // are shorter.
  void addChatterIndicator(double t_s, bool applicable, double indicator);
  // The supervisor's chatter signals (D or E); the first one sets the chatter time.
  void addDetectorSignal(double t_s, bool chatter_signalled);
  // A force controller restarts (L* or K*): a new force transient begins at t_s.
  void startForceTransient(double t_s);
  void addContactForce(double t_s, double F_Y_N);  // F_Y while the tool is in contact

  const SupervisionMetrics& current() const { return metrics_; }
  // The final metrics of a run that ended at cycle_time_s (simulated) after run_seconds (wall clock).
  SupervisionMetrics finish(double cycle_time_s, double run_seconds) const;

 private:
  MetricsSettings settings_;
  SupervisionMetrics metrics_;
  double tds_first_ = -1.0;          // start of the first sustained TDS chatter, -1 if none
  double tds_run_start_ = -1.0;      // start of the current run above the threshold, -1 if below
  double inside_band_since_ = -1.0;  // start of the current transient's stay in the band, -1 if outside
};

}  // namespace mx
