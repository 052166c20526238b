#pragma once
// Settings of the expert system (Rubio, De la Sen & Ibeas 2006, section 3; Pareto paper, Rules 5-7):
// the cutting-parameter grid, the machine and operation limits that bound the admissible space Q, the
// stability method and margins (Rule 1), and the time-domain refinement (Rule 5). SI units.
#include <limits>
#include <vector>

#include "model/spindle_power.h"
#include "stability/lobe_computation.h"  // StabilityMethod, DynamicsSource

namespace mx {

// Q = (N, b, s_t) on a grid: speeds from..to by step (plus, optionally, the Rule 7.2 speeds
// 60 f_n / (n_t k) of every mode), depths b_min/k, 2 b_min/k, ... (b_min: the minimum of the margined
// border line over the speed range, k = depth_divisions), feeds feed_step, 2 feed_step, ...
struct ExpertGrid {
  double speed_from_rev_per_s = 1000.0 / 60.0;
  double speed_to_rev_per_s = 12000.0 / 60.0;
  double speed_step_rev_per_s = 100.0 / 60.0;
  int depth_divisions = 10;
  double feed_step_m = 0.01e-3;
  bool modal_candidate_speeds = true;  // Pareto Rule 7.2
};

// Constraints of the admissible space besides the lobes. +inf = no limit. The peak cutting power
// (Pareto eq. 8) is bounded by the available power P_av(N) = min(P_max, 2 pi N T_max, curve(N)), and the
// peak resultant force by the tool's allowable force F_allow (Pareto Rules 3 and 7.1: breakage).
struct MachineLimits {
  double spindle_power_w = std::numeric_limits<double>::infinity();        // P_max
  double max_spindle_torque_nm = std::numeric_limits<double>::infinity();  // T_max: P <= 2 pi N T_max
  std::vector<SpindlePowerPoint> spindle_curve;                            // the machine's power curve
  double max_spindle_rev_per_s = std::numeric_limits<double>::infinity();
  double max_feed_velocity_m_per_s = std::numeric_limits<double>::infinity();  // feed drive (Pareto Rule 6)
  double max_feed_per_tooth_m = std::numeric_limits<double>::infinity();       // operation maximum
  double max_tool_force_n = std::numeric_limits<double>::infinity();           // F_allow of the tool

  SpindlePowerCurve spindlePower() const { return {spindle_power_w, max_spindle_torque_nm, spindle_curve}; }
};

struct StabilitySettings {
  StabilityMethod method = StabilityMethod::ZeroOrder;
  double delta_per_s = 0.0;                       // Rule 1.1
  double alpha = 1.0;                             // Rule 1.2
  double lobe_step_rev_per_s = 10.0 / 60.0;       // speed resolution of the lobes used for b_lim and Delta N_s (ZOA)
  double sdm_lobe_step_rev_per_s = 100.0 / 60.0;  // the same for semi-discretization (cost ~2 ms per speed)
  int sdm_steps_per_period = kAutoSdmSteps;       // autoSdmSteps per speed
  double max_depth_m = 0.02;                      // depth cap where no lobe lies below
  // The lobes are computed over [low_factor * from, high_factor * to] so that the lobe minima that
  // bound Delta N_s at the ends of the speed range are known (a minimum beyond 2 * to can never be the
  // nearer side of a point at or below `to`).
  double lobe_range_low_factor = 0.8;
  double lobe_range_high_factor = 2.0;
  DynamicsSource dynamics = DynamicsSource::Modal;  // ZOA: Measured uses the tools' measured FRFs (delta = 0)
};

// Rule 5 pattern search around q* (rule5_search.h). A start step of 0 is derived from the grid.
struct Rule5SearchSettings {
  double speed_step_rev_per_s = 0.0;  // 0: a quarter of the grid's speed step
  double depth_step_m = 0.0;          // 0: half the grid's depth step (b_min / depth_divisions)
  double feed_step_m = 0.0;           // 0: half the grid's feed step
  // A variable whose step has fallen below its resolution is no longer varied.
  double speed_resolution_rev_per_s = 10.0 / 60.0;
  double depth_resolution_m = 1e-6;
  double feed_resolution_m = 1e-6;
  int max_iterations = 20;  // 0: only the best K points by C are simulated
};

// Rule 5 refinement and Rule 6 malfunction loop.
struct RefinementSettings {
  int simulated_points = 12;  // K: the best K points by C of the selected tool seed the Rule 5 search
  Rule5SearchSettings search;
  int revolutions = 60;                  // per simulation, from rest
  int evaluated_revolutions = 20;        // spectra over the last ones
  int threads = 0;                       // 0 = std::thread::hardware_concurrency()
  int max_malfunction_iterations = 200;  // Rule 6
  double malfunction_ratio = 1.0;        // Rule 6 fires while A_chatter > ratio * A_toothpass (1 = as printed)
};

struct ExpertSettings {
  ExpertGrid grid;
  MachineLimits limits;
  StabilitySettings stability;
  RefinementSettings refinement;
};

}  // namespace mx
