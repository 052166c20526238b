#include "pareto/sampling_time.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

double samplingTime(double speed_rev_per_s, bool steady_state, int k) {
  if (!(speed_rev_per_s > 0.0) || !std::isfinite(speed_rev_per_s))
    throw InvalidInput("sampling time: spindle speed = " + std::to_string(speed_rev_per_s) + " rev/s: must be > 0");
  if (k < 1) throw InvalidInput("sampling time: steady_state_periods = " + std::to_string(k) + ": must be >= 1");
  return (steady_state ? static_cast<double>(k) : 1.0) / speed_rev_per_s;
}

SamplingTimeSelector::SamplingTimeSelector(SamplingTimeSettings settings) : settings_(settings) {
  if (settings_.steady_state_periods < 1)
    throw InvalidInput("sampling time: steady_state_periods = " + std::to_string(settings_.steady_state_periods) +
                       ": must be >= 1");
}

double SamplingTimeSelector::update(double n, double b) {
  auto same = [&](double a, double c) {
    return std::abs(a - c) <= settings_.relative_tolerance * std::max(std::abs(a), std::abs(c));
  };
  steady_ = has_previous_ && same(n, speed_) && same(b, depth_);
  speed_ = n;
  depth_ = b;
  has_previous_ = true;
  return samplingTime(n, steady_, settings_.steady_state_periods);
}

}  // namespace mx
