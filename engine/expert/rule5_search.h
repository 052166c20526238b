#pragma once
// Rule 5 of the 2006 expert system (section 3.C, eq. 18-20): q** minimises C_resultant "calculated for
// the allowable cutting space parameter". C_t and C_f need one time-domain simulation per point, so Q is
// not scored whole: a pattern search scores a neighbourhood of q* in speed, depth and feed and follows
// the descent.
//   Each iteration simulates every admissible point centre + (i dN, j db, k ds), i, j, k in {-1, 0, 1},
//   not simulated yet (a variable whose step fell below its resolution keeps the centre's value). The
//   centre becomes the argmin of C_resultant over every point simulated so far, with the maxima of
//   eq. 18-19 taken over that cumulative set, so the argmins of successive iterations are comparable and
//   the centre's C_resultant can only be beaten, never lost. When the centre stays, the steps halve.
//   The search stops when no variable is varied any more, or after max_iterations.
// The first iteration also simulates the seeds (the best K grid points by C): q** is never worse by
// C_resultant than the choice among the seeds alone, on the same normalisation.
#include <cstddef>
#include <functional>
#include <vector>

#include "expert/admissible_grid.h"
#include "expert/cost_weights.h"
#include "expert/expert_settings.h"
#include "expert/response_metrics.h"
#include "expert/resultant_cost.h"
#include "expert/tool_cost.h"

namespace mx {

struct Rule5Steps {
  double speed_rev_per_s = 0.0;
  double depth_m = 0.0;
  double feed_per_tooth_m = 0.0;
};

// The settings' start steps, each 0 replaced by one derived from the grid (see rule5_search.cpp).
Rule5Steps rule5StartSteps(const AdmissibleGrid& grid, const ExpertGrid& spacing, const Rule5SearchSettings& settings);

// The cost-function inputs at an arbitrary (N, b, s_t), computed as AdmissibleGrid computes its cells:
// peak power and MRR proportional to N b s_t, Delta N_s from the margined boundary.
ExpertPoint expertPointAt(const AdmissibleGrid& grid, double speed_rev_per_s, double depth_m, double feed_per_tooth_m);

struct Rule5Problem {
  const AdmissibleGrid* grid = nullptr;
  double speed_from_rev_per_s = 0.0;  // the grid's speed range bounds the search
  double speed_to_rev_per_s = 0.0;
  CostNormalisation nf;  // the session's NF1..NF3 (eq. 13, over all tools)
  CostWeights weights;
  std::function<bool(const ExpertPoint&)> admit;  // further constraints (operator rules); empty: none
  // The response metrics of the points, in order (the session's SimulationCache: parallel, cached).
  std::function<std::vector<ResponseMetrics>(const std::vector<ExpertPoint>&)> simulate;
};

struct Rule5Result {
  std::vector<RefinementCandidate> candidates;  // every point simulated: the seeds, then in search order
  std::size_t best = 0;                         // q** = candidates[best].q
  int iterations = 0;
  bool converged = false;  // stopped on the resolutions rather than on max_iterations
  Rule5Steps final_steps;
};

// True when the search may score (N, b, s_t): admissible in Q (AdmissibleGrid::isAdmissible), inside
// the grid's speed range and accepted by problem.admit.
bool rule5Admits(const Rule5Problem& problem, const ExpertPoint& point);

// q_star: the centre of the first iteration; seeds: grid points of Q, simulated in the first iteration
// (typically the best K by C, q* among them). Throws InvalidInput when nothing can be simulated.
// start: the first steps (rule5StartSteps). max_iterations = 0 simulates the seeds only.
Rule5Result searchRule5(const Rule5Problem& problem, const ExpertPoint& q_star, const std::vector<ExpertPoint>& seeds,
                        const Rule5Steps& start, const Rule5SearchSettings& settings);

}  // namespace mx
