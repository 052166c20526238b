#pragma once
// The non-dominated (Pareto) set of points with four "higher is better" scores (Rule 9 scores, SURF
// already reversed). a dominates b when a_i >= b_i for every i and a_j > b_j for some j; equal
// vectors do not dominate each other (both are kept).
//
// nonDominated: first SaLSa (Bartolini, Ciaccia & Patella 2008), a presorted skyline with early stop,
//   O(n m) for a front of m points and the fastest for the small fronts of real grids; it gives up
//   after kSkylineTestsPerPoint * n dominance tests and the divide and conquer below decides instead.
//   NaN counts as the worst score.
// nonDominatedDivideAndConquer: Kung, Luccio & Preparata (1975) in the CDQ form: the distinct vectors
//   sorted lexicographically descending (every dominator precedes what it dominates), halves solved
//   recursively, then every later-half point tested against the earlier half by one sweep in
//   descending objective 1 with a Fenwick tree over the ranks of objective 2 holding the best objective
//   3. O(n log^2 n) whatever the front size. bench/bench_pareto.cpp: 100k uniform and anti-correlated.
// nonDominatedBruteForce: the O(n^2) definition, for tests.
#include <cstddef>
#include <vector>

#include "pareto/objectives.h"

namespace mx {

inline constexpr std::size_t kSkylineTestsPerPoint = 256;

bool dominates(const ObjectiveVector& a, const ObjectiveVector& b);

// Indices into `scores` of the non-dominated points, ascending.
std::vector<std::size_t> nonDominated(const std::vector<ObjectiveVector>& scores);
std::vector<std::size_t> nonDominatedDivideAndConquer(const std::vector<ObjectiveVector>& scores);
std::vector<std::size_t> nonDominatedBruteForce(const std::vector<ObjectiveVector>& scores);

}  // namespace mx
