#pragma once
// Where a zero of H_beta leaves the unit circle as beta varies (the paper: for beta < -0.6).
#include <vector>

#include "control/froh_discretization.h"

namespace mx {

struct ZeroThresholdResult {
  double threshold_beta = -1.0;   // the crossing nearest to 0 from below; beta_min when !found
  bool found = false;             // a crossing exists in [beta_min, 0]
  std::vector<double> crossings;  // every beta in [beta_min, beta_max] where max|zero| = 1
  int evaluations = 0;
};

// max |zero| of H_beta for one beta.
double maxZeroModulus(const StateSpace2& plant, double T, double beta);
// Scans [beta_min, beta_max] on `grid` intervals for sign changes of max|zero| - 1, then bisects each to
// |d beta| <= tol. InvalidInput for an empty or out-of-range interval or grid < 2.
ZeroThresholdResult unstableZeroThreshold(const StateSpace2& plant, double T, double beta_min = -1.0,
                                          double beta_max = 1.0, int grid = 400, double tol = 1e-12);

}  // namespace mx
