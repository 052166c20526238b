#include "simulation/modal_dynamics.h"

#include <algorithm>

namespace mx {

ModalDynamics::ModalDynamics(const MillingSetup& setup) : x_modes_(static_cast<int>(setup.modes_x.size())) {
  auto add = [this](const Mode& mode) {
    const double w = mode.angularFrequency();
    damping_.push_back(2.0 * mode.damping_ratio * w);
    stiffness_.push_back(w * w);
    gain_.push_back(w * w / mode.stiffness_n_per_m);
    compliance_.push_back(1.0 / mode.stiffness_n_per_m);
    highest_hz_ = std::max(highest_hz_, mode.natural_frequency_hz);
  };
  for (const Mode& mode : setup.modes_x) add(mode);
  for (const Mode& mode : setup.modes_y) add(mode);
}

std::vector<double> ModalDynamics::initialState(double x0_m, double y0_m) const {
  std::vector<double> state(static_cast<std::size_t>(stateSize()), 0.0);
  const int m = modeCount();
  // Static deflection under a force F: q_r = F / k_r, so q_r = x0 (1/k_r) / sum_s (1/k_s).
  auto split = [&](int first, int last, double displacement) {
    double total = 0.0;
    for (int r = first; r < last; ++r) total += compliance_[r];
    for (int r = first; r < last; ++r) state[r] = displacement * compliance_[r] / total;
  };
  if (x_modes_ > 0) split(0, x_modes_, x0_m);
  if (m > x_modes_) split(x_modes_, m, y0_m);
  return state;
}

}  // namespace mx
