#include "control/zero_threshold.h"

#include <cmath>
#include <limits>
#include <string>

#include "core/invalid_input.h"

namespace mx {

double maxZeroModulus(const StateSpace2& plant, double T, double beta) {
  return frohDiscretize(plant, T, beta).maxZeroModulus();
}

ZeroThresholdResult unstableZeroThreshold(const StateSpace2& plant, double T, double beta_min, double beta_max,
                                          int grid, double tol) {
  if (!(beta_min >= -1.0 && beta_min < beta_max && beta_max <= 1.0))
    throw InvalidInput("zero threshold: [beta_min, beta_max] = [" + std::to_string(beta_min) + ", " +
                       std::to_string(beta_max) + "]: must satisfy -1 <= beta_min < beta_max <= 1");
  if (grid < 2) throw InvalidInput("zero threshold: grid = " + std::to_string(grid) + ": must be >= 2");
  if (!(tol > 0.0)) throw InvalidInput("zero threshold: tol = " + std::to_string(tol) + ": must be > 0");
  ZeroThresholdResult result;
  result.threshold_beta = beta_min;  // meaningful only when found
  auto f = [&](double beta) {
    ++result.evaluations;
    return maxZeroModulus(plant, T, beta) - 1.0;
  };
  double b0 = beta_min;
  double f0 = f(b0);
  for (int i = 1; i <= grid; ++i) {
    const double b1 = beta_min + (beta_max - beta_min) * i / grid;
    const double f1 = f(b1);
    if ((f0 < 0.0) != (f1 < 0.0)) {
      double lo = b0, hi = b1, flo = f0;
      while (hi - lo > tol) {
        const double mid = 0.5 * (lo + hi);
        const double fm = f(mid);
        if ((fm < 0.0) == (flo < 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      result.crossings.push_back(0.5 * (lo + hi));
    }
    b0 = b1;
    f0 = f1;
  }
  for (double c : result.crossings) {
    if (c <= 0.0 && (!result.found || c > result.threshold_beta)) {
      result.threshold_beta = c;
      result.found = true;
    }
  }
  return result;
}

}  // namespace mx
