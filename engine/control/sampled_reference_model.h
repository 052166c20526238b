#pragma once
// The reference model G_m(s) = wn^2 / (s^2 + 2 xi wn s + wn^2) (2006 paper, section 4) sampled with a period that
// may change from one sample to the next (Pareto paper, Rule 4: T = k 60/N in steady state, 60/N after a change),
// and whose wn may change with it (the rise time is a number of sampling periods). Its continuous state is
// propagated exactly over each period under the beta-FROH hold of its input; a change of wn keeps F_m and dF_m/dt
// continuous. At a constant T and wn it equals the discrete H_m,beta = frohDiscretize(G_m, T, beta) driven by the
// same inputs.
#include "control/froh_discretization.h"

namespace mx {

class SampledReferenceModel {
 public:
  SampledReferenceModel(double damping_ratio, double natural_frequency_rad_s, double beta);

  double output() const;  // F_m at the current sampling instant (0 before the first period)
  // Holds u_k over the next period_s with the beta-FROH u(t) = u_k + beta (u_k - u_{k-1}) t / T, with the natural
  // frequency wn over that period.
  void advance(double u_k, double period_s, double natural_frequency_rad_s);

 private:
  double damping_ratio_, natural_frequency_rad_s_;
  StateSpace2 model_;
  double beta_;
  Eigen::Vector2d x_ = Eigen::Vector2d::Zero();
  double u_prev_ = 0.0;
};

}  // namespace mx
