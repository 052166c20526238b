#pragma once
// The JSON of `millexpert-cli control` for Rule 4 and programmed points (Pareto paper, Rule 4 and Fig. 6): the
// sampling-period keys of every run, and the per-point summary and feed/force history of a control.programme.
#include <QJsonObject>

#include "control/closed_loop.h"
#include "services/control_request.h"

namespace mx::app {

// "sample_period", "rule4_periods", "sampling_period_min_s", "sampling_period_max_s", "spindle_revolutions".
void addSamplingPeriodJson(const AdaptiveControlSettings& settings, const ClosedLoopResult& run, QJsonObject& out);

// {"segments": [{speed_rpm, depth_mm, start_s, end_s, samples, mean_force_N, peak_force_N, overshoot_pct,
//   settled_force_N, settled_feed_mm_s, analytic_feed_mm_s, programmed_feed_mm_s, force_at_programmed_feed_N}],
//  "history": {"t_s", "feed_mm_s", "force_N", "sampling_period_s"}} (per sample; the programmed-feed keys are null
// when the point does not give its feed).
QJsonObject programmeJson(const ControlRequest& request, const ClosedLoopResult& run);

}  // namespace mx::app
