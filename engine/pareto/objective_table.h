#pragma once
// The objectives of every point of the admissible space Q of one tool (Pareto paper, eq. 10-13) and
// their Rule 9 normalisation (eq. 14) to "higher is better" scores, min and max over Q:
//   MinMax (the paper's Rule 9): n = (x - min) / (max - min); SURF reversed, (max - x) / (max - min).
//   Max: n = x / max; SURF 1 - x / max.
//   Log: TOL and SURF, power laws spanning decades, score ln(x / min) / ln(max / min) (SURF reversed);
//        MRR and ROS as MinMax. An equal ratio of tool life (or roughness) is then worth the same
//        anywhere in Q, which is how the Taylor model is fitted and read.
// A constant objective (max = min) scores 1 everywhere. Every variant is a strictly monotone map of
// each objective, so the non-dominated set does not depend on it.
//
// ROS (eq. 13) is StabilityBoundary::robustness, the one definition used everywhere: the distance from
// (N, b) to the margined boundary alpha * b_lim(N) relative to the point's own N and b. It does not
// depend on the feed.
#include <cstddef>
#include <optional>
#include <vector>

#include "expert/admissible_grid.h"
#include "pareto/empirical_models.h"
#include "pareto/objectives.h"

namespace mx {

enum class ParetoNormalisation { MinMax, Max, Log };

struct ObjectiveRange {
  ObjectiveVector min{};
  ObjectiveVector max{};
};

class ObjectiveTable {
 public:
  // Enumerates Q (every cell and admissible feed of the grid). Throws InvalidInput for invalid models.
  ObjectiveTable(const AdmissibleGrid& grid, const ParetoModels& models,
                 ParetoNormalisation normalisation = ParetoNormalisation::MinMax);

  const AdmissibleGrid& grid() const { return *grid_; }
  const ParetoModels& models() const { return models_; }
  ParetoNormalisation normalisation() const { return normalisation_; }
  const std::vector<ParetoPoint>& points() const { return points_; }
  const std::vector<ObjectiveVector>& scores() const { return scores_; }  // Rule 9, aligned with points()
  const ObjectiveRange& range() const { return range_; }
  std::size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }

  // Objectives of an arbitrary point (fine search) with the same models. Does not check
  // admissibility (AdmissibleGrid::isAdmissible does).
  // `ros` reuses a known ROS of (N, b).
  ParetoPoint evaluate(double speed_rev_per_s, double depth_m, double feed_per_tooth_m,
                       std::optional<double> ros = {}) const;
  // Rule 9 scores with Q's ranges (may leave [0, 1] for points outside Q's extremes).
  ObjectiveVector normalise(const ObjectiveVector& raw) const;

 private:
  double normaliseOne(std::size_t i, double x) const;

  const AdmissibleGrid* grid_;
  ParetoModels models_;
  ParetoNormalisation normalisation_;
  std::vector<ParetoPoint> points_;
  std::vector<ObjectiveVector> scores_;
  ObjectiveRange range_;
};

}  // namespace mx
