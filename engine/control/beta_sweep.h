#pragma once
// J_c(beta) over a grid of beta (the paper's figure 13) and the minimising beta, in parallel (std::thread).
#include <vector>

#include "control/closed_loop.h"

namespace mx {

struct BetaSweepSettings {
  double from = -1.0, to = 1.0, step = 0.1;  // inclusive grid; InvalidInput unless -1 <= from <= to <= 1, step > 0
  int threads = 0;                           // 0: hardware concurrency
};

struct BetaSweepResult {
  std::vector<double> beta, Jc_N_s, max_force_N, max_zero_modulus;
  std::vector<double> Jc_model_N_s;  // alternative reading of eq. 34 (against the reference model's samples)
  std::vector<bool> unstable_zero, completed;
  // argmin of J_c over the betas with stable zeros that completed the workpiece; `found` false if none.
  double best_beta = 0.0;
  double best_Jc_N_s = 0.0;
  bool found = false;
};

std::vector<double> betaGrid(double from, double to, double step);  // rounding-safe, endpoints included
BetaSweepResult sweepBeta(const AdaptiveControlSettings& base, const BetaSweepSettings& sweep,
                          const JobControl& job = {});

}  // namespace mx
