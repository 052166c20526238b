#pragma once
// Rule 14: initial weights for a new job from the most similar past jobs.
//
// Similarity (docs/learning-database.md): only past jobs on the SAME material (exact name) with the
// same number of weights qualify. Their distance to the new job is
//     d = |D_i - D| / D + |z_i - z| / z
// (relative difference of tool diameter D plus relative difference of the number of teeth z; both
// dimensionless, equally weighted; ties go to the newer job). The suggestion is the component-wise
// mean of the weights of the k nearest jobs, projected back onto the simplex (negatives clipped to 0,
// divided by the sum; uniform if everything clipped). No qualifying job: no suggestion.
#include <QString>
#include <optional>
#include <vector>

#include "services/learning_record.h"

namespace mx::app {

struct JobFeatures {
  QString material;
  double tool_diameter_mm = 0.0;
  int tool_teeth = 0;
  std::size_t weight_count = 4;  // tol, mrr, surf, ros
};

struct WeightSuggestion {
  std::vector<double> weights;    // on the simplex
  std::vector<qint64> from_ids;   // the k nearest records, nearest first
  std::vector<double> distances;  // their distances d
};

double jobDistance(const LearningRecord& past, const JobFeatures& job);

// Pure ranking over candidate records (any material; non-qualifying ones are ignored). k >= 1.
std::optional<WeightSuggestion> suggestWeights(const std::vector<LearningRecord>& candidates, const JobFeatures& job,
                                               int k);

// Clips negatives and divides by the sum; uniform when nothing positive remains.
std::vector<double> projectOntoSimplex(std::vector<double> weights);

}  // namespace mx::app
