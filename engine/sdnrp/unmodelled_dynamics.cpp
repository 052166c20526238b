#include "sdnrp/unmodelled_dynamics.h"

#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

UnmodelledDynamics::UnmodelledDynamics(UnmodelledDynamicsSettings s) : settings_(s), rng_(s.seed) {
  if (!(s.sigma_N >= 0.0) || !std::isfinite(s.sigma_N))
    throw InvalidInput("disturbance sigma = " + std::to_string(s.sigma_N) + " N: must be >= 0");
  if (!(s.hold_s > 0.0) || !std::isfinite(s.hold_s))
    throw InvalidInput("disturbance hold = " + std::to_string(s.hold_s) + " s: must be > 0");
}

double UnmodelledDynamics::at(double t) {
  if (!settings_.enabled || settings_.sigma_N == 0.0) return 0.0;
  const auto slot = static_cast<long long>(std::floor(t / settings_.hold_s + 1e-9));
  while (slot_ < slot) {  // one draw per elapsed slot, so the sequence does not depend on the step
    value_ = settings_.sigma_N * normal_(rng_);
    ++slot_;
  }
  return value_;
}

}  // namespace mx
