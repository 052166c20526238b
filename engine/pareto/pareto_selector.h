#pragma once
// Rule 10: Pareto-optimal cutting parameters for given weights.
//   10.1 coarse selection: q* = argmax over Q of J = sum w_i n_i (eq. 9, 16; the paper words it as the
//        minimum of a cost, with SURF entering inversely: maximising J with SURF reversed is the same).
//   10.2 fine selection (eq. 17): a finer grid around q*, spanning the neighbouring coarse grid values
//        in each direction (the adjacent grid speeds, b* +- one depth step, s_t* +- one feed step),
//        with `divisions` sub-steps per coarse step; every admissible point of it
//        (AdmissibleGrid::isAdmissible) is scored with Q's Rule 9 ranges. q* itself is a candidate,
//        so the fine J is never below the coarse J.
// An optional requirement filter (Rule 11/12) restricts the candidates; when no point of Q passes it,
// the unrestricted optimum is returned with `filtered = false`.
#include <cstddef>
#include <functional>
#include <optional>

#include "pareto/objective_table.h"
#include "pareto/pareto_weights.h"

namespace mx {

struct FineSearchSettings {
  int divisions = 5;  // sub-steps per coarse step; (2 divisions + 1)^3 candidates
};

struct ParetoSelection {
  ParetoPoint point;
  ObjectiveVector scores{};                // Rule 9 scores of point
  double j = 0.0;                          // eq. 9
  std::optional<std::size_t> table_index;  // index in the table (coarse) or nullopt (fine, off-grid)
  bool filtered = true;                    // false: the filter rejected every point and was ignored
  std::size_t candidates = 0;              // points scored
};

// Requirement bounds on raw objective values (Rule 11): value in [lo, hi].
struct ObjectiveRequirement {
  Objective objective = Objective::Mrr;
  double lo = 0.0;
  double hi = 0.0;
  bool satisfiedBy(const ParetoPoint& p) const {
    const double v = p.objectives[index(objective)];
    return v >= lo && v <= hi;
  }
};

class ParetoSelector {
 public:
  explicit ParetoSelector(const ObjectiveTable& table) : table_(&table) {}

  // Rule 10.1. Throws InvalidInput when the table is empty or the weights are off the simplex.
  ParetoSelection coarse(const ParetoWeights& w, const std::optional<ObjectiveRequirement>& filter = {}) const;
  // Rule 10.2 around a coarse selection.
  ParetoSelection fine(const ParetoSelection& coarse, const ParetoWeights& w, const FineSearchSettings& settings,
                       const std::optional<ObjectiveRequirement>& filter = {}) const;

 private:
  const ObjectiveTable* table_;
};

}  // namespace mx
