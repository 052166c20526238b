#include "pareto/weight_modulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/invalid_input.h"

namespace mx {

RequirementResult applyRequirement(const ParetoSelector& selector, const ParetoWeights& w,
                                   const ObjectiveRequirement& r, int bisections) {
  validateParetoWeights(w);
  if (!(r.lo <= r.hi)) throw InvalidInput("requirement: lo must be <= hi");
  RequirementResult out;
  out.weights = w;
  out.selection = selector.coarse(w);
  out.evaluations = 1;
  const std::size_t k = index(r.objective);
  const double v0 = out.selection.point.objectives[k];
  if (v0 >= r.lo && v0 <= r.hi) {
    out.satisfied = true;
    return out;
  }
  // Does the score n_k have to rise (true) or fall?
  const bool raise = isMinimised(k) ? v0 > r.hi : v0 < r.lo;
  // The bound on the good side of the monotone predicate.
  auto reached = [&](const ParetoSelection& s) {
    const double v = s.point.objectives[k];
    if (raise) return isMinimised(k) ? v <= r.hi : v >= r.lo;
    return isMinimised(k) ? v >= r.lo : v <= r.hi;
  };
  double bad = w[k];                // t where the bound is not reached
  double good = raise ? 1.0 : 0.0;  // candidate where it is
  ParetoSelection at_good = selector.coarse(withWeight(w, r.objective, good));
  ++out.evaluations;
  if (reached(at_good)) {
    for (int i = 0; i < bisections && std::abs(good - bad) > 1e-12; ++i) {
      const double mid = 0.5 * (good + bad);
      ParetoSelection s = selector.coarse(withWeight(w, r.objective, mid));
      ++out.evaluations;
      if (reached(s)) {
        good = mid;
        at_good = s;
      } else {
        bad = mid;
      }
    }
  }
  // Unreachable: the extreme weight is the best effort.
  out.weights = withWeight(w, r.objective, good);
  out.selection = at_good;
  out.changed = true;
  out.satisfied = r.satisfiedBy(at_good.point);
  return out;
}

GradientAscentResult ascendWeights(const ParetoSelector& selector, const ParetoWeights& start,
                                   const GradientAscentSettings& s,
                                   const std::optional<ObjectiveRequirement>& requirement) {
  validateParetoWeights(start);
  if (!(s.step > 0.0 && s.step <= 1.0))
    throw InvalidInput("auto_weights.step = " + std::to_string(s.step) + ": must be in (0, 1]");
  if (!(s.tolerance > 0.0 && s.tolerance < 1.0))
    throw InvalidInput("auto_weights.tolerance = " + std::to_string(s.tolerance) + ": must be in (0, 1)");
  if (s.max_iterations < 1 || s.max_iterations > 100000)
    throw InvalidInput("auto_weights.max_iterations = " + std::to_string(s.max_iterations) +
                       ": must be in [1, 100000]");
  GradientAscentResult out;
  out.weights = start;
  out.history.push_back(start);
  out.selection = selector.coarse(start, requirement);
  for (int it = 0; it < s.max_iterations; ++it) {
    const ObjectiveVector& g = out.selection.scores;  // grad_w J at the current optimum
    double mean = 0.0;
    for (double v : g) mean += v / static_cast<double>(kObjectiveCount);
    double norm = 0.0;
    ParetoWeights next = out.weights;
    for (std::size_t i = 0; i < kObjectiveCount; ++i) {
      const double pg = g[i] - mean;
      norm += pg * pg;
      next[i] += s.step * pg;
    }
    if (std::sqrt(norm) < s.tolerance) {
      out.converged = true;
      break;
    }
    next = renormaliseBySum(next);  // Rule 13, variant 1
    double moved = 0.0;
    for (std::size_t i = 0; i < kObjectiveCount; ++i) moved = std::max(moved, std::abs(next[i] - out.weights[i]));
    out.weights = next;
    out.history.push_back(next);
    out.selection = selector.coarse(next, requirement);
    out.iterations = it + 1;
    if (moved < s.tolerance) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace mx
