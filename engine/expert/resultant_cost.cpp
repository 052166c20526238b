#include "expert/resultant_cost.h"

#include <algorithm>

#include "core/invalid_input.h"
#include "expert/tool_cost.h"

namespace mx {

namespace {
// Below this the figures are round-off (a stable cut's R1ch is ~1e-17): a term whose maximum over the
// set is below it is zero instead of a ratio of noise.
constexpr double kNoiseFloor = 1e-9;
double ratio(double value, double max) {
  return max > kNoiseFloor ? value / max : 0.0;
}
}  // namespace

std::size_t selectByResultantCost(std::vector<RefinementCandidate>& candidates, const CostWeights& w) {
  if (candidates.empty()) throw InvalidInput("Rule 5: no candidate points to select from");
  double ts_max = 0.0, mp_max = 0.0, r12_max = 0.0, r1ch_max = 0.0;
  for (const RefinementCandidate& c : candidates) {
    ts_max = std::max(ts_max, c.metrics.settling_time_s);
    mp_max = std::max(mp_max, c.metrics.overshoot);
    r12_max = std::max(r12_max, c.metrics.r12h);
    r1ch_max = std::max(r1ch_max, c.metrics.r1ch);
  }
  std::size_t best = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    RefinementCandidate& c = candidates[i];
    c.time_cost = w.ct[0] * ratio(c.metrics.settling_time_s, ts_max) + w.ct[1] * ratio(c.metrics.overshoot, mp_max);
    c.frequency_cost = w.cf[0] * ratio(c.metrics.r12h, r12_max) + w.cf[1] * ratio(c.metrics.r1ch, r1ch_max);
    c.resultant = w.cr[0] * c.cost + w.cr[1] * c.time_cost + w.cr[2] * c.frequency_cost;
    const RefinementCandidate& b = candidates[best];
    if (i > 0 && rankBefore({c.resultant, c.q.mrr_m3_per_s, c.q.power_w, c.q.speed_rev_per_s, c.q.depth_m},
                            {b.resultant, b.q.mrr_m3_per_s, b.q.power_w, b.q.speed_rev_per_s, b.q.depth_m}))
      best = i;
  }
  return best;
}

}  // namespace mx
