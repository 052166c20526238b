#pragma once
// The objectives of every point of the admissible space Q of one tool (Pareto paper, eq. 10-13) and
// their Rule 9 min-max normalisation (eq. 14): n_i = (x_i - min_i) / (max_i - min_i) for TOL, MRR and
// ROS, n_SURF = (max - x) / (max - min) so that lower roughness scores higher; min and max over Q.
// A constant objective (max = min) scores 1 everywhere.
//
// ROS (eq. 13) is StabilityBoundary::robustness: the Euclidean distance from (N, b) to the nearest
// point of the margined boundary alpha * b_lim(N), with N divided by the span of Q's speeds and b by
// the span of Q's depths (robustnessSpans()). It does not depend on the feed.
#include <cstddef>
#include <optional>
#include <vector>

#include "expert/admissible_grid.h"
#include "pareto/empirical_models.h"
#include "pareto/objectives.h"

namespace mx {

struct ObjectiveRange {
  ObjectiveVector min{};
  ObjectiveVector max{};
};

class ObjectiveTable {
 public:
  // Enumerates Q (every cell and admissible feed of the grid). Throws InvalidInput for invalid models.
  ObjectiveTable(const AdmissibleGrid& grid, const ParetoModels& models);

  const AdmissibleGrid& grid() const { return *grid_; }
  const ParetoModels& models() const { return models_; }
  const std::vector<ParetoPoint>& points() const { return points_; }
  const std::vector<ObjectiveVector>& scores() const { return scores_; }  // Rule 9, aligned with points()
  const ObjectiveRange& range() const { return range_; }
  const NormalisationSpans& robustnessSpans() const { return spans_; }
  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }

  // Objectives of an arbitrary point (fine search): the same models and ROS spans. Does not check
  // admissibility (AdmissibleGrid::isAdmissible does).
  // `ros` reuses a known ROS of (N, b).
  ParetoPoint evaluate(double speed_rev_per_s, double depth_m, double feed_per_tooth_m,
                       std::optional<double> ros = {}) const;
  // Rule 9 scores with Q's ranges (may leave [0, 1] for points outside Q's extremes).
  ObjectiveVector normalise(const ObjectiveVector& raw) const;

 private:
  const AdmissibleGrid* grid_;
  ParetoModels models_;
  NormalisationSpans spans_;
  std::vector<ParetoPoint> points_;
  std::vector<ObjectiveVector> scores_;
  ObjectiveRange range_;
};

}  // namespace mx
