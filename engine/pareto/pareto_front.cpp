#include "pareto/pareto_front.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace mx {

namespace {

constexpr double kWorst = -std::numeric_limits<double>::infinity();

// Prefix maximum over ranks 0..r (Fenwick tree), with an undo list so each merge step resets only what
// it touched.
class PrefixMax {
 public:
  explicit PrefixMax(std::size_t n) : tree_(n + 1, kWorst) {}
  void raise(std::size_t rank, double value) {
    for (std::size_t i = rank + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] = std::max(tree_[i], value);
    touched_.push_back(rank);
  }
  double upTo(std::size_t rank) const {
    double m = kWorst;
    for (std::size_t i = rank + 1; i > 0; i -= i & (~i + 1)) m = std::max(m, tree_[i]);
    return m;
  }
  void reset() {
    for (std::size_t rank : touched_)
      for (std::size_t i = rank + 1; i < tree_.size(); i += i & (~i + 1)) tree_[i] = kWorst;
    touched_.clear();
  }

 private:
  std::vector<double> tree_;
  std::vector<std::size_t> touched_;
};

// Unique score vectors in lexicographically descending order: every dominator of a point comes before
// it, so "dominated" means "weakly dominated in objectives 1..3 by an earlier point" (objective 0 is
// then >= by the order, and distinct vectors make one inequality strict).
class DivideAndConquer {
 public:
  explicit DivideAndConquer(std::vector<ObjectiveVector> unique)
      : u_(std::move(unique)), dominated_(u_.size(), false), rank2_(u_.size()), fenwick_(u_.size()) {
    std::vector<double> values(u_.size());
    for (std::size_t i = 0; i < u_.size(); ++i) values[i] = u_[i][2];
    std::sort(values.begin(), values.end(), std::greater<>());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    for (std::size_t i = 0; i < u_.size(); ++i)  // rank 0 = the largest objective 2
      rank2_[i] = static_cast<std::size_t>(std::lower_bound(values.begin(), values.end(), u_[i][2], std::greater<>()) -
                                           values.begin());
  }

  std::vector<bool> run() {
    solve(0, u_.size());
    return dominated_;
  }

 private:
  // Points of [lo, mid) precede those of [mid, hi); sweep both in descending objective 1 (earlier half
  // first on ties) and ask, for each later point, whether an earlier one seen so far has objectives
  // 2 and 3 at least as good.
  void solve(std::size_t lo, std::size_t hi) {
    if (hi - lo < 2) return;
    const std::size_t mid = lo + (hi - lo) / 2;
    solve(lo, mid);
    solve(mid, hi);
    scratch_.resize(hi - lo);
    std::iota(scratch_.begin(), scratch_.end(), lo);
    std::sort(scratch_.begin(), scratch_.end(), [&](std::size_t a, std::size_t b) {
      if (u_[a][1] != u_[b][1]) return u_[a][1] > u_[b][1];
      return (a < mid) > (b < mid);
    });
    for (std::size_t i : scratch_) {
      if (i < mid)
        fenwick_.raise(rank2_[i], u_[i][3]);
      else if (!dominated_[i] && fenwick_.upTo(rank2_[i]) >= u_[i][3])
        dominated_[i] = true;
    }
    fenwick_.reset();
  }

  std::vector<ObjectiveVector> u_;
  std::vector<bool> dominated_;
  std::vector<std::size_t> rank2_;
  std::vector<std::size_t> scratch_;
  PrefixMax fenwick_;
};

// SaLSa (Bartolini, Ciaccia & Patella 2008): presorted skyline with early stop. Sorted by (max_i s_i
// desc, sum desc), a point can only be dominated by an earlier one, so the window of non-dominated
// points only grows; the window member with the largest min_i s_i stops the scan once that min exceeds
// the current max. O(n m) for a front of m points: fast for the small fronts of real grids, so it runs
// first, within `budget` dominance tests; nullopt when the budget runs out.
std::optional<std::vector<std::size_t>> presortedSkyline(const std::vector<ObjectiveVector>& s, std::size_t budget) {
  struct Key {
    double max, sum;
    std::size_t i;
  };
  std::vector<Key> order(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    order[i] = {*std::max_element(s[i].begin(), s[i].end()), s[i][0] + s[i][1] + s[i][2] + s[i][3], i};
  std::sort(order.begin(), order.end(), [](const Key& a, const Key& b) {
    if (a.max != b.max) return a.max > b.max;
    if (a.sum != b.sum) return a.sum > b.sum;
    return a.i < b.i;
  });
  std::array<std::vector<double>, kObjectiveCount> win;  // the window in SoA form
  std::vector<std::size_t> front;
  double stop_min = kWorst;
  std::size_t tests = 0;
  for (const Key& k : order) {
    if (stop_min > k.max) break;
    const ObjectiveVector& p = s[k.i];
    const std::size_t m = front.size();
    tests += m;
    if (tests > budget) return std::nullopt;
    bool dominated = false;
    for (std::size_t j = 0; j < m && !dominated; ++j)
      dominated = win[0][j] >= p[0] && win[1][j] >= p[1] && win[2][j] >= p[2] && win[3][j] >= p[3] &&
                  (win[0][j] > p[0] || win[1][j] > p[1] || win[2][j] > p[2] || win[3][j] > p[3]);
    if (dominated) continue;
    for (std::size_t d = 0; d < kObjectiveCount; ++d) win[d].push_back(p[d]);
    front.push_back(k.i);
    stop_min = std::max(stop_min, *std::min_element(p.begin(), p.end()));
  }
  std::sort(front.begin(), front.end());
  return front;
}

}  // namespace

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
  std::vector<ObjectiveVector> s(scores);
  for (ObjectiveVector& v : s)
    for (double& x : v)
      if (std::isnan(x)) x = kWorst;
  if (auto quick = presortedSkyline(s, kSkylineTestsPerPoint * n)) return *quick;
  return nonDominatedDivideAndConquer(s);
}

std::vector<std::size_t> nonDominatedDivideAndConquer(const std::vector<ObjectiveVector>& scores) {
  const std::size_t n = scores.size();
  std::vector<ObjectiveVector> s(scores);
  for (ObjectiveVector& v : s)
    for (double& x : v)
      if (std::isnan(x)) x = kWorst;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (s[a] != s[b]) return s[a] > s[b];
    return a < b;
  });
  std::vector<ObjectiveVector> unique;
  std::vector<std::size_t> group(n);  // group[k]: the unique vector of order[k]
  for (std::size_t k = 0; k < n; ++k) {
    if (k == 0 || s[order[k]] != s[order[k - 1]]) unique.push_back(s[order[k]]);
    group[k] = unique.size() - 1;
  }
  const std::vector<bool> dominated = DivideAndConquer(std::move(unique)).run();
  std::vector<std::size_t> front;
  for (std::size_t k = 0; k < n; ++k)
    if (!dominated[group[k]]) front.push_back(order[k]);
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
