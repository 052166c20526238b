#pragma once
// The non-dominated (Pareto) set of points with four "higher is better" scores (Rule 9 scores, SURF
// already reversed). a dominates b when a_i >= b_i for every i and a_j > b_j for some j; equal
// vectors do not dominate each other (both are kept).
//
// nonDominated: SaLSa (Bartolini, Ciaccia & Patella 2008), a presorted skyline with early stop.
//   1. Sort by (max_i s_i desc, sum_i s_i desc). A point can only be dominated by a point earlier in
//      this order (a dominator has max >= and a strictly larger sum), so a point not dominated by the
//      current window of non-dominated points is final: the window only grows.
//   2. Stop point: the window member with the largest min_i s_i. Once that min exceeds the current
//      point's max, it strictly dominates it and every later point: stop.
//   Cost O(n log n + n m) for a front of size m, m << n in practice (about (ln n)^3 / 6 for random
//   points); the window is scanned in SoA form. bench/bench_pareto.cpp measures it on 100k points.
// nonDominatedBruteForce: the O(n^2) definition, for tests.
#include <cstddef>
#include <vector>

#include "pareto/objectives.h"

namespace mx {

bool dominates(const ObjectiveVector& a, const ObjectiveVector& b);

// Indices into `scores` of the non-dominated points, ascending.
std::vector<std::size_t> nonDominated(const std::vector<ObjectiveVector>& scores);
std::vector<std::size_t> nonDominatedBruteForce(const std::vector<ObjectiveVector>& scores);

}  // namespace mx
