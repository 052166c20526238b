#include "services/weight_suggestion.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mx::app {

double jobDistance(const LearningRecord& past, const JobFeatures& job) {
  return std::abs(past.tool.diameter_mm - job.tool_diameter_mm) / job.tool_diameter_mm +
         std::abs(static_cast<double>(past.tool.teeth - job.tool_teeth)) / static_cast<double>(job.tool_teeth);
}

std::vector<double> projectOntoSimplex(std::vector<double> weights) {
  double sum = 0.0;
  for (double& w : weights) {
    if (!std::isfinite(w) || w < 0.0) w = 0.0;
    sum += w;
  }
  if (weights.empty()) return weights;
  if (sum <= 0.0) return std::vector<double>(weights.size(), 1.0 / static_cast<double>(weights.size()));
  for (double& w : weights) w /= sum;
  return weights;
}

std::optional<WeightSuggestion> suggestWeights(const std::vector<LearningRecord>& candidates, const JobFeatures& job,
                                               int k) {
  if (k < 1) throw std::invalid_argument("suggestWeights: k must be >= 1");
  if (!(job.tool_diameter_mm > 0.0) || job.tool_teeth < 1 || job.weight_count == 0)
    throw std::invalid_argument("suggestWeights: the job needs a diameter > 0, teeth >= 1 and weights");
  struct Ranked {
    const LearningRecord* record;
    double distance;
  };
  std::vector<Ranked> ranked;
  for (const LearningRecord& r : candidates)
    if (r.material == job.material && r.weights.size() == job.weight_count) ranked.push_back({&r, jobDistance(r, job)});
  if (ranked.empty()) return std::nullopt;
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
    if (a.distance != b.distance) return a.distance < b.distance;
    if (a.record->time != b.record->time) return a.record->time > b.record->time;  // newer first
    return a.record->id > b.record->id;
  });
  ranked.resize(std::min(ranked.size(), static_cast<std::size_t>(k)));

  WeightSuggestion s;
  std::vector<double> mean(job.weight_count, 0.0);
  for (const Ranked& r : ranked) {
    for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += r.record->weights[i];
    s.from_ids.push_back(r.record->id);
    s.distances.push_back(r.distance);
  }
  for (double& w : mean) w /= static_cast<double>(ranked.size());
  s.weights = projectOntoSimplex(std::move(mean));
  return s;
}

}  // namespace mx::app
