#include "pareto/pareto_front.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace mx {

bool dominates(const ObjectiveVector& a, const ObjectiveVector& b) {
  bool strict = false;
  for (std::size_t i = 0; i < kObjectiveCount; ++i) {
    if (a[i] < b[i]) return false;
    if (a[i] > b[i]) strict = true;
  }
  return strict;
}

std::vector<std::size_t> nonDominated(const std::vector<ObjectiveVector>& scores) {
  const std::size_t n = scores.size();
  struct Key {
    double max, sum;
    std::size_t i;
  };
  std::vector<Key> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ObjectiveVector& s = scores[i];
    order[i] = {*std::max_element(s.begin(), s.end()), s[0] + s[1] + s[2] + s[3], i};
  }
  std::sort(order.begin(), order.end(), [](const Key& a, const Key& b) {
    if (a.max != b.max) return a.max > b.max;
    if (a.sum != b.sum) return a.sum > b.sum;
    return a.i < b.i;
  });

  // Window of non-dominated points in SoA form.
  std::array<std::vector<double>, kObjectiveCount> win;
  std::vector<std::size_t> front;
  double stop_min = -std::numeric_limits<double>::infinity();
  for (const Key& k : order) {
    if (stop_min > k.max) break;  // the stop point strictly dominates this and every later point
    const ObjectiveVector& p = scores[k.i];
    bool dominated = false;
    const std::size_t m = front.size();
    const double* w0 = win[0].data();
    const double* w1 = win[1].data();
    const double* w2 = win[2].data();
    const double* w3 = win[3].data();
    for (std::size_t j = 0; j < m; ++j) {
      // Weak dominance plus strictness; an equal vector does not dominate.
      if (w0[j] >= p[0] && w1[j] >= p[1] && w2[j] >= p[2] && w3[j] >= p[3] &&
          (w0[j] > p[0] || w1[j] > p[1] || w2[j] > p[2] || w3[j] > p[3])) {
        dominated = true;
        break;
      }
    }
    if (dominated) continue;
    for (std::size_t d = 0; d < kObjectiveCount; ++d) win[d].push_back(p[d]);
    front.push_back(k.i);
    stop_min = std::max(stop_min, *std::min_element(p.begin(), p.end()));
  }
  std::sort(front.begin(), front.end());
  return front;
}

std::vector<std::size_t> nonDominatedBruteForce(const std::vector<ObjectiveVector>& scores) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < scores.size() && !dominated; ++j) dominated = j != i && dominates(scores[j], scores[i]);
    if (!dominated) front.push_back(i);
  }
  return front;
}

}  // namespace mx
