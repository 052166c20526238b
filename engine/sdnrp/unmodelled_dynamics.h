#pragma once
// The unmodelled dynamics of machine and process (Cus & Zuperl, Fig. 9: "random values corresponding
// with oscillations of the measured cutting forces"). The figure's block diagram was lost; we use a
// zero-mean Gaussian force held for a fixed period (a Simulink random-number block with a sample time),
// drawn from std::mt19937_64 with the seed in the settings, so a run is reproducible.
#include <cstdint>
#include <random>

namespace mx {

struct UnmodelledDynamicsSettings {
  bool enabled = true;
  std::uint64_t seed = 2008;
  double sigma_N = 3.0;  // standard deviation of the force oscillation
  double hold_s = 0.01;  // a new value every hold_s
};

class UnmodelledDynamics {
 public:
  // Throws InvalidInput for sigma < 0 or hold <= 0.
  explicit UnmodelledDynamics(UnmodelledDynamicsSettings settings);
  // The disturbance force [N] at time t; t must not decrease between calls.
  double at(double t_s);

 private:
  UnmodelledDynamicsSettings settings_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  long long slot_ = -1;
  double value_ = 0.0;
};

}  // namespace mx
