#pragma once
// The adaptive force controller run through a sequence of programmed points (N, b), one workpiece step each
// (Pareto paper, Fig. 6: the programmed feed for the Table 4 points in sequence, the force held at F_r): per
// point, the force reached and the feed velocity the controller settles at, beside the analytic feed that gives
// F_r in the force plant, f = F_r / K_p(N, b) with K_p = K_c b a / (N n_t) (force_plant.h).
#include <vector>

#include "control/closed_loop.h"

namespace mx {

struct ProgrammeSegmentSummary {
  double spindle_rev_s = 0.0, depth_m = 0.0;
  double start_s = 0.0, end_s = 0.0;  // from entering the step to leaving it (the run's end for the last)
  int samples = 0;
  double mean_force_N = 0.0;       // time average of the continuous force over the step
  double peak_force_N = 0.0;       // continuous force
  double overshoot_pct = 0.0;      // max(peak - F_r, 0) / F_r
  double settled_force_N = 0.0;    // mean of the sampled force over the last quarter of the step's samples
  double settled_feed_m_s = 0.0;   // mean of the feed commands over the same samples
  double analytic_feed_m_s = 0.0;  // F_r / K_p(N, b)
};

// One entry per workpiece step the tool entered.
std::vector<ProgrammeSegmentSummary> programmeSegmentSummaries(const ClosedLoopResult& run,
                                                               const AdaptiveControlSettings& settings);

}  // namespace mx
