#pragma once
// Automatic modification of the weights (Pareto paper, Rules 11-13). The symbols of the printed rules
// were lost in extraction; the rules implemented are:
//
// Rule 11 (requirement bounds, e.g. MRR in [lo, hi]): when the coarse optimum q*(w) violates the
//   bound, only the weight w_k of the required objective k is changed and the others keep their
//   proportions (Rule 13 variant 2). With w(t) = (w_k = t, others (1 - t) w_j / sum_{i!=k} w_i), the
//   score n_k(q*(w(t))) is non-decreasing in t (linear scalarisation: J = t n_k + (1 - t) g, so the
//   optimum's n_k cannot fall when t rises). If the value is too low (too high for SURF, which is
//   reversed) t is bisected in [w_k, 1] for the smallest t whose optimum reaches the bound; if too
//   high, in [0, w_k] for the largest such t. The smallest weight change that meets the violated
//   bound therefore also gives the optimum nearest to it; `satisfied` says whether the other bound
//   holds too (a gap in the front can make [lo, hi] unreachable by weights alone).
//
// Rule 12 (gradient ascent on the weights, Passino 2004): w[k+1] = w[k] + step * P grad_w J(w[k]),
//   with grad_w J = n(q*(w)) (envelope theorem: J(w) = max_q sum w_i n_i(q)) and P the projection on
//   the simplex's plane (subtract the mean), followed by Rule 13 (variant 1) to stay on the simplex.
//   Stops when |P grad| < tolerance, when the weights move by less than tolerance (a vertex or face of
//   the simplex), or after max_iterations. An optional requirement restricts the selection (the
//   requirement acts as a constraint of the ascent).
#include <optional>
#include <vector>

#include "pareto/pareto_selector.h"

namespace mx {

struct RequirementResult {
  ParetoWeights weights{};
  ParetoSelection selection;
  bool changed = false;    // the weights were modified
  bool satisfied = false;  // the final coarse optimum meets [lo, hi]
  int evaluations = 0;     // coarse selections made
};

RequirementResult applyRequirement(const ParetoSelector& selector, const ParetoWeights& w,
                                   const ObjectiveRequirement& requirement, int bisections = 40);

struct GradientAscentSettings {
  double step = 0.05;       // eta of Rule 12
  double tolerance = 1e-4;  // on |P grad| and on the weight change
  int max_iterations = 200;
};

struct GradientAscentResult {
  ParetoWeights weights{};
  ParetoSelection selection;
  int iterations = 0;
  bool converged = false;              // stopped by a tolerance, not by max_iterations
  std::vector<ParetoWeights> history;  // weights after each step (history[0] = start)
};

// Throws InvalidInput for step not in (0, 1], tolerance not in (0, 1) or max_iterations not in [1, 1e5].
GradientAscentResult ascendWeights(const ParetoSelector& selector, const ParetoWeights& start,
                                   const GradientAscentSettings& settings,
                                   const std::optional<ObjectiveRequirement>& requirement = {});

}  // namespace mx
