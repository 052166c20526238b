#pragma once
// Operator weights of the Pareto objective J = sum_i w_i n_i (eq. 9; Rule 8), on the simplex
// (w_i >= 0, sum w_i = 1), in the order TOL, MRR, SURF, ROS, and the two renormalisations of Rule 13.
//
// Rule 13 (the extracted text lost the symbols; read as):
//   variant 1 (Rule13Variant::Sum): w_i <- max(w_i, 0); w_i <- w_i / sum_j w_j (all weights scaled alike);
//   variant 2 (Rule13Variant::KeepChanged): the weight k that a rule just set is kept (clamped to
//     [0, 1]) and the others share 1 - w_k in their previous proportions,
//     w_j <- (1 - w_k) w_j / sum_{i != k} w_i (equal shares when they were all 0).
#include <array>

#include "pareto/objectives.h"

namespace mx {

using ParetoWeights = std::array<double, kObjectiveCount>;

inline constexpr double kParetoWeightTolerance = 1e-6;

// Throws InvalidInput "w = [..]: ..." when a weight is negative/not finite or the sum is off by > 1e-6.
void validateParetoWeights(const ParetoWeights& w);
bool onSimplex(const ParetoWeights& w, double tolerance = kParetoWeightTolerance);

enum class Rule13Variant { Sum, KeepChanged };

// Variant 1. All weights <= 0 (or not finite) gives equal weights.
ParetoWeights renormaliseBySum(ParetoWeights w);
// Variant 2, keeping weight `changed`.
ParetoWeights renormaliseKeeping(ParetoWeights w, Objective changed);

// The weights with w_k = value and the others rescaled by variant 2.
ParetoWeights withWeight(const ParetoWeights& w, Objective k, double value);

double objectiveJ(const ParetoWeights& w, const ObjectiveVector& scores);

}  // namespace mx
