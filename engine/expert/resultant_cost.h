#pragma once
// Rule 5 of the 2006 expert system: the cutting parameters of the selected tool minimise
//   C_resultant = c1r C + c2r C_t + c3r C_f                                         (eq. 20)
//   C_t = c1t t_s / t_s,max + c2t M_p / M_p,max                                    (eq. 18)
//   C_f = c1f R12h / R12h,max + c2f R1ch / R1ch,max                                (eq. 19, as read)
// with the maxima taken over the candidates passed in (the points actually simulated for this
// selection). A maximum below 1e-9 (round-off, e.g. R1ch of stable cuts) makes its term zero.
#include <cstddef>
#include <vector>

#include "expert/admissible_grid.h"
#include "expert/cost_weights.h"
#include "expert/response_metrics.h"

namespace mx {

struct RefinementCandidate {
  ExpertPoint q;
  double cost = 0.0;  // C (eq. 13)
  ResponseMetrics metrics;
  double time_cost = 0.0;       // C_t
  double frequency_cost = 0.0;  // C_f
  double resultant = 0.0;       // C_resultant
};

// Fills C_t, C_f and C_resultant of every candidate and returns the index of the minimum C_resultant
// (ties as in rankBefore). Throws InvalidInput for an empty set.
std::size_t selectByResultantCost(std::vector<RefinementCandidate>& candidates, const CostWeights& weights);

}  // namespace mx
