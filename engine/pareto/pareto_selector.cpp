#include "pareto/pareto_selector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/invalid_input.h"

namespace mx {

ParetoSelection ParetoSelector::coarse(const ParetoWeights& w,
                                       const std::optional<ObjectiveRequirement>& filter) const {
  validateParetoWeights(w);
  const ObjectiveTable& t = *table_;
  if (t.empty()) throw InvalidInput("the admissible space Q is empty: no Pareto selection");
  auto best_of = [&](bool use_filter) {
    std::optional<std::size_t> best;
    double best_j = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (use_filter && !filter->satisfiedBy(t.points()[i])) continue;
      const double j = objectiveJ(w, t.scores()[i]);
      if (j > best_j) {
        best_j = j;
        best = i;
      }
    }
    return best;
  };
  ParetoSelection s;
  std::optional<std::size_t> best = filter ? best_of(true) : best_of(false);
  if (!best) {
    best = best_of(false);
    s.filtered = false;
  }
  s.table_index = best;
  s.point = t.points()[*best];
  s.scores = t.scores()[*best];
  s.j = objectiveJ(w, s.scores);
  s.candidates = t.size();
  return s;
}

ParetoSelection ParetoSelector::fine(const ParetoSelection& coarse, const ParetoWeights& w,
                                     const FineSearchSettings& settings,
                                     const std::optional<ObjectiveRequirement>& filter) const {
  validateParetoWeights(w);
  if (settings.divisions < 1 || settings.divisions > 100)
    throw InvalidInput("fine.divisions = " + std::to_string(settings.divisions) + ": must be in [1, 100]");
  const ObjectiveTable& t = *table_;
  const AdmissibleGrid& g = t.grid();
  const ParetoPoint& q = coarse.point;

  // Neighbouring coarse speeds (the grid may be non-uniform: Rule 7.2 speeds).
  const std::vector<double>& speeds = g.speeds();
  double left = q.speed_rev_per_s, right = q.speed_rev_per_s;
  auto it = std::lower_bound(speeds.begin(), speeds.end(), q.speed_rev_per_s - 1e-9);
  if (it != speeds.begin()) left = *std::prev(it);
  auto jt = std::upper_bound(speeds.begin(), speeds.end(), q.speed_rev_per_s + 1e-9);
  if (jt != speeds.end()) right = *jt;

  const int d = settings.divisions;
  ParetoSelection best = coarse;
  best.table_index = coarse.table_index;
  std::size_t scored = 0;
  for (int i = -d; i <= d; ++i) {
    const double n = i < 0 ? q.speed_rev_per_s + (q.speed_rev_per_s - left) * i / d
                           : q.speed_rev_per_s + (right - q.speed_rev_per_s) * i / d;
    for (int k = -d; k <= d; ++k) {
      const double b = q.depth_m + g.depthStep() * k / d;
      // Stay inside Q's extent: the first grid depth and feed are its lower ends (the power laws of
      // TOL and SURF are singular at b, s_t -> 0, and Rule 9's ranges are Q's).
      if (b < g.depthStep() * (1.0 - 1e-9)) continue;
      std::optional<double> ros;  // depends on (N, b) only
      for (int l = -d; l <= d; ++l) {
        if (i == 0 && k == 0 && l == 0) continue;
        const double s = q.feed_per_tooth_m + g.feedStep() * l / d;
        if (s < g.feedStep() * (1.0 - 1e-9)) continue;
        if (!g.isAdmissible(n, b, s)) continue;
        ParetoPoint p = t.evaluate(n, b, s, ros);
        ros = p.ros();
        if (filter && coarse.filtered && !filter->satisfiedBy(p)) continue;
        ++scored;
        const ObjectiveVector sc = t.normalise(p.objectives);
        const double j = objectiveJ(w, sc);
        if (j > best.j) {
          best.point = p;
          best.scores = sc;
          best.j = j;
          best.table_index.reset();
        }
      }
    }
  }
  best.candidates = scored + 1;
  return best;
}

}  // namespace mx
